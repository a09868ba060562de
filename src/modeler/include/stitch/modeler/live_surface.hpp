// The smooth surface of the document, kept up to date incrementally.
//
// After an edit only the K-gons that can depend on it are rebuilt (update_kgons), then the
// control nets of the corners that use those K-gons; a patch is re-evaluated only when its net
// actually changed.
//
// Layout: the tessellation is unwelded with one vertex block per patch *slot*, and slot = the
// corner's half-edge index, so the blocks of untouched patches stay where they are when a
// topology edit adds or removes elements (the operators keep the numbers of untouched elements).
// A slot whose half-edge is deleted keeps its place with degenerate quads (nothing is drawn) and
// patch = -1. The live blocks, in corner order, are exactly tessellate(..., welded = false).
// The renderer re-uploads just the blocks of recomputed() patches and relaid() slots, also after
// a topology edit that adds or removes slots (Renderer::update_surface_blocks).
//
// A topology edit comes with the elements it touched (the mesh's journal, see Change): those
// seed the same local update as a vertex move, so its cost follows the size of the edit, not of
// the mesh. Rebuilt in full (documented in docs/modeler.md): remeshings and replaced documents,
// a change of the global K-gon control (it reaches every extraordinary K-gon; nets are still
// compared so only changed patches are re-evaluated), method and resolution changes, and every
// change for the Catmull-Clark method, whose OpenSubdiv limit surface is built for the whole
// mesh.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/modeler/document.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch::modeler {

/// Elements whose K-gons can change, and the corners whose nets use one of them: a superset of
/// what really changes.
struct AffectedSet {
  std::vector<Face> faces;  ///< their corner points are recomputed too
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  std::vector<Corner> corners;
};
/// For a geometry change: around the moved vertices; for a K-gon change: the edited elements.
AffectedSet affected_by(const HalfedgeMesh& mesh, const Change& change);

struct UpdateStats {
  bool full = false;            ///< everything was re-evaluated
  bool layout_changed = false;  ///< slots were added, removed, revived or killed (see relaid())
  int candidate_patches = 0;    ///< nets rebuilt and compared
  int recomputed_patches = 0;   ///< patches re-evaluated
  double milliseconds = 0.0;    ///< wall time of the update
};

class LiveSurface {
 public:
  LiveSurface() = default;
  /// Builds everything from scratch.
  UpdateStats rebuild(const HalfedgeMesh& mesh, const KgonOptions& options, Method method,
                      int resolution);
  /// Brings the surface up to date with `mesh` and `options` after `change`. The functions that
  /// can fail (cc on a mesh OpenSubdiv refuses) throw stitch::Error before changing anything.
  UpdateStats update(const HalfedgeMesh& mesh, const KgonOptions& options, const Change& change);
  UpdateStats set_method(const HalfedgeMesh& mesh, const KgonOptions& options, Method method);
  UpdateStats set_resolution(const HalfedgeMesh& mesh, const KgonOptions& options, int resolution);

  [[nodiscard]] Method method() const { return method_; }
  [[nodiscard]] int resolution() const { return resolution_; }
  [[nodiscard]] const KgonSet& kgons() const { return kgons_; }
  /// Indexed by corner (half-edge); empty nets for deleted half-edges.
  [[nodiscard]] const std::vector<ControlNet>& nets() const { return nets_; }
  /// The live corners in index order (a pass over every slot).
  [[nodiscard]] std::vector<Corner> corners() const;
  /// How many patches there are (live corners).
  [[nodiscard]] int num_patches() const { return num_patches_; }
  /// One block per half-edge slot (see above).
  [[nodiscard]] const TessellatedMesh& tessellation() const { return tess_; }
  /// The corners whose patches the last update re-evaluated, in increasing order (every live
  /// corner after a full rebuild).
  [[nodiscard]] const std::vector<Corner>& recomputed() const { return recomputed_; }
  /// The slots the last update laid out again (a patch appeared or went; every slot after a
  /// full rebuild). With recomputed(), the blocks a renderer must upload again
  /// (Renderer::update_surface_blocks).
  [[nodiscard]] const std::vector<int>& relaid() const { return relaid_; }
  /// Corner c's block is [c.idx * vertices_per_patch(), (c.idx + 1) * vertices_per_patch()),
  /// its quads [c.idx * quads_per_patch(), ...).
  [[nodiscard]] int vertices_per_patch() const { return (resolution_ + 1) * (resolution_ + 1); }
  [[nodiscard]] int quads_per_patch() const { return resolution_ * resolution_; }

 private:
  /// Evaluates the listed corners' patches into their blocks; `cc` is the Catmull-Clark surface
  /// when that is the method.
  void evaluate(const std::vector<Corner>& patches, const Surface* cc);
  /// Sizes the blocks to `slots` and sets uv, patch and quads of the listed slots from live_.
  void layout(int slots, const std::vector<int>& changed_slots);
  UpdateStats update_topology(const HalfedgeMesh& mesh, const KgonOptions& options,
                              const Change& change);

  Method method_ = Method::mdc;
  int resolution_ = 8;
  KgonSet kgons_;
  std::vector<ControlNet> nets_;
  std::vector<std::uint8_t> live_;  ///< per slot (half-edge): has a patch
  int num_patches_ = 0;
  TessellatedMesh tess_;
  std::vector<Corner> recomputed_;
  std::vector<int> relaid_;
};

}  // namespace stitch::modeler
