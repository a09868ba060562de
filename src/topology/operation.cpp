#include "stitch/topology/operation.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>

#include "raw_mesh.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/delete_face.hpp"
#include "stitch/topology/edge_ops.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/features.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/remesh.hpp"

namespace stitch {

std::vector<std::string_view> split_words(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    size_t j = i;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

namespace {

/// A positive 1-based number; `what` names it for the message.
int parse_number(std::string_view text, const char* what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 1)
    throw MeshError(fmt::format("'{}' is not a valid {} number (a positive integer)",
                                limits::quoted(text), what));
  return value;
}

int parse_int(std::string_view text, const char* what) {
  int value = 0;
  const char* first = text.data();
  if (!text.empty() && text[0] == '+') ++first;
  const auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || first == end)
    throw MeshError(fmt::format("'{}' is not a valid {} (an integer)", limits::quoted(text), what));
  return value;
}

double parse_double(std::string_view text, const char* what) {
  const std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(value))
    throw MeshError(
        fmt::format("'{}' is not a valid {} (a finite number)", limits::quoted(text), what));
  return value;
}

Vertex vertex_arg(const HalfedgeMesh& mesh, std::string_view text) {
  const Vertex v(parse_number(text, "vertex") - 1);
  if (v.idx >= mesh.vertex_capacity() || mesh.is_deleted(v))
    throw MeshError(fmt::format("there is no vertex {}", v.idx + 1));
  return v;
}

Face face_arg(const HalfedgeMesh& mesh, std::string_view text) {
  const Face f(parse_number(text, "face") - 1);
  if (f.idx >= mesh.face_capacity() || mesh.is_deleted(f))
    throw MeshError(fmt::format("there is no face {}", f.idx + 1));
  return f;
}

void expect_args(const std::vector<std::string_view>& words, size_t min, size_t max,
                 const char* usage) {
  const size_t n = words.size() - 1;
  if (n < min || n > max)
    throw MeshError(
        fmt::format("{} takes {}; got {} argument{}", words[0], usage, n, n == 1 ? "" : "s"));
}

/// Sharpness as the user wrote it; a sharpness is a number like any other here, the operator
/// says which values it refuses.
double parse_sharpness(std::string_view text) {
  const std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || std::isnan(value))
    throw MeshError(
        fmt::format("'{}' is not a valid sharpness (a number >= 0; {} or more is "
                    "infinitely sharp)",
                    limits::quoted(text), infinitely_sharp));
  return value;
}

std::string sharpness_text(double s) {
  return s >= infinitely_sharp ? fmt::format("{} (infinitely sharp)", s) : fmt::format("{}", s);
}

std::string stats_text(const TopologyStats& s) {
  std::string text = fmt::format("V {} E {} F {}, Euler {}, genus {}, components {}", s.vertices,
                                 s.edges, s.faces, s.euler, s.genus, s.components);
  // Only when present, so closed untagged meshes print exactly as before.
  if (s.boundary_loops > 0) text += fmt::format(", boundary loops {}", s.boundary_loops);
  if (s.crease_edges > 0) text += fmt::format(", creases {}", s.crease_edges);
  if (s.corner_vertices > 0) text += fmt::format(", corners {}", s.corner_vertices);
  return text;
}

std::string face_list(const std::vector<Face>& faces) {
  std::string out;
  for (Face f : faces) out += (out.empty() ? "" : ", ") + std::to_string(f.idx + 1);
  return out;
}

OperationReport run(HalfedgeMesh& mesh, const std::vector<std::string_view>& w, Census census) {
  const std::string_view op = w[0];
  OperationReport report;
  if (op == "insert-edge") {
    expect_args(w, 2, 2, "two corners: insert-edge V@F V@F");
    const Corner a = parse_corner(mesh, w[1]), b = parse_corner(mesh, w[2]);
    const InsertEdgeResult r = insert_edge(mesh, a, b);
    report.what = r.split
                      ? fmt::format("new edge {} split face {} into faces {} and {}",
                                    r.edge.idx + 1, r.face.idx + 1, r.face.idx + 1, r.other.idx + 1)
                      : fmt::format("new edge {} merged faces {} and {} into face {} ({} sides)",
                                    r.edge.idx + 1, r.face.idx + 1, r.other.idx + 1, r.face.idx + 1,
                                    mesh.degree(r.face));
  } else if (op == "delete-edge") {
    expect_args(w, 2, 2, "an edge: delete-edge V W or V W@F");
    const Edge e = parse_edge(mesh, w[1], w[2]);
    const DeleteEdgeResult r = delete_edge(mesh, e);
    report.what = r.split ? fmt::format("removed edge {}; face {} split into faces {} and {}",
                                        e.idx + 1, r.face.idx + 1, r.face.idx + 1, r.other.idx + 1)
                          : fmt::format("removed edge {}; faces {} and {} merged into face {}",
                                        e.idx + 1, r.face.idx + 1, r.other.idx + 1, r.face.idx + 1);
  } else if (op == "subdivide-edge") {
    expect_args(w, 2, 2, "an edge: subdivide-edge V W or V W@F");
    const Edge e = parse_edge(mesh, w[1], w[2]);
    const SubdivideEdgeResult r = subdivide_edge(mesh, e);
    report.what = fmt::format("new vertex {} splits edge {}; new edge {}", r.vertex.idx + 1,
                              e.idx + 1, r.edge.idx + 1);
  } else if (op == "collapse-edge") {
    expect_args(w, 2, 2, "an edge: collapse-edge V W or V W@F (V is kept)");
    const Edge e = parse_edge(mesh, w[1], w[2]);
    const Vertex keep = vertex_arg(mesh, w[1]);
    const Vertex gone = mesh.origin(HalfedgeMesh::halfedge(e, 0)) == keep
                            ? mesh.origin(HalfedgeMesh::halfedge(e, 1))
                            : mesh.origin(HalfedgeMesh::halfedge(e, 0));
    collapse_edge(mesh, e, keep);
    report.what = fmt::format("collapsed edge {}: vertex {} merged into vertex {}", e.idx + 1,
                              gone.idx + 1, keep.idx + 1);
  } else if (op == "extrude-face") {
    expect_args(w, 2, 3, "a face, a distance and an optional scale: extrude-face F DIST [SCALE]");
    const Face f = face_arg(mesh, w[1]);
    const double distance = parse_double(w[2], "distance");
    const double scale = w.size() > 3 ? parse_double(w[3], "scale") : 1.0;
    const ExtrudeResult r = extrude_face(mesh, f, distance, scale);
    report.what = fmt::format("face {} extruded: new vertices {}-{}, new side faces {}-{}",
                              f.idx + 1, r.first_vertex + 1, r.first_vertex + r.degree,
                              r.first_face + 1, r.first_face + r.degree);
  } else if (op == "connect-faces") {
    expect_args(w, 2, 5,
                "two faces, an optional twist (a number or auto), segments and waist: "
                "connect-faces F G [TWIST|auto] [SEGMENTS [WAIST]]");
    const Face f = face_arg(mesh, w[1]), g = face_arg(mesh, w[2]);
    HandleOptions handle;
    if (w.size() > 3 && w[3] != "auto") handle.twist = parse_int(w[3], "twist");
    if (w.size() > 4) {
      handle.segments = parse_number(w[4], "segments");
      if (handle.segments > limits::max_handle_segments)
        throw MeshError(fmt::format("connect-faces: at most {} segments, got {}",
                                    limits::max_handle_segments, handle.segments));
    }
    if (w.size() > 5) handle.waist = parse_double(w[5], "waist");
    const ConnectFacesResult r = connect_faces(mesh, f, g, handle);
    report.what = fmt::format(
        "faces {} and {} joined by a tube of {} quads{} (twist {}), new edges {}-{}", f.idx + 1,
        g.idx + 1, r.degree * handle.segments,
        handle.segments > 1 ? fmt::format(" in {} rings", handle.segments) : std::string(), r.twist,
        r.first_edge + 1, r.first_edge + r.degree);
  } else if (op == "delete-face") {
    expect_args(w, 1, 1, "a face: delete-face F");
    const Face f = face_arg(mesh, w[1]);
    const TopologyStats before = topology_stats(mesh);
    delete_face(mesh, f);
    const TopologyStats after = topology_stats(mesh);
    report.what = fmt::format("face {} deleted: {} vertices, {} edges, {} faces fewer", f.idx + 1,
                              before.vertices - after.vertices, before.edges - after.edges,
                              before.faces - after.faces);
  } else if (op == "open-face") {
    expect_args(w, 1, 1, "a face: open-face F");
    const Face f = face_arg(mesh, w[1]);
    const OpenFaceResult r = open_face(mesh, f);
    if (r.merged.empty()) {
      report.what = fmt::format("face {} is now a hole ({} sides)", f.idx + 1, mesh.degree(f));
    } else {
      report.what = fmt::format(
          "face {} opened and merged with hole{} {} into hole{} {} ({} sides); removed {} edge{}",
          f.idx + 1, r.merged.size() == 1 ? "" : "s", face_list(r.merged),
          r.holes.size() == 1 ? "" : "s", face_list(r.holes), mesh.degree(r.holes.front()),
          r.removed_edges, r.removed_edges == 1 ? "" : "s");
      if (r.removed_vertices > 0)
        report.what += fmt::format(" and {} vertex{}", r.removed_vertices,
                                   r.removed_vertices == 1 ? "" : "es");
    }
  } else if (op == "fill-hole") {
    expect_args(w, 1, 1, "a hole face: fill-hole F");
    const Face f = face_arg(mesh, w[1]);
    fill_hole(mesh, f);
    report.what = fmt::format("hole {} filled: now a face ({} sides)", f.idx + 1, mesh.degree(f));
  } else if (op == "crease") {
    expect_args(w, 3, 3, "an edge and a sharpness: crease V W[@F] SHARPNESS");
    const Edge e = parse_edge(mesh, w[1], w[2]);
    const double sharpness = parse_sharpness(w[3]);
    const double old = mesh.sharpness(e);
    set_crease(mesh, e, sharpness);
    const Halfedge h = HalfedgeMesh::halfedge(e, 0);
    report.what =
        fmt::format("edge {} (vertices {}-{}) sharpness {} -> {}{}", e.idx + 1,
                    mesh.origin(h).idx + 1, mesh.target(h).idx + 1, old, sharpness_text(sharpness),
                    mesh.is_boundary(e) ? " (a boundary edge: sharp anyway)" : "");
  } else if (op == "corner") {
    expect_args(w, 2, 2, "a vertex and a sharpness: corner V SHARPNESS");
    const Vertex v = vertex_arg(mesh, w[1]);
    const double sharpness = parse_sharpness(w[2]);
    const double old = mesh.sharpness(v);
    set_corner(mesh, v, sharpness);
    report.what =
        fmt::format("vertex {} sharpness {} -> {}", v.idx + 1, old, sharpness_text(sharpness));
  } else if (op == "doo-sabin" || op == "vertex-insertion" || op == "catmull-clark" ||
             op == "dual") {
    expect_args(w, 0, 0, "no arguments");
    HalfedgeMesh result = op == "doo-sabin"          ? doo_sabin(mesh)
                          : op == "vertex-insertion" ? vertex_insertion(mesh)
                          : op == "catmull-clark"    ? catmull_clark_step(mesh)
                                                     : dual(mesh);
    // New points are averages of old ones, so this holds unless the input was already wrong;
    // checked anyway because everything downstream trusts it.
    for (Vertex v : result.vertices())
      limits::check_coordinates(result.position(v),
                                fmt::format("{}: new vertex {}", op, v.idx + 1));
    mesh = std::move(result);
    report.what = "whole mesh remeshed and renumbered";
  } else {
    throw MeshError(
        fmt::format("unknown operation '{}' (known: insert-edge, delete-edge, "
                    "subdivide-edge, collapse-edge, extrude-face, connect-faces, "
                    "delete-face, open-face, fill-hole, crease, corner, doo-sabin, "
                    "vertex-insertion, catmull-clark, dual)",
                    limits::quoted(op)));
  }
  if (census == Census::full) {
    report.stats = topology_stats(mesh);
  } else {
    report.components_counted = false;
    report.stats.vertices = mesh.num_vertices();
    report.stats.edges = mesh.num_edges();
    report.stats.faces = mesh.num_faces();
    report.stats.euler = report.stats.vertices - report.stats.edges + report.stats.faces;
  }
  return report;
}

}  // namespace

std::string OperationReport::summary(std::string_view op_text) const {
  if (!components_counted)
    return fmt::format("{}: {}; V {} E {} F {}, Euler {}", op_text, what, stats.vertices,
                       stats.edges, stats.faces, stats.euler);
  return fmt::format("{}: {}; {}", op_text, what, stats_text(stats));
}

Corner parse_corner(const HalfedgeMesh& mesh, std::string_view text) {
  const size_t at = text.find('@');
  if (at == std::string_view::npos)
    throw MeshError(
        fmt::format("'{}' is not a corner; write V@F (vertex V on face F)", limits::quoted(text)));
  const std::string_view v_text = text.substr(0, at);
  std::string_view f_text = text.substr(at + 1);
  int occurrence = 0;
  if (const size_t hash = f_text.find('#'); hash != std::string_view::npos) {
    occurrence = parse_number(f_text.substr(hash + 1), "occurrence");
    f_text = f_text.substr(0, hash);
  }
  const Vertex v = vertex_arg(mesh, v_text);
  const Face f = face_arg(mesh, f_text);
  std::vector<Halfedge> found;
  for (Halfedge h : mesh.face_loop(f))
    if (mesh.origin(h) == v) found.push_back(h);
  if (found.empty())
    throw MeshError(
        fmt::format("corner {}: vertex {} is not on face {}", text, v.idx + 1, f.idx + 1));
  if (occurrence == 0 && found.size() > 1)
    throw MeshError(fmt::format(
        "corner {} is ambiguous: vertex {} appears {} times on face {}; write {}@{}#k with k = "
        "1..{} counted along the face from its first corner",
        text, v.idx + 1, found.size(), f.idx + 1, v.idx + 1, f.idx + 1, found.size()));
  if (occurrence > static_cast<int>(found.size()))
    throw MeshError(fmt::format("corner {}: vertex {} appears only {} time(s) on face {}", text,
                                v.idx + 1, found.size(), f.idx + 1));
  return found[occurrence == 0 ? 0 : occurrence - 1];
}

Edge parse_edge(const HalfedgeMesh& mesh, std::string_view v_text, std::string_view w_text) {
  std::string_view face_text;
  if (const size_t at = w_text.find('@'); at != std::string_view::npos) {
    face_text = w_text.substr(at + 1);
    w_text = w_text.substr(0, at);
  }
  const Vertex v = vertex_arg(mesh, v_text), w = vertex_arg(mesh, w_text);
  const std::vector<Edge> joining = topology_detail::edges_between(mesh, v, w);
  if (joining.empty())
    throw MeshError(fmt::format("no edge joins vertices {} and {}", v.idx + 1, w.idx + 1));
  if (face_text.empty()) {
    if (joining.size() > 1)
      throw MeshError(fmt::format(
          "vertices {} and {} are joined by {} edges; write {} {}@F to pick the one on face F",
          v.idx + 1, w.idx + 1, joining.size(), v.idx + 1, w.idx + 1));
    return joining.front();
  }
  const Face f = face_arg(mesh, face_text);
  std::set<int> on_face, forward;
  for (Halfedge h : mesh.face_loop(f)) {
    const bool vw = mesh.origin(h) == v && mesh.target(h) == w;
    const bool wv = mesh.origin(h) == w && mesh.target(h) == v;
    if (vw || wv) on_face.insert(HalfedgeMesh::edge(h).idx);
    if (vw) forward.insert(HalfedgeMesh::edge(h).idx);
  }
  if (on_face.empty())
    throw MeshError(fmt::format("no edge joining vertices {} and {} lies on face {}", v.idx + 1,
                                w.idx + 1, f.idx + 1));
  if (on_face.size() == 1) return Edge(*on_face.begin());
  // Several (e.g. both edges of a 2-sided face): the one face F runs along from V to W.
  if (forward.size() == 1) return Edge(*forward.begin());
  throw MeshError(
      fmt::format("several edges joining vertices {} and {} lie on face {}; the choice "
                  "is ambiguous",
                  v.idx + 1, w.idx + 1, f.idx + 1));
}

OperationReport apply_operation(HalfedgeMesh& mesh, std::string_view line, Census census) {
  if (const size_t hash = line.find('#'); hash != std::string_view::npos) {
    // '#' also marks an occurrence in a corner (V@F#k): only a '#' after a blank starts a comment.
    size_t comment = std::string_view::npos;
    for (size_t i = hash; i < line.size(); ++i)
      if (line[i] == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(line[i - 1])))) {
        comment = i;
        break;
      }
    line = line.substr(0, comment);
  }
  const std::vector<std::string_view> words = split_words(line);
  if (words.empty()) return {};
  try {
    if (census == Census::counts_only) return run(mesh, words, census);
    // The full census already costs a pass over the mesh; so does making sure the result reads
    // back from a file, which needs the mesh as it was to return to when it would not.
    HalfedgeMesh before = mesh;
    OperationReport report = run(mesh, words, census);
    try {
      check_reads_back(mesh);
    } catch (const MeshError& e) {
      mesh = std::move(before);
      throw MeshError(fmt::format("refused: {}", e.what()));
    }
    return report;
  } catch (const MeshError& e) {
    const std::string msg = e.what();
    // Operator messages already start with the operation's name; parser messages do not.
    if (msg.rfind(std::string(words[0]) + ":", 0) == 0) throw;
    throw MeshError(fmt::format("{}: {}", words[0], msg));
  }
}

std::vector<std::string> operation_synopsis() {
  return {"insert-edge V@F V@F",
          "delete-edge V W[@F]",
          "subdivide-edge V W[@F]",
          "collapse-edge V W[@F]",
          "extrude-face F DIST [SCALE]",
          "connect-faces F G [TWIST|auto] [SEGMENTS [WAIST]]",
          "delete-face F",
          "open-face F",
          "fill-hole F",
          "crease V W[@F] SHARPNESS",
          "corner V SHARPNESS",
          "doo-sabin",
          "vertex-insertion",
          "catmull-clark",
          "dual"};
}

}  // namespace stitch
