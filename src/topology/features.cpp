#include "stitch/topology/features.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/mesh/validate.hpp"
#include "topology/raw_mesh.hpp"

namespace stitch {

namespace {

int hole_corners(const HalfedgeMesh& mesh, Vertex v) {
  int n = 0;
  for (Halfedge c : mesh.vertex_fan(v)) n += mesh.is_hole(c);
  return n;
}

/// What meets at v in the mesh before opening f, for the message when the boundary would pinch.
std::string pinch_reason(const HalfedgeMesh& mesh, Face f, Vertex v) {
  std::set<int> holes;
  int own = 0;
  for (Halfedge c : mesh.vertex_fan(v)) {
    if (mesh.face(c) == f) ++own;
    if (mesh.is_hole(c)) holes.insert(mesh.face(c).idx + 1);
  }
  if (holes.empty() && own > 1) return fmt::format("face {} visits it twice", f.idx + 1);
  std::string names;
  for (int h : holes) names += (names.empty() ? "" : ", ") + std::to_string(h);
  return fmt::format(
      "face {} touches hole{} {} there without sharing an edge; open the faces between them "
      "first, or merge those into face {} (delete-edge)",
      f.idx + 1, holes.size() == 1 ? "" : "s", names, f.idx + 1);
}

Verdict sharpness_allowed(double s, const char* op) {
  if (!std::isfinite(s) || s < 0)
    return Verdict::refused(
        fmt::format("{}: sharpness {} is not allowed: it must be a finite number >= 0 (0 smooth, "
                    "{} or more infinitely sharp)",
                    op, s, infinitely_sharp));
  return {};
}

struct OpenFacePlan {
  OpenFaceResult result;
  std::optional<MeshDelta> delta;  ///< none: only f's hole flag changes
};

/// Plans opening f: the refusal, or (with `planned`) the result and the edited copy's journal to
/// apply. Without a merge only f's neighbourhood is read; with one, the work is done on a copy.
Verdict plan_open_face(const HalfedgeMesh& mesh, Face f, OpenFacePlan* planned) {
  if (Verdict v = detail::exists(mesh, f, "open-face"); !v) return v;
  if (mesh.is_hole(f))
    return Verdict::refused(fmt::format("open-face: face {} is a hole already", f.idx + 1));
  const std::vector<Halfedge> loop = mesh.face_loop(f);
  const bool merges = std::any_of(loop.begin(), loop.end(), [&](Halfedge h) {
    return mesh.is_hole(HalfedgeMesh::twin(h)) || mesh.face(HalfedgeMesh::twin(h)) == f;
  });
  auto refuse_slit = [&](int degree) {
    return Verdict::refused(fmt::format(
        "open-face: opening face {} would leave a hole of {} sides, a slit that a written file "
        "cannot tell from a closed seam",
        f.idx + 1, degree));
  };
  auto refuse_pinch = [&](Vertex v) {
    return Verdict::refused(
        fmt::format("open-face: the boundary would pass through vertex {} twice: {}", v.idx + 1,
                    pinch_reason(mesh, f, v)));
  };
  auto refuse_beside = [&](Vertex a, Vertex b) {
    return Verdict::refused(fmt::format(
        "open-face: vertices {} and {} are joined by more than one edge, and opening face {} "
        "would put one of them on the boundary, which would not read back ({})",
        a.idx + 1, b.idx + 1, f.idx + 1, detail::kBesideBoundary));
  };

  if (!merges) {
    // Only f's flag changes, so its own neighbourhood says everything (and the modeler does not
    // pay for a copy of the mesh).
    if (loop.size() < 3) return refuse_slit(static_cast<int>(loop.size()));
    for (Halfedge h : loop) {
      int corners_of_f = 0;
      for (Halfedge c : mesh.vertex_fan(mesh.origin(h))) corners_of_f += mesh.face(c) == f;
      if (hole_corners(mesh, mesh.origin(h)) + corners_of_f > 1)
        return refuse_pinch(mesh.origin(h));
    }
    for (Halfedge h : loop)
      if (detail::edges_between(mesh, mesh.origin(h), mesh.target(h)).size() > 1)
        return refuse_beside(mesh.origin(h), mesh.target(h));
    if (planned) planned->result.holes = {f};
    return {};
  }

  // Worked on a copy, as delete_face: the original changes only once the result is valid.
  HalfedgeMesh m = mesh;
  MeshJournal journal(m);
  OpenFaceResult result;
  m.set_hole(f, true);
  std::vector<std::uint8_t> gone(m.edge_capacity(), 0);
  for (Halfedge h : loop)
    if (m.is_hole(HalfedgeMesh::twin(h))) gone[HalfedgeMesh::edge(h).idx] = 1;
  const detail::EdgeRemoval plan = detail::plan_edge_removal(m, std::move(gone));
  if (plan.kept.empty())
    return Verdict::refused(fmt::format(
        "open-face: opening face {} would leave no surface (every other face is a hole)",
        f.idx + 1));
  for (int g : plan.touched_faces)
    if (g != f.idx) result.merged.emplace_back(g);
  for (Edge e : m.edges()) result.removed_edges += plan.gone[e.idx];
  const int vertices_before = m.num_vertices();
  result.holes = detail::remove_edges(m, plan);
  result.removed_vertices = vertices_before - m.num_vertices();
  // The edges of f's component all went: it was f and holes only.
  if (result.holes.empty())
    return Verdict::refused(fmt::format(
        "open-face: opening face {} would leave no surface in its component (every other face "
        "of it is a hole)",
        f.idx + 1));
  // A loop beyond the free numbers is a new face, which starts as no hole.
  for (Face h : result.holes) m.set_hole(h, true);

  for (Face h : result.holes)
    if (m.degree(h) < 3) return refuse_slit(m.degree(h));
  for (Halfedge h : loop) {
    const Vertex v = mesh.origin(h);
    if (!m.is_deleted(v) && hole_corners(m, v) > 1) return refuse_pinch(v);
  }
  for (Face h : result.holes)
    for (Halfedge x : m.face_loop(h))
      if (detail::edges_between(m, m.origin(x), m.target(x)).size() > 1)
        return refuse_beside(m.origin(x), m.target(x));
  const auto problems = find_problems(m);
  if (!problems.empty())
    return Verdict::refused(fmt::format(
        "open-face: opening face {} would not give a valid mesh: {}", f.idx + 1, problems.front()));
  if (planned) *planned = {std::move(result), journal.finish()};
  return {};
}

}  // namespace

Verdict can_open_face(const HalfedgeMesh& mesh, Face f) {
  return plan_open_face(mesh, f, nullptr);
}

OpenFaceResult open_face(HalfedgeMesh& mesh, Face f) {
  OpenFacePlan plan;
  plan_open_face(mesh, f, &plan).throw_if_refused();
  if (plan.delta)
    apply_delta(mesh, *plan.delta, true);
  else
    mesh.set_hole(f, true);
  return std::move(plan.result);
}

Verdict can_fill_hole(const HalfedgeMesh& mesh, Face f) {
  if (Verdict v = detail::exists(mesh, f, "fill-hole"); !v) return v;
  if (!mesh.is_hole(f))
    return Verdict::refused(fmt::format("fill-hole: face {} is not a hole", f.idx + 1));
  return {};
}

void fill_hole(HalfedgeMesh& mesh, Face f) {
  can_fill_hole(mesh, f).throw_if_refused();
  mesh.set_hole(f, false);
}

Verdict can_set_crease(const HalfedgeMesh& mesh, Edge e, double sharpness) {
  if (Verdict v = detail::exists(mesh, e, "crease"); !v) return v;
  return sharpness_allowed(sharpness, "crease");
}

void set_crease(HalfedgeMesh& mesh, Edge e, double sharpness) {
  can_set_crease(mesh, e, sharpness).throw_if_refused();
  mesh.set_sharpness(e, sharpness);
}

Verdict can_set_corner(const HalfedgeMesh& mesh, Vertex v, double sharpness) {
  if (Verdict x = detail::exists(mesh, v, "corner"); !x) return x;
  return sharpness_allowed(sharpness, "corner");
}

void set_corner(HalfedgeMesh& mesh, Vertex v, double sharpness) {
  can_set_corner(mesh, v, sharpness).throw_if_refused();
  mesh.set_sharpness(v, sharpness);
}

}  // namespace stitch
