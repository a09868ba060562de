#include "stitch/project/project_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "project/kgon_control_json.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch {

using nlohmann::json;

namespace {

constexpr const char* kFormat = "stitch-modeler-project";

json vec_json(const Vec3& p) {
  return json::array({p.x(), p.y(), p.z()});
}

Vec3 vec_from(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + " must be an array of 3 numbers");
  const Vec3 p(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
  limits::check_coordinates(p, what);
  return p;
}

/// `element` names the members that say which element the control is on, read by the caller.
KgonControl control_from(const json& j, const std::string& what,
                         std::initializer_list<std::string_view> element = {}) {
  if (!j.is_object()) throw InputError(what + " must be an object");
  KgonControl c;
  for (const auto& [key, value] : j.items()) {
    if (std::find(element.begin(), element.end(), key) != element.end()) continue;
    bool known = false;
    try {
      known = detail::read_kgon_control_member(key, value, c);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", what, e.what()));
    }
    if (!known)
      throw InputError(
          fmt::format("{}: unknown member \"{}\" ({})", what, key, kgon_control_field_names()));
  }
  // The same ranges as the command line's: a project file is input like any other.
  check_kgon_control(c, what + ": ");
  return c;
}

}  // namespace

bool is_project_path(const std::string& path) {
  const std::string ext = file_extension(path);
  return std::find(kProjectExtensions.begin(), kProjectExtensions.end(), ext) !=
         kProjectExtensions.end();
}

std::string write_project_json(const HalfedgeMesh& m, const KgonOptions& k,
                               const std::map<std::string, std::string>& sections) {
  // Saved numbers are ranks among the elements to_polygon_soup writes: live vertices, and live
  // faces that are not holes (holes read back as boundaries, numbered after the faces).
  std::vector<int> vertex_rank(m.vertex_capacity(), -1), face_rank(m.face_capacity(), -1);
  int rank = 0;
  for (Vertex v : m.vertices()) vertex_rank[v.idx] = rank++;
  rank = 0;
  for (Face f : m.surface_faces()) face_rank[f.idx] = rank++;

  const PolygonSoup soup = to_polygon_soup(m);
  json positions = json::array(), faces = json::array();
  for (const Vec3& p : soup.positions) positions.push_back(vec_json(p));
  for (const auto& f : soup.faces) faces.push_back(f);
  json mesh = {{"positions", positions}, {"faces", faces}};
  // The tags as the OBJ writer writes them (to_polygon_soup), so a project keeps its creases.
  if (!soup.creases.empty()) {
    json creases = json::array();
    for (const SoupCrease& c : soup.creases) creases.push_back({c.a, c.b, c.sharpness});
    mesh["creases"] = creases;
  }
  if (!soup.corners.empty()) {
    json corners = json::array();
    for (const SoupCorner& c : soup.corners) corners.push_back({c.vertex, c.sharpness});
    mesh["corners"] = corners;
  }
  if (soup.crease_method == CreaseMethod::chaikin) mesh["crease_method"] = "chaikin";

  json kf = json::array(), kv = json::array(), ke = json::array();
  for (const auto& [f, c] : k.face) {
    if (face_rank[f] < 0) continue;  // a hole has no K-gon
    json j = detail::kgon_control_json(c);
    j["face"] = face_rank[f];
    kf.push_back(j);
  }
  for (const auto& [v, c] : k.vertex) {
    json j = detail::kgon_control_json(c);
    j["vertex"] = vertex_rank[v];
    kv.push_back(j);
  }
  for (const auto& [e, c] : k.edge) {
    // Named by a side on a face the file keeps: no edge has holes on both sides.
    Halfedge h = HalfedgeMesh::halfedge(Edge(e), 0);
    if (m.is_hole(h)) h = HalfedgeMesh::twin(h);
    json j = detail::kgon_control_json(c);
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

  json j = {{"format", kFormat},
            {"version", 1},
            {"mesh", mesh},
            {"kgons",
             {{"global", detail::kgon_control_json(k.global)},
              {"faces", kf},
              {"vertices", kv},
              {"edges", ke}}}};
  for (const auto& [name, text] : sections) j[name] = json::parse(text);
  return j.dump(1) + "\n";
}

ProjectFile parse_project_json(const std::string& text, const std::string& source,
                               BuildOptions build, BuildReport* report_out) {
  try {
    const json j = json::parse(text);
    if (!j.is_object() || j.value("format", "") != kFormat)
      throw InputError(
          fmt::format("not a stitch modeler project (\"format\" is not \"{}\")", kFormat));
    if (j.value("version", 0) != 1)
      throw InputError(fmt::format("unsupported project version {}", j.value("version", 0)));
    ProjectFile p;
    PolygonSoup soup;
    soup.source = source;
    const json& mesh = j.at("mesh");
    for (const json& q : mesh.at("positions")) soup.positions.push_back(vec_from(q, "a position"));
    for (const json& f : mesh.at("faces")) soup.faces.push_back(f.get<std::vector<int>>());
    // build_mesh checks the tags as it checks a file's (vertices in range, sharpness >= 0).
    for (const json& c : mesh.value("creases", json::array()))
      soup.creases.push_back({c.at(0).get<int>(), c.at(1).get<int>(), c.at(2).get<double>(), 0});
    for (const json& c : mesh.value("corners", json::array()))
      soup.corners.push_back({c.at(0).get<int>(), c.at(1).get<double>(), 0});
    const std::string creasing = mesh.value("crease_method", "uniform");
    if (creasing != "uniform" && creasing != "chaikin")
      throw InputError(fmt::format("crease_method \"{}\" is neither uniform nor chaikin",
                                   limits::quoted(creasing)));
    soup.crease_method = creasing == "chaikin" ? CreaseMethod::chaikin : CreaseMethod::uniform;
    build.allow_two_gons = true;
    // Its K-gon controls number the faces and vertices as stored: stitch wrote them, so they
    // need no repair, and a repair would renumber them.
    build.repair = false;
    BuildReport local;
    BuildReport& report = report_out ? *report_out : local;
    p.mesh = build_mesh(soup, build, &report);
    const HalfedgeMesh& m = p.mesh;

    std::vector<int> vertex_of(soup.positions.size(), -1);
    for (size_t v = 0; v < report.vertex_source.size(); ++v)
      vertex_of[report.vertex_source[v]] = int(v);
    const int soup_faces = static_cast<int>(soup.faces.size());  // holes come after them
    const json& k = j.at("kgons");
    p.kgons.global = control_from(k.at("global"), "the global K-gon control");
    for (const json& c : k.at("faces")) {
      const int f = c.at("face").get<int>();
      if (f < 0 || f >= soup_faces)
        throw InputError(fmt::format("K-gon control of face {}: no such face", f));
      p.kgons.face[f] = control_from(c, fmt::format("K-gon control of face {}", f), {"face"});
    }
    for (const json& c : k.at("vertices")) {
      const int v = c.at("vertex").get<int>();
      if (v < 0 || v >= int(vertex_of.size()) || vertex_of[v] < 0)
        throw InputError(fmt::format("K-gon control of vertex {}: no such vertex", v));
      p.kgons.vertex[vertex_of[v]] =
          control_from(c, fmt::format("K-gon control of vertex {}", v), {"vertex"});
    }
    for (const json& c : k.at("edges")) {
      const int f = c.at("face").get<int>(), i = c.at("corner").get<int>();
      if (f < 0 || f >= soup_faces || i < 0 || i >= m.degree(Face(f)))
        throw InputError(
            fmt::format("K-gon control of the edge at corner {} of face {}: no such corner", i, f));
      const Halfedge h = m.face_loop(Face(f))[i];
      p.kgons.edge[HalfedgeMesh::edge(h).idx] =
          control_from(c, fmt::format("K-gon control of the edge at corner {} of face {}", i, f),
                       {"face", "corner"});
    }
    if (j.contains("display") && j["display"].contains("method")) {
      try {
        p.method = parse_method(j["display"]["method"].get<std::string>());
      } catch (const UsageError& e) {
        throw InputError(fmt::format("display: {}", e.what()));
      }
    }
    for (const auto& [name, value] : j.items())
      if (name != "format" && name != "version" && name != "mesh" && name != "kgons")
        p.sections[name] = value.dump();
    return p;
  } catch (const Error& e) {
    const std::string msg = e.what();
    if (msg.rfind(source, 0) == 0) throw;
    throw_with_message(e, fmt::format("{}: {}", source, msg));
  } catch (const std::exception& e) {  // JSON syntax and type errors, missing members
    throw InputError(fmt::format("{}: {}", source, e.what()));
  }
}

ProjectFile read_project_file(const std::string& path, const BuildOptions& build,
                              BuildReport* report) {
  return parse_project_json(read_regular_file(path), path, build, report);
}

}  // namespace stitch
