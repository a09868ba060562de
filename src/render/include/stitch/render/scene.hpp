// Everything drawn for one mesh and method, built on the CPU in one call: the glue between
// the evaluation pipeline and the Renderer, shared by `stitch render`, `stitch compare` and
// the modeler.
#pragma once

#include <array>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/render/overlays.hpp"
#include "stitch/render/renderer.hpp"

namespace stitch {

struct SceneGeometry {
  SurfaceMesh surface;                         ///< unwelded: one vertex block per patch
  SurfaceMesh input;                           ///< the input polygons (input_faces)
  std::array<LineSet, num_overlays> overlays;  ///< indexed by Overlay
  std::vector<ExtraordinaryPoint> extraordinary;
  BoundingBox bounds;  ///< of the surface and the input mesh
};

/// Which overlays build_scene makes (indexed by Overlay); the others stay empty, which saves
/// time and memory on large meshes (the tessellation's lines are 4 segments per quad).
using OverlaySelection = std::array<bool, num_overlays>;
inline constexpr OverlaySelection all_overlays{true, true, true, true};

/// Tessellates `surface` at `resolution` segments per patch side (unwelded) and builds the
/// selected overlays, the input polygons and the extraordinary points.
SceneGeometry build_scene(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                          const OverlaySelection& overlays = all_overlays);

/// Uploads the scene: the smooth surface, or the input polygons when `input_polygons`.
void upload_scene(Renderer& renderer, const SceneGeometry& scene, bool input_polygons = false);

/// A close-up of an extraordinary point: seen along its normal tilted by 30 degrees towards the
/// world's up (so reflection lines cross the patch boundaries leaving it), framing the sphere
/// of radius `radius_patches` times the size of the patches there (ExtraordinaryPoint::extent).
/// The near plane cuts away whatever lies in front of that sphere (a cutaway view), so points
/// inside the model are seen too.
Camera focus_camera(const ExtraordinaryPoint& point, const SceneGeometry& scene, double aspect,
                    double radius_patches = 0.6);

}  // namespace stitch
