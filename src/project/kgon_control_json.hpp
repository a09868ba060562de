// A K-gon control as JSON, for project files and --kgon-controls files alike: the members are the
// fields of kgon_control_fields(), by name.
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

#include "stitch/kgon/kgon_control.hpp"

namespace stitch::detail {

/// The fields that differ from their defaults (an unchanged control is {}).
nlohmann::json kgon_control_json(const KgonControl& c);

/// Sets the field named `key` of `c` from `value`. Returns false when no field has that name;
/// throws InputError when the value is not of the field's kind. Ranges are check_kgon_control's.
bool read_kgon_control_member(std::string_view key, const nlohmann::json& value, KgonControl& c);

}  // namespace stitch::detail
