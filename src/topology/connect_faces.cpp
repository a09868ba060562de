#include "stitch/topology/connect_faces.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "stitch/mesh/limits.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "topology/raw_mesh.hpp"

namespace stitch {

namespace {

/// Faces f and g as connect-faces needs them: live, distinct, of one degree.
Verdict pair_of_faces(const HalfedgeMesh& mesh, Face f, Face g) {
  for (Face x : {f, g})
    if (Verdict v = detail::exists(mesh, x, "connect-faces"); !v) return v;
  if (f == g) return Verdict::refused(fmt::format("connect-faces: face {} given twice", f.idx + 1));
  if (mesh.degree(g) != mesh.degree(f))
    return Verdict::refused(fmt::format(
        "connect-faces: face {} has {} sides but face {} has {}; they must match (subdivide-edge "
        "or insert-edge first)",
        f.idx + 1, mesh.degree(f), g.idx + 1, mesh.degree(g)));
  return {};
}

/// Twist reduced to 0..k-1 (first, so that twist - i cannot overflow for a twist near INT_MIN).
int reduced(int twist, int k) {
  return (twist % k + k) % k;
}

/// Which corner of g corner i of f is joined to.
int partner_index(int turn, int i, int k) {
  return (turn - i + k) % k;
}

/// The first pair of joined corners at one vertex (its index in f), or -1.
int pair_at_one_vertex(const HalfedgeMesh& mesh, const std::vector<Halfedge>& lf,
                       const std::vector<Halfedge>& lg, int turn) {
  const int k = static_cast<int>(lf.size());
  for (int i = 0; i < k; ++i)
    if (mesh.origin(lf[i]) == mesh.origin(lg[partner_index(turn, i, k)])) return i;
  return -1;
}

Verdict no_loops(const HalfedgeMesh& mesh, Face f, Face g, const std::vector<Halfedge>& lf,
                 const std::vector<Halfedge>& lg, int turn) {
  const int k = static_cast<int>(lf.size());
  if (const int i = pair_at_one_vertex(mesh, lf, lg, turn); i >= 0)
    return Verdict::refused(fmt::format(
        "connect-faces: corner {} of face {} and corner {} of face {} are both vertex {}; the "
        "edge joining them would be a loop",
        i + 1, f.idx + 1, partner_index(turn, i, k) + 1, g.idx + 1, mesh.origin(lf[i]).idx + 1));
  return {};
}

/// The least twist, or the refusal when every twist joins a corner to itself.
std::optional<int> closest_twist(const HalfedgeMesh& mesh, Face f, Face g) {
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  std::optional<int> best;
  double best_sum = std::numeric_limits<double>::infinity();
  for (int turn = 0; turn < k; ++turn) {
    if (pair_at_one_vertex(mesh, lf, lg, turn) >= 0) continue;
    double sum = 0;
    for (int i = 0; i < k; ++i)
      sum += (mesh.position(mesh.origin(lf[i])) -
              mesh.position(mesh.origin(lg[partner_index(turn, i, k)])))
                 .squaredNorm();
    if (sum < best_sum) {
      best_sum = sum;
      best = turn;
    }
  }
  return best;
}

std::string every_twist_loops(Face f, Face g) {
  return fmt::format(
      "connect-faces: every twist joins a corner of face {} to a corner of face {} at the same "
      "vertex (the edge would be a loop)",
      f.idx + 1, g.idx + 1);
}

}  // namespace

int least_twist(const HalfedgeMesh& mesh, Face f, Face g) {
  pair_of_faces(mesh, f, g).throw_if_refused();
  const std::optional<int> best = closest_twist(mesh, f, g);
  if (!best) throw TopologyError(every_twist_loops(f, g));
  return *best;
}

Verdict can_connect_faces(const HalfedgeMesh& mesh, Face f, Face g, int twist) {
  if (Verdict v = pair_of_faces(mesh, f, g); !v) return v;
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  const int turn = reduced(twist, k);
  auto partner = [&](int i) { return lg[partner_index(turn, i, k)]; };
  if (Verdict v = no_loops(mesh, f, g, lf, lg, turn); !v) return v;
  // An edge still on the boundary afterwards (a hole other than f and g on one side) must not get
  // a tube edge beside it.
  auto stays_boundary = [&](Halfedge h) {
    const Face side = mesh.face(h);
    return mesh.is_hole(side) && side != f && side != g;
  };
  for (int i = 0; i < k; ++i) {
    const Vertex u = mesh.origin(lf[i]), v = mesh.origin(partner(i));
    for (Edge y : detail::edges_between(mesh, u, v))
      if (stays_boundary(HalfedgeMesh::halfedge(y, 0)) ||
          stays_boundary(HalfedgeMesh::halfedge(y, 1)))
        return Verdict::refused(fmt::format(
            "connect-faces: vertices {} and {} are joined by boundary edge {}; a tube edge beside "
            "it would not read back ({})",
            u.idx + 1, v.idx + 1, y.idx + 1, detail::kBesideBoundary));
  }
  return {};
}

ConnectFacesResult connect_faces(HalfedgeMesh& mesh, Face f, Face g, int twist) {
  can_connect_faces(mesh, f, g, twist).throw_if_refused();
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  const int turn = reduced(twist, k);
  auto partner = [&](int i) { return lg[partner_index(turn, i, k)]; };

  ConnectFacesResult result;
  result.degree = k;
  result.twist = turn;
  // Both faces are removed, so a hole given is closed by the tube (bridging boundary loops);
  // the quads are surface, which insert_edge only builds between surface faces.
  mesh.set_hole(f, false);
  mesh.set_hole(g, false);
  // Checked above: none of these insertions can be refused, so the mesh is never left half-done.
  for (int i = 0; i < k; ++i) {
    const InsertEdgeResult r = insert_edge(mesh, lf[i], partner(i));
    if (i == 0) result.first_edge = r.edge.idx;
  }
  return result;
}

namespace {

/// The Hermite path of a handle and the rings along it (connect_faces with HandleOptions).
struct HandlePath {
  Vec3 start, end, leave, arrive;  ///< centroids; tangents at each end (length: their distance)

  [[nodiscard]] Vec3 at(double t) const {
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * start + (t3 - 2 * t2 + t) * leave + (-2 * t3 + 3 * t2) * end +
           (t3 - t2) * arrive;
  }
  [[nodiscard]] Vec3 tangent(double t) const {
    const double t2 = t * t;
    return (6 * t2 - 6 * t) * start + (3 * t2 - 4 * t + 1) * leave + (-6 * t2 + 6 * t) * end +
           (3 * t2 - 2 * t) * arrive;
  }
};

/// Ring positions for t = j / segments, j = 1..segments-1: ring j - 1 holds one point per corner
/// of f (in f's loop order).
Verdict handle_rings(const HalfedgeMesh& mesh, Face f, Face g, int turn,
                     const HandleOptions& options, std::vector<std::vector<Vec3>>& rings) {
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  const int k = static_cast<int>(lf.size());
  HandlePath path;
  path.start = detail::face_centroid(mesh, f);
  path.end = detail::face_centroid(mesh, g);
  const Vec3 across = path.end - path.start;
  const double length = across.norm();
  if (!(length > 0))
    return Verdict::refused(fmt::format(
        "connect-faces: faces {} and {} have the same centroid; a handle needs a path between them",
        f.idx + 1, g.idx + 1));
  const Vec3 nf = face_normal(mesh, f), ng = face_normal(mesh, g);
  if (nf.isZero() || ng.isZero())
    return Verdict::refused(fmt::format("connect-faces: face {} has no normal (zero area)",
                                        (nf.isZero() ? f : g).idx + 1));
  // Each end leaves towards the other face's side of it: into the solid between faces facing
  // away from each other, across the gap between faces facing each other.
  path.leave = (nf.dot(across) < 0 ? -nf : nf) * length;
  path.arrive = (ng.dot(across) > 0 ? ng : -ng) * length;
  const Vec3 leave_dir = path.leave.normalized(), arrive_dir = path.arrive.normalized();
  for (int j = 1; j < options.segments; ++j) {
    const double t = static_cast<double>(j) / options.segments;
    const Vec3 direction = path.tangent(t).normalized();
    const Eigen::Quaterniond turn_f = Eigen::Quaterniond::FromTwoVectors(leave_dir, direction);
    const Eigen::Quaterniond turn_g = Eigen::Quaterniond::FromTwoVectors(arrive_dir, direction);
    const double scale = 1 - (1 - options.waist) * 4 * t * (1 - t);
    const Vec3 centre = path.at(t);
    // Each pair's offsets about the path, turned to this ring's direction; the tube turns from
    // one to the other by their mean angle about the path (a twisted tube's rings turn, rather
    // than shrink through the middle, as a straight blend of opposite corners would).
    std::vector<Vec3> from(k), to(k);
    double across_sum = 0, along_sum = 0;
    for (int i = 0; i < k; ++i) {
      from[i] = turn_f * Vec3(mesh.position(mesh.origin(lf[i])) - path.start);
      to[i] = turn_g * Vec3(mesh.position(mesh.origin(lg[partner_index(turn, i, k)])) - path.end);
      across_sum += from[i].cross(to[i]).dot(direction);
      along_sum += from[i].dot(to[i]);
    }
    const double angle = std::atan2(across_sum, along_sum);
    const Eigen::AngleAxisd forward(t * angle, direction), back(-(1 - t) * angle, direction);
    std::vector<Vec3> ring;
    for (int i = 0; i < k; ++i) {
      ring.push_back(centre + scale * ((1 - t) * (forward * from[i]) + t * (back * to[i])));
      if (const std::string problem = limits::coordinate_problem(ring.back()); !problem.empty())
        return Verdict::refused(fmt::format("connect-faces: ring {} of the handle {}", j, problem));
    }
    rings.push_back(std::move(ring));
  }
  return {};
}

/// Everything a handle can be refused for, checked before the first change: the refusal, or the
/// twist and the rings between the faces.
Verdict plan_handle(const HalfedgeMesh& mesh, Face f, Face g, const HandleOptions& options,
                    int& turn, std::vector<std::vector<Vec3>>& rings) {
  if (Verdict v = pair_of_faces(mesh, f, g); !v) return v;
  const int k = mesh.degree(f);
  if (options.segments < 1)
    return Verdict::refused(
        fmt::format("connect-faces: needs at least 1 segment, got {}", options.segments));
  if (!std::isfinite(options.waist) || options.waist <= 0)
    return Verdict::refused("connect-faces: the waist must be a positive number");
  if (options.twist) {
    turn = reduced(*options.twist, k);
  } else if (const std::optional<int> best = closest_twist(mesh, f, g)) {
    turn = *best;
  } else {
    return Verdict::refused(every_twist_loops(f, g));
  }
  if (options.segments == 1) return can_connect_faces(mesh, f, g, turn);
  const std::vector<Halfedge> lf = mesh.face_loop(f), lg = mesh.face_loop(g);
  if (Verdict v = no_loops(mesh, f, g, lf, lg, turn); !v) return v;
  if (const Vertex twice = detail::vertex_visited_twice(mesh, f); twice.valid())
    return Verdict::refused(
        fmt::format("connect-faces: face {} visits vertex {} twice; a handle with segments starts "
                    "from one new vertex per corner",
                    f.idx + 1, twice.idx + 1));
  return handle_rings(mesh, f, g, turn, options, rings);
}

}  // namespace

Verdict can_connect_faces(const HalfedgeMesh& mesh, Face f, Face g, const HandleOptions& options) {
  int turn = 0;
  std::vector<std::vector<Vec3>> rings;
  return plan_handle(mesh, f, g, options, turn, rings);
}

ConnectFacesResult connect_faces(HalfedgeMesh& mesh, Face f, Face g, const HandleOptions& options) {
  int turn = 0;
  std::vector<std::vector<Vec3>> rings;
  plan_handle(mesh, f, g, options, turn, rings).throw_if_refused();
  if (options.segments == 1) return connect_faces(mesh, f, g, turn);
  const int k = mesh.degree(f);
  for (const std::vector<Vec3>& ring : rings) {
    const ExtrudeResult r = extrude_face(mesh, f, 0.0);
    for (int i = 0; i < k; ++i) {
      const Vertex v(r.first_vertex + i);
      mesh.position(v) = ring[i];
      mesh.set_sharpness(v, 0);
    }
    // The ring is inside the tube: smooth, whatever the face's border was tagged.
    for (Halfedge h : mesh.face_loop(f)) mesh.set_sharpness(HalfedgeMesh::edge(h), 0);
  }
  // The top's corner i stands over f's corner i, so the same twist joins it to g.
  return connect_faces(mesh, f, g, turn);
}

}  // namespace stitch
