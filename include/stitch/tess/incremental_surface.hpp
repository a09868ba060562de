// A smooth surface kept up to date incrementally as its mesh is edited, for any client that
// edits a mesh and wants the surface after each edit: the modeler (Session), a script, an
// animation loop. The client describes each edit as a SurfaceChange (surface_change.hpp).
//
// After an edit only the K-gons that can depend on it are rebuilt (update_kgons), then the
// control nets of the corners that use those K-gons; a patch is re-evaluated only when its net
// actually changed.
//
// Layout: the tessellation is unwelded with one vertex block per patch *slot*, and slot = the
// corner's half-edge index, so the blocks of untouched patches stay where they are when a
// topology edit adds or removes elements (the operators keep the numbers of untouched elements).
// Every block is laid out by the same PatchGrid as tessellate(..., welded = false). A slot whose
// half-edge is deleted keeps its place with degenerate quads (nothing is drawn) and patch = -1.
// The live blocks, in corner order, are exactly tessellate(..., welded = false).
// A renderer re-uploads just the blocks of recomputed() patches and relaid() slots, also after
// a topology edit that adds or removes slots (the modeler's Renderer::update_surface_blocks).
//
// A topology edit comes with the elements it touched (the mesh's journal, topology_change):
// those seed the same local update as a vertex move, so its cost follows the size of the edit,
// not of the mesh. Rebuilt in full (documented in docs/modeler.md): remeshings and replaced
// meshes (whole_change), a change of the global K-gon control (it reaches every extraordinary
// K-gon; nets are still compared so only changed patches are re-evaluated), method and
// resolution changes, and every change for the Catmull-Clark method, whose OpenSubdiv limit
// surface is built for the whole mesh.
//
// Topology apart from point data (as OpenSubdiv's Bfr separates them): the slots, which of them
// hold a patch, every block's (u, v), patch id and quads depend on the connectivity and the
// resolution alone, and so does the K-gons' preparation (kgon_topology.hpp: corners, vertex
// kinds, sharp edges, openings, Doo-Sabin weights). update_positions is the path for "every
// vertex may have moved, the connectivity did not" (a deforming animation): it keeps all of that
// (the K-gons' preparation from its first call after a topology change) and recomputes only the
// K-gons' points, the nets and the samples of the patches whose nets changed.
//
// Semi-sharp tags are taken as build_surface takes them (eval/semi_sharp.hpp): honoured by
// default, the surface is then built on the mesh refined for them, whose corners number the
// slots, nets, K-gons and blocks (mesh(input) is that mesh). A move re-refines the points (the
// refinement is linear in them, the connectivity the same) and updates as update_positions does;
// a K-gon control change updates the same way; a topology or tag edit refines again and rebuilds.
// Face and edge K-gon controls name elements the refinement replaced and are not applied there.
// SemiSharp::round rounds the tags at KgonOptions::sharp_from instead, one patch per corner.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "stitch/eval/semi_sharp.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/kgon/kgon_topology.hpp"
#include "stitch/tess/patch_grid.hpp"
#include "stitch/tess/surface_change.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

struct SurfaceUpdateStats {
  bool full = false;            ///< everything was re-evaluated
  bool layout_changed = false;  ///< slots were added, removed, revived or killed (see relaid())
  int candidate_patches = 0;    ///< nets rebuilt and compared
  int recomputed_patches = 0;   ///< patches re-evaluated
  double milliseconds = 0.0;    ///< wall time of the update
};

/// The slots to allocate room for when a surface has `slots`: edits that add up to half as many
/// again find their room there, so the first topology edit after a rebuild does not move every
/// array (at 10k faces and resolution 8, about 300 MB). The renderer's block buffers use the same
/// rule. Untouched room costs address space, not resident memory.
constexpr int slot_capacity_for(int slots) {
  return slots + slots / 2 + 16;
}

class IncrementalSurface {
 public:
  IncrementalSurface() = default;
  /// Builds everything from scratch.
  SurfaceUpdateStats rebuild(const HalfedgeMesh& mesh, const KgonOptions& options, Method method,
                             int resolution, SemiSharp semi_sharp = SemiSharp::refine);
  /// Brings the surface up to date with `mesh` and `options` after `change`. The functions that
  /// can fail (cc on a mesh OpenSubdiv refuses) throw stitch::Error before changing anything.
  SurfaceUpdateStats update(const HalfedgeMesh& mesh, const KgonOptions& options,
                            const SurfaceChange& change);
  /// Brings the surface up to date after any of the mesh's vertices moved (and the K-gon
  /// controls possibly changed) while its connectivity, holes and tags stayed as they were at
  /// the last rebuild or update: the layout (slots, uv, patch ids, quads) is kept, relaid() is
  /// empty. Throws UsageError when the mesh's element capacities differ from the surface's (a
  /// sign of a topology edit, which needs update with its SurfaceChange); other topology edits
  /// cannot be detected cheaply and give a wrong surface.
  SurfaceUpdateStats update_positions(const HalfedgeMesh& mesh, const KgonOptions& options);
  SurfaceUpdateStats set_method(const HalfedgeMesh& mesh, const KgonOptions& options,
                                Method method);
  SurfaceUpdateStats set_resolution(const HalfedgeMesh& mesh, const KgonOptions& options,
                                    int resolution);

  [[nodiscard]] SemiSharp semi_sharp() const { return semi_sharp_; }
  /// What honouring the semi-sharp tags took (levels == 0: the patches are the input's corners).
  [[nodiscard]] const SemiSharpRefinement& refinement() const { return refinement_; }
  /// The refined mesh and its map from the input's corners, when refinement.levels > 0.
  [[nodiscard]] const SemiSharpMesh* refined() const { return refined_ ? &*refined_ : nullptr; }
  /// The mesh whose corners number the patches: `input`, or its refinement.
  [[nodiscard]] const HalfedgeMesh& mesh(const HalfedgeMesh& input) const {
    return refined_ ? refined_->mesh : input;
  }
  [[nodiscard]] Method method() const { return method_; }
  [[nodiscard]] int resolution() const { return grid_.resolution(); }
  /// The sample layout of every block.
  [[nodiscard]] const PatchGrid& grid() const { return grid_; }
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
  /// (the modeler's Renderer::update_surface_blocks).
  [[nodiscard]] const std::vector<int>& relaid() const { return relaid_; }
  /// Corner c's block is [c.idx * vertices_per_patch(), (c.idx + 1) * vertices_per_patch()),
  /// its quads [c.idx * quads_per_patch(), ...).
  [[nodiscard]] int vertices_per_patch() const { return grid_.num_samples(); }
  [[nodiscard]] int quads_per_patch() const { return grid_.num_quads(); }

 private:
  /// Evaluates the listed corners' patches into their blocks; `cc` is the Catmull-Clark surface
  /// when that is the method.
  void evaluate(const std::vector<Corner>& patches, const Surface* cc);
  /// Rebuilds the nets of `candidates` (or takes them from `fresh`, by half-edge) and returns
  /// those whose net changed.
  std::vector<Corner> changed_nets(const HalfedgeMesh& mesh, const std::vector<Corner>& candidates,
                                   const std::vector<ControlNet>* fresh = nullptr);
  /// Allocates room for slot_capacity_for(...) of every element kind (after the K-gons and nets
  /// of a rebuild, before the layout).
  void reserve_room(const HalfedgeMesh& mesh);
  /// An empty tessellation with room for `room_slots` blocks at the current resolution.
  void fresh_tessellation(int room_slots);
  /// Sizes the blocks to `slots` and sets uv, patch and quads of the listed slots from live_.
  void layout(int slots, const std::vector<int>& changed_slots);
  SurfaceUpdateStats update_topology(const HalfedgeMesh& mesh, const KgonOptions& options,
                                     const SurfaceChange& change);
  // The surface's own steps on the mesh the patches are built on (mesh(input)), with its
  // options (on()); the public functions above refine first where the tags ask for it, and
  // pass the input (and the refined mesh where refined_ is not it yet) for semi_sharp_nets.
  SurfaceUpdateStats rebuild_on(const HalfedgeMesh& mesh, const KgonOptions& options, Method method,
                                int resolution, const HalfedgeMesh* input = nullptr);
  SurfaceUpdateStats update_on(const HalfedgeMesh& mesh, const KgonOptions& options,
                               const SurfaceChange& change);
  SurfaceUpdateStats update_positions_on(const HalfedgeMesh& mesh, const KgonOptions& options,
                                         const HalfedgeMesh* input = nullptr,
                                         const SemiSharpMesh* refined = nullptr);
  /// The K-gon options on mesh(input): sharp_from as build_surface sets it, face and edge
  /// controls dropped on a refined mesh.
  [[nodiscard]] KgonOptions on(const KgonOptions& options, Method method) const;
  /// The input refined again for the same levels, or a throw where its element capacities
  /// differ from the input the surface was refined from (a topology edit).
  [[nodiscard]] SemiSharpMesh refine_again(const HalfedgeMesh& input,
                                           const KgonOptions& options) const;

  Method method_ = Method::mdc;
  SemiSharp semi_sharp_ = SemiSharp::refine;
  SemiSharpRefinement refinement_;
  std::optional<SemiSharpMesh> refined_;
  /// The input's half-edge and vertex capacities when refined_ was made, which a position-only
  /// update keeps.
  int input_halfedges_ = 0, input_vertices_ = 0;
  PatchGrid grid_{8};
  KgonSet kgons_;
  /// The K-gons' topology update_positions placed kgons_ from; none after a rebuild or a topology
  /// edit (the next update_positions prepares it again).
  std::optional<KgonTopology> kgon_topology_;
  std::vector<ControlNet> nets_;
  std::vector<std::uint8_t> live_;  ///< per slot (half-edge): has a patch
  int num_patches_ = 0;
  TessellatedMesh tess_;
  std::vector<Corner> recomputed_;
  std::vector<int> relaid_;
};

}  // namespace stitch
