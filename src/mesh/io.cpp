#include "stitch/mesh/io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <random>
#include <sstream>
#include <utility>

#include "mesh/mesh_reader.hpp"
#include "mesh/mesh_writer.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch {

namespace detail {

std::string at_line(const std::string& path, int line) {
  return fmt::format("{}, line {}", path, line);
}

namespace {

// std::from_chars does not take a leading '+', which some writers emit.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
    token.remove_prefix(1);
  return token;
}

}  // namespace

double parse_number(std::string_view token, const Where& where) {
  const std::string_view t = without_plus(token);
  double value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw InputError(fmt::format("{}: number '{}' is out of range", where, limits::quoted(token)));
  if (ec != std::errc() || end != t.data() + t.size())
    throw InputError(fmt::format("{}: '{}' is not a number", where, limits::quoted(token)));
  return value;
}

double parse_double(std::string_view token, const Where& where) {
  const double value = parse_number(token, where);
  if (!std::isfinite(value))
    throw InputError(
        fmt::format("{}: coordinate '{}' is not finite", where, limits::quoted(token)));
  return value;
}

long long parse_integer(std::string_view token, const Where& where) {
  const std::string_view t = without_plus(token);
  long long value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw InputError(fmt::format("{}: integer '{}' is out of range", where, limits::quoted(token)));
  if (ec != std::errc() || end != t.data() + t.size())
    throw InputError(fmt::format("{}: '{}' is not an integer", where, limits::quoted(token)));
  return value;
}

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  tokens(line, out);
  return out;
}

void tokens(std::string_view line, std::vector<std::string_view>& out) {
  if (const size_t hash = line.find('#'); hash != std::string_view::npos)
    line = line.substr(0, hash);
  out.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end + 1;
  ++line_;
  return true;
}

void require_text(std::string_view line, const std::string& path, int line_number) {
  for (char c : line) {
    const auto byte = static_cast<unsigned char>(c);
    // Control characters other than tab/CR/form feed do not occur in text; bytes >= 0x80 may
    // (UTF-8 in comments), so they are left to the parsers.
    if (byte < 0x20 && c != '\t' && c != '\r' && c != '\f')
      throw InputError(
          fmt::format("{}: not a text file (byte 0x{:02x})", at_line(path, line_number), byte));
  }
}

}  // namespace detail

namespace {

constexpr std::string_view kComment = "written by stitch";

/// The soup's crease and corner tags as OpenSubdiv's `t` lines (vertices counted from 0, one
/// line per element so a diff shows which changed), and its crease method when not the default;
/// the OBJ reader reads them back.
void write_obj_tags(detail::OutputFile& out, const PolygonSoup& soup) {
  if (soup.crease_method == CreaseMethod::chaikin) out << "t creasemethod 0/0/1 chaikin\n";
  for (const SoupCrease& c : soup.creases)
    out << fmt::format("t crease 2/1/0 {} {} {}\n", c.a, c.b, c.sharpness);
  for (const SoupCorner& c : soup.corners)
    out << fmt::format("t corner 1/1/0 {} {}\n", c.vertex, c.sharpness);
}

/// Refuses tags that would not read back (what is written must read again).
void check_tags(const std::string& path, const PolygonSoup& soup) {
  const int nv = static_cast<int>(soup.positions.size());
  auto check = [&](double sharpness, std::initializer_list<int> vertices, const char* what) {
    if (!std::isfinite(sharpness) || sharpness < 0)
      throw OutputError(
          fmt::format("cannot write {}: a {} tag has sharpness {}", path, what, sharpness));
    for (int v : vertices)
      if (v < 0 || v >= nv)
        throw OutputError(fmt::format("cannot write {}: a {} tag refers to vertex {} of {}", path,
                                      what, v + 1, nv));
  };
  for (const SoupCrease& c : soup.creases) check(c.sharpness, {c.a, c.b}, "crease");
  for (const SoupCorner& c : soup.corners) check(c.sharpness, {c.vertex}, "corner");
}

}  // namespace

std::string read_regular_file(const std::string& path,
                              const std::function<void(double)>& progress) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);  // follows symbolic links
  if (ec) throw InputError(fmt::format("{}: cannot open: {}", path, ec.message()));
  if (std::filesystem::is_directory(status))
    throw InputError(fmt::format("{}: is a folder, not a file", path));
  // A FIFO, a device such as /dev/zero or a socket may never end: only plain files are read.
  if (!std::filesystem::is_regular_file(status))
    throw InputError(fmt::format("{}: not a regular file (a pipe, device or socket)", path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open: {}", path, std::strerror(errno)));
  if (progress) {
    // In large pieces, so that a slow disk shows how far it is.
    const auto size = std::filesystem::file_size(path, ec);
    std::string bytes;
    if (!ec) bytes.reserve(size);
    std::vector<char> piece(std::size_t{16} << 20);
    while (in) {
      in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
      bytes.append(piece.data(), static_cast<std::size_t>(in.gcount()));
      if (!ec && size > 0) progress(static_cast<double>(bytes.size()) / static_cast<double>(size));
    }
    if (in.bad()) throw InputError(fmt::format("{}: read error", path));
    return bytes;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(fmt::format("{}: read error", path));
  return std::move(buffer).str();
}

std::string extension_list(std::span<const std::string_view> extensions) {
  std::string list;
  for (std::string_view e : extensions) list += (list.empty() ? "" : ", ") + std::string(e);
  return list;
}

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::optional<MeshFileFormat> mesh_file_format(const std::string& path,
                                               std::span<const std::string_view> extensions) {
  static constexpr std::array<std::pair<std::string_view, MeshFileFormat>, 6> kFormats{{
      {".obj", MeshFileFormat::obj},
      {".ply", MeshFileFormat::ply},
      {".off", MeshFileFormat::off},
      {".stl", MeshFileFormat::stl},
      {".glb", MeshFileFormat::glb},
      {".gltf", MeshFileFormat::gltf},
  }};
  const std::string ext = file_extension(path);
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) return std::nullopt;
  for (const auto& [extension, format] : kFormats)
    if (extension == ext) return format;
  return std::nullopt;
}

PolygonSoup read_polygon_soup(const std::string& path, std::vector<std::string>* warnings,
                              const std::function<void(double)>& progress) {
  const std::optional<MeshFileFormat> format = mesh_file_format(path, kMeshReadExtensions);
  if (!format)
    throw UsageError(fmt::format("{}: cannot read files with extension '{}' (supported: {})", path,
                                 limits::quoted(file_extension(path)),
                                 extension_list(kMeshReadExtensions)));
  // Reading the bytes is the first third of the work, parsing them the rest.
  auto part = [&progress](double from, double to) -> std::function<void(double)> {
    if (!progress) return {};
    return [&progress, from, to](double done) { progress(from + (to - from) * done); };
  };
  const std::string text = read_regular_file(path, part(0, 1.0 / 3));
  if (text.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
    throw InputError(fmt::format("{}: the file is empty", path));
  PolygonSoup soup;
  switch (*format) {
    case MeshFileFormat::obj:
      soup = detail::read_obj(text, path, warnings, part(1.0 / 3, 1));
      break;
    case MeshFileFormat::ply:
      soup = detail::read_ply(text, path, warnings);
      break;
    case MeshFileFormat::off:
      soup = detail::read_off(text, path, warnings);
      break;
    case MeshFileFormat::stl:
      soup = detail::read_stl(text, path, warnings);
      break;
    case MeshFileFormat::glb:
    case MeshFileFormat::gltf:
      soup = detail::read_gltf(text, path, warnings);
      break;
  }
  soup.source = path;
  // Messages quote the numbers the file uses (repair.hpp, soup_places.hpp).
  soup.numbering = *format == MeshFileFormat::obj ? Numbering::from_one
                   : *format == MeshFileFormat::off || *format == MeshFileFormat::ply
                       ? Numbering::from_zero
                       : Numbering::none;
  if (soup.faces.empty()) throw InputError(fmt::format("{}: the file contains no faces", path));
  if (progress) progress(1);
  return soup;
}

HalfedgeMesh read_mesh(const std::string& path, const BuildOptions& options, BuildReport* report,
                       std::vector<std::string>* warnings,
                       const std::function<void(double)>& progress) {
  std::function<void(double)> reading;
  if (progress) reading = [&progress](double done) { progress(0.9 * done); };
  const PolygonSoup soup = read_polygon_soup(path, warnings, reading);
  try {
    HalfedgeMesh mesh = build_mesh(soup, options, report);
    if (progress) progress(1);
    return mesh;
  } catch (const Error& e) {
    // build_mesh names the file only where it knows a line (not for binary PLY, nor for
    // problems of the whole mesh); every message about a file must say which file.
    if (std::string_view(e.what()).find(path) != std::string_view::npos) throw;
    throw InputError(fmt::format("{}: {}", path, e.what()));
  }
}

void write_polygon_soup(const std::string& path, const PolygonSoup& soup) {
  const int nv = static_cast<int>(soup.positions.size());
  for (const auto& loop : soup.faces)
    for (int v : loop)
      if (v < 0 || v >= nv)
        throw OutputError(
            fmt::format("cannot write {}: a face refers to vertex {} of {}", path, v + 1, nv));
  // What is written must read back, so it meets the reader's coordinate limits.
  for (int v = 0; v < nv; ++v)
    if (const std::string problem = limits::coordinate_problem(soup.positions[v]); !problem.empty())
      throw OutputError(fmt::format("cannot write {}: vertex {} {}", path, v + 1, problem));
  check_tags(path, soup);
  const std::optional<MeshFileFormat> format = mesh_file_format(path, kMeshWriteExtensions);
  if (!format)
    throw OutputError(fmt::format("cannot write {}: unknown extension '{}' (supported: {})", path,
                                  file_extension(path), extension_list(kMeshWriteExtensions)));
  detail::MeshFileOptions options;
  options.ply_encoding = detail::PlyEncoding::ascii;  // edited meshes are small; people read them
  options.comment = kComment;
  // Only OBJ has a place for the crease and corner tags (OpenSubdiv's `t` lines); the other
  // formats have no standard one, so they are written without them (docs/formats.md).
  options.obj_statements = [&](detail::OutputFile& out) { write_obj_tags(out, soup); };
  detail::write_mesh_stream(path, *format,
                            detail::stream_arrays(soup.positions, nullptr, soup.faces),
                            soup.positions, options);
}

void write_mesh(const std::string& path, const HalfedgeMesh& mesh) {
  write_polygon_soup(path, to_polygon_soup(mesh));
}

void detail::write_mesh_stream(const std::string& path, MeshFileFormat format,
                               const MeshStream& mesh, const std::vector<Vec3>& positions,
                               const MeshFileOptions& options) {
  if (is_gltf(format)) {
    write_gltf(path, mesh, positions, format == MeshFileFormat::glb, options.progress);
    return;
  }
  write_mesh_file(path, [&](OutputFile& out) {
    switch (format) {
      case MeshFileFormat::obj:
        write_obj(out, mesh, options.comment, options.progress);
        if (options.obj_statements) options.obj_statements(out);
        break;
      case MeshFileFormat::ply:
        write_ply(out, mesh, options.ply_encoding, options.ply_precision, options.comment,
                  options.progress);
        break;
      case MeshFileFormat::off:
        write_off(out, mesh, options.comment, options.progress);
        break;
      case MeshFileFormat::stl:
        write_stl(out, mesh, positions, options.comment, options.progress);
        break;
      case MeshFileFormat::glb:  // above: a .gltf is two files
      case MeshFileFormat::gltf:
        break;
    }
  });
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  write_file_atomically_at(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
    if (!out)
      throw OutputError(fmt::format("cannot write {}: {}", temporary, std::strerror(errno)));
    write(out);
    out.flush();
    if (!out) throw OutputError(fmt::format("cannot write {}: write error (disk full?)", path));
    out.close();
    if (out.fail()) throw OutputError(fmt::format("cannot write {}: error closing the file", path));
  });
}

namespace {

/// A fresh empty file in `folder` named after `target` (O_EXCL: never someone else's file; mode
/// 0666 lets the umask decide permissions).
std::filesystem::path create_temporary(const std::filesystem::path& folder,
                                       const std::filesystem::path& target,
                                       const std::string& path) {
  std::random_device entropy;
  std::filesystem::path temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
    temporary = folder / fmt::format(".{}.tmp-{:08x}", target.filename().string(), entropy());
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0)
    throw OutputError(fmt::format("cannot write {}: cannot create a file in '{}': {}", path,
                                  folder.string(), std::strerror(errno)));
  ::close(fd);
  return temporary;
}

}  // namespace

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw OutputError(
        fmt::format("cannot write {}: folder '{}' does not exist", path, folder.string()));
  if (fs::is_directory(target, ec))
    throw OutputError(fmt::format("cannot write {}: it is a folder", path));
}

void write_file_atomically_at(const std::string& path,
                              const std::function<void(const std::string&)>& write) {
  namespace fs = std::filesystem;
  check_output_path(path);
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  // A device or pipe (/dev/stdout, /dev/full) must not be renamed over: the bytes are made in a
  // temporary file elsewhere and then sent to it, and a failed send is still an error.
  const auto status = fs::status(target, ec);
  const bool device = fs::exists(status) && !fs::is_regular_file(status);

  // Beside the target (same file system, so the rename is atomic).
  const fs::path temporary =
      create_temporary(device ? fs::temp_directory_path() : folder, target, path);
  try {
    write(temporary.string());
    if (device) {
      std::ifstream in(temporary, std::ios::binary);
      std::ofstream out(target, std::ios::binary);
      if (!in || !out)
        throw OutputError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
      out << in.rdbuf();
      out.flush();
      if (!out) throw OutputError(fmt::format("cannot write {}: write error (disk full?)", path));
      fs::remove(temporary, ec);
      return;
    }
    // Make the data durable before the rename makes it visible under the final name.
    if (const int sync_fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC); sync_fd >= 0) {
      const int synced = ::fsync(sync_fd);
      ::close(sync_fd);
      if (synced != 0)
        throw OutputError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
    }
    fs::rename(temporary, target, ec);
    if (ec) throw OutputError(fmt::format("cannot write {}: {}", path, ec.message()));
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
}

}  // namespace stitch
