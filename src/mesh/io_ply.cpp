// Stanford PLY, ASCII and binary (either byte order): vertex x y z, per-vertex texture
// coordinates and a face list of vertex indices; every other element and property is read past
// and ignored. Written as ASCII or binary little-endian x y z (nx ny nz), doubles or floats
// (write_ply, at the end).
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <optional>

#include "mesh/mesh_reader.hpp"
#include "mesh/writer_kit.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::detail {

namespace {

enum class Format { ascii, binary_little_endian, binary_big_endian };

struct Type {
  int size = 0;
  bool is_float = false;
  bool is_signed = false;
};

std::optional<Type> parse_type(std::string_view name) {
  if (name == "char" || name == "int8") return Type{1, false, true};
  if (name == "uchar" || name == "uint8") return Type{1, false, false};
  if (name == "short" || name == "int16") return Type{2, false, true};
  if (name == "ushort" || name == "uint16") return Type{2, false, false};
  if (name == "int" || name == "int32") return Type{4, false, true};
  if (name == "uint" || name == "uint32") return Type{4, false, false};
  if (name == "float" || name == "float32") return Type{4, true, true};
  if (name == "double" || name == "float64") return Type{8, true, true};
  return std::nullopt;
}

struct Property {
  std::string name;
  Type type;  // of the value, or of the list items
  std::optional<Type> list_count;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
  int header_line = 0;
};

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  size_t body_offset = 0;
  int body_line = 0;  // line number of the first body line (ASCII)
};

Header read_header(std::string_view text, const std::string& path) {
  LineReader lines(text);
  std::string_view line;
  if (!lines.next(line) || line != "ply")
    throw InputError(
        fmt::format("{}: not a PLY file (the first line must be 'ply')", at_line(path, 1)));
  Header header;
  bool have_format = false;
  while (lines.next(line)) {
    const int number = lines.line_number();
    const std::string where = at_line(path, number);
    require_text(line, path, number);
    // Comments may contain '#', so split them by hand rather than with tokens().
    if (line.starts_with("comment") || line.starts_with("obj_info")) continue;
    const auto words = tokens(line);
    if (words.empty()) continue;
    if (words[0] == "end_header") {
      if (!have_format) throw InputError(fmt::format("{}: header has no 'format' line", where));
      header.body_offset = lines.offset();
      header.body_line = number + 1;
      return header;
    }
    if (words[0] == "format") {
      if (words.size() != 3 || words[2] != "1.0")
        throw InputError(
            fmt::format("{}: expected 'format <ascii|binary_little_endian|"
                        "binary_big_endian> 1.0'",
                        where));
      if (words[1] == "ascii")
        header.format = Format::ascii;
      else if (words[1] == "binary_little_endian")
        header.format = Format::binary_little_endian;
      else if (words[1] == "binary_big_endian")
        header.format = Format::binary_big_endian;
      else
        throw InputError(
            fmt::format("{}: unknown PLY format '{}'", where, limits::quoted(words[1])));
      have_format = true;
    } else if (words[0] == "element") {
      if (words.size() != 3)
        throw InputError(fmt::format("{}: expected 'element <name> <count>'", where));
      Element element{limits::quoted(words[1]), parse_integer(words[2], where), {}, number};
      if (element.count < 0 || element.count > std::numeric_limits<int>::max())
        throw InputError(fmt::format("{}: invalid element count {}", where, element.count));
      header.elements.push_back(std::move(element));
    } else if (words[0] == "property") {
      if (header.elements.empty())
        throw InputError(fmt::format("{}: property before any element", where));
      Property property;
      if (words.size() == 5 && words[1] == "list") {
        property.list_count = parse_type(words[2]);
        const auto item = parse_type(words[3]);
        if (!property.list_count || property.list_count->is_float || !item)
          throw InputError(fmt::format("{}: invalid list property types '{} {}'", where,
                                       limits::quoted(words[2]), limits::quoted(words[3])));
        property.type = *item;
        property.name = limits::quoted(words[4]);
      } else if (words.size() == 3) {
        const auto type = parse_type(words[1]);
        if (!type)
          throw InputError(
              fmt::format("{}: unknown property type '{}'", where, limits::quoted(words[1])));
        property.type = *type;
        property.name = limits::quoted(words[2]);
      } else {
        throw InputError(
            fmt::format("{}: expected 'property <type> <name>' or 'property list "
                        "<count type> <item type> <name>'",
                        where));
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      throw InputError(
          fmt::format("{}: unknown header line '{}'", where, limits::quoted(words[0])));
    }
  }
  throw InputError(fmt::format("{}: the header has no 'end_header' line", path));
}

/// Which properties of the vertex and face elements carry the mesh.
struct Roles {
  int vertex_element = -1, face_element = -1;
  std::array<int, 3> xyz{-1, -1, -1};
  std::array<int, 2> uv{-1, -1};  ///< texture coordinates; -1 when the file has none
  int indices = -1;
};

/// Texture coordinate property pairs in the order they are preferred: writers name them
/// differently (s t: stitch, Blender; texture_u texture_v: Meshlab; u v: others), and a file
/// with several pairs keeps the first.
constexpr std::array<std::array<std::string_view, 2>, 4> kUvNames = {
    {{"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}, {"u", "v"}}};

/// The vertex element's texture coordinate properties, or {-1, -1}.
std::array<int, 2> find_uv(const Element& element, const std::string& where) {
  // stitch's `--unwelded` samples have `u v`, the position in the patch, beside `int patch`.
  const bool samples = std::any_of(element.properties.begin(), element.properties.end(),
                                   [](const Property& p) { return p.name == "patch"; });
  for (const auto& names : kUvNames) {
    if (samples && names[0] == "u") continue;
    std::array<int, 2> found{-1, -1};
    for (int p = 0; p < static_cast<int>(element.properties.size()); ++p)
      for (int k = 0; k < 2; ++k)
        if (element.properties[p].name == names[k]) found[k] = p;
    if (found[0] < 0 || found[1] < 0) continue;
    for (int k = 0; k < 2; ++k)
      if (element.properties[found[k]].list_count)
        throw InputError(fmt::format("{}: vertex property {} is a list", where, names[k]));
    return found;
  }
  return {-1, -1};
}

Roles find_roles(const Header& header, const std::string& path) {
  Roles roles;
  for (int e = 0; e < static_cast<int>(header.elements.size()); ++e) {
    const Element& element = header.elements[e];
    const std::string where = at_line(path, element.header_line);
    if (element.name == "vertex") {
      roles.vertex_element = e;
      for (int p = 0; p < static_cast<int>(element.properties.size()); ++p) {
        const Property& property = element.properties[p];
        for (int k = 0; k < 3; ++k)
          if (property.name == std::string_view(&"xyz"[k], 1)) {
            if (property.list_count)
              throw InputError(
                  fmt::format("{}: vertex property {} is a list", where, property.name));
            roles.xyz[k] = p;
          }
      }
      for (int k = 0; k < 3; ++k)
        if (roles.xyz[k] < 0)
          throw InputError(
              fmt::format("{}: the vertex element has no '{}' property", where, "xyz"[k]));
      roles.uv = find_uv(element, where);
    } else if (element.name == "face") {
      roles.face_element = e;
      for (int p = 0; p < static_cast<int>(element.properties.size()); ++p) {
        const Property& property = element.properties[p];
        if (property.name == "vertex_indices" || property.name == "vertex_index") {
          if (!property.list_count || property.type.is_float)
            throw InputError(fmt::format("{}: face property {} must be a list of integers", where,
                                         property.name));
          roles.indices = p;
        }
      }
      if (roles.indices < 0)
        throw InputError(
            fmt::format("{}: the face element has no 'vertex_indices' list property", where));
    }
  }
  if (roles.vertex_element < 0)
    throw InputError(fmt::format("{}: the header declares no 'vertex' element", path));
  if (roles.face_element < 0)
    throw InputError(fmt::format("{}: the header declares no 'face' element", path));
  return roles;
}

/// Refuses element counts that the data after the header cannot hold, before anything is
/// allocated or looped over: a binary element takes at least one byte per scalar and per list
/// length, an ASCII one at least two characters ("0 ") per value.
void check_counts_fit(const Header& header, size_t body_size, const std::string& path) {
  size_t left = body_size + 1;  // an ASCII file's last value needs no separator after it
  for (const Element& element : header.elements) {
    size_t least = 0;
    for (const Property& property : element.properties)
      least += header.format == Format::ascii ? 2
               : property.list_count          ? property.list_count->size
                                              : property.type.size;
    if (least == 0) continue;
    const auto count = static_cast<size_t>(element.count);
    if (count > left / least)
      throw InputError(fmt::format(
          "{}: the header declares {} '{}' elements of at least {} bytes each, but only {} bytes "
          "follow the header (truncated, or a wrong count?)",
          at_line(path, element.header_line), element.count, element.name, least, body_size));
    left -= count * least;
  }
}

/// Reads the values of one element instance (ASCII: one line; binary: a run of bytes) and hands
/// each scalar or list item to `use(property index, item index, value)`.
class BodyReader {
 public:
  BodyReader(std::string_view text, const Header& header, const std::string& path)
      : header_(header), path_(path), body_(text.substr(header.body_offset)), lines_(body_) {}

  /// Returns the element's line (0 for binary files, which have none).
  template <class Use>
  int read(const Element& element, long long index, Use&& use) {
    if (header_.format != Format::ascii) {
      read_binary(element, index, use);
      return 0;
    }
    read_ascii(element, index, use);
    return line_number();
  }

  /// True when nothing but white space follows the last element.
  bool at_end() {
    if (header_.format != Format::ascii) return position_ == body_.size();
    std::string_view line;
    while (lines_.next(line))
      if (!tokens(line).empty()) return false;
    return true;
  }

 private:
  template <class Use>
  void read_ascii(const Element& element, long long index, Use& use) {
    std::string_view line;
    std::vector<std::string_view>& words = words_;
    words.clear();
    while (words.empty()) {
      if (!lines_.next(line))
        throw InputError(
            fmt::format("{}: the file ends after {} of the {} '{}' elements declared "
                        "in the header (line {}; truncated?)",
                        at_line(path_, header_.body_line + lines_.line_number() - 1), index,
                        element.count, element.name, element.header_line));
      require_text(line, path_, line_number());
      tokens(line, words);
    }
    const Where where(path_, line_number());
    size_t next = 0;
    auto take = [&](const Type& type) {
      if (next == words.size())
        throw InputError(fmt::format("{}: too few values for a '{}' element", where, element.name));
      const std::string_view word = words[next++];
      return type.is_float ? parse_double(word, where)
                           : static_cast<double>(parse_integer(word, where));
    };
    read_properties(element, take, use, [&] { return where; });
    if (next != words.size())
      throw InputError(fmt::format("{}: {} values more than a '{}' element has", where,
                                   words.size() - next, element.name));
  }

  /// Hands every property value of one element to `use(property, list_index, value)`
  /// (list_index -1 for a scalar or a list's length), reading values with `take(type)`;
  /// `where()` places the element for messages.
  template <class Take, class Use, class Place>
  static void read_properties(const Element& element, Take& take, Use& use, const Place& where) {
    for (int p = 0; p < static_cast<int>(element.properties.size()); ++p) {
      const Property& property = element.properties[p];
      if (!property.list_count) {
        use(p, -1, take(property.type));
        continue;
      }
      const double count = take(*property.list_count);
      if (count < 0) throw InputError(fmt::format("{}: negative list length {}", where(), count));
      if (count > limits::max_halfedges)
        throw InputError(fmt::format("{}: list length {} is more than the {} a face may have",
                                     where(), count, limits::max_halfedges));
      use(p, -1, count);
      for (int i = 0; i < static_cast<int>(count); ++i) use(p, i, take(property.type));
    }
  }

  template <class Use>
  void read_binary(const Element& element, long long index, Use& use) {
    // Formatted only for a message: binary elements are many and cheap to read.
    auto where = [&] {
      return fmt::format("{}, {} element {} (counting from 0, binary data)", path_, element.name,
                         index);
    };
    auto take = [&](const Type& type) {
      if (position_ + type.size > body_.size())
        throw InputError(
            fmt::format("{}: the file ends in {} element {} of the {} declared in the "
                        "header (truncated?)",
                        path_, element.name, index, element.count));
      std::array<unsigned char, 8> bytes{};
      std::memcpy(bytes.data(), body_.data() + position_, type.size);
      position_ += type.size;
      const bool big = header_.format == Format::binary_big_endian;
      if (big != (std::endian::native == std::endian::big))
        std::reverse(bytes.begin(), bytes.begin() + type.size);
      if (type.is_float) {
        double value;
        if (type.size == 4) {
          float f;
          std::memcpy(&f, bytes.data(), 4);
          value = f;
        } else {
          std::memcpy(&value, bytes.data(), 8);
        }
        return value;
      }
      std::uint32_t raw = 0;
      std::memcpy(&raw, bytes.data(), type.size);  // little-endian host assumed below
      if constexpr (std::endian::native == std::endian::big) raw >>= 8 * (4 - type.size);
      if (type.is_signed) {
        const int shift = 32 - 8 * type.size;
        return static_cast<double>(static_cast<std::int32_t>(raw << shift) >> shift);
      }
      return static_cast<double>(raw);
    };
    read_properties(element, take, use, where);
  }

  [[nodiscard]] int line_number() const { return header_.body_line + lines_.line_number() - 1; }

  const Header& header_;
  const std::string& path_;
  std::string_view body_;
  LineReader lines_;
  std::vector<std::string_view> words_;  ///< an ASCII element's values, reused
  size_t position_ = 0;
};

}  // namespace

PolygonSoup read_ply(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings) {
  const Header header = read_header(text, path);
  const Roles roles = find_roles(header, path);
  check_counts_fit(header, text.size() - header.body_offset, path);
  const long long nv = header.elements[roles.vertex_element].count;
  PolygonSoup soup;
  BodyReader body(text, header, path);
  const bool ascii = header.format == Format::ascii;
  for (int e = 0; e < static_cast<int>(header.elements.size()); ++e) {
    const Element& element = header.elements[e];
    // A binary element without properties takes no bytes: there is nothing to read, however
    // many the header declares.
    if (element.properties.empty() && !ascii) continue;
    for (long long i = 0; i < element.count; ++i) {
      if (e == roles.vertex_element) {
        Vec3 p = Vec3::Zero();
        Eigen::Vector2d uv = Eigen::Vector2d::Zero();
        const int line = body.read(element, i, [&](int property, int, double value) {
          for (int k = 0; k < 3; ++k)
            if (property == roles.xyz[k]) p[k] = value;
          for (int k = 0; k < 2; ++k)
            if (property == roles.uv[k]) uv[k] = value;
        });
        if (!p.allFinite() || !uv.allFinite())
          throw InputError(fmt::format("{}, vertex element {} (counting from 0): {} is not finite",
                                       path, i,
                                       p.allFinite() ? "a texture coordinate" : "coordinate"));
        soup.positions.push_back(p);
        if (roles.uv[0] >= 0) soup.uvs.push_back(uv);
        // For binary files there is no line (0); build_mesh then names the vertex number only.
        soup.vertex_lines.push_back(line);
      } else if (e == roles.face_element) {
        std::vector<int> loop;
        std::string bad_index;
        const int line = body.read(element, i, [&](int property, int item, double value) {
          if (property != roles.indices || item < 0) return;
          if (value < 0 || value >= static_cast<double>(nv)) {
            if (bad_index.empty())
              bad_index = fmt::format(
                  "face refers to vertex {} (0-based), but the file has {} "
                  "vertices",
                  value, nv);
            return;
          }
          loop.push_back(static_cast<int>(value));
        });
        if (!bad_index.empty())
          throw InputError(
              fmt::format("{}: {}",
                          ascii ? at_line(path, line)
                                : fmt::format("{}, face element {} (counting from 0)", path, i),
                          bad_index));
        soup.faces.push_back(std::move(loop));
        soup.face_lines.push_back(line);
      } else {
        body.read(element, i, [](int, int, double) {});
      }
    }
  }
  // Per-vertex coordinates: each corner takes its vertex's.
  if (roles.uv[0] >= 0) soup.face_uvs = soup.faces;
  if (!body.at_end() && warnings)
    warnings->push_back(fmt::format("{}: ignoring data after the last declared element", path));
  return soup;
}

// --- writing ---

namespace {

/// Binary PLY vertex records: x y z (nx ny nz), little-endian doubles or floats.
void ply_binary_vertices(const VertexBlock& block, bool normals, bool single, OutputBuffer& bytes) {
  const size_t count = block.positions.size();
  const size_t scalars = normals ? 6 : 3;
  if constexpr (std::endian::native == std::endian::little) {
    // A record is the values' own bytes: copied whole, not value by value (the PLY writer's
    // share of the CPU was as large as the evaluation's).
    if (!single) {
      char* at = bytes.extend(count * scalars * sizeof(double));
      static_assert(sizeof(Vec3) == 3 * sizeof(double));
      if (!normals) {
        std::memcpy(at, block.positions.data(), count * sizeof(Vec3));
        return;
      }
      for (size_t i = 0; i < count; ++i) {
        std::memcpy(at, block.positions[i].data(), sizeof(Vec3));
        std::memcpy(at + sizeof(Vec3), block.normals[i].data(), sizeof(Vec3));
        at += 2 * sizeof(Vec3);
      }
      return;
    }
    char* at = bytes.extend(count * scalars * sizeof(float));
    for (size_t i = 0; i < count; ++i) {
      std::array<float, 6> record{};
      for (int axis = 0; axis < 3; ++axis) {
        record[axis] = static_cast<float>(block.positions[i][axis]);
        if (normals) record[3 + axis] = static_cast<float>(block.normals[i][axis]);
      }
      std::memcpy(at, record.data(), scalars * sizeof(float));
      at += scalars * sizeof(float);
    }
    return;
  }
  LittleEndianWriter record(bytes, count * scalars * (single ? sizeof(float) : sizeof(double)));
  const auto put = [&](const Vec3& p) {
    if (single)
      record.put(p.cast<float>().eval());
    else
      record.put(p);
  };
  for (size_t i = 0; i < count; ++i) {
    put(block.positions[i]);
    if (normals) put(block.normals[i]);
  }
}

/// Binary PLY faces: the vertex count (uchar when `byte_counts`, else int), then int indices.
void ply_binary_faces(const FaceBlock& block, bool byte_counts, OutputBuffer& bytes) {
  const size_t size = block.sizes.size() * (byte_counts ? 1 : 4) + block.indices.size() * 4;
  if constexpr (std::endian::native == std::endian::little) {
    static_assert(sizeof(int) == sizeof(std::int32_t));
    if (byte_counts) {
      char* at = bytes.extend(size);
      for_each_face(block, [&](int count, const int* loop) {
        *at++ = static_cast<char>(static_cast<std::uint8_t>(count));
        // A fixed size for the usual quads and triangles: a move, not a call to memcpy.
        if (count == 4)
          std::memcpy(at, loop, 4 * sizeof(int));
        else if (count == 3)
          std::memcpy(at, loop, 3 * sizeof(int));
        else
          std::memcpy(at, loop, static_cast<size_t>(count) * sizeof(int));
        at += static_cast<size_t>(count) * sizeof(int);
      });
      return;
    }
  }
  LittleEndianWriter record(bytes, size);
  for_each_face(block, [&](int count, const int* loop) {
    if (byte_counts)
      record.put(static_cast<std::uint8_t>(count));
    else
      record.put(static_cast<std::int32_t>(count));
    for (int k = 0; k < count; ++k) record.put(static_cast<std::int32_t>(loop[k]));
  });
}

}  // namespace

void write_ply(OutputFile& out, const MeshStream& mesh, PlyEncoding encoding,
               PlyPrecision precision, std::string_view comment, const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_faces);
  const bool binary = encoding == PlyEncoding::binary_little_endian;
  const bool single = precision == PlyPrecision::single;
  const bool byte_counts = mesh.max_face_degree <= 255;
  const char* type = single ? "float" : "double";
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\ncomment "
      << comment << "\nelement vertex " << mesh.num_vertices;
  for (const char* name : {"x", "y", "z"}) out << "\nproperty " << type << ' ' << name;
  if (mesh.has_normals)
    for (const char* name : {"nx", "ny", "nz"}) out << "\nproperty " << type << ' ' << name;
  out << '\n';
  out << "element face " << mesh.num_faces << "\nproperty list " << (byte_counts ? "uchar" : "int")
      << " int vertex_indices\nend_header\n";
  if (binary) {
    write_vertices(
        out, mesh,
        [&](const VertexBlock& block, OutputBuffer& bytes) {
          ply_binary_vertices(block, mesh.has_normals, single, bytes);
        },
        progress);
    write_faces(
        out, mesh,
        [&](const FaceBlock& block, OutputBuffer& bytes) {
          ply_binary_faces(block, byte_counts, bytes);
        },
        progress);
    return;
  }
  write_vertices(
      out, mesh,
      [&](const VertexBlock& block, OutputBuffer& text) {
        char* at = text.claim(block.positions.size() * line_room(1, 6));
        for (size_t i = 0; i < block.positions.size(); ++i) {
          at = put_xyz(at, "", block.positions[i], single);
          if (mesh.has_normals) at = put_xyz(at, " ", block.normals[i], single);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  write_faces(out, mesh, text_faces("", true, 0, false), progress);
}

}  // namespace stitch::detail
