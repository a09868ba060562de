// The modeler's camera (orbit, pan, zoom, framing, standard views) and picking by CPU ray casting
// against the input mesh. No GL here, so both are unit-tested.
#pragma once

#include <optional>
#include <string>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/render/camera.hpp"

namespace stitch::modeler {

/// A camera orbiting `target` about the world's up axis: yaw turns about it, pitch lifts the eye.
/// yaw = pitch = 0 is the front view (for z up: eye on -y, looking along +y; for y up the same
/// turned by from_z_up).
struct OrbitView {
  UpAxis up = UpAxis::z;
  Vec3 target = Vec3::Zero();
  double distance = 6.0;
  double yaw_deg = 0.0;
  double pitch_deg = 0.0;
  double fov_y_deg = 30.0;
  bool operator==(const OrbitView&) const = default;

  /// Unit vector from the target to the eye.
  [[nodiscard]] Vec3 eye_direction() const;
  [[nodiscard]] Vec3 eye() const { return target + distance * eye_direction(); }
  /// The render camera; near and far planes contain `scene`.
  [[nodiscard]] Camera camera(const BoundingBox& scene) const;

  /// Mouse motions, in pixels of a viewport `height` pixels high.
  void orbit(double dx_px, double dy_px);
  void pan(double dx_px, double dy_px, double height_px);
  /// Positive steps move closer (by 10% each).
  void zoom(double steps);
  /// Keeps the direction, shows the whole sphere (center, radius) in a viewport of this width /
  /// height: a narrow one is framed by its horizontal angle.
  void frame(const Vec3& center, double radius, double aspect = 1.0);
  /// One of the standard views of camera.hpp (view_direction), framing `box`.
  void set_standard(View view, const BoundingBox& box, double aspect = 1.0);
};

/// A ray from the eye through pixel (x, y) (origin top-left) of a width x height viewport.
struct Ray {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitZ();  ///< unit
};
Ray pixel_ray(const Camera& camera, double x, double y, int width, int height);

enum class PickKind { vertex, edge, face, corner };
/// Parses "vertex", "edge", "face", "corner"; throws stitch::Error otherwise.
PickKind parse_pick_kind(const std::string& name);
std::string to_string(PickKind kind);

/// A picked element: for a corner the half-edge, for an edge one of its half-edges (the one on
/// the hit face), for a vertex and a face their indices.
struct Pick {
  PickKind kind = PickKind::face;
  int index = -1;
  Vec3 point = Vec3::Zero();  ///< where the ray hit the input mesh
  bool operator==(const Pick& o) const { return kind == o.kind && index == o.index; }
};

/// The nearest face hit by the ray (faces fanned around their centroid, as they are drawn), and
/// of that face the element nearest the hit point: its vertex, its edge, itself, or its corner.
std::optional<Pick> pick(const HalfedgeMesh& mesh, const Ray& ray, PickKind kind);

/// A short text naming the pick in operation-line numbers: "vertex 5", "edge 1 5@2",
/// "face 3", "corner 1@3".
std::string describe(const HalfedgeMesh& mesh, const Pick& pick);

}  // namespace stitch::modeler
