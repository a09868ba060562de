// Cameras that frame a model: named views of its bounding box, explicit eye/target, and a
// close-up of one point (e.g. an extraordinary point) seen along its normal.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

struct BoundingBox {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  [[nodiscard]] bool empty() const { return !(min.array() <= max.array()).all(); }
  [[nodiscard]] Vec3 center() const { return 0.5 * (min + max); }
  /// Radius of the sphere around the box (half its diagonal).
  [[nodiscard]] double radius() const { return 0.5 * (max - min).norm(); }
};

BoundingBox bounding_box(const std::vector<Vec3>& points);

/// A perspective camera. Right-handed world, the image's y points along `up`.
struct Camera {
  Vec3 eye = Vec3(0, 0, 5);
  Vec3 target = Vec3::Zero();
  Vec3 up = Vec3::UnitY();
  double fov_y_deg = 30.0;
  double near_plane = 0.1;
  double far_plane = 100.0;
};

/// front: looking down -z (eye on +z), back: eye on -z, left: eye on -x, right: eye on +x,
/// top: eye on +y (image up = -z), bottom: eye on -y, iso: eye along (1, 1, 1).
enum class View { front, back, left, right, top, bottom, iso };

/// Parses the names above; throws std::invalid_argument listing them otherwise.
View parse_view(const std::string& name);
std::string to_string(View view);

/// The camera that shows the whole box from `view`, filling the smaller image side.
Camera frame_view(View view, const BoundingBox& box, double aspect);
/// Looks from `eye` at `target`; near/far planes are chosen to contain `box`. Throws
/// std::invalid_argument when eye == target.
Camera look_at(const Vec3& eye, const Vec3& target, const BoundingBox& box);
/// Frames the sphere (center, radius) seen from direction `from` (pointing from the center
/// towards the eye); `scene` sets the clipping planes so the rest of the model is not cut.
Camera frame_sphere(const Vec3& center, double radius, const Vec3& from, double aspect,
                    const BoundingBox& scene);

/// Column-major 4x4 matrices for OpenGL.
Eigen::Matrix4f view_matrix(const Camera& camera);
Eigen::Matrix4f projection_matrix(const Camera& camera, double aspect);

}  // namespace stitch
