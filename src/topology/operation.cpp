#include "stitch/topology/operation.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <type_traits>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/delete_face.hpp"
#include "stitch/topology/edge_ops.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/features.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/remesh.hpp"
#include "topology/raw_mesh.hpp"

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
    throw UsageError(fmt::format("'{}' is not a valid {} number (a positive integer)",
                                 limits::quoted(text), what));
  return value;
}

int parse_int(std::string_view text, const char* what) {
  int value = 0;
  const char* first = text.data();
  if (!text.empty() && text[0] == '+') ++first;
  const auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || first == end)
    throw UsageError(
        fmt::format("'{}' is not a valid {} (an integer)", limits::quoted(text), what));
  return value;
}

double parse_double(std::string_view text, const char* what) {
  const std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(value))
    throw UsageError(
        fmt::format("'{}' is not a valid {} (a finite number)", limits::quoted(text), what));
  return value;
}

Vertex vertex_arg(const HalfedgeMesh& mesh, std::string_view text) {
  const Vertex v(parse_number(text, "vertex") - 1);
  if (v.idx >= mesh.vertex_capacity() || mesh.is_deleted(v))
    throw UsageError(fmt::format("there is no vertex {}", v.idx + 1));
  return v;
}

Face face_arg(const HalfedgeMesh& mesh, std::string_view text) {
  const Face f(parse_number(text, "face") - 1);
  if (f.idx >= mesh.face_capacity() || mesh.is_deleted(f))
    throw UsageError(fmt::format("there is no face {}", f.idx + 1));
  return f;
}

void expect_args(const std::vector<std::string_view>& words, size_t min, size_t max,
                 const OperationInfo& info) {
  const size_t n = words.size() - 1;
  if (n < min || n > max)
    throw UsageError(fmt::format("{} takes {}{}{}; got {} argument{}", info.name, info.arguments,
                                 max == 0 ? "" : ": ", max == 0 ? "" : info.synopsis, n,
                                 n == 1 ? "" : "s"));
}

/// Sharpness as the user wrote it; a sharpness is a number like any other here, the operator
/// says which values it refuses.
double parse_sharpness(std::string_view text) {
  const std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || std::isnan(value))
    throw UsageError(
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

/// The table, in the variant's order: operation_info indexes it by the alternative.
constexpr std::array<OperationInfo, 15> kTable{{
    {"insert-edge", "insert-edge V@F V@F", "two corners",
     "join two corners: splits their face, or merges two faces (a hole or handle)", false},
    {"delete-edge", "delete-edge V W[@F]", "an edge", "remove an edge: the inverse of insert-edge",
     false},
    {"subdivide-edge", "subdivide-edge V W[@F]", "an edge", "split an edge at its midpoint", false},
    {"collapse-edge", "collapse-edge V W[@F]", "an edge (V is kept)",
     "merge W into V at the edge's midpoint", false},
    {"extrude-face", "extrude-face F DIST [SCALE]", "a face, a distance and an optional scale",
     "move a face out along its normal, with a quad on every side", false},
    {"connect-faces", "connect-faces F G [TWIST|auto] [SEGMENTS [WAIST]]",
     "two faces, an optional twist (a number or auto), segments and waist",
     "join two faces by a tube of quads (a handle)", false},
    {"delete-face", "delete-face F", "a face", "merge a face into the faces around it", false},
    {"open-face", "open-face F", "a face", "make a face a hole (a boundary of the surface)", false},
    {"fill-hole", "fill-hole F", "a hole face", "make a hole a face again", false},
    {"crease", "crease V W[@F] SHARPNESS", "an edge and a sharpness",
     "set an edge's sharpness (10 or more: a crease)", false},
    {"corner", "corner V SHARPNESS", "a vertex and a sharpness",
     "set a vertex's sharpness (10 or more: a corner)", false},
    {"doo-sabin", "doo-sabin", "no arguments", "one Doo-Sabin step of the whole mesh", true},
    {"vertex-insertion", "vertex-insertion", "no arguments",
     "a vertex in every face joined to its corners", true},
    {"catmull-clark", "catmull-clark", "no arguments", "one Catmull-Clark step of the whole mesh",
     true},
    {"dual", "dual", "no arguments", "the dual mesh: a vertex per face, a face per vertex", true},
}};

/// The table's rows by name, so that the parser's cases cannot drift from the table's order; the
/// remeshings follow the last in Remeshing's order.
enum Row : size_t {
  kInsertEdge,
  kDeleteEdge,
  kSubdivideEdge,
  kCollapseEdge,
  kExtrudeFace,
  kConnectFaces,
  kDeleteFace,
  kOpenFace,
  kFillHole,
  kCrease,
  kCorner,
  kFirstRemeshing
};
static_assert(kFirstRemeshing + 4 == kTable.size());

Operation parse_words(const HalfedgeMesh& mesh, const std::vector<std::string_view>& w) {
  const OperationInfo* info = find_operation(w[0]);
  if (!info)
    throw UsageError(
        fmt::format("unknown operation '{}' (known: {})", limits::quoted(w[0]), operation_names()));
  const size_t row = static_cast<size_t>(info - kTable.data());
  switch (row) {
    case kInsertEdge:
      expect_args(w, 2, 2, *info);
      return ops::InsertEdge{parse_corner(mesh, w[1]), parse_corner(mesh, w[2])};
    case kDeleteEdge:
      expect_args(w, 2, 2, *info);
      return ops::DeleteEdge{parse_edge(mesh, w[1], w[2])};
    case kSubdivideEdge:
      expect_args(w, 2, 2, *info);
      return ops::SubdivideEdge{parse_edge(mesh, w[1], w[2])};
    case kCollapseEdge:
      expect_args(w, 2, 2, *info);
      return ops::CollapseEdge{parse_edge(mesh, w[1], w[2]), vertex_arg(mesh, w[1])};
    case kExtrudeFace:
      expect_args(w, 2, 3, *info);
      return ops::ExtrudeFace{face_arg(mesh, w[1]), parse_double(w[2], "distance"),
                              w.size() > 3 ? parse_double(w[3], "scale") : 1.0};
    case kConnectFaces: {
      expect_args(w, 2, 5, *info);
      ops::ConnectFaces op{face_arg(mesh, w[1]), face_arg(mesh, w[2]), {}};
      if (w.size() > 3 && w[3] != "auto") op.handle.twist = parse_int(w[3], "twist");
      if (w.size() > 4) {
        op.handle.segments = parse_number(w[4], "segments");
        if (op.handle.segments > limits::max_handle_segments)
          throw UsageError(fmt::format("at most {} segments, got {}", limits::max_handle_segments,
                                       op.handle.segments));
      }
      if (w.size() > 5) op.handle.waist = parse_double(w[5], "waist");
      return op;
    }
    case kDeleteFace:
      expect_args(w, 1, 1, *info);
      return ops::DeleteFace{face_arg(mesh, w[1])};
    case kOpenFace:
      expect_args(w, 1, 1, *info);
      return ops::OpenFace{face_arg(mesh, w[1])};
    case kFillHole:
      expect_args(w, 1, 1, *info);
      return ops::FillHole{face_arg(mesh, w[1])};
    case kCrease:
      expect_args(w, 3, 3, *info);
      return ops::SetCrease{parse_edge(mesh, w[1], w[2]), parse_sharpness(w[3])};
    case kCorner:
      expect_args(w, 2, 2, *info);
      return ops::SetCorner{vertex_arg(mesh, w[1]), parse_sharpness(w[2])};
    default:
      expect_args(w, 0, 0, *info);
      return ops::Remesh{static_cast<Remeshing>(row - kFirstRemeshing)};
  }
}

/// The number as the user reads it.
int number(Vertex v) {
  return v.idx + 1;
}
int number(Face f) {
  return f.idx + 1;
}

/// Carries out a typed operation (refusals are the operators'), saying what changed.
std::string carry_out(HalfedgeMesh& mesh, const Operation& operation) {
  return std::visit(
      [&](const auto& op) -> std::string {
        using T = std::decay_t<decltype(op)>;
        if constexpr (std::is_same_v<T, ops::InsertEdge>) {
          const InsertEdgeResult r = insert_edge(mesh, op.a, op.b);
          return r.split
                     ? fmt::format("new edge {} split face {} into faces {} and {}", r.edge.idx + 1,
                                   number(r.face), number(r.face), number(r.other))
                     : fmt::format("new edge {} merged faces {} and {} into face {} ({} sides)",
                                   r.edge.idx + 1, number(r.face), number(r.other), number(r.face),
                                   mesh.degree(r.face));
        } else if constexpr (std::is_same_v<T, ops::DeleteEdge>) {
          const DeleteEdgeResult r = delete_edge(mesh, op.edge);
          return r.split
                     ? fmt::format("removed edge {}; face {} split into faces {} and {}",
                                   op.edge.idx + 1, number(r.face), number(r.face), number(r.other))
                     : fmt::format("removed edge {}; faces {} and {} merged into face {}",
                                   op.edge.idx + 1, number(r.face), number(r.other),
                                   number(r.face));
        } else if constexpr (std::is_same_v<T, ops::SubdivideEdge>) {
          const SubdivideEdgeResult r = subdivide_edge(mesh, op.edge);
          return fmt::format("new vertex {} splits edge {}; new edge {}", number(r.vertex),
                             op.edge.idx + 1, r.edge.idx + 1);
        } else if constexpr (std::is_same_v<T, ops::CollapseEdge>) {
          const Halfedge h = HalfedgeMesh::halfedge(op.edge, 0);
          const Vertex gone =
              mesh.origin(h) == op.keep ? mesh.origin(HalfedgeMesh::twin(h)) : mesh.origin(h);
          collapse_edge(mesh, op.edge, op.keep);
          return fmt::format("collapsed edge {}: vertex {} merged into vertex {}", op.edge.idx + 1,
                             number(gone), number(op.keep));
        } else if constexpr (std::is_same_v<T, ops::ExtrudeFace>) {
          const ExtrudeResult r = extrude_face(mesh, op.face, op.distance, op.scale);
          return fmt::format("face {} extruded: new vertices {}-{}, new side faces {}-{}",
                             number(op.face), r.first_vertex + 1, r.first_vertex + r.degree,
                             r.first_face + 1, r.first_face + r.degree);
        } else if constexpr (std::is_same_v<T, ops::ConnectFaces>) {
          const ConnectFacesResult r = connect_faces(mesh, op.f, op.g, op.handle);
          const int segments = op.handle.segments;
          return fmt::format(
              "faces {} and {} joined by a tube of {} quads{} (twist {}), new edges {}-{}",
              number(op.f), number(op.g), r.degree * segments,
              segments > 1 ? fmt::format(" in {} rings", segments) : std::string(), r.twist,
              r.first_edge + 1, r.first_edge + r.degree);
        } else if constexpr (std::is_same_v<T, ops::DeleteFace>) {
          const TopologyStats before = topology_stats(mesh);
          delete_face(mesh, op.face);
          const TopologyStats after = topology_stats(mesh);
          return fmt::format("face {} deleted: {} vertices, {} edges, {} faces fewer",
                             number(op.face), before.vertices - after.vertices,
                             before.edges - after.edges, before.faces - after.faces);
        } else if constexpr (std::is_same_v<T, ops::OpenFace>) {
          const OpenFaceResult r = open_face(mesh, op.face);
          if (r.merged.empty())
            return fmt::format("face {} is now a hole ({} sides)", number(op.face),
                               mesh.degree(op.face));
          std::string what = fmt::format(
              "face {} opened and merged with hole{} {} into hole{} {} ({} sides); removed {} "
              "edge{}",
              number(op.face), r.merged.size() == 1 ? "" : "s", face_list(r.merged),
              r.holes.size() == 1 ? "" : "s", face_list(r.holes), mesh.degree(r.holes.front()),
              r.removed_edges, r.removed_edges == 1 ? "" : "s");
          if (r.removed_vertices > 0)
            what += fmt::format(" and {} vertex{}", r.removed_vertices,
                                r.removed_vertices == 1 ? "" : "es");
          return what;
        } else if constexpr (std::is_same_v<T, ops::FillHole>) {
          fill_hole(mesh, op.face);
          return fmt::format("hole {} filled: now a face ({} sides)", number(op.face),
                             mesh.degree(op.face));
        } else if constexpr (std::is_same_v<T, ops::SetCrease>) {
          const double old = mesh.sharpness(op.edge);
          set_crease(mesh, op.edge, op.sharpness);
          const Halfedge h = HalfedgeMesh::halfedge(op.edge, 0);
          return fmt::format("edge {} (vertices {}-{}) sharpness {} -> {}{}", op.edge.idx + 1,
                             number(mesh.origin(h)), number(mesh.target(h)), old,
                             sharpness_text(op.sharpness),
                             mesh.is_boundary(op.edge) ? " (a boundary edge: sharp anyway)" : "");
        } else if constexpr (std::is_same_v<T, ops::SetCorner>) {
          const double old = mesh.sharpness(op.vertex);
          set_corner(mesh, op.vertex, op.sharpness);
          return fmt::format("vertex {} sharpness {} -> {}", number(op.vertex), old,
                             sharpness_text(op.sharpness));
        } else {
          static_assert(std::is_same_v<T, ops::Remesh>);
          HalfedgeMesh result = remesh(mesh, op.scheme);
          // New points are averages of old ones, so this holds unless the input was already
          // wrong; checked anyway because everything downstream trusts it.
          for (Vertex v : result.vertices())
            limits::check_coordinates(
                result.position(v),
                fmt::format("{}: new vertex {}", remeshing_name(op.scheme), number(v)));
          mesh = std::move(result);
          return "whole mesh remeshed and renumbered";
        }
      },
      operation);
}

OperationReport report_of(const HalfedgeMesh& mesh, std::string what, Census census) {
  OperationReport report;
  report.what = std::move(what);
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

/// Prefixes the operation's name to a message that does not start with it yet (the parser's).
[[noreturn]] void rethrow_named(std::string_view name) {
  try {
    throw;
  } catch (const Error& e) {
    const std::string msg = e.what();
    if (msg.rfind(std::string(name) + ":", 0) == 0) throw;
    throw_with_message(e, fmt::format("{}: {}", name, msg));
  }
}

}  // namespace

std::string_view without_comment(std::string_view line) {
  for (size_t i = 0; i < line.size(); ++i)
    if (line[i] == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(line[i - 1]))))
      return line.substr(0, i);
  return line;
}

std::span<const OperationInfo> operation_table() {
  return kTable;
}

const OperationInfo* find_operation(std::string_view name) {
  for (const OperationInfo& info : kTable)
    if (info.name == name) return &info;
  return nullptr;
}

const OperationInfo& operation_info(const Operation& op) {
  const size_t i = op.index();
  if (std::holds_alternative<ops::Remesh>(op))
    return kTable[kFirstRemeshing + static_cast<size_t>(std::get<ops::Remesh>(op).scheme)];
  return kTable[i];
}

std::string operation_names() {
  std::string out;
  for (const OperationInfo& info : kTable)
    out += (out.empty() ? "" : ", ") + std::string(info.name);
  return out;
}

std::optional<Operation> parse_operation(const HalfedgeMesh& mesh, std::string_view line) {
  const std::vector<std::string_view> words = split_words(without_comment(line));
  if (words.empty()) return std::nullopt;
  try {
    return parse_words(mesh, words);
  } catch (const Error&) {
    rethrow_named(words[0]);
  }
}

std::string format_operation(const HalfedgeMesh& mesh, const Operation& operation) {
  const std::string_view name = operation_info(operation).name;
  const std::string args = std::visit(
      [&](const auto& op) -> std::string {
        using T = std::decay_t<decltype(op)>;
        if constexpr (std::is_same_v<T, ops::InsertEdge>) {
          return fmt::format(" {} {}", corner_name(mesh, op.a), corner_name(mesh, op.b));
        } else if constexpr (std::is_same_v<T, ops::DeleteEdge> ||
                             std::is_same_v<T, ops::SubdivideEdge>) {
          return fmt::format(" {}", edge_name(mesh, op.edge));
        } else if constexpr (std::is_same_v<T, ops::CollapseEdge>) {
          return fmt::format(" {}", edge_name(mesh, op.edge, op.keep));  // the kept end first
        } else if constexpr (std::is_same_v<T, ops::ExtrudeFace>) {
          return fmt::format(" {} {} {}", number(op.face), op.distance, op.scale);
        } else if constexpr (std::is_same_v<T, ops::ConnectFaces>) {
          const HandleOptions& h = op.handle;
          std::string text = fmt::format(" {} {} {}", number(op.f), number(op.g),
                                         h.twist ? std::to_string(*h.twist) : "auto");
          const bool waist = h.waist != HandleOptions{}.waist;
          if (waist || h.segments != 1) text += fmt::format(" {}", h.segments);
          if (waist) text += fmt::format(" {}", h.waist);
          return text;
        } else if constexpr (std::is_same_v<T, ops::DeleteFace> ||
                             std::is_same_v<T, ops::OpenFace> || std::is_same_v<T, ops::FillHole>) {
          return fmt::format(" {}", number(op.face));
        } else if constexpr (std::is_same_v<T, ops::SetCrease>) {
          return fmt::format(" {} {}", edge_name(mesh, op.edge), op.sharpness);
        } else if constexpr (std::is_same_v<T, ops::SetCorner>) {
          return fmt::format(" {} {}", number(op.vertex), op.sharpness);
        } else {
          return "";
        }
      },
      operation);
  return std::string(name) + args;
}

Verdict can_apply(const HalfedgeMesh& mesh, const Operation& operation) {
  return std::visit(
      [&](const auto& op) -> Verdict {
        using T = std::decay_t<decltype(op)>;
        if constexpr (std::is_same_v<T, ops::InsertEdge>) {
          return can_insert_edge(mesh, op.a, op.b);
        } else if constexpr (std::is_same_v<T, ops::DeleteEdge>) {
          return can_delete_edge(mesh, op.edge);
        } else if constexpr (std::is_same_v<T, ops::SubdivideEdge>) {
          return can_subdivide_edge(mesh, op.edge);
        } else if constexpr (std::is_same_v<T, ops::CollapseEdge>) {
          return can_collapse_edge(mesh, op.edge, op.keep);
        } else if constexpr (std::is_same_v<T, ops::ExtrudeFace>) {
          return can_extrude_face(mesh, op.face, op.distance, op.scale);
        } else if constexpr (std::is_same_v<T, ops::ConnectFaces>) {
          return can_connect_faces(mesh, op.f, op.g, op.handle);
        } else if constexpr (std::is_same_v<T, ops::DeleteFace>) {
          return can_delete_face(mesh, op.face);
        } else if constexpr (std::is_same_v<T, ops::OpenFace>) {
          return can_open_face(mesh, op.face);
        } else if constexpr (std::is_same_v<T, ops::FillHole>) {
          return can_fill_hole(mesh, op.face);
        } else if constexpr (std::is_same_v<T, ops::SetCrease>) {
          return can_set_crease(mesh, op.edge, op.sharpness);
        } else if constexpr (std::is_same_v<T, ops::SetCorner>) {
          return can_set_corner(mesh, op.vertex, op.sharpness);
        } else {
          static_assert(std::is_same_v<T, ops::Remesh>);
          return can_remesh(mesh, op.scheme);
        }
      },
      operation);
}

OperationReport apply_operation(HalfedgeMesh& mesh, const Operation& op, Census census) {
  const std::string_view name = operation_info(op).name;
  try {
    if (census == Census::counts_only) return report_of(mesh, carry_out(mesh, op), census);
    // The full census already costs a pass over the mesh; so does making sure the result reads
    // back from a file, which needs the mesh as it was to return to when it would not.
    HalfedgeMesh before = mesh;
    std::string what = carry_out(mesh, op);
    try {
      check_reads_back(mesh);
    } catch (const Error& e) {
      mesh = std::move(before);
      throw TopologyError(fmt::format("refused: {}", e.what()));
    }
    return report_of(mesh, std::move(what), census);
  } catch (const Error&) {
    rethrow_named(name);
  }
}

OperationReport apply_operation(HalfedgeMesh& mesh, std::string_view line, Census census) {
  const std::optional<Operation> op = parse_operation(mesh, line);
  if (!op) return {};
  return apply_operation(mesh, *op, census);
}

std::string OperationReport::summary(std::string_view op_text) const {
  if (!components_counted)
    return fmt::format("{}: {}; V {} E {} F {}, Euler {}", op_text, what, stats.vertices,
                       stats.edges, stats.faces, stats.euler);
  return fmt::format("{}: {}; {}", op_text, what, stats_text(stats));
}

Corner parse_corner(const HalfedgeMesh& mesh, std::string_view text) {
  const size_t at = text.find('@');
  if (at == std::string_view::npos)
    throw UsageError(
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
    throw UsageError(
        fmt::format("corner {}: vertex {} is not on face {}", text, v.idx + 1, f.idx + 1));
  if (occurrence == 0 && found.size() > 1)
    throw UsageError(fmt::format(
        "corner {} is ambiguous: vertex {} appears {} times on face {}; write {}@{}#k with k = "
        "1..{} counted along the face from its first corner",
        text, v.idx + 1, found.size(), f.idx + 1, v.idx + 1, f.idx + 1, found.size()));
  if (occurrence > static_cast<int>(found.size()))
    throw UsageError(fmt::format("corner {}: vertex {} appears only {} time(s) on face {}", text,
                                 v.idx + 1, found.size(), f.idx + 1));
  return found[occurrence == 0 ? 0 : occurrence - 1];
}

int corner_occurrence(const HalfedgeMesh& mesh, Corner c) {
  const Vertex v = mesh.origin(c);
  int count = 0, occurrence = 0;
  for (Halfedge h : mesh.face_loop(mesh.face(c)))
    if (mesh.origin(h) == v) {
      ++count;
      if (h == c) occurrence = count;
    }
  return count > 1 ? occurrence : 0;
}

std::string corner_name(int vertex, int face, int occurrence) {
  if (occurrence > 0) return fmt::format("{}@{}#{}", vertex + 1, face + 1, occurrence);
  return fmt::format("{}@{}", vertex + 1, face + 1);
}

std::string corner_name(const HalfedgeMesh& mesh, Corner c) {
  return corner_name(mesh.origin(c).idx, mesh.face(c).idx, corner_occurrence(mesh, c));
}

Edge parse_edge(const HalfedgeMesh& mesh, std::string_view v_text, std::string_view w_text) {
  std::string_view face_text;
  if (const size_t at = w_text.find('@'); at != std::string_view::npos) {
    face_text = w_text.substr(at + 1);
    w_text = w_text.substr(0, at);
  }
  const Vertex v = vertex_arg(mesh, v_text), w = vertex_arg(mesh, w_text);
  const std::vector<Edge> joining = detail::edges_between(mesh, v, w);
  if (joining.empty())
    throw UsageError(fmt::format("no edge joins vertices {} and {}", v.idx + 1, w.idx + 1));
  if (face_text.empty()) {
    if (joining.size() > 1)
      throw UsageError(fmt::format(
          "vertices {} and {} are joined by {} edges; write {} {}@F to pick the one on face F",
          v.idx + 1, w.idx + 1, joining.size(), v.idx + 1, w.idx + 1));
    return joining.front();
  }
  int occurrence = 0;
  if (const size_t hash = face_text.find('#'); hash != std::string_view::npos) {
    occurrence = parse_number(face_text.substr(hash + 1), "occurrence");
    face_text = face_text.substr(0, hash);
  }
  const Face f = face_arg(mesh, face_text);
  if (occurrence > 0) {
    // The k-th time F's loop runs from V to W, counted from F's first corner, as for corners.
    int seen = 0;
    for (Halfedge h : mesh.face_loop(f))
      if (mesh.origin(h) == v && mesh.target(h) == w && ++seen == occurrence)
        return HalfedgeMesh::edge(h);
    throw UsageError(fmt::format("face {} runs from vertex {} to vertex {} only {} time(s)",
                                 f.idx + 1, v.idx + 1, w.idx + 1, seen));
  }
  std::set<int> on_face, forward;
  for (Halfedge h : mesh.face_loop(f)) {
    const bool vw = mesh.origin(h) == v && mesh.target(h) == w;
    const bool wv = mesh.origin(h) == w && mesh.target(h) == v;
    if (vw || wv) on_face.insert(HalfedgeMesh::edge(h).idx);
    if (vw) forward.insert(HalfedgeMesh::edge(h).idx);
  }
  if (on_face.empty())
    throw UsageError(fmt::format("no edge joining vertices {} and {} lies on face {}", v.idx + 1,
                                 w.idx + 1, f.idx + 1));
  if (on_face.size() == 1) return Edge(*on_face.begin());
  // Several (e.g. both edges of a 2-sided face): the one face F runs along from V to W.
  if (forward.size() == 1) return Edge(*forward.begin());
  throw UsageError(
      fmt::format("several edges joining vertices {} and {} lie on face {} the same way; write "
                  "{} {}@{}#k for the k-th along the face from its first corner",
                  v.idx + 1, w.idx + 1, f.idx + 1, v.idx + 1, w.idx + 1, f.idx + 1));
}

std::string edge_name(const HalfedgeMesh& mesh, Edge e, Vertex first) {
  Halfedge h = HalfedgeMesh::halfedge(e, 0);
  if (first.valid() && mesh.origin(h) != first) h = HalfedgeMesh::twin(h);
  const std::string v = std::to_string(number(mesh.origin(h)));
  const std::string w = std::to_string(number(mesh.target(h)));
  if (detail::edges_between(mesh, mesh.origin(h), mesh.target(h)).size() == 1) return v + " " + w;
  // Several edges join the two vertices: the face on the side running from v to w, and which
  // time along that face when it runs from v to w more than once.
  const Face f = mesh.face(h);
  int count = 0, occurrence = 0;
  for (Halfedge g : mesh.face_loop(f))
    if (mesh.origin(g) == mesh.origin(h) && mesh.target(g) == mesh.target(h)) {
      ++count;
      if (g == h) occurrence = count;
    }
  if (count > 1) return fmt::format("{} {}@{}#{}", v, w, number(f), occurrence);
  return fmt::format("{} {}@{}", v, w, number(f));
}

}  // namespace stitch
