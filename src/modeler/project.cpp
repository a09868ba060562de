#include "stitch/modeler/project.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/project/project_file.hpp"

namespace stitch::modeler {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* overlay_names[num_overlays] = {"mesh", "kgons", "nets", "tess"};

json vec_json(const Vec3& p) {
  return json::array({p.x(), p.y(), p.z()});
}

Vec3 vec_from(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + " must be an array of 3 numbers");
  const Vec3 p(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
  limits::check_coordinates(p, what);
  return p;
}

/// A section of the project the core reader passed through, or an InputError naming it.
json section(const ProjectFile& file, const char* name) {
  const auto it = file.sections.find(name);
  if (it == file.sections.end()) throw InputError(fmt::format("the project has no \"{}\"", name));
  return json::parse(it->second);
}

/// The rows of a library's table, as rows of a modeler's table of a wider type.
template <class T, class Library>
std::vector<Choice<T>> rows_of(ChoiceTable<Library> library) {
  std::vector<Choice<T>> rows;
  for (const Choice<Library>& c : library) rows.push_back({c.name, c.value, c.help});
  return rows;
}

}  // namespace

ChoiceTable<DisplayMode> display_mode_table() {
  static const std::vector<Choice<DisplayMode>> table = [] {
    std::vector<Choice<DisplayMode>> rows = rows_of<DisplayMode>(shading_mode_table());
    // The modeler's own mode: the renderer has none for the input polygons, the modeler draws
    // them itself.
    rows.push_back({"input", std::nullopt, "the input polygons instead of the smooth surface"});
    return rows;
  }();
  return table;
}

DisplayMode display_mode(const DisplaySettings& display) {
  return display.input_polygons ? DisplayMode() : DisplayMode(display.mode);
}

void set_display_mode(DisplaySettings& display, DisplayMode mode) {
  display.input_polygons = !mode;
  if (mode) display.mode = *mode;
}

ChoiceTable<std::optional<Method>> split_table() {
  static const std::vector<Choice<std::optional<Method>>> table = [] {
    // The modeler's own choice first: no second view.
    std::vector<Choice<std::optional<Method>>> rows{{"off", std::nullopt, "one view"}};
    const auto methods = rows_of<std::optional<Method>>(method_table());
    rows.insert(rows.end(), methods.begin(), methods.end());
    return rows;
  }();
  return table;
}

bool is_project_path(const std::string& path) {
  return stitch::is_project_path(path);
}

std::string project_to_json(const Project& project) {
  const DisplaySettings& d = project.display;
  json overlays = json::array();
  for (int o = 0; o < num_overlays; ++o)
    if (d.overlays[o]) overlays.push_back(overlay_names[o]);
  const OrbitView& v = project.view;
  const json view = {{"up", choice_name(up_axis_table(), v.up)},
                     {"target", vec_json(v.target)},
                     {"distance", v.distance},
                     {"yaw", v.yaw_deg},
                     {"pitch", v.pitch_deg},
                     {"fov", v.fov_y_deg}};
  const json display = {{"method", to_string(d.method)},
                        {"resolution", d.resolution},
                        {"mode", to_string(d.mode)},
                        {"input", d.input_polygons},
                        {"overlays", overlays},
                        {"markers", d.markers},
                        {"split", d.split ? json(to_string(*d.split)) : json(nullptr)}};
  // The mesh and K-gon controls are the core's part of the file, which `stitch` reads too.
  return write_project_json(project.state.mesh, project.state.kgons,
                            {{"view", view.dump()}, {"display", display.dump()}});
}

Project project_from_json(const std::string& text, const std::string& source) {
  ProjectFile file = parse_project_json(text, source);
  try {
    Project p;
    p.state.mesh = std::move(file.mesh);
    p.state.kgons = std::move(file.kgons);

    const json v = section(file, "view");
    p.view.up = parse_choice(up_axis_table(), v.value("up", "z"), "up axis");
    p.view.target = vec_from(v.at("target"), "the view target");
    p.view.distance = v.at("distance").get<double>();
    p.view.yaw_deg = v.at("yaw").get<double>();
    p.view.pitch_deg = v.at("pitch").get<double>();
    p.view.fov_y_deg = v.value("fov", 30.0);
    if (!(p.view.distance > 0 && std::isfinite(p.view.distance)) ||
        !(p.view.fov_y_deg > 0 && p.view.fov_y_deg < 180))
      throw InputError("the view needs a positive distance and a field of view in (0, 180)");
    limits::check_range(p.view.yaw_deg, -limits::max_rotation_deg, limits::max_rotation_deg,
                        "the view's yaw");
    limits::check_range(p.view.pitch_deg, -90, 90, "the view's pitch");

    const json d = section(file, "display");
    p.display.method = parse_method(d.at("method").get<std::string>());
    p.display.resolution = d.at("resolution").get<int>();
    limits::check_resolution(p.display.resolution, "the display's resolution");
    p.display.mode = parse_shading_mode(d.at("mode").get<std::string>());
    p.display.input_polygons = d.value("input", false);
    for (const json& o : d.value("overlays", json::array())) {
      const auto name = o.get<std::string>();
      const auto* it = std::find(std::begin(overlay_names), std::end(overlay_names), name);
      if (it == std::end(overlay_names))
        throw InputError("unknown overlay '" + limits::quoted(name) + "'");
      p.display.overlays[it - std::begin(overlay_names)] = true;
    }
    p.display.markers = d.value("markers", false);
    if (d.contains("split") && !d["split"].is_null())
      p.display.split = parse_method(d["split"].get<std::string>());
    return p;
  } catch (const std::exception& e) {  // stitch::Error, JSON type errors, bad names
    throw InputError(fmt::format("{}: {}", source, e.what()));
  }
}

void save_project(const std::string& path, const Project& project) {
  const std::string text = project_to_json(project);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

Project load_project(const std::string& path) {
  return project_from_json(read_regular_file(path), path);
}

std::string autosave_path(const std::string& document_path) {
  if (document_path.empty()) {
    fs::path base;
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) {
      base = xdg;
    } else if (const char* home = std::getenv("HOME"); home && *home) {
      base = fs::path(home) / ".local" / "share";
    } else {
      base = fs::temp_directory_path();
    }
    return (base / "stitch" / "autosave" / ("untitled" + std::string(kProjectExtensions.front())))
        .string();
  }
  const fs::path p(document_path);
  return (p.parent_path() /
          fmt::format(".{}.autosave{}", p.filename().string(), kProjectExtensions.front()))
      .string();
}

bool autosave_is_newer(const std::string& autosave, const std::string& document_path) {
  std::error_code ec;
  if (!fs::exists(autosave, ec)) return false;
  if (document_path.empty() || !fs::exists(document_path, ec)) return true;
  return fs::last_write_time(autosave, ec) > fs::last_write_time(document_path, ec);
}

}  // namespace stitch::modeler
