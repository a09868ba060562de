// The one recipe of a smooth surface that every front end asks for: a method, the user's K-gon
// controls, and the policy for tubes whose fitted K-gons fold (unfold_tubes). `stitch smooth`,
// Python's stitch.Surface and the modeler build through it, so the same request gives the same
// surface wherever it is made.
#pragma once

#include <vector>

#include "stitch/analysis/unfold_tubes.hpp"
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
};

/// The K-gon options a request's surface is built with.
struct SurfaceKgons {
  KgonOptions kgons;                 ///< spec.kgons and the controls chosen for folding tubes
  std::vector<TubeUnfolding> tubes;  ///< what unfold_tubes found, for the front end to report
};
SurfaceKgons surface_kgons(const HalfedgeMesh& mesh, const SurfaceSpec& spec);

struct BuiltSurface {
  Surface surface;
  KgonOptions kgons;  ///< what `surface` was built with
  std::vector<TubeUnfolding> tubes;
};
/// The surface of the request: Surface(mesh, spec.method, surface_kgons(mesh, spec).kgons).
BuiltSurface build_surface(const HalfedgeMesh& mesh, const SurfaceSpec& spec);

}  // namespace stitch
