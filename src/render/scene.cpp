#include "stitch/render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "stitch/tess/tessellate.hpp"

namespace stitch {

namespace {

int block_patches(int resolution, int patches_per_block) {
  return patches_per_block > 0
             ? patches_per_block
             : std::max(1, kSceneBlockVertices / ((resolution + 1) * (resolution + 1)));
}

TessellationOptions unwelded(int resolution) {
  TessellationOptions options;
  options.resolution = resolution;
  options.welded = false;
  return options;
}

}  // namespace

SceneGeometry build_scene(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                          const OverlaySelection& overlays, SceneSurface tessellation) {
  SceneGeometry scene;
  const auto wanted = [&](Overlay o) { return overlays[static_cast<int>(o)]; };
  auto& lines = scene.overlays;
  if (tessellation == SceneSurface::whole) {
    TessellationOptions options = unwelded(resolution);
    // Every attribute: the levels and patches modes shade by them, texture coordinates come from
    // each sample's patch and (u, v).
    options.uv = options.patch = options.level = true;
    scene.surface = tessellate(mesh, surface, options);
    for (const Vec3& p : scene.surface.positions) scene.bounds.extend(p);
    if (wanted(Overlay::tessellation))
      lines[static_cast<int>(Overlay::tessellation)] = surface_mesh_lines(scene.surface);
  } else {
    tessellate_blocks(mesh, surface, unwelded(resolution), block_patches(resolution, 0),
                      [&scene](const TessellatedMesh& block, int) {
                        for (const Vec3& p : block.positions) scene.bounds.extend(p);
                      });
  }
  if (tessellation == SceneSurface::whole) scene.input = input_faces(mesh);
  const BezierSurface& bezier = surface.bezier();
  if (wanted(Overlay::mesh)) lines[static_cast<int>(Overlay::mesh)] = mesh_lines(mesh);
  if (wanted(Overlay::kgons))
    lines[static_cast<int>(Overlay::kgons)] = kgon_lines(mesh, bezier.kgons);
  if (wanted(Overlay::nets)) {
    lines[static_cast<int>(Overlay::nets)] = control_net_lines(bezier.nets, bezier.corners);
  }
  scene.extraordinary = extraordinary_points(mesh, bezier.kgons);
  scene.sharp_curves = sharp_curve_lines(mesh, surface, resolution);
  for (const Vertex v : mesh.vertices()) scene.bounds.extend(mesh.position(v));
  return scene;
}

std::vector<Eigen::Vector2d> surface_texcoords(const TessellatedMesh& surface,
                                               const UvSurface& uvs) {
  if (surface.uv.size() != surface.positions.size() ||
      surface.patch.size() != surface.positions.size())
    throw std::invalid_argument("texture coordinates need every sample's patch and (u, v)");
  std::vector<Eigen::Vector2d> out(surface.positions.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = uvs.evaluate(Corner(surface.patch[i]), surface.uv[i].x(), surface.uv[i].y());
  return out;
}

SurfaceBlocks surface_blocks(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                             const UvSurface* uvs, int patches_per_block,
                             std::function<void(double)> progress) {
  SurfaceBlocks blocks;
  const int per_block = block_patches(resolution, patches_per_block);
  blocks.for_each = [&mesh, &surface, uvs, resolution, per_block,
                     progress = std::move(progress)](const SurfaceBlockVisitor& visit) {
    TessellationOptions options = unwelded(resolution);
    options.patch = options.level = true;  // for the levels and patches modes
    options.uv = uvs != nullptr;           // with the patch, where a texture coordinate comes from
    const auto patches = static_cast<double>(surface.corners().size());
    std::vector<Eigen::Vector2d> texcoords;
    tessellate_blocks(
        mesh, surface, options, per_block, [&](const TessellatedMesh& block, int first) {
          if (uvs) texcoords = surface_texcoords(block, *uvs);
          visit(block, texcoords);
          if (progress) progress(std::min(1.0, (first + static_cast<double>(per_block)) / patches));
        });
  };
  return blocks;
}

void add_texcoords(SceneGeometry& scene, const HalfedgeMesh& mesh, const CornerUvs& corner_uvs,
                   const UvSurface& uvs) {
  scene.surface_texcoords = surface_texcoords(scene.surface, uvs);
  scene.input_texcoords = input_face_texcoords(mesh, corner_uvs);
}

void upload_scene(Renderer& renderer, const SceneGeometry& scene, bool input_polygons) {
  renderer.set_surface(input_polygons ? scene.input : scene.surface);
  const auto& texcoords = input_polygons ? scene.input_texcoords : scene.surface_texcoords;
  if (!texcoords.empty()) renderer.set_surface_texcoords(texcoords);
  for (int o = 0; o < num_overlays; ++o) {
    renderer.set_overlay(static_cast<Overlay>(o), scene.overlays[o]);
  }
  MarkerSet markers = extraordinary_markers(scene.extraordinary);
  markers.curves = scene.sharp_curves;
  renderer.set_markers(markers);
}

Camera focus_camera(const ExtraordinaryPoint& point, const SceneGeometry& scene, double aspect,
                    double radius_patches, UpAxis up) {
  const Vec3 n = point.normal.normalized();
  // Tilt the eye off the normal so the view is oblique: towards +y of the z-up frame (or its +z
  // when the normal is along that y). Not towards the image's up: a point on the wall of a hole
  // along the up axis would then be seen along the tube, where the zebra stripes of the whole
  // wall crowd the close-up.
  const Vec3 y = from_z_up(Vec3::UnitY(), up), z = from_z_up(Vec3::UnitZ(), up);
  Vec3 towards = y - y.dot(n) * n;
  if (towards.norm() < 1e-6) towards = z - z.dot(n) * n;
  const double tilt = 30.0 * std::numbers::pi / 180.0;
  const Vec3 from = std::cos(tilt) * n + std::sin(tilt) * towards.normalized();
  const double extent = point.extent > 0 ? point.extent : scene.bounds.radius() * 0.25;
  const double radius = radius_patches * extent;
  Camera camera = frame_sphere(point.position, radius, from, aspect, scene.bounds, up);
  // Cut away everything in front of the framed sphere: an extraordinary point can lie inside
  // the model (e.g. that of a face whose loop runs around a handle), hidden by other sheets.
  camera.near_plane = std::max(camera.near_plane, (camera.eye - point.position).norm() - radius);
  return camera;
}

}  // namespace stitch
