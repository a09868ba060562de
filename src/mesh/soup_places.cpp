#include "mesh/soup_places.hpp"

#include <fmt/format.h>

#include "stitch/error.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::soup_places {

namespace {

std::string at(const PolygonSoup& soup, int line, bool with_source) {
  if (line <= 0) return "";
  return fmt::format(" ({}line {})", with_source && !soup.source.empty() ? soup.source + ", " : "",
                     line);
}

std::string point(const Vec3& p) {
  return fmt::format("({:.7g}, {:.7g}, {:.7g})", p.x(), p.y(), p.z());
}

int line_of(const std::vector<int>& lines, int i) {
  return i < static_cast<int>(lines.size()) ? lines[i] : 0;
}

}  // namespace

int file_face(const PolygonSoup& soup, int f) {
  return f < static_cast<int>(soup.face_origin.size()) ? soup.face_origin[f] : f;
}

int file_vertex(const PolygonSoup& soup, int v) {
  return v < static_cast<int>(soup.vertex_origin.size()) ? soup.vertex_origin[v] : v;
}

int quoted(const PolygonSoup& soup, int file_index) {
  return soup.numbering == Numbering::from_one ? file_index + 1 : file_index;
}

std::string face(const PolygonSoup& soup, int f, bool with_source) {
  const int line = line_of(soup.face_lines, f);
  if (soup.numbering != Numbering::none)
    return fmt::format("face {}{}", quoted(soup, file_face(soup, f)), at(soup, line, with_source));
  if (line > 0)
    return fmt::format("the face on line {}{}", line,
                       with_source && !soup.source.empty() ? " of " + soup.source : "");
  // Without numbers or lines, its corners say where it is (a triangle has three).
  std::string corners;
  const auto& loop = soup.faces[f];
  for (size_t i = 0; i < loop.size() && i < 3; ++i)
    if (loop[i] >= 0 && loop[i] < static_cast<int>(soup.positions.size()))
      corners += (corners.empty() ? "" : ", ") + point(soup.positions[loop[i]]);
  return fmt::format("the face with corners {}{}", corners, loop.size() > 3 ? ", ..." : "");
}

std::string vertex(const PolygonSoup& soup, int v, bool with_source) {
  if (soup.numbering == Numbering::none)
    return fmt::format("the vertex at {}", point(soup.positions[v]));
  return fmt::format("vertex {}{}", quoted(soup, file_vertex(soup, v)),
                     at(soup, line_of(soup.vertex_lines, v), with_source));
}

std::string edge(const PolygonSoup& soup, int a, int b) {
  if (soup.numbering == Numbering::none)
    return fmt::format("the edge from {} to {}", point(soup.positions[a]),
                       point(soup.positions[b]));
  return fmt::format("edge ({}, {})", quoted(soup, file_vertex(soup, a)),
                     quoted(soup, file_vertex(soup, b)));
}

std::string listed(const std::vector<std::string>& names, size_t shown) {
  std::string s;
  for (size_t k = 0; k < names.size() && k < shown; ++k) s += (k ? ", " : "") + names[k];
  if (names.size() > shown) s += fmt::format(", ... ({} more)", names.size() - shown);
  return s;
}

void check_face_indices(const PolygonSoup& soup) {
  const int nv = static_cast<int>(soup.positions.size());
  size_t corners = 0;
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    corners += soup.faces[f].size();
    if (corners > static_cast<size_t>(limits::max_halfedges))
      throw InputError(
          fmt::format("the mesh has more than {} corners ({}); stitch numbers its elements with "
                      "32-bit integers",
                      limits::max_halfedges, face(soup, f)));
    for (int v : soup.faces[f])
      if (v < 0 || v >= nv)
        throw InputError(fmt::format("{} refers to vertex {}, but there are {} vertices",
                                     face(soup, f), quoted(soup, v), nv));
  }
}

}  // namespace stitch::soup_places
