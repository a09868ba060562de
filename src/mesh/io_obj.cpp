// Wavefront OBJ: `v` and `f` statements; everything about materials, texture and normals is
// ignored because only the polygon mesh matters here.
#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <set>

#include "io_detail.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::io_detail {

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
  static constexpr std::array<std::string_view, 9> kIgnored = {"vt", "vn", "vp",     "g",     "o",
                                                               "s",  "l",  "mtllib", "usemtl"};
  return std::find(kIgnored.begin(), kIgnored.end(), keyword) != kIgnored.end();
}

/// The position index of one `f` entry (`v`, `v/vt`, `v//vn`, `v/vt/vn`), 0-based.
int face_vertex(std::string_view entry, int vertices_so_far, const std::string& where) {
  std::array<std::string_view, 3> parts;
  size_t count = 0, start = 0;
  while (true) {
    const size_t slash = entry.find('/', start);
    if (count == parts.size())
      throw MeshError(fmt::format("{}: face entry '{}' has more than three parts", where,
                                  limits::quoted(entry)));
    parts[count++] = entry.substr(start, slash == std::string_view::npos ? slash : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  if (parts[0].empty())
    throw MeshError(
        fmt::format("{}: face entry '{}' has no vertex index", where, limits::quoted(entry)));
  // Texture and normal indices are not used, but must still be numbers.
  for (size_t i = 1; i < count; ++i)
    if (!parts[i].empty()) parse_integer(parts[i], where);
  const long long index = parse_integer(parts[0], where);
  if (index == 0)
    throw MeshError(fmt::format("{}: vertex index 0 in face (OBJ indices start at 1)", where));
  if (index < 0) {
    // Relative: -1 is the last vertex defined so far.
    if (-index > vertices_so_far)
      throw MeshError(fmt::format(
          "{}: relative vertex index {} points before the first vertex ({} defined so far)", where,
          index, vertices_so_far));
    return static_cast<int>(vertices_so_far + index);
  }
  if (index > std::numeric_limits<int>::max())
    throw MeshError(fmt::format("{}: vertex index {} is out of range", where, index));
  return static_cast<int>(index - 1);
}

}  // namespace

PolygonSoup read_obj(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  PolygonSoup soup;
  std::set<std::string, std::less<>> warned;
  LineReader lines(text);
  std::string_view line;
  while (lines.next(line)) {
    const int number = lines.line_number();
    require_text(line, path, number);
    const auto words = tokens(line);
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (keyword == "v") {
      const std::string where = at_line(path, number);
      if (words.size() < 4)
        throw MeshError(
            fmt::format("{}: a vertex needs 3 coordinates, found {}", where, words.size() - 1));
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = parse_double(words[k + 1], where);
      // Optional w or colour values: not used, but must be numbers.
      for (size_t k = 4; k < words.size(); ++k) parse_double(words[k], where);
      soup.positions.push_back(p);
      soup.vertex_lines.push_back(number);
    } else if (keyword == "f") {
      const std::string where = at_line(path, number);
      std::vector<int> loop;
      loop.reserve(words.size() - 1);
      for (size_t k = 1; k < words.size(); ++k)
        loop.push_back(face_vertex(words[k], static_cast<int>(soup.positions.size()), where));
      soup.faces.push_back(std::move(loop));
      soup.face_lines.push_back(number);
    } else if (is_silently_ignored(keyword)) {
      continue;
    } else if (is_keyword(keyword)) {
      if (warnings && warned.insert(std::string(keyword)).second)
        warnings->push_back(
            fmt::format("{}: ignoring unsupported OBJ statement '{}' (and any later ones)",
                        at_line(path, number), limits::quoted(keyword)));
    } else {
      throw MeshError(fmt::format("{}: unrecognised statement '{}'", at_line(path, number),
                                  limits::quoted(keyword)));
    }
  }
  // Positive indices may refer to vertices defined further down, so they are checked at the end.
  const int nv = static_cast<int>(soup.positions.size());
  for (size_t f = 0; f < soup.faces.size(); ++f)
    for (int v : soup.faces[f])
      if (v >= nv)
        throw MeshError(fmt::format("{}: face refers to vertex {}, but the file has {} vertices",
                                    at_line(path, soup.face_lines[f]), v + 1, nv));
  return soup;
}

}  // namespace stitch::io_detail
