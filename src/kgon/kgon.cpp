#include "stitch/kgon/kgon.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "kgon/openings.hpp"
#include "kgon/sharp.hpp"
#include "stitch/kgon/kgon_topology.hpp"
#include "stitch/mesh/polygon.hpp"
#include "support/fresh_storage.hpp"

namespace stitch {

ChoiceTable<KgonConstruction> kgon_construction_table() {
  static constexpr Choice<KgonConstruction> kConstructions[] = {
      {"openings", KgonConstruction::openings,
       "faces made by inserting an edge between two faces get a K-gon on the wall of the tube "
       "between their openings (docs/method.md)"},
      {"doo-sabin", KgonConstruction::doo_sabin,
       "section 2 of the method as it stands for every face"},
  };
  return kConstructions;
}

ChoiceTable<BoundaryInterpolation> boundary_table() {
  static constexpr Choice<BoundaryInterpolation> kRules[] = {
      {"edge-and-corner", BoundaryInterpolation::edge_and_corner,
       "boundary vertices with one face are corners the surface passes through (OpenSubdiv's "
       "default)"},
      {"edge-only", BoundaryInterpolation::edge_only,
       "boundary vertices with one face lie on the smooth boundary curve"},
  };
  return kRules;
}

std::vector<double> doo_sabin_weights(int n) {
  std::vector<double> a(n);
  a[0] = 0.25 + 5.0 / (4.0 * n);
  for (int k = 1; k < n; ++k)
    a[k] = (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * k / n)) / (4.0 * n);
  return a;
}

namespace {

/// Point i of the Doo-Sabin shrink of the n points point(0..n-1) with weights a, handed to
/// out(i, point). Every path sums in this one order, so every path gets the same bits.
template <class PointAt, class Out>
void shrink(int n, const double* a, PointAt point, Out out) {
  for (int i = 0; i < n; ++i) {
    Vec3 sum = Vec3::Zero();
    // a[(j - i) mod n] for j = 0, 1, ..., n - 1, without a division per term.
    for (int j = 0, w = (n - i) % n; j < n; ++j, w = w + 1 == n ? 0 : w + 1) sum += a[w] * point(j);
    out(i, sum);
  }
}

/// newell_normal of the k points point(0..k-1), in its order, without a list of them.
template <class PointAt>
Vec3 newell_normal_of(int k, PointAt point) {
  Vec3 n = Vec3::Zero();
  for (int i = 0; i < k; ++i) n += point(i).cross(point((i + 1) % k));
  return n;
}

using WeightTable = std::vector<std::vector<double>>;

/// Makes table[k] hold doo_sabin_weights(k).
void cover(WeightTable& table, int k) {
  for (int n = static_cast<int>(table.size()); n <= k; ++n)
    table.push_back(n > 0 ? doo_sabin_weights(n) : std::vector<double>{});
}

}  // namespace

std::vector<Vec3> doo_sabin_shrink(const std::vector<Vec3>& loop) {
  const int n = static_cast<int>(loop.size());
  const auto a = doo_sabin_weights(n);
  std::vector<Vec3> out(n);
  shrink(
      n, a.data(), [&](int j) -> const Vec3& { return loop[j]; },
      [&](int i, const Vec3& p) { out[i] = p; });
  return out;
}

namespace {

/// Least-squares plane normal through the centroid, oriented like the loop's winding. The
/// winding decides the side because the smallest-eigenvalue eigenvector has no sign of its own.
Vec3 plane_normal(std::span<const Vec3> pts, const Vec3& centroid, const Vec3& orientation) {
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
void regularize(std::span<Vec3> pts, const Vec3& c) {
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

/// Whether every corner of g turns counter-clockwise about its normal from the one before,
/// seen from its centroid, by less than half a turn.
bool star_shaped(const Kgon& g) {
  const int k = g.size();
  for (int i = 0; i < k; ++i) {
    const Vec3 a = g.points[i] - g.centroid, b = g.points[(i + 1) % k] - g.centroid;
    if (!(a.cross(b).dot(g.normal) > 0)) return false;
  }
  return true;
}

void apply_control(Kgon& g, const KgonControl& ctl) {
  if (ctl == KgonControl{}) return;
  if (ctl.regularize) regularize(g.points, g.centroid);
  const Eigen::AngleAxisd rot(ctl.rotate_deg * std::numbers::pi / 180.0, g.normal);
  Vec3 along = ctl.stretch_along - ctl.stretch_along.dot(g.normal) * g.normal;
  // Relative to the direction's own length, so that a direction (nearly) along the normal
  // stretches nothing rather than an arbitrary in-plane direction left by round-off.
  const bool stretched = ctl.stretch != 1 && along.norm() > 1e-9 * ctl.stretch_along.norm();
  if (stretched) along.normalize();
  for (Vec3& p : g.points) {
    Vec3 q = ctl.scale * (rot * (p - g.centroid));
    if (stretched) q += (ctl.stretch - 1) * q.dot(along) * along;
    p = g.centroid + q + ctl.offset;
  }
  g.centroid += ctl.offset;
}

/// Shrinks the polygon over the corner points of g's corners once more into g's points (weights
/// for its K), and flattens it unless K = 4.
void shape_kgon(Kgon& g, const std::vector<Vec3>& corner_point, const std::vector<double>& weights,
                const Vec3& fallback_normal) {
  const int k = static_cast<int>(g.corners.size());
  g.points.resize(k);
  shrink(
      k, weights.data(), [&](int j) -> const Vec3& { return corner_point[g.corners[j].idx]; },
      [&](int i, const Vec3& p) { g.points[i] = p; });
  g.centroid = centroid(g.points);
  const Vec3 winding = newell_normal(g.points);
  if (k == 2) {
    // Two points span no plane: keep them, and take the normal from the faces around.
    g.normal = fallback_normal.norm() > 0 ? fallback_normal.normalized() : Vec3::UnitZ();
    return;
  }
  if (k == 4 || (k == 3 && winding.norm() > 0)) {
    // No plane is fitted. A 4-gon is not flattened (edge 4-gons are skew): its normal only
    // orients rotations and displays, and the eigen-solve of the fit was most of the surface
    // build on a quad mesh; the Newell normal is the fit's normal for a planar 4-gon. Three
    // points that span a plane lie in it: the fit's normal is their Newell normal, and flattening
    // would move them by round-off only (the eigen-solve was a quarter of the surface build on a
    // triangle mesh).
    const Vec3 n = winding.norm() > 0 ? winding : fallback_normal;
    g.normal = n.norm() > 0 ? n.normalized() : Vec3::UnitZ();
    return;
  }
  g.normal = plane_normal(g.points, g.centroid, winding.norm() > 0 ? winding : fallback_normal);
  for (Vec3& p : g.points) p -= (p - g.centroid).dot(g.normal) * g.normal;
}

// Each element's K-gon in two steps: prepare_* writes what connectivity, tags and options decide
// (corners, per-corner indices), place_* what positions decide. build_kgons runs every prepare
// once and then every place (place_kgons alone when only positions changed); update_kgons runs
// both per listed element. Either way each element goes through the same code.

void prepare_face(const HalfedgeMesh& m, KgonSet& set, Face f) {
  if (m.is_hole(f)) {
    set.face[f.idx] = Kgon{};
    return;
  }
  Kgon& g = set.face[f.idx];
  g.corners = m.face_loop(f);
  for (size_t i = 0; i < g.corners.size(); ++i) set.in_face[g.corners[i].idx] = static_cast<int>(i);
}

struct VertexTopology {
  VertexKind kind = VertexKind::smooth;
  int sharp_spokes = 0;
  /// The K-gons of sectors are tied to the sharp curves through the vertex and made whole from
  /// the points (detail::build_sector_kgons); the user's controls would tear them off.
  [[nodiscard]] bool by_sectors() const {
    return kind == VertexKind::crease || (kind == VertexKind::corner && sharp_spokes >= 2);
  }
};

VertexTopology prepare_vertex(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set,
                              Vertex v) {
  VertexTopology t;
  t.kind = vertex_kind(m, v, options);
  auto fan = m.vertex_fan(v);
  for (Halfedge h : fan) t.sharp_spokes += is_sharp(m, HalfedgeMesh::edge(h), options);
  if (t.by_sectors()) return t;
  for (size_t i = 0; i < fan.size(); ++i) {
    set.in_vertex[fan[i].idx] = static_cast<int>(i);
    set.vertex_k[fan[i].idx] = static_cast<int>(fan.size());
  }
  set.vertex[v.idx].corners = std::move(fan);
  return t;
}

/// Returns whether the edge is sharp.
bool prepare_edge(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Edge e) {
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  set.edge[e.idx].corners = detail::edge_kgon_corners(m, e);
  set.in_next_edge[h.idx] = 0;
  set.in_prev_edge[m.next(t).idx] = 1;
  set.in_next_edge[t.idx] = 2;
  set.in_prev_edge[m.next(h).idx] = 3;
  const bool sharp = is_sharp(m, e, options);
  if (!set.sharp_edge.empty()) set.sharp_edge[e.idx] = sharp ? 1 : 0;
  return sharp;
}

/// The positions of the corners of face f (prepared), in loop order.
auto corner_positions(const HalfedgeMesh& m, std::span<const Corner> loop) {
  return [&m, loop](int i) -> const Vec3& { return m.position(m.origin(loop[i])); };
}

/// Face f's Newell normal.
Vec3 face_normal(const HalfedgeMesh& m, const KgonSet& set, Face f) {
  // A hole has no K-gon to hold its loop; holes are few.
  if (m.is_hole(f)) return newell_normal(face_points(m, f));
  const auto& loop = set.face[f.idx].corners;
  return newell_normal_of(static_cast<int>(loop.size()), corner_positions(m, loop));
}

void place_corner_points(const HalfedgeMesh& m, KgonSet& set, Face f, const TwoOpenings* openings,
                         const WeightTable& weights) {
  if (m.is_hole(f)) return;
  if (openings) {
    detail::set_opening_corner_points(m, *openings, set.corner_point);
    detail::slide_acute_sides(m, *openings, set.corner_point);
    return;
  }
  const auto& loop = set.face[f.idx].corners;
  const int n = static_cast<int>(loop.size());
  shrink(n, weights[n].data(), corner_positions(m, loop),
         [&](int i, const Vec3& p) { set.corner_point[loop[i].idx] = p; });
}

/// The normal of the faces around a set of corners, for K-gons too small to have a plane.
template <class NormalOf>
Vec3 normal_around(const HalfedgeMesh& m, std::span<const Corner> corners, NormalOf& normal_of) {
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
void place_face(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Face f,
                const TwoOpenings* openings, const WeightTable& weights, NormalOf& normal_of) {
  if (m.is_hole(f)) return;
  Kgon& g = set.face[f.idx];
  std::optional<Kgon> placed;
  if (openings) placed = detail::place_tube_kgon(m, f, *openings, set.corner_point);
  if (placed) {
    g = std::move(*placed);
  } else {
    shape_kgon(g, set.corner_point, weights[g.corners.size()],
               normal_around(m, g.corners, normal_of));
    if (openings && !star_shaped(g)) {
      // Section 2's shrink of the rims' own corner points can wind back on itself (two faces
      // that share an edge, method.md): its fan of patches then folds at the face's centre.
      // Where the bridge starts at an end of the shared edge, the bent tube's K-gon is taken;
      // elsewhere the nearest affinely regular polygon in the plane, when it turns the same way.
      std::optional<Kgon> other =
          detail::place_pinched_tube_kgon(m, f, *openings, set.corner_point);
      if (!other) {
        other = g;
        regularize(other->points, other->centroid);
      }
      if (star_shaped(*other)) g = std::move(*other);
    }
  }
  apply_control(g, control_for(options, options.face, f.idx, g.size()));
}

template <class NormalOf>
void place_vertex(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Vertex v,
                  VertexTopology t, const WeightTable& weights, NormalOf& normal_of) {
  if (t.by_sectors()) {
    detail::build_sector_kgons(m, options, t.kind, v, set);
    return;
  }
  Kgon& g = set.vertex[v.idx];
  shape_kgon(g, set.corner_point, weights[g.corners.size()],
             normal_around(m, g.corners, normal_of));
  apply_control(g, control_for(options, options.vertex, v.idx, g.size()));
  if (t.kind == VertexKind::corner) {
    // A corner with fewer than two sharp edges has no sectors: the surface passes through the
    // vertex with the whole fan's tangent plane.
    const Vec3 shift = m.position(v) - g.centroid;
    for (Vec3& p : g.points) p += shift;
    g.centroid = m.position(v);
    if (t.sharp_spokes > 0) detail::turn_to_corner_curve(m, options, v, g, set);
  } else if (t.sharp_spokes > 0) {
    detail::set_dart_curve(m, options, v, set);
  }
}

/// `bridge_openings`: the openings of the face on both sides of e, if it is one.
template <class NormalOf>
void place_edge(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& set, Edge e, bool sharp,
                const TwoOpenings* bridge_openings, const WeightTable& weights,
                NormalOf& normal_of) {
  if (sharp) {
    set.edge[e.idx] = detail::sharp_edge_kgon(m, e, set);
    return;
  }
  const Halfedge h = HalfedgeMesh::halfedge(e, 0);
  Kgon& g = set.edge[e.idx];
  std::optional<Kgon> bridge;
  if (bridge_openings)
    bridge = detail::place_bridge_kgon(m, m.face(h), *bridge_openings, g.corners.to_vector(),
                                       set.corner_point);
  if (bridge)
    g = std::move(*bridge);
  else
    shape_kgon(g, set.corner_point, weights[4], normal_around(m, {&h, 1}, normal_of));
  if (auto it = options.edge.find(e.idx); it != options.edge.end()) apply_control(g, it->second);
}

/// The face whose openings the bridge e joins, if e runs twice along one face's loop.
Face bridged_face(const HalfedgeMesh& m, Edge e) {
  const Halfedge h = HalfedgeMesh::halfedge(e, 0);
  return m.face(h) == m.face(HalfedgeMesh::twin(h)) ? m.face(h) : Face();
}

}  // namespace

std::optional<TwoOpenings> two_openings(const HalfedgeMesh& m, Face f, const KgonOptions& options) {
  if (options.construction != KgonConstruction::openings || m.is_hole(f)) return std::nullopt;
  return detail::find_two_openings(m, f);
}

bool KgonTopology::fits(const HalfedgeMesh& mesh, const KgonOptions& options) const {
  return construction == options.construction && boundary == options.boundary &&
         sharp_from == options.sharp_from &&
         static_cast<int>(skeleton.corner_point.size()) == mesh.halfedge_capacity() &&
         static_cast<int>(skeleton.face.size()) == mesh.face_capacity() &&
         static_cast<int>(skeleton.vertex.size()) == mesh.vertex_capacity() &&
         static_cast<int>(skeleton.edge.size()) == mesh.edge_capacity();
}

namespace {

/// prepare_kgons into t, whose skeleton's storage is reused where it is large enough.
void prepare_into(const HalfedgeMesh& m, const KgonOptions& options, KgonTopology& t) {
  t.construction = options.construction;
  t.boundary = options.boundary;
  t.sharp_from = options.sharp_from;
  KgonSet& set = t.skeleton;
  const auto nh = static_cast<size_t>(m.halfedge_capacity());
  detail::assign_for_overwrite(set.corner_point, nh, Vec3(Vec3::Zero()));
  detail::assign_for_overwrite(set.in_face, nh, -1);
  detail::assign_for_overwrite(set.in_vertex, nh, -1);
  detail::assign_for_overwrite(set.in_next_edge, nh, -1);
  detail::assign_for_overwrite(set.in_prev_edge, nh, -1);
  detail::assign_for_overwrite(set.vertex_k, nh, 4);
  if (m.has_features()) {
    detail::assign_for_overwrite(set.sharp_curve, nh,
                                 std::array<Vec3, 2>{Vec3::Zero(), Vec3::Zero()});
    detail::assign_for_overwrite(set.cone, nh, std::uint8_t{0});
    detail::assign_for_overwrite(set.sharp_edge, static_cast<size_t>(m.edge_capacity()),
                                 std::uint8_t{0});
  } else {
    set.sharp_curve.clear();
    set.cone.clear();
    set.sharp_edge.clear();
  }
  detail::assign_for_overwrite(set.face, static_cast<size_t>(m.face_capacity()), Kgon{});
  detail::assign_for_overwrite(set.vertex, static_cast<size_t>(m.vertex_capacity()), Kgon{});
  detail::assign_for_overwrite(set.edge, static_cast<size_t>(m.edge_capacity()), Kgon{});
  t.faces = m.faces().to_vector();
  t.vertices = m.vertices().to_vector();
  t.edges = m.edges().to_vector();
  t.openings.resize(m.face_capacity());
  t.vertex_kind.assign(m.vertex_capacity(), VertexKind::smooth);
  t.sharp_spokes.assign(m.vertex_capacity(), 0);
  t.sharp.assign(m.edge_capacity(), 0);

  // Every step writes only its own element's entries (a face's corners, a vertex's fan, an
  // edge's four corners), so each runs over its elements in parallel with the same result.
  tbb::parallel_for(size_t{0}, t.faces.size(), [&](size_t i) {
    prepare_face(m, set, t.faces[i]);
    t.openings[t.faces[i].idx] = two_openings(m, t.faces[i], options);
  });
  tbb::parallel_for(size_t{0}, t.vertices.size(), [&](size_t i) {
    const VertexTopology v = prepare_vertex(m, options, set, t.vertices[i]);
    t.vertex_kind[t.vertices[i].idx] = v.kind;
    t.sharp_spokes[t.vertices[i].idx] = v.sharp_spokes;
  });
  tbb::parallel_for(size_t{0}, t.edges.size(), [&](size_t i) {
    t.sharp[t.edges[i].idx] = prepare_edge(m, options, set, t.edges[i]) ? 1 : 0;
  });
  size_t largest = 4;
  for (Face f : t.faces) largest = std::max(largest, set.face[f.idx].corners.size());
  for (Vertex v : t.vertices) largest = std::max(largest, set.vertex[v.idx].corners.size());
  cover(t.doo_sabin, static_cast<int>(largest));
}

}  // namespace

KgonTopology prepare_kgons(const HalfedgeMesh& m, const KgonOptions& options) {
  KgonTopology t;
  prepare_into(m, options, t);
  return t;
}

void place_kgons(const HalfedgeMesh& m, const KgonOptions& options, const KgonTopology& t,
                 KgonSet& set) {
  auto openings_at = [&](Face f) -> const TwoOpenings* {
    return f.valid() && t.openings[f.idx] ? &*t.openings[f.idx] : nullptr;
  };
  std::vector<Vec3> normals(m.face_capacity(), Vec3::Zero());
  tbb::parallel_for(size_t{0}, t.faces.size(), [&](size_t i) {
    const Face f = t.faces[i];
    normals[f.idx] = face_normal(m, set, f);
    place_corner_points(m, set, f, openings_at(f), t.doo_sabin);
  });
  auto normal_of = [&](Face f) { return normals[f.idx]; };
  tbb::parallel_for(size_t{0}, t.faces.size(), [&](size_t i) {
    place_face(m, options, set, t.faces[i], openings_at(t.faces[i]), t.doo_sabin, normal_of);
  });
  tbb::parallel_for(size_t{0}, t.vertices.size(), [&](size_t i) {
    const Vertex v = t.vertices[i];
    place_vertex(m, options, set, v, {t.vertex_kind[v.idx], t.sharp_spokes[v.idx]}, t.doo_sabin,
                 normal_of);
  });
  tbb::parallel_for(size_t{0}, t.edges.size(), [&](size_t i) {
    const Edge e = t.edges[i];
    place_edge(m, options, set, e, t.sharp[e.idx] != 0, openings_at(bridged_face(m, e)),
               t.doo_sabin, normal_of);
  });
}

KgonSet build_kgons(const HalfedgeMesh& m, const KgonOptions& options) {
  KgonSet set;
  build_kgons(m, options, set);
  return set;
}

void build_kgons(const HalfedgeMesh& m, const KgonOptions& options, KgonSet& into) {
  KgonTopology t;
  t.skeleton = std::move(into);
  prepare_into(m, options, t);
  into = std::move(t.skeleton);  // place_kgons reads the rest of t, not the skeleton
  place_kgons(m, options, t, into);
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
  WeightTable weights;
  cover(weights, 4);
  std::vector<std::optional<TwoOpenings>> openings(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    prepare_face(m, set, faces[i]);
    openings[i] = two_openings(m, faces[i], options);
    cover(weights, static_cast<int>(set.face[faces[i].idx].corners.size()));
  }
  auto at = [](const std::optional<TwoOpenings>& o) { return o ? &*o : nullptr; };
  for (size_t i = 0; i < faces.size(); ++i)
    place_corner_points(m, set, faces[i], at(openings[i]), weights);
  for (size_t i = 0; i < faces.size(); ++i)
    place_face(m, options, set, faces[i], at(openings[i]), weights, normal_of);
  for (Vertex v : vertices) {
    const VertexTopology t = prepare_vertex(m, options, set, v);
    if (!t.by_sectors()) cover(weights, static_cast<int>(set.vertex[v.idx].corners.size()));
    place_vertex(m, options, set, v, t, weights, normal_of);
  }
  for (Edge e : edges) {
    const bool sharp = prepare_edge(m, options, set, e);
    const Face bridged = bridged_face(m, e);
    const auto bridge_openings = bridged.valid() && !sharp ? two_openings(m, bridged, options)
                                                           : std::optional<TwoOpenings>();
    place_edge(m, options, set, e, sharp, at(bridge_openings), weights, normal_of);
  }
}

}  // namespace stitch
