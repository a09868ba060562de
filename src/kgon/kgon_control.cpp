#include "stitch/kgon/kgon_control.hpp"

#include <array>

#include "stitch/mesh/limits.hpp"

namespace stitch {

namespace {

using Kind = KgonControlField::Kind;

KgonControlField number(std::string_view name, std::string_view description,
                        double KgonControl::*member, double lo, double hi) {
  return {.name = name,
          .description = description,
          .kind = Kind::number,
          .number = member,
          .min = lo,
          .max = hi};
}

KgonControlField vector(std::string_view name, std::string_view description,
                        Vec3 KgonControl::*member) {
  return {.name = name, .description = description, .kind = Kind::vector, .vector = member};
}

KgonControlField flag(std::string_view name, std::string_view description,
                      bool KgonControl::*member) {
  return {.name = name, .description = description, .kind = Kind::flag, .flag = member};
}

const std::array<KgonControlField, 6>& fields() {
  static const std::array<KgonControlField, 6> table = {
      number("scale", "the scale", &KgonControl::scale, limits::min_kgon_scale,
             limits::max_kgon_scale),
      number("rotate", "the rotation", &KgonControl::rotate_deg, -limits::max_rotation_deg,
             limits::max_rotation_deg),
      vector("offset", "the offset", &KgonControl::offset),
      flag("regularize", "regularize", &KgonControl::regularize),
      number("stretch", "the stretch", &KgonControl::stretch, limits::min_kgon_scale,
             limits::max_kgon_scale),
      vector("stretch_along", "the stretch direction", &KgonControl::stretch_along),
  };
  return table;
}

}  // namespace

bool KgonControlField::is_default(const KgonControl& c) const {
  static const KgonControl none;
  switch (kind) {
    case Kind::number:
      return c.*number == none.*number;
    case Kind::vector:
      return c.*vector == none.*vector;
    case Kind::flag:
      return c.*flag == none.*flag;
  }
  return true;
}

std::span<const KgonControlField> kgon_control_fields() {
  return fields();
}

const KgonControlField* find_kgon_control_field(std::string_view name) {
  for (const KgonControlField& f : fields())
    if (f.name == name) return &f;
  return nullptr;
}

std::string kgon_control_field_names() {
  std::string out;
  for (const KgonControlField& f : fields()) {
    if (!out.empty()) out += ", ";
    out += f.name;
  }
  return out;
}

void check_kgon_control(const KgonControl& c, const std::string& prefix) {
  for (const KgonControlField& f : fields()) {
    const std::string what = prefix + std::string(f.description);
    if (f.kind == Kind::number) limits::check_range(c.*f.number, f.min, f.max, what);
    if (f.kind == Kind::vector) limits::check_coordinates(c.*f.vector, what);
  }
}

}  // namespace stitch
