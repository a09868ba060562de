#include "stitch/render/camera.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "stitch/error.hpp"

namespace stitch {

namespace {

constexpr std::array<const char*, 7> kViewNames{"front", "back",   "left", "right",
                                                "top",   "bottom", "iso"};

double deg_to_rad(double d) {
  return d * std::numbers::pi / 180.0;
}

constexpr Choice<UpAxis> kUpAxes[] = {
    {"z", UpAxis::z, "z is up (stitch's primitives, CAD)"},
    {"y", UpAxis::y, "y is up (most scanners' and DCC tools' exports: glTF, Blender's OBJ)"},
};

// Screen-up for a camera looking along `dir`: the world's up axis, as for the standard views,
// except when looking (almost) straight along it, where the z-up frame's +y is up as in `top`.
Vec3 world_up(const Vec3& dir, UpAxis up) {
  const Vec3 d = to_z_up(dir, up);
  return from_z_up(std::abs(d.normalized().z()) < 0.99 ? Vec3::UnitZ() : Vec3::UnitY(), up);
}

void set_clip_planes(Camera& camera, const BoundingBox& box) {
  const double distance = (box.center() - camera.eye).norm();
  const double r = std::max(box.radius(), 1e-9) * 1.05;
  camera.far_plane = distance + r;
  camera.near_plane = std::max(distance - r, camera.far_plane * 1e-4);
}

}  // namespace

ChoiceTable<UpAxis> up_axis_table() {
  return kUpAxes;
}

Vec3 from_z_up(const Vec3& d, UpAxis up) {
  return up == UpAxis::y ? Vec3(d.x(), d.z(), -d.y()) : d;
}

Vec3 to_z_up(const Vec3& d, UpAxis up) {
  return up == UpAxis::y ? Vec3(d.x(), -d.z(), d.y()) : d;
}

BoundingBox bounding_box(const std::vector<Vec3>& points) {
  BoundingBox box;
  for (const Vec3& p : points) box.extend(p);
  return box;
}

View parse_view(const std::string& name) {
  for (size_t i = 0; i < kViewNames.size(); ++i) {
    if (name == kViewNames[i]) return static_cast<View>(i);
  }
  throw UsageError("unknown view '" + name +
                   "' (expected front, back, left, right, top, bottom or iso)");
}

std::string to_string(View view) {
  return kViewNames[static_cast<size_t>(view)];
}

Camera frame_sphere(const Vec3& center, double radius, const Vec3& from, double aspect,
                    const BoundingBox& scene, UpAxis up) {
  Camera camera;
  const Vec3 dir = from.normalized();
  const double half_fov_y = deg_to_rad(camera.fov_y_deg) / 2;
  const double half_fov_x = std::atan(std::tan(half_fov_y) * aspect);
  const double distance = std::max(radius, 1e-9) / std::sin(std::min(half_fov_x, half_fov_y));
  camera.target = center;
  camera.eye = center + distance * dir;
  camera.up = world_up(dir, up);
  BoundingBox clip = scene;
  clip.extend(center + Vec3::Constant(radius));
  clip.extend(center - Vec3::Constant(radius));
  set_clip_planes(camera, clip);
  // Close-ups put the eye inside the scene's box: keep some depth precision for the overlays.
  camera.near_plane = std::max(camera.near_plane, 0.05 * distance);
  return camera;
}

ViewDirection view_direction(View view, UpAxis up) {
  if (up != UpAxis::z) {
    const ViewDirection d = view_direction(view, UpAxis::z);
    return {from_z_up(d.from, up), from_z_up(d.up, up)};
  }
  switch (view) {
    case View::front:
      return {-Vec3::UnitY(), Vec3::UnitZ()};
    case View::back:
      return {Vec3::UnitY(), Vec3::UnitZ()};
    case View::left:
      return {-Vec3::UnitX(), Vec3::UnitZ()};
    case View::right:
      return {Vec3::UnitX(), Vec3::UnitZ()};
    case View::top:
      return {Vec3::UnitZ(), Vec3::UnitY()};
    case View::bottom:
      return {-Vec3::UnitZ(), Vec3::UnitY()};
    case View::iso:
      break;
  }
  // From (1, 1, 1), as before z was up: a third of a turn about that diagonal maps the cube and
  // the tetrahedron onto themselves, so their default-view pictures in the docs stay true.
  const Vec3 from = Vec3(1, 1, 1).normalized();
  return {from, (Vec3::UnitZ() - from.z() * from).normalized()};
}

Camera frame_view(View view, const BoundingBox& box, double aspect, UpAxis up_axis) {
  const auto [from, up] = view_direction(view, up_axis);
  // Fit the box's eight corners (tighter than its bounding sphere): each corner at lateral
  // offsets (x, y) and depth z towards the eye needs distance >= z + |x| / tan(half fov x).
  Camera camera;
  const Vec3 dir = from.normalized();
  const Vec3 side = up.cross(dir).normalized();
  const Vec3 image_up = dir.cross(side);
  const double tan_y = std::tan(deg_to_rad(camera.fov_y_deg) / 2);
  const double tan_x = tan_y * aspect;
  const Vec3 c = box.center();
  double distance = 1e-9;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p((i & 1) ? box.max.x() : box.min.x(), (i & 2) ? box.max.y() : box.min.y(),
                 (i & 4) ? box.max.z() : box.min.z());
    const Vec3 d = p - c;
    distance = std::max({distance, d.dot(dir) + std::abs(d.dot(side)) / tan_x,
                         d.dot(dir) + std::abs(d.dot(image_up)) / tan_y});
  }
  camera.target = c;
  camera.eye = c + 1.08 * distance * dir;
  camera.up = up;
  set_clip_planes(camera, box);
  return camera;
}

Camera look_at(const Vec3& eye, const Vec3& target, const BoundingBox& box, UpAxis up) {
  if ((eye - target).norm() <= 1e-12 * std::max(1.0, eye.norm())) {
    throw UsageError("the camera's eye and target are the same point");
  }
  Camera camera;
  camera.eye = eye;
  camera.target = target;
  camera.up = world_up(target - eye, up);
  set_clip_planes(camera, box);
  return camera;
}

Eigen::Matrix4f view_matrix(const Camera& camera) {
  const Vec3 f = (camera.target - camera.eye).normalized();
  Vec3 s = f.cross(camera.up);
  if (s.norm() < 1e-9) s = f.cross(world_up(f, UpAxis::z));
  s.normalize();
  const Vec3 u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(camera.eye);
  m(1, 3) = -u.dot(camera.eye);
  m(2, 3) = f.dot(camera.eye);
  return m.cast<float>();
}

Eigen::Matrix4f projection_matrix(const Camera& camera, double aspect) {
  const double t = 1.0 / std::tan(deg_to_rad(camera.fov_y_deg) / 2);
  const double n = camera.near_plane, f = camera.far_plane;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = -(f + n) / (f - n);
  m(2, 3) = -2 * f * n / (f - n);
  m(3, 2) = -1;
  return m.cast<float>();
}

}  // namespace stitch
