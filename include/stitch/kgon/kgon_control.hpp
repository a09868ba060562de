// The user's controls on one K-gon, and the table of their fields that every front end reads
// (project files, --kgon-controls files, the modeler's `kgon` line, Python, the command line's
// global flags): a field's name, what it holds and its range are written once, here.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// The user's controls on one K-gon (paper, section "Discussion"). The defaults change nothing.
struct KgonControl {
  double scale = 1.0;          ///< scale about the centroid
  double rotate_deg = 0.0;     ///< rotation about the K-gon normal, in the K-gon plane
  Vec3 offset = Vec3::Zero();  ///< translation of the whole K-gon (moves the centre)
  bool regularize = false;     ///< replace by the best-fitting affinely regular polygon
  /// Scale along one direction of the K-gon plane (after scale and rotation): `stretch_along`
  /// projected into the plane. No stretch where that projection is zero. The K-gon stays planar,
  /// so it keeps C1 and G1 as the other controls do; unfold_tubes stretches a tube's face K-gon
  /// along the tube with it.
  double stretch = 1.0;
  Vec3 stretch_along = Vec3::Zero();
  bool operator==(const KgonControl&) const = default;
};

/// One field of KgonControl. Exactly one of the three member pointers is set, by `kind`.
struct KgonControlField {
  enum class Kind { number, vector, flag };
  std::string_view name;         ///< as files and command lines spell it: "scale", "stretch_along"
  std::string_view description;  ///< in messages: "the scale"
  Kind kind = Kind::number;
  double KgonControl::*number = nullptr;
  Vec3 KgonControl::*vector = nullptr;
  bool KgonControl::*flag = nullptr;
  double min = 0, max = 0;  ///< a number's range (inclusive); vectors need finite coordinates

  /// Whether `c` holds this field's default value.
  [[nodiscard]] bool is_default(const KgonControl& c) const;
};

/// Every field, in the order files write them.
std::span<const KgonControlField> kgon_control_fields();

/// The field of that name (as `name` above), or nullptr.
const KgonControlField* find_kgon_control_field(std::string_view name);

/// The fields' names, comma-separated, for messages that list what is allowed.
std::string kgon_control_field_names();

/// Throws InputError naming the first field of `c` outside its range, or with a coordinate that
/// is not finite: "{prefix}the scale 0 is out of range ...".
void check_kgon_control(const KgonControl& c, const std::string& prefix = "");

}  // namespace stitch
