#include "stitch/analysis/build_surface.hpp"

#include <fmt/format.h>

namespace stitch {

SemiSharpRefinement semi_sharp_refinement(const HalfedgeMesh& mesh, const SurfaceSpec& spec) {
  return semi_sharp_refinement(mesh, spec.method, spec.semi_sharp);
}

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
  const SemiSharpRefinement refinement = semi_sharp_refinement(mesh, spec);
  std::optional<SemiSharpMesh> refined;
  if (refinement.levels > 0) {
    if (!spec.kgons.face.empty() || !spec.kgons.edge.empty()) {
      throw UsageError(fmt::format(
          "per-element K-gon controls of faces or edges name elements of the input mesh, which "
          "the refinement for its semi-sharp tags replaces; round the tags instead (sharp_from, "
          "--sharp-from) to use them ({})",
          refinement.summary()));
    }
    refined.emplace(
        refine_semi_sharp(mesh, refinement.levels, spec.kgons.boundary,
                          spec.uvs != nullptr && !spec.uvs->empty() ? spec.uvs : nullptr));
  }
  const HalfedgeMesh& m = refined ? refined->mesh : mesh;
  SurfaceSpec on_m = spec;
  on_m.kgons = semi_sharp_kgons(spec.kgons, spec.method, spec.semi_sharp);
  SurfaceKgons k = surface_kgons(m, on_m);
  Surface surface(m, spec.method, k.kgons);
  if (refined && spec.method != Method::cc) {
    // The input's K-gons as its untagged surface has them, tubes unfolded too.
    const KgonOptions input_kgons = surface_kgons(mesh, on_m).kgons;
    surface.edit_nets([&](std::vector<ControlNet>& nets) {
      semi_sharp_nets(mesh, input_kgons, *refined, k.kgons, spec.method, nets);
    });
  }
  return {std::move(surface), std::move(k.kgons), std::move(k.tubes), refinement,
          std::move(refined)};
}

}  // namespace stitch
