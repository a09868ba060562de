// How messages name the elements of a polygon soup: as the file it came from numbers them
// (PolygonSoup::numbering, from 1 or from 0), with the line that declared them where known, and
// by position for files that give vertices no numbers (STL, glTF). build_mesh's refusals and
// repair()'s report both name places this way.
#pragma once

#include <string>
#include <vector>

#include "stitch/mesh/polygon_soup.hpp"

namespace stitch::soup_places {

/// The file's 0-based index of soup face f and vertex v (PolygonSoup::face_origin and
/// vertex_origin when set).
int file_face(const PolygonSoup& soup, int f);
int file_vertex(const PolygonSoup& soup, int v);
/// The number a message quotes for a file's 0-based index: index + 1 for files counting from 1.
int quoted(const PolygonSoup& soup, int file_index);

/// "face 14 (a.obj, line 95)" (without the file name unless with_source); in a file without
/// numbers, the face's line or its first corners' positions.
std::string face(const PolygonSoup& soup, int f, bool with_source = true);
/// "vertex 7 (a.obj, line 9)", or "the vertex at (x, y, z)" in a file without numbers.
std::string vertex(const PolygonSoup& soup, int v, bool with_source = true);
/// "edge (7, 8)", or "the edge from (x, y, z) to (x, y, z)" in a file without numbers.
std::string edge(const PolygonSoup& soup, int a, int b);

/// The first `shown` names, then how many more there are: "a, b, c, ... (4 more)".
std::string listed(const std::vector<std::string>& names, size_t shown = 5);

/// Throws InputError unless every face refers to vertices of the soup and the corners can be
/// numbered with 32-bit integers.
void check_face_indices(const PolygonSoup& soup);

}  // namespace stitch::soup_places
