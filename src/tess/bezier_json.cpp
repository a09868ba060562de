#include "stitch/tess/bezier_json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "stitch/mesh/io.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch {

namespace {

using nlohmann::json;

constexpr const char* kFormatName = "stitch-bezier-patches";

json point(const Vec3& p) {
  return json::array({p.x(), p.y(), p.z()});
}

json kgon_list(const std::vector<Kgon>& kgons) {
  json list = json::array();
  for (size_t i = 0; i < kgons.size(); ++i) {
    const Kgon& k = kgons[i];
    if (k.points.empty()) continue;  // a deleted element
    json points = json::array();
    for (const Vec3& p : k.points) points.push_back(point(p));
    json corners = json::array();
    for (Corner c : k.corners) corners.push_back(c.idx);
    list.push_back({{"index", i + 1},
                    {"points", std::move(points)},
                    {"corners", std::move(corners)},
                    {"centroid", point(k.centroid)},
                    {"normal", point(k.normal)}});
  }
  return list;
}

json to_json(const PatchSet& set, const KgonSet* kgons) {
  json patches = json::array();
  for (const BezierPatch& patch : set.patches) {
    json points = json::array();
    for (const Vec3& p : patch.net.p) points.push_back(point(p));
    patches.push_back({{"corner", patch.corner.idx},
                       {"corner_name", corner_name(patch.vertex, patch.face, patch.occurrence)},
                       {"face", patch.face + 1},
                       {"vertex", patch.vertex + 1},
                       {"level", patch.level},
                       {"cell", {patch.cell_u, patch.cell_v}},
                       {"exact", patch.exact},
                       {"points", std::move(points)}});
  }
  json doc = {
      {"format", kFormatName},
      {"version", kBezierJsonVersion},
      {"generator", "stitch"},
      {"method", to_string(set.method)},
      {"degree", {3, 3}},
      {"depth", set.depth},
      {"model_size", set.model_size},
      {"tolerance", {{"position", set.tolerance}, {"normal_deg", set.angle_tolerance_deg}}},
      {"deviation",
       {{"position", set.max_position_deviation}, {"normal_deg", set.max_normal_deviation_deg}}},
      {"patch_count", set.patches.size()},
      {"patches", std::move(patches)}};
  if (kgons)
    doc["kgons"] = {{"face", kgon_list(kgons->face)},
                    {"vertex", kgon_list(kgons->vertex)},
                    {"edge", kgon_list(kgons->edge)}};
  return doc;
}

/// Checked access, so that a malformed file names the entry at fault.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  const json& member(const json& object, const char* key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key))
      throw error(where, fmt::format("has no \"{}\"", key));
    return object[key];
  }
  double number(const json& value, const std::string& where) const {
    if (!value.is_number()) throw error(where, "is not a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw error(where, "is not finite");
    return x;
  }
  int integer(const json& value, const std::string& where, int lo) const {
    if (!value.is_number_integer()) throw error(where, "is not an integer");
    const auto x = value.get<long long>();
    if (x < lo || x > std::numeric_limits<int>::max())
      throw error(where, fmt::format("is out of range ({})", x));
    return static_cast<int>(x);
  }
  Vec3 vec3(const json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != 3) throw error(where, "is not [x, y, z]");
    return {number(value[0], where), number(value[1], where), number(value[2], where)};
  }
  [[nodiscard]] InputError error(const std::string& where, const std::string& what) const {
    return InputError(fmt::format("{}: {} {}", path_, where, what));
  }

 private:
  std::string path_;
};

}  // namespace

void write_bezier_json(const std::string& path, const PatchSet& patches, const KgonSet* kgons) {
  // Compact: a model of 10k faces has some 100k patches, and indentation would double the size.
  const std::string text = to_json(patches, kgons).dump();
  write_file_atomically(path, [&](std::ostream& out) { out << text << '\n'; });
}

PatchSet read_bezier_json(const std::string& path) {
  const std::string text = read_regular_file(path);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(fmt::format("{}: not JSON: {}", path, e.what()));
  }
  const Reader r(path);
  const json& format = r.member(doc, "format", "the file");
  if (!format.is_string() || format.get<std::string>() != kFormatName)
    throw r.error("the file", fmt::format("is not \"{}\"", kFormatName));
  const int version = r.integer(r.member(doc, "version", "the file"), "\"version\"", 1);
  if (version > kBezierJsonVersion)
    throw r.error("the file", fmt::format("has version {}; this stitch reads up to {}", version,
                                          kBezierJsonVersion));
  PatchSet set;
  const json& method = r.member(doc, "method", "the file");
  if (!method.is_string()) throw r.error("\"method\"", "is not a string");
  try {
    set.method = parse_method(method.get<std::string>());
  } catch (const UsageError& e) {
    throw r.error("\"method\"", e.what());
  }
  set.depth = r.integer(r.member(doc, "depth", "the file"), "\"depth\"", 0);
  set.model_size = r.number(r.member(doc, "model_size", "the file"), "\"model_size\"");
  const json& tolerance = r.member(doc, "tolerance", "the file");
  set.tolerance = r.number(r.member(tolerance, "position", "\"tolerance\""), "\"tolerance\"");
  set.angle_tolerance_deg =
      r.number(r.member(tolerance, "normal_deg", "\"tolerance\""), "\"tolerance\"");
  const json& deviation = r.member(doc, "deviation", "the file");
  set.max_position_deviation =
      r.number(r.member(deviation, "position", "\"deviation\""), "\"deviation\"");
  set.max_normal_deviation_deg =
      r.number(r.member(deviation, "normal_deg", "\"deviation\""), "\"deviation\"");
  const json& patches = r.member(doc, "patches", "the file");
  if (!patches.is_array()) throw r.error("\"patches\"", "is not an array");
  set.patches.reserve(patches.size());
  for (size_t i = 0; i < patches.size(); ++i) {
    const std::string where = fmt::format("patch {}", i + 1);
    const json& p = patches[i];
    BezierPatch patch;
    patch.corner = Corner(r.integer(r.member(p, "corner", where), where + " corner", 0));
    patch.face = r.integer(r.member(p, "face", where), where + " face", 1) - 1;
    patch.vertex = r.integer(r.member(p, "vertex", where), where + " vertex", 1) - 1;
    // Optional (files written before it was added have none): V@F#k gives the occurrence.
    if (p.contains("corner_name")) {
      const json& name = p["corner_name"];
      if (!name.is_string()) throw r.error(where, "corner_name is not a string");
      const std::string text = name.get<std::string>();
      if (const size_t hash = text.find('#'); hash != std::string::npos)
        patch.occurrence = r.integer(json::parse(text.substr(hash + 1), nullptr, false),
                                     where + " corner_name", 1);
      if (text != corner_name(patch.vertex, patch.face, patch.occurrence))
        throw r.error(where, fmt::format("corner_name \"{}\" is not vertex {} on face {}", text,
                                         patch.vertex + 1, patch.face + 1));
    }
    patch.level = r.integer(r.member(p, "level", where), where + " level", 0);
    const json& cell = r.member(p, "cell", where);
    if (!cell.is_array() || cell.size() != 2) throw r.error(where, "cell is not [u, v]");
    patch.cell_u = r.integer(cell[0], where + " cell", 0);
    patch.cell_v = r.integer(cell[1], where + " cell", 0);
    if (patch.level > 30 || patch.cell_u >> patch.level != 0 || patch.cell_v >> patch.level != 0)
      throw r.error(where, "cell lies outside its root patch");
    const json& exact = r.member(p, "exact", where);
    if (!exact.is_boolean()) throw r.error(where, "exact is not true or false");
    patch.exact = exact.get<bool>();
    const json& points = r.member(p, "points", where);
    if (!points.is_array() || points.size() != 16)
      throw r.error(where, "does not have 16 control points");
    for (int k = 0; k < 16; ++k) patch.net.p[k] = r.vec3(points[k], where + " point");
    set.patches.push_back(patch);
  }
  const json& count = r.member(doc, "patch_count", "the file");
  if (r.integer(count, "\"patch_count\"", 0) != static_cast<int>(set.patches.size()))
    throw r.error("\"patch_count\"", "does not match the number of patches");
  return set;
}

}  // namespace stitch
