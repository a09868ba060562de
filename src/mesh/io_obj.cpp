// Wavefront OBJ: `v`, `vt` and `f` statements, and OpenSubdiv's `t` tags for creases and
// corners; materials and normals are ignored because the smooth surface makes its own normals.
// Written with `vn` and `vt` where the stream has them (write_obj, at the end).
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "mesh/mesh_reader.hpp"
#include "mesh/writer_kit.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::detail {

namespace {

bool is_keyword(std::string_view word) {
  if (word.empty() || !(std::isalpha(static_cast<unsigned char>(word[0])) || word[0] == '_'))
    return false;
  return std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// Statements that carry nothing a polygon mesh needs; skipped without a word.
bool is_silently_ignored(std::string_view keyword) {
  static constexpr std::array<std::string_view, 8> kIgnored = {"vn", "vp", "g",      "o",
                                                               "s",  "l",  "mtllib", "usemtl"};
  return std::find(kIgnored.begin(), kIgnored.end(), keyword) != kIgnored.end();
}

/// An OBJ index (`f` entry part), 0-based; negative ones count back from the last `what`
/// defined so far. Positive ones may refer to later lines, so the caller checks them at the end.
int obj_index(std::string_view token, int defined_so_far, const char* what, const Where& where) {
  const long long index = parse_integer(token, where);
  if (index == 0)
    throw InputError(fmt::format("{}: {} index 0 in face (OBJ indices start at 1)", where, what));
  if (index < 0) {
    // Relative: -1 is the last one defined so far.
    if (-index > defined_so_far)
      throw InputError(
          fmt::format("{}: relative {} index {} points before the first {} ({} defined so far)",
                      where, what, index, what, defined_so_far));
    return static_cast<int>(defined_so_far + index);
  }
  if (index > std::numeric_limits<int>::max())
    throw InputError(fmt::format("{}: {} index {} is out of range", where, what, index));
  return static_cast<int>(index - 1);
}

/// One `f` entry (`v`, `v/vt`, `v//vn`, `v/vt/vn`): the position index and the texture
/// coordinate index (-1 when there is none), 0-based.
struct FaceEntry {
  int vertex = 0;
  int uv = -1;
};

FaceEntry face_entry(std::string_view entry, int vertices_so_far, int uvs_so_far,
                     const Where& where) {
  std::array<std::string_view, 3> parts;
  size_t count = 0, start = 0;
  while (true) {
    const size_t slash = entry.find('/', start);
    if (count == parts.size())
      throw InputError(fmt::format("{}: face entry '{}' has more than three parts", where,
                                   limits::quoted(entry)));
    parts[count++] = entry.substr(start, slash == std::string_view::npos ? slash : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  if (parts[0].empty())
    throw InputError(
        fmt::format("{}: face entry '{}' has no vertex index", where, limits::quoted(entry)));
  // Normal indices are not used, but must still be numbers.
  if (count == 3 && !parts[2].empty()) parse_integer(parts[2], where);
  FaceEntry out;
  out.vertex = obj_index(parts[0], vertices_so_far, "vertex", where);
  if (count >= 2 && !parts[1].empty())
    out.uv = obj_index(parts[1], uvs_so_far, "texture coordinate", where);
  return out;
}

/// One `t NAME I/F/S ints... floats... strings...` line, as OpenSubdiv's shape parser
/// (regression/common/shape_utils.cpp) reads it.
struct Tag {
  std::string_view name;
  std::vector<long long> ints;
  std::vector<double> floats;
  std::vector<std::string_view> strings;
};

Tag parse_tag(const std::vector<std::string_view>& words, const Where& where) {
  if (words.size() < 3)
    throw InputError(
        fmt::format("{}: a tag needs a name and its argument counts INTS/FLOATS/STRINGS, e.g. "
                    "'t crease 2/1/0 0 1 10'",
                    where));
  Tag tag;
  tag.name = words[1];
  std::array<long long, 3> counts{};
  std::string_view rest = words[2];
  for (size_t k = 0; k < counts.size(); ++k) {
    const size_t slash = rest.find('/');
    const bool last = k + 1 == counts.size();
    if (last != (slash == std::string_view::npos))
      throw InputError(fmt::format(
          "{}: tag '{}' has argument counts '{}'; they must be three integers INTS/FLOATS/STRINGS "
          "such as 2/1/0",
          where, limits::quoted(tag.name), limits::quoted(words[2])));
    counts[k] = parse_integer(rest.substr(0, slash), where);
    if (counts[k] < 0)
      throw InputError(fmt::format("{}: tag '{}' declares a negative number of arguments ('{}')",
                                   where, limits::quoted(tag.name), limits::quoted(words[2])));
    if (!last) rest.remove_prefix(slash + 1);
  }
  // Compared before anything is allocated: the counts are the file's word, the words are real.
  const auto given = static_cast<long long>(words.size() - 3);
  if (counts[0] > given || counts[1] > given || counts[2] > given ||
      counts[0] + counts[1] + counts[2] != given)
    throw InputError(fmt::format(
        "{}: tag '{}' declares {} integer, {} float and {} string arguments, but {} follow", where,
        limits::quoted(tag.name), counts[0], counts[1], counts[2], given));
  size_t at = 3;
  for (long long i = 0; i < counts[0]; ++i) tag.ints.push_back(parse_integer(words[at++], where));
  for (long long i = 0; i < counts[1]; ++i) tag.floats.push_back(parse_number(words[at++], where));
  for (long long i = 0; i < counts[2]; ++i) tag.strings.push_back(words[at++]);
  return tag;
}

/// The sharpness of argument `k`: one float applies to all, else one float per element
/// (OpenSubdiv's far_utils.h and hbr_utils.h).
double tag_sharpness(const Tag& tag, size_t k, const Where& where) {
  const double s = tag.floats.size() == 1 ? tag.floats[0] : tag.floats[k];
  if (!std::isfinite(s) || s < 0)
    throw InputError(fmt::format("{}: {} tag has sharpness {}; it must be a finite number >= 0",
                                 where, tag.name, s));
  return s;
}

int tag_vertex(long long index, const Tag& tag, const Where& where) {
  // OpenSubdiv's tags count vertices from 0 (unlike OBJ's faces) and have no relative form.
  if (index < 0)
    throw InputError(
        fmt::format("{}: {} tag names vertex {}; tags count vertices from 0, so it must be >= 0",
                    where, tag.name, index));
  if (index > std::numeric_limits<int>::max())
    throw InputError(
        fmt::format("{}: {} tag names vertex {}, which is out of range", where, tag.name, index));
  return static_cast<int>(index);
}

void read_crease(const Tag& tag, int line, const Where& where, PolygonSoup& soup) {
  // OpenSubdiv reads the integers in pairs, one edge each (not as a chain of vertices).
  const size_t edges = tag.ints.size() / 2;
  if (tag.ints.empty() || tag.ints.size() % 2 != 0)
    throw InputError(
        fmt::format("{}: crease tag has {} vertices; it needs pairs of vertices, one pair per edge "
                    "('t crease 2/1/0 A B SHARPNESS')",
                    where, tag.ints.size()));
  if (tag.floats.size() != 1 && tag.floats.size() != edges)
    throw InputError(fmt::format(
        "{}: crease tag names {} edge(s) but has {} sharpness values; it needs 1 for all or 1 "
        "per edge",
        where, edges, tag.floats.size()));
  if (!tag.strings.empty())
    throw InputError(fmt::format("{}: crease tag has string arguments; it takes none", where));
  for (size_t e = 0; e < edges; ++e) {
    const int a = tag_vertex(tag.ints[2 * e], tag, where);
    const int b = tag_vertex(tag.ints[2 * e + 1], tag, where);
    if (a == b)
      throw InputError(
          fmt::format("{}: crease tag joins vertex {} to itself; an edge has two ends", where, a));
    soup.creases.push_back({a, b, tag_sharpness(tag, e, where), line});
  }
}

void read_corner(const Tag& tag, int line, const Where& where, PolygonSoup& soup) {
  if (tag.ints.empty())
    throw InputError(
        fmt::format("{}: corner tag names no vertex ('t corner 1/1/0 V SHARPNESS')", where));
  if (tag.floats.size() != 1 && tag.floats.size() != tag.ints.size())
    throw InputError(fmt::format(
        "{}: corner tag names {} vertices but has {} sharpness values; it needs 1 for all or 1 "
        "per vertex",
        where, tag.ints.size(), tag.floats.size()));
  if (!tag.strings.empty())
    throw InputError(fmt::format("{}: corner tag has string arguments; it takes none", where));
  for (size_t k = 0; k < tag.ints.size(); ++k)
    soup.corners.push_back(
        {tag_vertex(tag.ints[k], tag, where), tag_sharpness(tag, k, where), line});
}

/// OpenSubdiv's shape reader takes "chaikin" for Chaikin's rule and anything else ("normal") for
/// the uniform one; here anything else is refused, so that a typo is not a silent difference.
CreaseMethod read_crease_method(const Tag& tag, const Where& where) {
  if (!tag.ints.empty() || !tag.floats.empty() || tag.strings.size() != 1 ||
      (tag.strings[0] != "chaikin" && tag.strings[0] != "normal" && tag.strings[0] != "uniform"))
    throw InputError(fmt::format(
        "{}: creasemethod tag takes one string, chaikin or normal ('t creasemethod 0/0/1 "
        "chaikin')",
        where));
  return tag.strings[0] == "chaikin" ? CreaseMethod::chaikin : CreaseMethod::uniform;
}

/// Why stitch does not use an OpenSubdiv tag it knows.
std::string_view why_ignored(std::string_view name) {
  if (name == "interpolateboundary")
    return "stitch's boundary rule is its own option, KgonOptions::boundary, whose default "
           "makes boundary vertices with one face corners";
  if (name == "facevaryinginterpolateboundary" || name == "facevaryingpropagatecorners")
    return "stitch's texture coordinates follow its own rule: a UV seam is a boundary of the UV "
           "layout, smoothed like the surface (docs/formats.md)";
  if (name == "smoothtriangles") return "stitch has no special rule for triangles";
  if (name == "hole") return "the faces it names stay part of the surface";
  return "stitch does not know it";
}

/// Tags stitch reads but does not use, by name: the first line and how many there were.
struct IgnoredTag {
  int first_line = 0;
  int count = 0;
  size_t order = 0;
};

}  // namespace

PolygonSoup read_obj(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings,
                     const std::function<void(double)>& progress) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  PolygonSoup soup;
  std::vector<int> uv_loop;
  // Lines of the first `vt` and of the first face with and without texture coordinates (0: none).
  int first_uv_line = 0, first_face_with_uv = 0, first_face_without_uv = 0;
  std::set<std::string, std::less<>> warned;
  std::map<std::string, IgnoredTag, std::less<>> ignored_tags;
  LineReader lines(text);
  std::string_view line;
  std::vector<std::string_view> words;
  while (lines.next(line)) {
    const int number = lines.line_number();
    if (progress && number % 65536 == 0)
      progress(static_cast<double>(lines.offset()) / static_cast<double>(text.size()));
    require_text(line, path, number);
    tokens(line, words);
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (keyword == "v") {
      const Where where(path, number);
      if (words.size() < 4)
        throw InputError(
            fmt::format("{}: a vertex needs 3 coordinates, found {}", where, words.size() - 1));
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = parse_double(words[k + 1], where);
      // Optional w or colour values: not used, but must be numbers.
      for (size_t k = 4; k < words.size(); ++k) parse_double(words[k], where);
      soup.positions.push_back(p);
      soup.vertex_lines.push_back(number);
    } else if (keyword == "vt") {
      const Where where(path, number);
      if (words.size() < 2 || words.size() > 4)
        throw InputError(fmt::format("{}: a texture coordinate needs 1 to 3 numbers, found {}",
                                     where, words.size() - 1));
      // `vt u [v [w]]`: v defaults to 0; w (3D textures) is not used but must be a number.
      Eigen::Vector2d uv(parse_double(words[1], where),
                         words.size() > 2 ? parse_double(words[2], where) : 0.0);
      if (words.size() > 3) parse_double(words[3], where);
      soup.uvs.push_back(uv);
      if (first_uv_line == 0) first_uv_line = number;
    } else if (keyword == "f") {
      const Where where(path, number);
      std::vector<int> loop;
      loop.reserve(words.size() - 1);
      uv_loop.clear();
      for (size_t k = 1; k < words.size(); ++k) {
        const FaceEntry entry = face_entry(words[k], static_cast<int>(soup.positions.size()),
                                           static_cast<int>(soup.uvs.size()), where);
        loop.push_back(entry.vertex);
        if (entry.uv >= 0) uv_loop.push_back(entry.uv);
      }
      if (!uv_loop.empty() && uv_loop.size() != loop.size())
        throw InputError(fmt::format(
            "{}: {} of the face's {} corners have a texture coordinate index; a face needs one on "
            "every corner or on none",
            where, uv_loop.size(), loop.size()));
      // Mixed faces are refused once all are read, naming the first face of each kind.
      int& first = uv_loop.empty() ? first_face_without_uv : first_face_with_uv;
      if (first == 0) first = number;
      if (!uv_loop.empty()) soup.face_uvs.push_back(uv_loop);
      soup.faces.push_back(std::move(loop));
      soup.face_lines.push_back(number);
    } else if (keyword == "t") {
      const Where where(path, number);
      const Tag tag = parse_tag(words, where);
      if (tag.name == "crease") {
        read_crease(tag, number, where, soup);
      } else if (tag.name == "corner") {
        read_corner(tag, number, where, soup);
      } else if (tag.name == "creasemethod") {
        soup.crease_method = read_crease_method(tag, where);
      } else {
        auto [it, fresh] = ignored_tags.try_emplace(std::string(tag.name));
        if (fresh) it->second = {number, 0, ignored_tags.size()};
        ++it->second.count;
      }
    } else if (is_silently_ignored(keyword)) {
      continue;
    } else if (is_keyword(keyword)) {
      if (warnings && warned.insert(std::string(keyword)).second)
        warnings->push_back(
            fmt::format("{}: ignoring unsupported OBJ statement '{}' (and any later ones)",
                        at_line(path, number), limits::quoted(keyword)));
    } else {
      throw InputError(fmt::format("{}: unrecognised statement '{}'", at_line(path, number),
                                   limits::quoted(keyword)));
    }
  }
  // Positive indices may refer to vertices defined further down, so they are checked at the end.
  const int nv = static_cast<int>(soup.positions.size());
  for (size_t f = 0; f < soup.faces.size(); ++f)
    for (int v : soup.faces[f])
      if (v >= nv)
        throw InputError(fmt::format("{}: face refers to vertex {}, but the file has {} vertices",
                                     at_line(path, soup.face_lines[f]), v + 1, nv));
  // Some faces with texture coordinates and some without: the file has no UV map to carry over
  // (Blender and other importers then invent zeros); say so and go on without UVs.
  if (first_face_with_uv > 0 && first_face_without_uv > 0) {
    if (warnings)
      warnings->push_back(fmt::format(
          "{}: the face has no texture coordinate indices, but the face on line {} has; the "
          "texture coordinates are not used",
          at_line(path, first_face_without_uv), first_face_with_uv));
    first_face_with_uv = 0;
    first_uv_line = 0;
  }
  if (first_face_with_uv > 0) {
    const int nuv = static_cast<int>(soup.uvs.size());
    for (size_t f = 0; f < soup.faces.size(); ++f)
      for (int t : soup.face_uvs[f])
        if (t >= nuv)
          throw InputError(
              fmt::format("{}: face refers to texture coordinate {}, but the file has {}",
                          at_line(path, soup.face_lines[f]), t + 1, nuv));
  } else {
    if (!soup.uvs.empty() && first_uv_line > 0 && warnings)
      warnings->push_back(
          fmt::format("{}: ignoring {} texture coordinates (vt) that no face refers to",
                      at_line(path, first_uv_line), soup.uvs.size()));
    soup.uvs.clear();
    soup.face_uvs.clear();
  }
  for (const SoupCrease& c : soup.creases)
    for (int v : {c.a, c.b})
      if (v >= nv)
        throw InputError(fmt::format(
            "{}: crease tag names vertex {}, but the file has {} vertices (tags count from 0: "
            "0 to {})",
            at_line(path, c.line), v, nv, nv - 1));
  for (const SoupCorner& c : soup.corners)
    if (c.vertex >= nv)
      throw InputError(fmt::format(
          "{}: corner tag names vertex {}, but the file has {} vertices (tags count from 0: 0 "
          "to {})",
          at_line(path, c.line), c.vertex, nv, nv - 1));
  if (warnings) {
    std::vector<std::pair<std::string_view, const IgnoredTag*>> order;
    for (const auto& [name, tag] : ignored_tags) order.emplace_back(name, &tag);
    std::sort(order.begin(), order.end(),
              [](const auto& x, const auto& y) { return x.second->order < y.second->order; });
    for (const auto& [name, tag] : order)
      warnings->push_back(
          fmt::format("{}: OpenSubdiv tag '{}' ignored{}: {}", at_line(path, tag->first_line),
                      limits::quoted(name),
                      tag->count > 1 ? fmt::format(" (and {} more like it)", tag->count - 1) : "",
                      why_ignored(name)));
  }
  return soup;
}

// --- writing ---

namespace {

/// OBJ faces with texture coordinates: `f a/t/a ...` (or `a/t` without normals), 1-based. Apart
/// from text_faces so that files without them take no branch per corner.
FaceFormat obj_textured_faces(bool normals) {
  return [=](const FaceBlock& block, OutputBuffer& text) {
    char* at = text.claim(block.indices.size() * (3 * (kMaxDecimalChars + 1) + 1) +
                          block.sizes.size() * 3);
    const int* uv = block.texcoords.data();
    for_each_face(block, [&](int size, const int* loop) {
      *at++ = 'f';
      for (int k = 0; k < size; ++k) {
        *at++ = ' ';
        char* const index = at;
        at = put_index(at, loop[k], 1);
        const size_t length = static_cast<size_t>(at - index);
        *at++ = '/';
        at = put_index(at, *uv++, 1);
        if (normals) {
          *at++ = '/';
          std::memmove(at, index, length);  // the same number again
          at += length;
        }
      }
      *at++ = '\n';
    });
    text.commit(at);
  };
}

}  // namespace

void write_obj(OutputFile& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_texcoords + mesh.num_faces);
  out << "# " << comment << '\n';
  write_vertices(
      out, mesh,
      [&](const VertexBlock& block, OutputBuffer& text) {
        char* at = text.claim((block.positions.size() + block.normals.size()) * line_room(3, 3));
        for (const Vec3& p : block.positions) {
          at = put_xyz(at, "v ", p);
          *at++ = '\n';
        }
        // OBJ numbers `vn` lines separately from `v` lines, so they may follow block by block.
        for (const Vec3& n : block.normals) {
          at = put_xyz(at, "vn ", n);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  if (mesh.num_texcoords == 0) {
    write_faces(out, mesh, text_faces("f", false, 1, mesh.has_normals), progress);
    return;
  }
  write_records<std::vector<Eigen::Vector2d>>(
      out, mesh.num_texcoords, kVerticesPerBlock, mesh.texcoords,
      [](const std::vector<Eigen::Vector2d>& block, OutputBuffer& text) {
        char* at = text.claim(block.size() * line_room(3, 2));
        for (const Eigen::Vector2d& t : block) {
          at = put(at, "vt ");
          at = put(at, t.x(), false);
          *at++ = ' ';
          at = put(at, t.y(), false);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  write_faces(out, mesh, obj_textured_faces(mesh.has_normals), progress);
}

}  // namespace stitch::detail
