// A polygon mesh as a file gives it: positions, face loops of vertex indices, the sharpness tags
// and texture coordinates, and where each element was declared, so messages can point at it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// How a file numbers its vertices and faces, so that messages quote the numbers a user finds
/// in it: OBJ counts from 1, OFF and PLY from 0, STL and glTF give no numbers (their vertices
/// are found again by position, so messages give positions).
enum class Numbering { from_one, from_zero, none };

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

/// A polygon soup as read from a file. Indices are 0-based. face_lines[i] (optional) is the
/// 1-based line of the file that declared face i, vertex_lines[i] likewise.
struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  std::vector<int> face_lines;
  std::vector<int> vertex_lines;
  std::vector<SoupCrease> creases;
  std::vector<SoupCorner> corners;
  /// OBJ's `t creasemethod 0/0/1 chaikin|normal` (the last one given).
  CreaseMethod crease_method = CreaseMethod::uniform;
  /// Texture coordinates (OBJ `vt`, PLY s t, glTF TEXCOORD_0 with v flipped to OBJ's
  /// bottom-left origin) and, per face, the index into `uvs` of each corner (face_uvs[f][i] for
  /// faces[f][i]). Both empty when the file has none; otherwise every face has them.
  std::vector<Eigen::Vector2d> uvs;
  std::vector<std::vector<int>> face_uvs;
  std::string source;  ///< file name, for messages
  Numbering numbering = Numbering::from_one;
  /// The file's (0-based) index of each face and vertex where it differs from the position in
  /// these arrays: repair() drops faces and splits vertices (a copy names the vertex it copies).
  /// Empty: the same.
  std::vector<int> face_origin, vertex_origin;
};

}  // namespace stitch
