// What an edit changed, in the terms an incremental surface needs: which vertices moved, which
// elements' K-gon controls changed, which elements a topology edit touched. Any client that
// edits a mesh (the modeler's Document, a script, an animation loop) describes its edits this way
// and hands them to IncrementalSurface::update.
#pragma once

#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/mesh_journal.hpp"

namespace stitch {

/// What an edit changed, so the surface can update only what depends on it.
struct SurfaceChange {
  enum class Kind { none, geometry, kgons, topology };
  Kind kind = Kind::none;
  std::vector<Vertex> moved;  ///< geometry: the vertices that moved
  /// kgons: the elements whose controls changed (all_kgons: the global control changed).
  /// topology: the elements the edit touched (MeshDelta), unless `whole`.
  std::vector<Face> faces;
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  bool all_kgons = false;
  bool whole = false;  ///< topology: everything may have changed (renumbered or replaced)

  [[nodiscard]] bool empty() const { return kind == Kind::none; }
};

/// The topology change of the edits a MeshJournal recorded.
SurfaceChange topology_change(const MeshDelta& delta);
/// A topology change after which nothing can be assumed (a remeshing or a replaced mesh, which
/// renumber every element): the surface is rebuilt.
SurfaceChange whole_change();

/// One topology change covering `changes` made one after the other, for a surface that has seen
/// none of them: the union of what they touched (moved vertices count as touched), whole if any
/// was. K-gon control changes are not covered (the surface needs the controls themselves).
/// Kind none when `changes` is empty.
SurfaceChange combined(const std::vector<SurfaceChange>& changes);

/// Elements whose K-gons can change, and the corners whose nets use one of them: a superset of
/// what really changes.
struct AffectedSet {
  std::vector<Face> faces;  ///< their corner points are recomputed too
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  std::vector<Corner> corners;
};
/// For a geometry change: around the moved vertices; for a K-gon change: the edited elements
/// (by the library's dependency rules, kgons_reading and nets_reading).
AffectedSet affected_by(const HalfedgeMesh& mesh, const SurfaceChange& change);
/// Everything that can read the corner points or normals of `moved_faces` (faces whose vertices
/// moved or whose loops changed), besides the seed elements of `seeds`.
AffectedSet affected_by(const HalfedgeMesh& mesh, std::vector<Face> moved_faces, AffectedSet seeds);

}  // namespace stitch
