#include "project/kgon_control_json.hpp"

#include <fmt/format.h>

#include "stitch/error.hpp"

namespace stitch::detail {

using nlohmann::json;
using Kind = KgonControlField::Kind;

json kgon_control_json(const KgonControl& c) {
  json j = json::object();
  for (const KgonControlField& f : kgon_control_fields()) {
    if (f.is_default(c)) continue;
    const std::string name(f.name);
    switch (f.kind) {
      case Kind::number:
        j[name] = c.*f.number;
        break;
      case Kind::vector: {
        const Vec3& v = c.*f.vector;
        j[name] = json::array({v.x(), v.y(), v.z()});
        break;
      }
      case Kind::flag:
        j[name] = c.*f.flag;
        break;
    }
  }
  return j;
}

bool read_kgon_control_member(std::string_view key, const json& value, KgonControl& c) {
  const KgonControlField* f = find_kgon_control_field(key);
  if (!f) return false;
  switch (f->kind) {
    case Kind::number:
      if (!value.is_number()) throw InputError(fmt::format("\"{}\" must be a number", key));
      c.*f->number = value.get<double>();
      break;
    case Kind::vector:
      if (!value.is_array() || value.size() != 3 ||
          !(value[0].is_number() && value[1].is_number() && value[2].is_number()))
        throw InputError(fmt::format("\"{}\" must be an array of 3 numbers", key));
      c.*f->vector = Vec3(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
      break;
    case Kind::flag:
      if (!value.is_boolean()) throw InputError(fmt::format("\"{}\" must be true or false", key));
      c.*f->flag = value.get<bool>();
      break;
  }
  return true;
}

}  // namespace stitch::detail
