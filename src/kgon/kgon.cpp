#include "stitch/kgon/kgon.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <optional>

#include "openings.hpp"
#include "sharp.hpp"
#include "stitch/mesh/polygon.hpp"

namespace stitch {

std::vector<double> doo_sabin_weights(int n) {
  std::vector<double> a(n);
  a[0] = 0.25 + 5.0 / (4.0 * n);
  for (int k = 1; k < n; ++k)
    a[k] = (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * k / n)) / (4.0 * n);
  return a;
}

std::vector<Vec3> doo_sabin_shrink(const std::vector<Vec3>& loop) {
  const int n = static_cast<int>(loop.size());
  const auto a = doo_sabin_weights(n);
  std::vector<Vec3> out(n, Vec3::Zero());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) out[i] += a[((j - i) % n + n) % n] * loop[j];
  return out;
}

namespace {

/// Least-squares plane normal through the centroid, oriented like the loop's winding. The
/// winding decides the side because the smallest-eigenvalue eigenvector has no sign of its own.
Vec3 plane_normal(const std::vector<Vec3>& pts, const Vec3& centroid, const Vec3& orientation) {
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : pts) cov += (p - centroid) * (p - centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  Vec3 n = solver.eigenvectors().col(0);
  if (n.dot(orientation) < 0) n = -n;
  return n;
}

/// Least-squares fit by an affinely regular polygon: the projection of the loop onto its first
/// harmonic (k = +-1), which is what repeated midpoint polygons converge to up to scale. It is
/// convex whatever the input's shape (a star polygon becomes convex).
void regularize(std::vector<Vec3>& pts, const Vec3& c) {
  const int k = static_cast<int>(pts.size());
  if (k < 3) return;
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  for (int j = 0; j < k; ++j) {
    const double t = 2.0 * std::numbers::pi * j / k;
    a += (pts[j] - c) * std::cos(t);
    b += (pts[j] - c) * std::sin(t);
  }
  a *= 2.0 / k;
  b *= 2.0 / k;
  for (int j = 0; j < k; ++j) {
    const double t = 2.0 * std::numbers::pi * j / k;
    pts[j] = c + a * std::cos(t) + b * std::sin(t);
  }
}

void apply_control(Kgon& g, const KgonControl& ctl) {
  if (ctl == KgonControl{}) return;
  if (ctl.regularize) regularize(g.points, g.centroid);
  const Eigen::AngleAxisd rot(ctl.rotate_deg * std::numbers::pi / 180.0, g.normal);
  for (Vec3& p : g.points) p = g.centroid + ctl.scale * (rot * (p - g.centroid)) + ctl.offset;
  g.centroid += ctl.offset;
}

/// Shrinks the polygon over the corner points once more, and flattens it unless K = 4.
Kgon make_kgon(const KgonSet& set, std::vector<Corner> corners, const Vec3& fallback_normal) {
  Kgon g;
  std::vector<Vec3> polygon;
  for (Corner c : corners) polygon.push_back(set.corner_point[c.idx]);
  g.corners = std::move(corners);
  g.points = doo_sabin_shrink(polygon);
  g.centroid = centroid(g.points);
  const Vec3 winding = newell_normal(g.points);
  const int k = g.size();
  if (k == 2) {
    // Two points span no plane: keep them, and take the normal from the faces around.
    g.normal = fallback_normal.norm() > 0 ? fallback_normal.normalized() : Vec3::UnitZ();
    return g;
  }
  g.normal = plane_normal(g.points, g.centroid, winding.norm() > 0 ? winding : fallback_normal);
  if (k != 4)
    for (Vec3& p : g.points) p -= (p - g.centroid).dot(g.normal) * g.normal;
  return g;
}

}  // namespace

namespace {

/// The per-element steps of build_kgons, shared with update_kgons so both give identical K-gons.
/// `normal_of(f)` is face f's Newell normal.
void set_corner_points(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Face f) {
  if (m.is_hole(f)) return;
  if (options.construction == KgonConstruction::openings)
    if (const auto openings = detail::find_two_openings(m, f)) {
      detail::set_opening_corner_points(m, *openings, set.corner_point);
      return;
    }
  const auto loop = m.face_loop(f);
  std::vector<Vec3> pts;
  for (Halfedge h : loop) pts.push_back(m.position(m.origin(h)));
  const auto w = doo_sabin_shrink(pts);
  for (size_t i = 0; i < loop.size(); ++i) set.corner_point[loop[i].idx] = w[i];
}

/// The normal of the faces around a set of corners, for K-gons too small to have a plane.
template <class NormalOf>
Vec3 normal_around(const HalfedgeMesh& m, const std::vector<Corner>& corners, NormalOf& normal_of) {
  Vec3 n = Vec3::Zero();
  for (Corner c : corners) n += normal_of(m.face(c)) + normal_of(m.face(HalfedgeMesh::twin(c)));
  return n;
}

KgonControl control_for(const KgonOptions& options,
                        const std::unordered_map<int, KgonControl>& per_element, int idx, int k) {
  if (auto it = per_element.find(idx); it != per_element.end()) return it->second;
  return k != 4 ? options.global : KgonControl{};
}

template <class NormalOf>
void build_face_kgon(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Face f,
                     NormalOf& normal_of) {
  if (m.is_hole(f)) {
    set.face[f.idx] = Kgon{};
    return;
  }
  auto loop = m.face_loop(f);
  for (size_t i = 0; i < loop.size(); ++i) set.in_face[loop[i].idx] = static_cast<int>(i);
  std::optional<Kgon> placed;
  if (options.construction == KgonConstruction::openings)
    if (const auto openings = detail::find_two_openings(m, f))
      placed = detail::place_tube_kgon(m, f, *openings, set.corner_point);
  const Vec3 fallback = normal_around(m, loop, normal_of);
  Kgon g = placed ? std::move(*placed) : make_kgon(set, std::move(loop), fallback);
  apply_control(g, control_for(options, options.face, f.idx, g.size()));
  set.face[f.idx] = std::move(g);
}

template <class NormalOf>
void build_vertex_kgon(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Vertex v,
                       NormalOf& normal_of) {
  const VertexKind kind = vertex_kind(m, v, options);
  auto fan = m.vertex_fan(v);
  int sharp_spokes = 0;
  for (Halfedge h : fan) sharp_spokes += is_sharp(m, HalfedgeMesh::edge(h), options);
  if (kind == VertexKind::crease || (kind == VertexKind::corner && sharp_spokes >= 2)) {
    // The K-gons of sectors are tied to the sharp curves through the vertex; the user's
    // controls would tear them off, so they do not apply here.
    detail::build_sector_kgons(m, options, kind, v, set);
    return;
  }
  for (size_t i = 0; i < fan.size(); ++i) {
    set.in_vertex[fan[i].idx] = static_cast<int>(i);
    set.vertex_k[fan[i].idx] = static_cast<int>(fan.size());
  }
  const Vec3 fallback = normal_around(m, fan, normal_of);
  Kgon g = make_kgon(set, std::move(fan), fallback);
  apply_control(g, control_for(options, options.vertex, v.idx, g.size()));
  if (kind == VertexKind::corner) {
    // A corner with fewer than two sharp edges has no sectors: the surface passes through the
    // vertex with the whole fan's tangent plane.
    const Vec3 shift = m.position(v) - g.centroid;
    for (Vec3& p : g.points) p += shift;
    g.centroid = m.position(v);
  }
  set.vertex[v.idx] = std::move(g);
  if (sharp_spokes > 0) detail::set_dart_curve(m, options, v, set);
}

template <class NormalOf>
void build_edge_kgon(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Edge e,
                     NormalOf& normal_of) {
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  std::vector<Corner> corners = detail::edge_kgon_corners(m, e);
  set.in_next_edge[h.idx] = 0;
  set.in_prev_edge[m.next(t).idx] = 1;
  set.in_next_edge[t.idx] = 2;
  set.in_prev_edge[m.next(h).idx] = 3;
  const bool sharp = is_sharp(m, e, options);
  if (!set.sharp_edge.empty()) set.sharp_edge[e.idx] = sharp ? 1 : 0;
  if (sharp) {
    set.edge[e.idx] = detail::sharp_edge_kgon(m, e, set);
    return;
  }
  std::optional<Kgon> bridge;
  if (options.construction == KgonConstruction::openings && m.face(h) == m.face(t))
    if (const auto openings = detail::find_two_openings(m, m.face(h)))
      bridge = detail::place_bridge_kgon(m, m.face(h), *openings, corners, set.corner_point);
  Kgon g = bridge ? std::move(*bridge) : make_kgon(set, corners, normal_around(m, {h}, normal_of));
  if (auto it = options.edge.find(e.idx); it != options.edge.end()) apply_control(g, it->second);
  set.edge[e.idx] = std::move(g);
}

}  // namespace

KgonSet build_kgons(const HalfedgeMesh& m, const KgonOptions& options) {
  KgonSet set;
  const int nh = m.halfedge_capacity();
  set.corner_point.assign(nh, Vec3::Zero());
  set.in_face.assign(nh, -1);
  set.in_vertex.assign(nh, -1);
  set.in_next_edge.assign(nh, -1);
  set.in_prev_edge.assign(nh, -1);
  set.vertex_k.assign(nh, 4);
  if (m.has_features()) {
    set.sharp_curve.assign(nh, {Vec3::Zero(), Vec3::Zero()});
    set.cone.assign(nh, 0);
    set.sharp_edge.assign(m.edge_capacity(), 0);
  }
  set.face.resize(m.face_capacity());
  set.vertex.resize(m.vertex_capacity());
  set.edge.resize(m.edge_capacity());

  // Every step writes only its own element's entries (a face's corners, a vertex's fan, an
  // edge's four corners), so each runs over its elements in parallel with the same result.
  const std::vector<Face> faces = m.faces().to_vector();
  const std::vector<Vertex> vertices = m.vertices().to_vector();
  const std::vector<Edge> edges = m.edges().to_vector();
  std::vector<Vec3> face_normal(m.face_capacity(), Vec3::Zero());
  tbb::parallel_for(size_t{0}, faces.size(), [&](size_t i) {
    face_normal[faces[i].idx] = newell_normal(face_points(m, faces[i]));
    set_corner_points(m, options, set, faces[i]);
  });
  auto normal_of = [&](Face f) { return face_normal[f.idx]; };
  tbb::parallel_for(size_t{0}, faces.size(),
                    [&](size_t i) { build_face_kgon(m, options, set, faces[i], normal_of); });
  tbb::parallel_for(size_t{0}, vertices.size(),
                    [&](size_t i) { build_vertex_kgon(m, options, set, vertices[i], normal_of); });
  tbb::parallel_for(size_t{0}, edges.size(),
                    [&](size_t i) { build_edge_kgon(m, options, set, edges[i], normal_of); });
  return set;
}

void update_kgons(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set,
                  const std::vector<Face>& faces, const std::vector<Vertex>& vertices,
                  const std::vector<Edge>& edges) {
  std::unordered_map<int, Vec3> cache;
  auto normal_of = [&](Face f) {
    auto [it, fresh] = cache.try_emplace(f.idx);
    if (fresh) it->second = newell_normal(face_points(m, f));
    return it->second;
  };
  // Sharp curves appear with the first tag an edit makes; arrays grow with the mesh.
  const auto nh = static_cast<size_t>(m.halfedge_capacity());
  if (set.sharp_curve.size() < nh) set.sharp_curve.resize(nh, {Vec3::Zero(), Vec3::Zero()});
  if (set.vertex_k.size() < nh) set.vertex_k.resize(nh, 4);
  if (set.cone.size() < nh) set.cone.resize(nh, 0);
  if (set.sharp_edge.size() < nh / 2) set.sharp_edge.resize(nh / 2, 0);
  for (Face f : faces) set_corner_points(m, options, set, f);
  for (Face f : faces) build_face_kgon(m, options, set, f, normal_of);
  for (Vertex v : vertices) build_vertex_kgon(m, options, set, v, normal_of);
  for (Edge e : edges) build_edge_kgon(m, options, set, e, normal_of);
}

}  // namespace stitch
