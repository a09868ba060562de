// From a polygon soup (positions + index loops) to a closed half-edge mesh, with every check a
// user's file needs: indices in range, no repeated consecutive vertex, finite coordinates,
// consistent orientation, manifold edges and vertices (boundary loops included).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// A polygon soup as read from a file. Indices are 0-based. face_lines[i] (optional) is the
/// 1-based line of the file that declared face i, so messages can point at it.
/// A sharpness tag on the edge(s) joining two vertices (OpenSubdiv's `t crease`).
struct SoupCrease {
  int a = 0, b = 0;  ///< 0-based vertex indices
  double sharpness = 0;
  int line = 0;  ///< 1-based line of the file that declared it (0: unknown)
};
/// A sharpness tag on a vertex (OpenSubdiv's `t corner`).
struct SoupCorner {
  int vertex = 0;  ///< 0-based
  double sharpness = 0;
  int line = 0;
};

struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  std::vector<int> face_lines;
  std::vector<int> vertex_lines;
  std::vector<SoupCrease> creases;
  std::vector<SoupCorner> corners;
  /// Texture coordinates (OBJ `vt`, PLY s t, glTF TEXCOORD_0 with v flipped to OBJ's
  /// bottom-left origin) and, per face, the index into `uvs` of each corner (face_uvs[f][i] for
  /// faces[f][i]). Both empty when the file has none; otherwise every face has them.
  std::vector<Eigen::Vector2d> uvs;
  std::vector<std::vector<int>> face_uvs;
  std::string source;  ///< file name, for messages
};

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
};

struct BuildReport {
  std::vector<std::string> warnings;
  int dropped_vertices = 0;  ///< unused vertices removed
  int filled_holes = 0;      ///< boundary loops found (hole faces, or faces with fill_holes)
  /// new vertex index -> index in the soup (unused vertices are dropped, so they can differ).
  std::vector<int> vertex_source;
  /// The soup's texture coordinates on the mesh's corners; empty when the soup has none.
  CornerUvs corner_uvs;
};

/// Builds the half-edge mesh, or throws stitch::Error naming the problem and where it is.
HalfedgeMesh build_mesh(const PolygonSoup& soup, const BuildOptions& options = {},
                        BuildReport* report = nullptr);

/// The inverse: positions, face loops (0-based, live elements only, in index order; holes are
/// left out, so they read back as boundaries) and the sharpness tags.
PolygonSoup to_polygon_soup(const HalfedgeMesh& mesh);

/// Throws stitch::Error saying why unless the mesh, written as a file (to_polygon_soup), reads back
/// through build_mesh (2-sided faces allowed) with the same counts, components and genus. Every
/// edit passes this before it is accepted, so everything stitch writes it can read again.
void check_reads_back(const HalfedgeMesh& mesh);

}  // namespace stitch
