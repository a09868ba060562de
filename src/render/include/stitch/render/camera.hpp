// Cameras that frame a model: named views of its bounding box, explicit eye/target, and a
// close-up of one point (e.g. an extraordinary point) seen along its normal.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "stitch/choices.hpp"
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

/// A perspective camera. Right-handed world, the image's y points along `up`. The default is
/// the front view (z up).
struct Camera {
  Vec3 eye = Vec3(0, -5, 0);
  Vec3 target = Vec3::Zero();
  Vec3 up = Vec3::UnitZ();
  double fov_y_deg = 30.0;
  double near_plane = 0.1;
  double far_plane = 100.0;
};

/// Which world axis is up in pictures: z, as in stitch's primitives and CAD, or y, as in most
/// meshes from scanners and DCC tools (glTF, Blender's and Maya's OBJ exports), which would
/// otherwise lie on their side. The views below are defined for z up; for y up every direction
/// d of them is from_z_up(d, y).
enum class UpAxis { z, y };
/// The up axes by name, for --up and the modeler's view settings.
ChoiceTable<UpAxis> up_axis_table();
/// A direction of the z-up frame in a world whose up axis is `up`: unchanged for z; for y,
/// (x, y, z) -> (x, z, -y), the turn that takes z to y and keeps x (front then looks along -z
/// at the z = 1 side with +y up). to_z_up is its inverse.
Vec3 from_z_up(const Vec3& d, UpAxis up);
Vec3 to_z_up(const Vec3& d, UpAxis up);

/// The named views. z is up, as in the primitives and the docs (the cube's bottom and top faces
/// are z = -1 and z = 1): front looks along +y at the y = -1 side, back along -y, left along +x
/// at the x = -1 side, right along -x, all with +z up in the image; top looks down -z onto the
/// z = 1 face and bottom up +z, both with +y up in the image; iso looks from (1, 1, 1) with +z
/// up.
enum class View { front, back, left, right, top, bottom, iso };

/// A named view's direction from the target towards the eye and the world direction shown up in
/// the image (perpendicular to `from`): the one definition of the views, which the renderer's
/// framing and the modeler's orbit camera share.
struct ViewDirection {
  Vec3 from;
  Vec3 up;
};
ViewDirection view_direction(View view, UpAxis up = UpAxis::z);

/// Parses the names above; throws stitch::UsageError listing them otherwise.
View parse_view(const std::string& name);
std::string to_string(View view);

/// The camera that shows the whole box from `view`, filling the smaller image side.
Camera frame_view(View view, const BoundingBox& box, double aspect, UpAxis up = UpAxis::z);
/// Looks from `eye` at `target`; near/far planes are chosen to contain `box`. The image's up is
/// the world's up axis, as in the named views (for z up: +y when looking straight along z, as
/// in `top`). Throws UsageError when eye == target.
Camera look_at(const Vec3& eye, const Vec3& target, const BoundingBox& box, UpAxis up = UpAxis::z);
/// Frames the sphere (center, radius) seen from direction `from` (pointing from the center
/// towards the eye), with the world's up axis up in the image (as look_at); `scene` sets the
/// clipping planes so the rest of the model is not cut.
Camera frame_sphere(const Vec3& center, double radius, const Vec3& from, double aspect,
                    const BoundingBox& scene, UpAxis up = UpAxis::z);

/// Column-major 4x4 matrices for OpenGL.
Eigen::Matrix4f view_matrix(const Camera& camera);
Eigen::Matrix4f projection_matrix(const Camera& camera, double aspect);

}  // namespace stitch
