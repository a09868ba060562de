#include "stitch/analysis/build_surface.hpp"

namespace stitch {

SurfaceKgons surface_kgons(const HalfedgeMesh& mesh, const SurfaceSpec& spec) {
  SurfaceKgons out{spec.kgons, {}};
  if (spec.unfold_tubes && spec.method != Method::cc) {
    UnfoldTubesOptions unfold;
    unfold.method = spec.method;
    out.tubes = unfold_tubes(mesh, out.kgons, unfold);
  }
  return out;
}

BuiltSurface build_surface(const HalfedgeMesh& mesh, const SurfaceSpec& spec) {
  SurfaceKgons k = surface_kgons(mesh, spec);
  Surface surface(mesh, spec.method, k.kgons);
  return {std::move(surface), std::move(k.kgons), std::move(k.tubes)};
}

}  // namespace stitch
