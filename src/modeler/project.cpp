#include "stitch/modeler/project.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::modeler {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* overlay_names[num_overlays] = {"mesh", "kgons", "nets", "tess"};

json vec_json(const Vec3& p) {
  return json::array({p.x(), p.y(), p.z()});
}

Vec3 vec_from(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw MeshError(what + " must be an array of 3 numbers");
  const Vec3 p(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
  limits::check_coordinates(p, what);
  return p;
}

json control_json(const KgonControl& c) {
  return {{"scale", c.scale},
          {"rotate", c.rotate_deg},
          {"offset", vec_json(c.offset)},
          {"regularize", c.regularize}};
}

KgonControl control_from(const json& j, const std::string& what) {
  KgonControl c;
  c.scale = j.value("scale", 1.0);
  c.rotate_deg = j.value("rotate", 0.0);
  if (j.contains("offset")) c.offset = vec_from(j["offset"], what + " offset");
  c.regularize = j.value("regularize", false);
  // The same ranges as the `kgon` command: a project file is input like any other.
  limits::check_range(c.scale, limits::min_kgon_scale, limits::max_kgon_scale, what + ": scale");
  limits::check_range(c.rotate_deg, -limits::max_rotation_deg, limits::max_rotation_deg,
                      what + ": rotate");
  return c;
}

}  // namespace

bool is_project_path(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == ".stitch" || ext == ".json";
}

std::string project_to_json(const Project& project) {
  const HalfedgeMesh& m = project.state.mesh;
  const KgonOptions& k = project.state.kgons;
  // Saved numbers are ranks among live elements (what to_polygon_soup writes).
  std::vector<int> vertex_rank(m.vertex_capacity(), -1), face_rank(m.face_capacity(), -1);
  int rank = 0;
  for (Vertex v : m.vertices()) vertex_rank[v.idx] = rank++;
  rank = 0;
  for (Face f : m.faces()) face_rank[f.idx] = rank++;

  const PolygonSoup soup = to_polygon_soup(m);
  json positions = json::array(), faces = json::array();
  for (const Vec3& p : soup.positions) positions.push_back(vec_json(p));
  for (const auto& f : soup.faces) faces.push_back(f);

  json kf = json::array(), kv = json::array(), ke = json::array();
  for (const auto& [f, c] : k.face) {
    json j = control_json(c);
    j["face"] = face_rank[f];
    kf.push_back(j);
  }
  for (const auto& [v, c] : k.vertex) {
    json j = control_json(c);
    j["vertex"] = vertex_rank[v];
    kv.push_back(j);
  }
  for (const auto& [e, c] : k.edge) {
    const Halfedge h = HalfedgeMesh::halfedge(Edge(e), 0);
    json j = control_json(c);
    j["face"] = face_rank[m.face(h).idx];
    j["corner"] = m.index_in_face(h);
    ke.push_back(j);
  }
  // Sorted so the same project always gives the same file.
  auto by = [](const char* key) {
    return [key](const json& a, const json& b) {
      return std::make_pair(a[key].get<int>(), a.value("corner", 0)) <
             std::make_pair(b[key].get<int>(), b.value("corner", 0));
    };
  };
  std::sort(kf.begin(), kf.end(), by("face"));
  std::sort(kv.begin(), kv.end(), by("vertex"));
  std::sort(ke.begin(), ke.end(), by("face"));

  const DisplaySettings& d = project.display;
  json overlays = json::array();
  for (int o = 0; o < num_overlays; ++o)
    if (d.overlays[o]) overlays.push_back(overlay_names[o]);
  const OrbitView& v = project.view;
  json j = {{"format", "stitch-modeler-project"},
            {"version", 1},
            {"mesh", {{"positions", positions}, {"faces", faces}}},
            {"kgons",
             {{"global", control_json(k.global)}, {"faces", kf}, {"vertices", kv}, {"edges", ke}}},
            {"view",
             {{"target", vec_json(v.target)},
              {"distance", v.distance},
              {"yaw", v.yaw_deg},
              {"pitch", v.pitch_deg},
              {"fov", v.fov_y_deg}}},
            {"display",
             {{"method", to_string(d.method)},
              {"resolution", d.resolution},
              {"mode", to_string(d.mode)},
              {"input", d.input_polygons},
              {"overlays", overlays},
              {"markers", d.markers},
              {"split", d.split ? json(to_string(*d.split)) : json(nullptr)}}}};
  return j.dump(1) + "\n";
}

Project project_from_json(const std::string& text, const std::string& source) {
  try {
    const json j = json::parse(text);
    if (j.value("format", "") != "stitch-modeler-project")
      throw MeshError(
          "not a stitch modeler project (\"format\" is not \"stitch-modeler-project\")");
    if (j.value("version", 0) != 1)
      throw MeshError(fmt::format("unsupported project version {}", j.value("version", 0)));
    Project p;
    PolygonSoup soup;
    soup.source = source;
    const json& mesh = j.at("mesh");
    for (const json& q : mesh.at("positions")) soup.positions.push_back(vec_from(q, "a position"));
    for (const json& f : mesh.at("faces")) soup.faces.push_back(f.get<std::vector<int>>());
    BuildOptions build;
    build.allow_two_gons = true;
    BuildReport report;
    p.state.mesh = build_mesh(soup, build, &report);
    const HalfedgeMesh& m = p.state.mesh;

    std::vector<int> vertex_of(soup.positions.size(), -1);
    for (size_t v = 0; v < report.vertex_source.size(); ++v)
      vertex_of[report.vertex_source[v]] = int(v);
    const json& k = j.at("kgons");
    p.state.kgons.global = control_from(k.at("global"), "the global K-gon control");
    for (const json& c : k.at("faces")) {
      const int f = c.at("face").get<int>();
      if (f < 0 || f >= m.face_capacity())
        throw MeshError(fmt::format("K-gon control of face {}: no such face", f));
      p.state.kgons.face[f] = control_from(c, fmt::format("K-gon control of face {}", f));
    }
    for (const json& c : k.at("vertices")) {
      const int v = c.at("vertex").get<int>();
      if (v < 0 || v >= int(vertex_of.size()) || vertex_of[v] < 0)
        throw MeshError(fmt::format("K-gon control of vertex {}: no such vertex", v));
      p.state.kgons.vertex[vertex_of[v]] =
          control_from(c, fmt::format("K-gon control of vertex {}", v));
    }
    for (const json& c : k.at("edges")) {
      const int f = c.at("face").get<int>(), i = c.at("corner").get<int>();
      if (f < 0 || f >= m.face_capacity() || i < 0 || i >= m.degree(Face(f)))
        throw MeshError(
            fmt::format("K-gon control of the edge at corner {} of face {}: no such corner", i, f));
      const Halfedge h = m.face_loop(Face(f))[i];
      p.state.kgons.edge[HalfedgeMesh::edge(h).idx] =
          control_from(c, fmt::format("K-gon control of the edge at corner {} of face {}", i, f));
    }

    const json& v = j.at("view");
    p.view.target = vec_from(v.at("target"), "the view target");
    p.view.distance = v.at("distance").get<double>();
    p.view.yaw_deg = v.at("yaw").get<double>();
    p.view.pitch_deg = v.at("pitch").get<double>();
    p.view.fov_y_deg = v.value("fov", 30.0);
    if (!(p.view.distance > 0 && std::isfinite(p.view.distance)) ||
        !(p.view.fov_y_deg > 0 && p.view.fov_y_deg < 180))
      throw MeshError("the view needs a positive distance and a field of view in (0, 180)");
    limits::check_range(p.view.yaw_deg, -limits::max_rotation_deg, limits::max_rotation_deg,
                        "the view's yaw");
    limits::check_range(p.view.pitch_deg, -90, 90, "the view's pitch");

    const json& d = j.at("display");
    p.display.method = parse_method(d.at("method").get<std::string>());
    p.display.resolution = d.at("resolution").get<int>();
    if (p.display.resolution < 1 || p.display.resolution > 64)
      throw MeshError(fmt::format("the resolution {} is not in 1..64", p.display.resolution));
    p.display.mode = parse_shading_mode(d.at("mode").get<std::string>());
    p.display.input_polygons = d.value("input", false);
    for (const json& o : d.value("overlays", json::array())) {
      const auto name = o.get<std::string>();
      const auto* it = std::find(std::begin(overlay_names), std::end(overlay_names), name);
      if (it == std::end(overlay_names))
        throw MeshError("unknown overlay '" + limits::quoted(name) + "'");
      p.display.overlays[it - std::begin(overlay_names)] = true;
    }
    p.display.markers = d.value("markers", false);
    if (d.contains("split") && !d["split"].is_null())
      p.display.split = parse_method(d["split"].get<std::string>());
    return p;
  } catch (const MeshError& e) {
    const std::string msg = e.what();
    if (msg.rfind(source, 0) == 0) throw;
    throw MeshError(fmt::format("{}: {}", source, msg));
  } catch (const std::exception& e) {  // JSON syntax and type errors, bad names
    throw MeshError(fmt::format("{}: {}", source, e.what()));
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
    return (base / "stitch" / "autosave" / "untitled.stitch").string();
  }
  const fs::path p(document_path);
  return (p.parent_path() / fmt::format(".{}.autosave.stitch", p.filename().string())).string();
}

bool autosave_is_newer(const std::string& autosave, const std::string& document_path) {
  std::error_code ec;
  if (!fs::exists(autosave, ec)) return false;
  if (document_path.empty() || !fs::exists(document_path, ec)) return true;
  return fs::last_write_time(autosave, ec) > fs::last_write_time(document_path, ec);
}

}  // namespace stitch::modeler
