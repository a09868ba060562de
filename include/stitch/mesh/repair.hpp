// Repair on the way in: the defects of meshes as people have them (mixed winding, sheets that
// touch at a vertex or share an edge, repeated vertices, degenerate and duplicate faces) made into
// a polygon soup that build_mesh accepts, every change named. build_mesh applies it unless
// BuildOptions::repair is off (`--strict`); docs/formats.md, "What is repaired on reading".
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stitch/choices.hpp"
#include "stitch/mesh/polygon_soup.hpp"

namespace stitch {

/// What repair() changes, one kind per defect.
enum class RepairKind {
  repeated_vertex,      ///< a vertex repeated at consecutive positions (or a spike): removed
  degenerate_face,      ///< a face with fewer than 3 distinct vertices: dropped
  duplicate_face,       ///< the same loop as an earlier face, same direction: dropped
  flipped_face,         ///< wound against its neighbours: reversed, texture coordinates too
  non_manifold_edge,    ///< 3 or more faces on an edge: split into a sharp edge and boundaries
  non_manifold_vertex,  ///< several fans of faces at a vertex: one vertex per fan
  dropped_tag,          ///< a crease or corner tag on an element only dropped faces had
};

/// The kinds by name ("flipped_face", ...), in the order above, each with a line of help.
ChoiceTable<RepairKind> repair_kind_table();

/// One change: the defect, where it is and what was done.
struct RepairChange {
  RepairKind kind = RepairKind::repeated_vertex;
  /// The faces and vertices concerned, as 0-based indices of the file's elements (of the soup
  /// as read: PolygonSoup::face_origin and vertex_origin when the soup was repaired before).
  /// An edge lists its two ends.
  std::vector<int> faces, vertices;
  std::vector<int> lines;       ///< the faces' lines in the file (0: unknown)
  std::vector<Vec3> positions;  ///< the vertices' positions
  std::string defect;  ///< what was wrong, in the file's numbering ("face 14 (line 95) ...")
  std::string action;  ///< what repair() did about it
};

struct RepairReport {
  std::string source;  ///< the soup's file name
  Numbering numbering = Numbering::from_one;
  std::vector<RepairChange> changes;
  [[nodiscard]] bool empty() const { return changes.empty(); }
  [[nodiscard]] int count(RepairKind kind) const;
  /// The count of each kind that occurs, by name ("flipped_face", 3), in the table's order.
  [[nodiscard]] std::vector<std::pair<std::string_view, int>> counts() const;
  /// One line per kind of change, for warnings: what was done, how often, and the first few
  /// places ("flipped 3 faces wound against their neighbours (...): face 2 (line 4), ...").
  [[nodiscard]] std::vector<std::string> summary() const;
};

struct RepairOptions {
  /// Keep faces given with two vertices (BuildOptions::allow_two_gons); faces that a repair
  /// leaves with two are dropped all the same.
  bool allow_two_gons = false;
};

/// Repairs the soup in place and says what it changed (nothing for an oriented manifold soup;
/// build_mesh repairs only a soup it cannot build as it is, so a mesh that reads is never
/// changed):
/// - vertices repeated at consecutive positions of a face are removed, and so are spikes (a face
///   running out along an edge and straight back: a b a), then faces with fewer than 3 distinct
///   vertices and exact duplicates (same loop, same direction) are dropped, with their texture
///   coordinates;
/// - an edge of 3 or more faces is split: faces running along it in opposite directions pair up
///   (neighbours around the edge, preferring the pairs that enclose a solid), each pair keeps a
///   manifold edge tagged infinitely sharp, the others get boundary edges at the same place, so
///   the pieces' surfaces meet along one sharp curve (OpenSubdiv makes such edges sharp);
/// - a vertex whose faces form several fans gets one vertex per fan at the same position,
///   tagged as an infinitely sharp corner as OpenSubdiv tags non-manifold vertices (except inside
///   a chain of split edges, where the copies are crease vertices of the shared curve); a copy
///   keeps the vertex's tags;
/// - the faces of each connected piece are flipped to one orientation, the larger part keeping
///   its winding (on a tie, the part under which the piece points outward; flat or open, the
///   part with the piece's first face).
/// Throws InputError naming the place when a piece cannot be oriented (a Möbius strip), and for
/// faces that refer to missing vertices.
RepairReport repair(PolygonSoup& soup, const RepairOptions& options = {});

/// The report as JSON text: {"file", "numbered_from" (1, 0 or null), "counts" by kind,
/// "changes": [{"kind", "faces", "vertices" (numbered as the file numbers them; no vertices
/// for files without numbers), "lines", "positions", "defect", "action"}]}.
std::string to_json(const RepairReport& report);

}  // namespace stitch
