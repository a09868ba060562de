#include "stitch/topology/delete_face.hpp"

#include <fmt/format.h>

#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/mesh/validate.hpp"
#include "topology/raw_mesh.hpp"

namespace stitch {

namespace {

/// Plans deleting f: the refusal, or (with `delta`) the edited copy's journal to apply.
Verdict plan_delete_face(const HalfedgeMesh& mesh, Face f, MeshDelta* delta) {
  if (Verdict v = detail::exists(mesh, f, "delete-face"); !v) return v;
  // Merging a hole with its neighbours would leave one loop that is partly boundary and partly
  // surface: neither a hole nor a face says it, so the user picks (fill-hole or open-face).
  if (mesh.is_hole(f))
    return Verdict::refused(fmt::format(
        "delete-face: face {} is a hole (a boundary loop of the surface); fill-hole {} makes it a "
        "face first",
        f.idx + 1, f.idx + 1));
  // Worked on a copy: the original changes only once the result is known to be valid, and then
  // only in the elements the copy's journal says were touched.
  HalfedgeMesh m = mesh;
  MeshJournal journal(m);
  std::vector<std::uint8_t> gone(m.edge_capacity(), 0);
  for (Halfedge h : m.face_loop(f)) gone[HalfedgeMesh::edge(h).idx] = 1;
  const detail::EdgeRemoval plan = detail::plan_edge_removal(m, std::move(gone));
  if (plan.kept.empty())
    return Verdict::refused(
        fmt::format("delete-face: deleting face {} would leave nothing", f.idx + 1));
  for (int g : plan.touched_faces)
    if (m.is_hole(Face(g)))
      return Verdict::refused(fmt::format(
          "delete-face: face {} borders hole {} (the surface's boundary); deleting it would merge "
          "the hole with the faces around it (open-face {} makes face {} part of the hole)",
          f.idx + 1, g + 1, f.idx + 1, f.idx + 1));
  detail::remove_edges(m, plan);
  const auto problems = find_problems(m);
  if (!problems.empty())
    return Verdict::refused(
        fmt::format("delete-face: deleting face {} would not give a valid mesh: {}", f.idx + 1,
                    problems.front()));
  if (delta) *delta = journal.finish();
  return {};
}

}  // namespace

Verdict can_delete_face(const HalfedgeMesh& mesh, Face f) {
  return plan_delete_face(mesh, f, nullptr);
}

void delete_face(HalfedgeMesh& mesh, Face f) {
  MeshDelta delta;
  plan_delete_face(mesh, f, &delta).throw_if_refused();
  apply_delta(mesh, delta, true);
}

}  // namespace stitch
