// From a polygon soup (positions + index loops) to a closed half-edge mesh, with every check a
// user's file needs: indices in range, no repeated consecutive vertex, finite coordinates,
// consistent orientation, manifold edges and vertices (boundary loops included). What can be
// repaired is repaired first (repair.hpp) unless BuildOptions::repair is off.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/polygon_soup.hpp"
#include "stitch/mesh/repair.hpp"

namespace stitch {

/// The texture coordinates of a built mesh's corners. They live beside the mesh, not in it: the
/// topology operators do not maintain them, so an edited mesh has none.
struct CornerUvs {
  std::vector<Eigen::Vector2d> uv;
  /// By half-edge: the index into `uv` of the corner's coordinates; -1 for the corners of holes
  /// (and of faces --fill-holes added).
  std::vector<int> index;
  [[nodiscard]] bool empty() const { return uv.empty(); }
};

struct BuildOptions {
  /// Close every boundary loop with one new face. Without it, each boundary loop becomes a hole
  /// face (HalfedgeMesh::is_hole): the surface keeps its boundary there.
  bool fill_holes = false;
  /// Allow faces of degree 2 (the topology operators create them; files normally do not).
  bool allow_two_gons = false;
  /// Repair the soup first (repair.hpp) and say what was done; off, the mesh must be orientable
  /// and manifold as it is, and a refusal lists every defect repair() would fix (`--strict`).
  bool repair = true;
};

struct BuildReport {
  std::vector<std::string> warnings;
  int dropped_vertices = 0;  ///< unused vertices removed
  int filled_holes = 0;      ///< boundary loops found (hole faces, or faces with fill_holes)
  /// new vertex index -> index in the soup (unused vertices are dropped, so they can differ; a
  /// vertex the repair split maps each copy to it).
  std::vector<int> vertex_source;
  /// face index -> index of the face in the soup (-1 for the faces of boundary loops): they differ
  /// where the repair dropped faces.
  std::vector<int> face_source;
  /// What the repair changed (its summary lines open `warnings`).
  RepairReport repair;
  /// The soup's texture coordinates on the mesh's corners; empty when the soup has none.
  CornerUvs corner_uvs;
};

/// Builds the half-edge mesh, or throws stitch::Error naming the problem and where it is (in the
/// numbering of the soup's file, PolygonSoup::numbering).
HalfedgeMesh build_mesh(const PolygonSoup& soup, const BuildOptions& options = {},
                        BuildReport* report = nullptr);

/// The inverse: positions, face loops (0-based, live elements only, in index order; holes are
/// left out, so they read back as boundaries) and the sharpness tags.
PolygonSoup to_polygon_soup(const HalfedgeMesh& mesh);

/// Throws stitch::Error saying why unless the mesh, written as a file (to_polygon_soup), reads back
/// through build_mesh (2-sided faces allowed, nothing repaired) with the same counts, components
/// and genus. Every edit passes this before it is accepted, so everything stitch writes it can
/// read again.
void check_reads_back(const HalfedgeMesh& mesh);

}  // namespace stitch
