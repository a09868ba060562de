// From a polygon soup (positions + index loops) to a closed half-edge mesh, with every check a
// user's file needs: indices in range, no repeated consecutive vertex, finite coordinates,
// consistent orientation, manifold edges and vertices, and (unless holes are filled) no boundary.
#pragma once

#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// A polygon soup as read from a file. Indices are 0-based. face_lines[i] (optional) is the
/// 1-based line of the file that declared face i, so messages can point at it.
struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  std::vector<int> face_lines;
  std::vector<int> vertex_lines;
  std::string source;  ///< file name, for messages
};

struct BuildOptions {
  /// Close every boundary loop with one new face instead of refusing the mesh.
  bool fill_holes = false;
  /// Allow faces of degree 2 (the topology operators create them; files normally do not).
  bool allow_two_gons = false;
};

struct BuildReport {
  std::vector<std::string> warnings;
  int dropped_vertices = 0;  ///< unused vertices removed
  int filled_holes = 0;      ///< boundary loops closed by fill_holes
  /// new vertex index -> index in the soup (unused vertices are dropped, so they can differ).
  std::vector<int> vertex_source;
};

/// Builds the half-edge mesh, or throws MeshError naming the problem and where it is.
HalfedgeMesh build_mesh(const PolygonSoup& soup, const BuildOptions& options = {},
                        BuildReport* report = nullptr);

/// The inverse: positions and face loops (0-based, live elements only, in index order).
PolygonSoup to_polygon_soup(const HalfedgeMesh& mesh);

/// Throws MeshError saying why unless the mesh, written as a file (to_polygon_soup), reads back
/// through build_mesh (2-sided faces allowed) with the same counts, components and genus. Every
/// edit passes this before it is accepted, so everything stitch writes it can read again.
void check_reads_back(const HalfedgeMesh& mesh);

}  // namespace stitch
