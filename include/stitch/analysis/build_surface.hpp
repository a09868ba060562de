// The one recipe of a smooth surface that every front end asks for: a method, the user's K-gon
// controls, how semi-sharp tags are taken, and the policy for tubes whose fitted K-gons fold
// (unfold_tubes). `stitch smooth`, Python's stitch.Surface and the modeler build through it, so
// the same request gives the same surface wherever it is made.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "stitch/analysis/unfold_tubes.hpp"
#include "stitch/eval/semi_sharp.hpp"
#include "stitch/eval/surface.hpp"

namespace stitch {

struct SurfaceSpec {
  Method method = Method::mdc;
  /// The user's controls (global and per element), the construction, the boundary rule and
  /// sharp_from.
  KgonOptions kgons;
  /// Where a tube made by inserting an edge between two faces folds with its fitted K-gons,
  /// choose K-gon controls that unfold it (unfold_tubes.hpp); off keeps the fitted ones. Nothing
  /// is searched for cc, whose surface does not come from the K-gons.
  bool unfold_tubes = true;
  /// Semi-sharp tags honoured by refinement (the default; kgons.sharp_from is then
  /// infinitely_sharp) or rounded at kgons.sharp_from.
  SemiSharp semi_sharp = SemiSharp::refine;
  /// The mesh's texture coordinates, if any (not owned): refined with the mesh
  /// (SemiSharpMesh::uvs), so that they go with the refined surface.
  const CornerUvs* uvs = nullptr;
};

/// The refinement build_surface does for this request, found from the tags alone (no work on
/// the points).
SemiSharpRefinement semi_sharp_refinement(const HalfedgeMesh& mesh, const SurfaceSpec& spec);

/// The K-gon options a request's surface is built with.
struct SurfaceKgons {
  KgonOptions kgons;                 ///< spec.kgons and the controls chosen for folding tubes
  std::vector<TubeUnfolding> tubes;  ///< what unfold_tubes found, for the front end to report
};
/// For `mesh` as it is: no refinement (the modeler's document as loaded, and build_surface on
/// its refined mesh).
SurfaceKgons surface_kgons(const HalfedgeMesh& mesh, const SurfaceSpec& spec);

struct BuiltSurface {
  Surface surface;
  KgonOptions kgons;                 ///< what `surface` was built with
  std::vector<TubeUnfolding> tubes;  ///< numbered in mesh(input)
  SemiSharpRefinement refinement;
  /// The mesh `surface` is built on when the request refined the input (refinement.levels > 0),
  /// empty otherwise. The surface's corners, the tubes and the tessellation's layout are this
  /// mesh's: use mesh(input) wherever the surface goes with a mesh.
  std::optional<SemiSharpMesh> refined;
  [[nodiscard]] const HalfedgeMesh& mesh(const HalfedgeMesh& input) const {
    return refined ? refined->mesh : input;
  }
};
/// The surface of the request: with semi-sharp tags to honour, the mesh refined first
/// (refine_semi_sharp); then Surface(m, spec.method, surface_kgons(m, spec).kgons) on that mesh
/// m. Per-element face and edge K-gon controls name elements of the input and are refused
/// (UsageError) when the mesh is refined; vertex controls keep their vertices.
BuiltSurface build_surface(const HalfedgeMesh& mesh, const SurfaceSpec& spec);

}  // namespace stitch
