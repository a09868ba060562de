// Everything drawn for one mesh and method, built on the CPU in one call: the glue between
// the evaluation pipeline and the Renderer, shared by `stitch render`, `stitch compare` and
// the modeler.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/render/overlays.hpp"
#include "stitch/render/renderer.hpp"

namespace stitch {

struct SceneGeometry {
  /// Unwelded: one vertex block per patch; empty when built with SceneSurface::blocks.
  TessellatedMesh surface;
  TessellatedMesh input;                       ///< the input polygons (input_faces)
  std::array<LineSet, num_overlays> overlays;  ///< indexed by Overlay
  std::vector<ExtraordinaryPoint> extraordinary;
  /// The surface's boundary and crease curves, shown with the extraordinary points.
  LineSet sharp_curves;
  BoundingBox bounds;  ///< of the surface and the input mesh
  /// Texture coordinates of the vertices of `surface` and of `input` (add_texcoords); empty
  /// when the input has none.
  std::vector<Eigen::Vector2d> surface_texcoords, input_texcoords;
};

/// Which overlays build_scene makes (indexed by Overlay); the others stay empty, which saves
/// time and memory on large meshes (the tessellation's lines are 4 segments per quad).
using OverlaySelection = std::array<bool, num_overlays>;
inline constexpr OverlaySelection all_overlays{true, true, true, true};

/// Where a scene's smooth surface is tessellated.
enum class SceneSurface {
  whole,  ///< once, into SceneGeometry::surface (and the tessellation overlay from it)
  /// each time it is drawn, a block at a time (surface_blocks): neither the scene nor a picture
  /// of it then holds more of the tessellation than a block, whatever the mesh and resolution
  blocks,
};

/// Tessellates `surface` at `resolution` segments per patch side (unwelded) and builds the
/// selected overlays, the input polygons and the extraordinary points. With SceneSurface::blocks
/// the tessellation is only passed over for the bounds (the same as whole) and kept neither in
/// `surface` nor in the tessellation overlay: draw it from surface_blocks; `input` is left empty
/// too (input_faces, for a picture of the input polygons: 0.4 GB for a million quads).
SceneGeometry build_scene(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                          const OverlaySelection& overlays = all_overlays,
                          SceneSurface tessellation = SceneSurface::whole);

/// About this many vertices a block (some 15 MB with its upload): enough that the draw calls
/// cost nothing beside the evaluation, few enough to leave the memory to the mesh's surface.
inline constexpr int kSceneBlockVertices = 1 << 17;

/// The unwelded tessellation of `surface` at `resolution`, produced block by block as it is
/// drawn (Renderer::draw, render_image): blocks of `patches_per_block` patches (0: about
/// kSceneBlockVertices vertices), with patch ids and levels, and texture coordinates from `uvs`
/// when given. Keeps references to `mesh`, `surface` and `uvs`. `progress`, if set, is told the
/// fraction of the patches drawn after each block, on the drawing thread.
SurfaceBlocks surface_blocks(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                             const UvSurface* uvs = nullptr, int patches_per_block = 0,
                             std::function<void(double)> progress = {});

/// The UV of every sample of `surface`: `uvs` at the sample's patch and (u, v).
std::vector<Eigen::Vector2d> surface_texcoords(const TessellatedMesh& surface,
                                               const UvSurface& uvs);
/// Fills scene.surface_texcoords from `uvs` and scene.input_texcoords from `corner_uvs` (the
/// mesh's, which `uvs` was built on). Throws stitch::Error as input_face_texcoords does.
void add_texcoords(SceneGeometry& scene, const HalfedgeMesh& mesh, const CornerUvs& corner_uvs,
                   const UvSurface& uvs);

/// Uploads the scene: the smooth surface, or the input polygons when `input_polygons`, with their
/// texture coordinates when the scene has them; the markers carry the sharp curves.
void upload_scene(Renderer& renderer, const SceneGeometry& scene, bool input_polygons = false);

/// A close-up of an extraordinary point: seen along its normal tilted by 30 degrees towards the
/// world's up (so reflection lines cross the patch boundaries leaving it), framing the sphere
/// of radius `radius_patches` times the size of the patches there (ExtraordinaryPoint::extent).
/// The near plane cuts away whatever lies in front of that sphere (a cutaway view), so points
/// inside the model are seen too.
Camera focus_camera(const ExtraordinaryPoint& point, const SceneGeometry& scene, double aspect,
                    double radius_patches = 0.6, UpAxis up = UpAxis::z);

}  // namespace stitch
