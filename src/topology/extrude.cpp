#include "stitch/topology/extrude.hpp"

#include <fmt/format.h>

#include <cmath>

#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/polygon.hpp"
#include "topology/raw_mesh.hpp"

namespace stitch {

Vec3 face_normal(const HalfedgeMesh& mesh, Face f) {
  const Vec3 n = newell_normal(face_points(mesh, f));
  const double len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

Verdict can_extrude_face(const HalfedgeMesh& mesh, Face f, double distance, double scale) {
  if (Verdict v = detail::exists(mesh, f, "extrude-face"); !v) return v;
  if (!std::isfinite(distance))
    return Verdict::refused("extrude-face: the distance must be a finite number");
  if (!std::isfinite(scale) || scale <= 0)
    return Verdict::refused("extrude-face: the scale must be a positive number");
  const Vec3 n = face_normal(mesh, f);
  if (n.isZero())
    return Verdict::refused(
        fmt::format("extrude-face: face {} has no normal (zero area)", f.idx + 1));
  const std::vector<Halfedge> loop = mesh.face_loop(f);
  const int k = static_cast<int>(loop.size());
  // Every corner gets its own new vertex, so a loop that visits a vertex twice would put two
  // new vertices at the same point: a degenerate surface.
  if (const Vertex twice = detail::vertex_visited_twice(mesh, f); twice.valid())
    return Verdict::refused(fmt::format(
        "extrude-face: face {} visits vertex {} twice (its loop touches itself); its extruded "
        "top would have two vertices at the same point",
        f.idx + 1, twice.idx + 1));
  // Checked before the mesh changes, so a refused extrusion leaves it as it was.
  const Vec3 centre = detail::face_centroid(mesh, f);
  for (int i = 0; i < k; ++i) {
    const Vec3 p = mesh.position(mesh.origin(loop[i]));
    const Vec3 top = centre + scale * (p - centre) + distance * n;
    if (const std::string problem = limits::coordinate_problem(top); !problem.empty())
      return Verdict::refused(fmt::format("extrude-face: the extruded corner {} of face {} {}",
                                          i + 1, f.idx + 1, problem));
  }
  return {};
}

ExtrudeResult extrude_face(HalfedgeMesh& mesh, Face f, double distance, double scale) {
  can_extrude_face(mesh, f, distance, scale).throw_if_refused();
  const Vec3 n = face_normal(mesh, f);
  const std::vector<Halfedge> loop = mesh.face_loop(f);
  const int k = static_cast<int>(loop.size());

  ExtrudeResult result;
  result.degree = k;
  const Vec3 centre = detail::face_centroid(mesh, f);
  std::vector<Vertex> top(k);
  for (int i = 0; i < k; ++i) {
    const Vec3 p = mesh.position(mesh.origin(loop[i]));
    top[i] = mesh.add_vertex(centre + scale * (p - centre) + distance * n);
    if (i == 0) result.first_vertex = top[i].idx;
  }
  std::vector<Face> side(k);
  for (int i = 0; i < k; ++i) {
    side[i] = mesh.add_face();
    if (i == 0) result.first_face = side[i].idx;
  }
  // up[i]: bottom corner i -> top corner i (its twin runs down); rim[i]: top i -> top i+1.
  std::vector<Halfedge> up(k), rim(k);
  for (int i = 0; i < k; ++i) up[i] = mesh.add_edge(mesh.origin(loop[i]), top[i]);
  for (int i = 0; i < k; ++i) rim[i] = mesh.add_edge(top[i], top[(i + 1) % k]);
  for (int i = 0; i < k; ++i) {
    const int j = (i + 1) % k;
    // Side i: loop[i] (v_i -> v_j), up[j], twin(rim[i]) (w_j -> w_i), twin(up[i]) (w_i -> v_i).
    const Halfedge down_i = HalfedgeMesh::twin(up[i]), rim_back = HalfedgeMesh::twin(rim[i]);
    mesh.link(loop[i], up[j]);
    mesh.link(up[j], rim_back);
    mesh.link(rim_back, down_i);
    mesh.link(down_i, loop[i]);
    mesh.assign_loop(loop[i], side[i]);
    mesh.link(rim[i], rim[j]);
    mesh.set_halfedge(top[i], rim[i]);
  }
  // The top is the face moved: its border keeps the tags it had, and so does the base, which
  // still bounds the faces around. On a hole the top stays the hole: the boundary moves out.
  for (int i = 0; i < k; ++i) {
    mesh.set_sharpness(HalfedgeMesh::edge(rim[i]), mesh.sharpness(HalfedgeMesh::edge(loop[i])));
    mesh.set_sharpness(top[i], mesh.sharpness(mesh.origin(loop[i])));
  }
  mesh.assign_loop(rim[0], f);
  return result;
}

}  // namespace stitch
