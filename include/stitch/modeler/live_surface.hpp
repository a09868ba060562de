// The smooth surface of the document, kept up to date incrementally.
//
// After a vertex move or a K-gon edit only the K-gons that can depend on the change are rebuilt
// (update_kgons), then the control nets of the corners that use those K-gons; a patch is
// re-tessellated only when its net actually changed. The tessellation is unwelded, one
// contiguous vertex block per patch in corner order (exactly tessellate(..., welded = false)),
// so the renderer can re-upload just the changed blocks.
//
// What is rebuilt in full (documented in docs/modeler.md): a topology edit (the operators
// renumber elements, so every array is rebuilt), a change of the global K-gon control (it
// reaches every extraordinary K-gon; nets are still compared so only changed patches are
// re-tessellated), a change of resolution, and everything for the Catmull-Clark method, whose
// OpenSubdiv limit surface is built for the whole mesh.
#pragma once

#include <memory>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/modeler/document.hpp"
#include "stitch/tess/surface_mesh.hpp"

namespace stitch::modeler {

/// The elements whose K-gons can change when `change` is applied (geometry or kgons kinds), and
/// the corners whose nets use one of them: a superset of what really changes.
struct AffectedSet {
  std::vector<Face> faces;  ///< also: the faces whose corner points must be recomputed
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  std::vector<Corner> corners;
};
/// The faces listed first are those whose corner points move (the faces around moved vertices,
/// or none for a K-gon edit); the rest only need their K-gons rebuilt.
AffectedSet affected_by(const HalfedgeMesh& mesh, const Change& change);

struct UpdateStats {
  bool full = false;               ///< everything was rebuilt
  int candidate_patches = 0;       ///< nets rebuilt and compared
  int recomputed_patches = 0;      ///< patches re-tessellated
  double milliseconds = 0.0;       ///< wall time of the update
};

class LiveSurface {
 public:
  LiveSurface() = default;
  /// Builds everything from scratch.
  UpdateStats rebuild(const HalfedgeMesh& mesh, const KgonOptions& options, Method method,
                      int resolution);
  /// Brings the surface up to date with `mesh` and `options` after `change`. The functions
  /// that can fail (cc on a mesh OpenSubdiv refuses) throw MeshError before changing anything.
  UpdateStats update(const HalfedgeMesh& mesh, const KgonOptions& options, const Change& change);
  UpdateStats set_method(const HalfedgeMesh& mesh, const KgonOptions& options, Method method);
  UpdateStats set_resolution(const HalfedgeMesh& mesh, const KgonOptions& options, int resolution);

  [[nodiscard]] Method method() const { return method_; }
  [[nodiscard]] int resolution() const { return resolution_; }
  [[nodiscard]] const KgonSet& kgons() const { return kgons_; }
  /// Indexed by corner (half-edge); empty nets for deleted half-edges.
  [[nodiscard]] const std::vector<ControlNet>& nets() const { return nets_; }
  /// The live corners in index order: patch k of the tessellation is corners()[k].
  [[nodiscard]] const std::vector<Corner>& corners() const { return corners_; }
  [[nodiscard]] const SurfaceMesh& tessellation() const { return tess_; }
  /// The corners whose patches the last update re-tessellated, in increasing order (every
  /// corner after a full rebuild).
  [[nodiscard]] const std::vector<Corner>& recomputed() const { return recomputed_; }
  /// The vertex block of patch k: [k * vertices_per_patch(), (k + 1) * vertices_per_patch()).
  [[nodiscard]] int vertices_per_patch() const { return (resolution_ + 1) * (resolution_ + 1); }
  /// Index of corner c's patch in corners(), or -1.
  [[nodiscard]] int patch_index(Corner c) const { return c.idx < int(slot_.size()) ? slot_[c.idx] : -1; }

 private:
  /// Evaluates the listed patches (indices into corners_) into their vertex blocks; `cc` is
  /// the Catmull-Clark surface when that is the method.
  void tessellate_patches(const std::vector<int>& patches, const Surface* cc);
  void layout(const HalfedgeMesh& mesh);

  Method method_ = Method::mdc;
  int resolution_ = 8;
  KgonSet kgons_;
  std::vector<ControlNet> nets_;
  std::vector<Corner> corners_;
  std::vector<int> slot_;
  SurfaceMesh tess_;
  std::vector<Corner> recomputed_;
};

}  // namespace stitch::modeler
