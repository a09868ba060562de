#include "stitch/modeler/navigation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "stitch/topology/operation.hpp"

namespace stitch::modeler {

namespace {

double rad(double deg) {
  return deg * std::numbers::pi / 180.0;
}

/// Moller-Trumbore; the distance along the ray, or nothing. Both sides count (a picked face may
/// be seen from inside through a hole).
std::optional<double> hit_triangle(const Ray& r, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = r.direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return std::nullopt;
  const Vec3 s = r.origin - a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3 q = s.cross(e1);
  const double v = r.direction.dot(q) / det;
  if (v < 0 || u + v > 1) return std::nullopt;
  const double t = e2.dot(q) / det;
  if (t <= 0) return std::nullopt;
  return t;
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

Vec3 OrbitView::eye_direction() const {
  const double y = rad(yaw_deg), p = rad(pitch_deg);
  return from_z_up({std::cos(p) * std::sin(y), -std::cos(p) * std::cos(y), std::sin(p)}, up);
}

Camera OrbitView::camera(const BoundingBox& scene) const {
  Camera c;
  c.eye = eye();
  c.target = target;
  const double y = rad(yaw_deg), p = rad(pitch_deg);
  // d(eye direction)/d(pitch): always perpendicular to the view, so straight up/down views work.
  c.up = from_z_up({-std::sin(p) * std::sin(y), std::sin(p) * std::cos(y), std::cos(p)}, up);
  c.fov_y_deg = fov_y_deg;
  const double radius = scene.empty() ? 1.0 : std::max(scene.radius(), 1e-9);
  const double to_center = scene.empty() ? distance : (scene.center() - c.eye).norm();
  c.far_plane = to_center + 2.0 * radius;
  c.near_plane = std::max(to_center - 2.0 * radius, c.far_plane * 1e-4);
  return c;
}

void OrbitView::orbit(double dx_px, double dy_px) {
  yaw_deg = std::remainder(yaw_deg - 0.4 * dx_px, 360.0);
  pitch_deg = std::clamp(pitch_deg + 0.4 * dy_px, -90.0, 90.0);
}

void OrbitView::pan(double dx_px, double dy_px, double height_px) {
  const Camera c = camera({});
  const Vec3 forward = (c.target - c.eye).normalized();
  const Vec3 right = forward.cross(c.up).normalized();
  // World units per pixel at the target's depth.
  const double scale = 2.0 * distance * std::tan(rad(fov_y_deg) / 2) / std::max(height_px, 1.0);
  target += scale * (-dx_px * right + dy_px * c.up);
}

void OrbitView::zoom(double steps) {
  // Bounded so that no sequence of zooms reaches 0 or infinity (models span up to 1e50 units).
  distance = std::clamp(distance * std::pow(0.9, steps), 1e-60, 1e60);
}

void OrbitView::frame(const Vec3& center, double radius, double aspect) {
  target = center;
  // The sphere touches the narrower pair of frustum sides.
  const double half_y = rad(fov_y_deg) / 2;
  const double half_x = std::atan(std::tan(half_y) * std::max(aspect, 1e-3));
  distance = std::max(radius, 1e-6) / std::sin(std::min(half_x, half_y)) * 1.05;
}

void OrbitView::set_standard(View view, const BoundingBox& box, double aspect) {
  const auto [from, up] = view_direction(view);  // the angles are those of the z-up frame
  const double deg = 180.0 / std::numbers::pi;
  // Exactly +-90 straight up and down: projects refuse a pitch beyond that.
  pitch_deg = from.z() >= 1.0 ? 90.0 : from.z() <= -1.0 ? -90.0 : std::asin(from.z()) * deg;
  if (std::abs(pitch_deg) < 90.0) {
    yaw_deg = std::atan2(from.x(), -from.y()) * deg;
  } else {
    // Looking straight along z the yaw only turns the image: the one that shows `up` upwards
    // (camera(): up = (-sin yaw, cos yaw, 0) at the top, (sin yaw, -cos yaw, 0) at the bottom).
    yaw_deg = pitch_deg > 0 ? std::atan2(-up.x(), up.y()) * deg : std::atan2(up.x(), -up.y()) * deg;
  }
  if (!box.empty()) frame(box.center(), box.radius(), aspect);
}

Ray pixel_ray(const Camera& camera, double x, double y, int width, int height) {
  const Vec3 f = (camera.target - camera.eye).normalized();
  const Vec3 s = f.cross(camera.up).normalized();
  const Vec3 u = s.cross(f);
  const double t = std::tan(rad(camera.fov_y_deg) / 2);
  const double aspect = static_cast<double>(width) / std::max(height, 1);
  const double ndc_x = 2.0 * (x + 0.5) / width - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / height;
  return {camera.eye, (f + ndc_x * t * aspect * s + ndc_y * t * u).normalized()};
}

PickKind parse_pick_kind(const std::string& name) {
  if (name == "vertex") return PickKind::vertex;
  if (name == "edge") return PickKind::edge;
  if (name == "face") return PickKind::face;
  if (name == "corner") return PickKind::corner;
  throw UsageError(
      fmt::format("unknown element kind '{}' (expected vertex, edge, face or corner)", name));
}

std::string to_string(PickKind kind) {
  static constexpr const char* names[] = {"vertex", "edge", "face", "corner"};
  return names[static_cast<int>(kind)];
}

std::optional<Pick> pick(const HalfedgeMesh& mesh, const Ray& ray, PickKind kind) {
  double best = std::numeric_limits<double>::infinity();
  Face hit_face;
  for (Face f : mesh.faces()) {
    const auto loop = mesh.face_loop(f);
    Vec3 centroid = Vec3::Zero();
    for (Halfedge h : loop) centroid += mesh.position(mesh.origin(h));
    centroid /= static_cast<double>(loop.size());
    for (Halfedge h : loop) {
      const auto t =
          hit_triangle(ray, centroid, mesh.position(mesh.origin(h)), mesh.position(mesh.target(h)));
      if (t && *t < best) {
        best = *t;
        hit_face = f;
      }
    }
  }
  if (!hit_face.valid()) return std::nullopt;
  Pick p;
  p.kind = kind;
  p.point = ray.origin + best * ray.direction;
  if (kind == PickKind::face) {
    p.index = hit_face.idx;
    return p;
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (Halfedge h : mesh.face_loop(hit_face)) {
    const Vec3& a = mesh.position(mesh.origin(h));
    const double d = kind == PickKind::edge
                         ? distance_to_segment(p.point, a, mesh.position(mesh.target(h)))
                         : (a - p.point).norm();
    if (d < nearest) {
      nearest = d;
      p.index = kind == PickKind::vertex ? mesh.origin(h).idx : h.idx;
    }
  }
  return p;
}

std::string describe(const HalfedgeMesh& mesh, const Pick& p) {
  switch (p.kind) {
    case PickKind::vertex:
      return fmt::format("vertex {}", p.index + 1);
    case PickKind::face:
      return fmt::format("face {}", p.index + 1);
    case PickKind::edge: {
      const Halfedge h(p.index);
      return fmt::format("edge {} {}@{}", mesh.origin(h).idx + 1, mesh.target(h).idx + 1,
                         mesh.face(h).idx + 1);
    }
    case PickKind::corner:
      return "corner " + corner_name(mesh, Halfedge(p.index));
  }
  return {};
}

}  // namespace stitch::modeler
