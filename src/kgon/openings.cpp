#include "kgon/openings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "stitch/mesh/polygon.hpp"

namespace stitch::detail {

namespace {

/// The split of f's loop at bridge b1 (b2 its twin) into its two openings; rims that share a
/// vertex are allowed only at the ends of `shared` (an edge the loop also runs along twice, or
/// none). Nothing unless each opening visits its bridge vertex at its two ends and every other
/// vertex once.
std::optional<TwoOpenings> split_at(const HalfedgeMesh& m, Halfedge b1, Edge shared) {
  const Halfedge b2 = HalfedgeMesh::twin(b1);
  TwoOpenings o;
  for (Halfedge h = m.next(b2);; h = m.next(h)) {
    o.first.push_back(h);
    if (h == b1) break;
  }
  for (Halfedge h = m.next(b1);; h = m.next(h)) {
    o.second.push_back(h);
    if (h == b2) break;
  }
  if (o.first.size() < 2 || o.second.size() < 2) return std::nullopt;
  std::vector<int> seen(m.vertex_capacity(), 0);
  Vertex s0, s1;
  if (shared.valid()) {
    const Halfedge hs = HalfedgeMesh::halfedge(shared, 0);
    s0 = m.origin(hs);
    s1 = m.origin(HalfedgeMesh::twin(hs));
  }
  for (const auto* corners : {&o.first, &o.second}) {
    const Vertex bridge_end = m.origin(corners->front());
    if (m.origin(corners->back()) != bridge_end) return std::nullopt;
    std::vector<int> here(m.vertex_capacity(), 0);
    for (size_t i = 1; i < corners->size(); ++i) {
      const Vertex v = m.origin((*corners)[i]);
      if (here[v.idx]++) return std::nullopt;
      if (seen[v.idx]++ && v != s0 && v != s1) return std::nullopt;
    }
  }
  return o;
}

/// How far an opening's rim is from planar: the largest distance of a vertex from the plane
/// through its centroid with its Newell normal, over the rim's size.
double non_planarity(const HalfedgeMesh& m, const std::vector<Corner>& corners) {
  std::vector<Vec3> pts;
  for (size_t i = 0; i + 1 < corners.size(); ++i) pts.push_back(m.position(m.origin(corners[i])));
  const Vec3 c = centroid(pts);
  Vec3 n = newell_normal(pts);
  double size = 0;
  for (const Vec3& p : pts) size = std::max(size, (p - c).norm());
  if (!(n.norm() > 0) || !(size > 0)) return 1;
  n.normalize();
  double d = 0;
  for (const Vec3& p : pts) d = std::max(d, std::abs((p - c).dot(n)));
  return d / size;
}

}  // namespace

std::optional<TwoOpenings> find_two_openings(const HalfedgeMesh& m, Face f) {
  const auto loop = m.face_loop(f);
  std::vector<Halfedge> doubled;
  for (Halfedge h : loop)
    if (m.face(HalfedgeMesh::twin(h)) == f) doubled.push_back(h);
  // One edge twice: the bridge between two separate rims. Anything else (random edits make such
  // faces) is not a tube between two openings, and keeps section 2's K-gon, but for two edges
  // twice (an edge inserted between two faces that share an edge: the loop reads
  // S B S^-1 B^-1): either edge can be taken as the bridge, and the rims then share the other's
  // two vertices. The bridge is the one whose rims are planar (the faces before the merge).
  if (doubled.size() == 2) return split_at(m, doubled[0], Edge());
  if (doubled.size() != 4) return std::nullopt;
  std::optional<TwoOpenings> best;
  double best_score = 0;
  std::vector<Edge> edges;
  for (Halfedge h : doubled) {
    const Edge e = HalfedgeMesh::edge(h);
    if (std::find(edges.begin(), edges.end(), e) == edges.end()) edges.push_back(e);
  }
  if (edges.size() != 2) return std::nullopt;
  for (int i = 0; i < 2; ++i) {
    auto o = split_at(m, HalfedgeMesh::halfedge(edges[i], 0), edges[1 - i]);
    if (!o) continue;
    const double score = non_planarity(m, o->first) + non_planarity(m, o->second);
    if (!best || score < best_score - 1e-9) {
      best = std::move(o);
      best_score = score;
    }
  }
  return best;
}

namespace {

/// How far along the rim's polygon of corner points the bridge vertex's point is split towards
/// the points on either side (set_opening_corner_points).
constexpr double kSplit = 0.6;

}  // namespace

void set_opening_corner_points(const HalfedgeMesh& m, const TwoOpenings& openings,
                               std::vector<Vec3>& corner_point) {
  // An opening's corners run from its bridge vertex around the rim and back to it: n + 1 corners
  // over a rim of n vertices. Every corner but the two at the bridge vertex keeps the point the
  // Doo-Sabin rule gave it over the rim alone (the face before the merge). The bridge vertex's
  // point w0 is split in two along the rim polygon, kSplit of the way towards the points on
  // either side, so that the bridge's edge K-gon keeps a width. (Shrinking the loop with the
  // bridge vertex twice instead weights that vertex double and pushes the whole rim towards it:
  // on a triangle the two points at the bridge vertex then lie as far out as the corner points
  // of the side faces there, the wall between the hole and the outside has no thickness, and
  // every tube through a triangular prism intersected itself.) kSplit is measured, not derived
  // (docs/method.md): from 0.55 to 0.65 every cube and prism tube but prism 6's half twists is
  // clean and open along the axis (measured before place_on_twisted_tube stretched their K-gon); at
  // 0.5 the cube's half twists are clean but off the axis, at 0.7 three of prism 3's tubes are, and
  // at 0.2 or less the twisted tubes fold.
  for (const auto* corners : {&openings.first, &openings.second}) {
    const size_t n = corners->size() - 1;
    std::vector<Vec3> rim;
    for (size_t i = 0; i < n; ++i) rim.push_back(m.position(m.origin((*corners)[i])));
    const auto w = doo_sabin_shrink(rim);
    for (size_t i = 1; i < n; ++i) corner_point[(*corners)[i].idx] = w[i];
    corner_point[corners->front().idx] = w[0] + kSplit * (w[1] - w[0]);
    corner_point[corners->back().idx] = w[0] + kSplit * (w[n - 1] - w[0]);
  }
}

namespace {

struct RimSample {
  Vec3 point, tangent;
};

/// The point halfway along the chain of an opening's corner points, and the chain's direction
/// there: the part of the rim farthest from the bridge. The direction is that of the chord from
/// half a mean segment before the point to half one after it: the segment's own direction when
/// the point is inside a segment of at least the mean length (an odd rim's far edge), and the
/// bisector of the two segments when it is at a corner (an even rim's far corner). Taking the
/// direction of the segment the point falls in, as before, chose one of the two at a corner by
/// rounding: the straight tubes of an even prism, congruent but for rounding, got K-gons in
/// planes a corner step apart (0.08 apart on `prism 8` with one top vertex turned by 1e-12
/// radians), the single fold of `prism 4`'s straight tubes at height 0.5 and of 4 of the
/// elliptic `prism 10`'s came and went with it (method.md, "Uneven rims").
std::optional<RimSample> far_point(const std::vector<Vec3>& chain) {
  double length = 0;
  for (size_t i = 0; i + 1 < chain.size(); ++i) length += (chain[i + 1] - chain[i]).norm();
  if (!(length > 0)) return std::nullopt;
  // The point at arc length s along the chain (clamped to its ends).
  const auto at = [&](double s) {
    for (size_t i = 0; i + 1 < chain.size(); ++i) {
      const Vec3 d = chain[i + 1] - chain[i];
      const double l = d.norm();
      if (l >= s && l > 0) return Vec3(chain[i] + d * (std::max(s, 0.0) / l));
      s -= l;
    }
    return chain.back();
  };
  const double h = length / (2 * static_cast<double>(chain.size() - 1));
  const Vec3 tangent = at(length / 2 + h) - at(length / 2 - h);
  if (!(tangent.norm() > 0)) return std::nullopt;
  return RimSample{at(length / 2), tangent.normalized()};
}

/// The tube between the two openings as a cylinder: its axis runs from the first rim's
/// centroid to the second's; angles are measured around the axis from the first rim's bridge
/// vertex. `twist` is the angle of the second rim's bridge vertex, in (-pi, pi]: the shortest
/// way the bridge can turn around the tube.
struct Tube {
  Vec3 base = Vec3::Zero(), axis = Vec3::UnitZ(), x0 = Vec3::UnitX(), y0 = Vec3::UnitY();
  double length = 1, twist = 0;
  bool hole = true;  ///< openings facing away from each other (else a handle between solids)

  [[nodiscard]] Vec3 radial(double angle) const {
    return std::cos(angle) * x0 + std::sin(angle) * y0;
  }
  [[nodiscard]] Vec3 wall(double angle, double height, double radius) const {
    return base + height * length * axis + radius * radial(angle);
  }
  [[nodiscard]] double radius_of(const Vec3& p) const {
    const Vec3 d = p - base;
    return (d - d.dot(axis) * axis).norm();
  }
  /// The mean radius_of these corners' points.
  [[nodiscard]] double mean_radius(const std::vector<Corner>& corners,
                                   const std::vector<Vec3>& corner_point) const {
    double sum = 0;
    for (Corner c : corners) sum += radius_of(corner_point[c.idx]);
    return sum / static_cast<double>(corners.size());
  }
  [[nodiscard]] double height_of(const Vec3& p) const { return (p - base).dot(axis) / length; }
  /// The surface's normal on the wall: into the tube around a hole, out of it on a handle.
  [[nodiscard]] Vec3 normal(double angle) const { return hole ? -radial(angle) : radial(angle); }
};

/// The openings (rim normals normal_a, normal_b; `across` from the first to the second) face
/// away from each other around a hole through the solid (the surface's outside is the tube's
/// inside): true; towards each other across a handle joining two solids: false; else nothing.
std::optional<bool> hole_between(const Vec3& normal_a, const Vec3& normal_b, const Vec3& across) {
  const double sa = normal_a.dot(across), sb = normal_b.dot(across);
  if (sa < 0 && sb > 0) return true;
  if (sa > 0 && sb < 0) return false;
  return std::nullopt;
}

std::optional<Tube> tube_of(const HalfedgeMesh& m, const TwoOpenings& o) {
  const auto rim_a = rim_points(m, o.first), rim_b = rim_points(m, o.second);
  Tube t;
  t.base = centroid(rim_a);
  const Vec3 across = centroid(rim_b) - t.base;
  t.length = across.norm();
  if (!(t.length > 0)) return std::nullopt;
  t.axis = across / t.length;
  const auto hole = hole_between(newell_normal(rim_a), newell_normal(rim_b), across);
  if (!hole) return std::nullopt;
  t.hole = *hole;
  const Vec3 a = m.position(m.origin(o.first.front())) - t.base;
  const Vec3 ra = a - a.dot(t.axis) * t.axis;
  if (!(ra.norm() > 1e-9 * t.length)) return std::nullopt;
  t.x0 = ra.normalized();
  t.y0 = t.axis.cross(t.x0);
  const Vec3 b = m.position(m.origin(o.second.front())) - t.base;
  t.twist = std::atan2(b.dot(t.y0), b.dot(t.x0));
  return t;
}

/// A twist smaller than this is no twist: the bridge runs along the wall.
constexpr double kNoTwist = 1e-6;

/// The mean number of corners of the two openings' rims (each opening's corners visit its bridge
/// vertex twice). Items 6 to 8 (method.md) apply to rims of more than six.
double rim_corners(const TwoOpenings& o) {
  return static_cast<double>(o.first.size() + o.second.size() - 2) / 2;
}

/// The face K-gon's width across the helix on a twisted tube whose corner points
/// slide_acute_sides moved, as a part of item 6's (place_on_twisted_tube).
constexpr double kSlidWidth = 0.5;

/// How far that face K-gon is turned in its plane the way of the twist on rims of twelve corners
/// and more (place_on_twisted_tube; none up to eight corners, linearly in between). Fitted on
/// prisms 8 to 13 (method.md, item 8).
constexpr double kTwistTurn = 12 * std::numbers::pi / 180;

/// How many times section 2's size the face K-gon of a straight tube whose rims have more than
/// six corners reaches along the tube (place_tube_kgon), as item 6 stretches a twisted one.
constexpr double kStraightAlong = 1.8;

/// A regular K-gon over the face's loop in the plane (centre; e1, e2), e1 pointing from the
/// first opening towards the second, turned so that the middle of the first opening's corners
/// faces that opening. Size: half the mean distance to the corner points, as section 2 gives a
/// regular polygon (each Doo-Sabin shrink halves its first harmonic: corner points at 1/2 of the
/// vertices' radius, K-gon points at 1/4). `turn` turns it further about `normal` (radians,
/// counter-clockwise from e1 towards e2).
Kgon regular_tube_kgon(const std::vector<Halfedge>& loop, const TwoOpenings& openings,
                       const Vec3& centre, const Vec3& normal, const Vec3& e1, const Vec3& e2,
                       const std::vector<Vec3>& corner_point, double turn = 0) {
  const int k = static_cast<int>(loop.size());
  double s = 0, c = 0;
  for (int i = 0; i < k; ++i)
    for (Corner a : openings.first)
      if (loop[i] == a) {
        s += std::sin(2 * std::numbers::pi * i / k);
        c += std::cos(2 * std::numbers::pi * i / k);
      }
  const double phase = std::numbers::pi - std::atan2(s, c) + turn;
  double radius = 0;
  for (Corner cn : loop) radius += (corner_point[cn.idx] - centre).norm();
  radius *= 0.5 / k;
  Kgon g;
  g.corners = loop;
  g.centroid = centre;
  g.normal = normal;
  for (int i = 0; i < k; ++i) {
    const double t = phase + 2 * std::numbers::pi * i / k;
    g.points.push_back(centre + radius * (std::cos(t) * e1 + std::sin(t) * e2));
  }
  return g;
}

/// The face K-gon of a tube that twists, at `centre` on its wall (`normal` the surface's normal
/// there, `radius` the tube's): the regular K-gon of regular_tube_kgon with its axis along
/// `along`, the direction of the curve the bridge stands for carried around the tube to `centre`
/// (the wall, unrolled, is a parallelogram whose sides run along that curve), and with its extent
/// across that direction cut to the tube's radius. A plane touching a cylinder of radius r is
/// sqrt(r^2 + d^2) - r off the wall at a distance d to the side, so K-gon points farther out pull
/// the patches off the wall (the twisted tubes of a triangular prism, K-gon radius 1.4 r, folded).
/// The K-gon is affinely regular and planar. `along_scale` and `across_scale` stretch it further
/// for tubes whose fan has to reach far around, and `turn` turns the regular K-gon before that
/// stretch (place_on_twisted_tube).
Kgon wall_kgon(const std::vector<Halfedge>& loop, const TwoOpenings& openings, const Vec3& centre,
               const Vec3& normal, const Vec3& along, double radius,
               const std::vector<Vec3>& corner_point, double along_scale = 1,
               double across_scale = 1, double turn = 0) {
  const Vec3 e1 = (along - along.dot(normal) * normal).normalized();
  const Vec3 e2 = normal.cross(e1);
  Kgon g = regular_tube_kgon(loop, openings, centre, normal, e1, e2, corner_point, turn);
  const double extent = (g.points[0] - centre).norm();
  const double across = std::min(extent, radius) * across_scale;
  if (along_scale != 1 || across != extent)
    for (Vec3& p : g.points) {
      const Vec3 d = p - centre;
      p += (along_scale - 1) * d.dot(e1) * e1 - (1 - across / extent) * d.dot(e2) * e2;
    }
  return g;
}

/// How far around a tube the face's fan has to reach: the largest angle about the tube from the
/// face K-gon's centre (opposite the middle of the bridge) to the middle of a rim's edge,
/// measured on the face unrolled (between the bridge and its copy a full turn on). `angle_of`
/// gives a point's angle around the tube from the first rim's bridge vertex; the second's is at
/// `twist`.
template <class AngleOf>
double longest_spoke(const HalfedgeMesh& m, double twist, const TwoOpenings& openings,
                     const AngleOf& angle_of) {
  const double centre = std::numbers::pi + twist / 2;
  double longest = 0;
  for (const auto* corners : {&openings.first, &openings.second}) {
    const double bridge = corners == &openings.first ? 0 : twist;
    for (size_t i = 0; i + 1 < corners->size(); ++i) {
      const Vec3 mid =
          0.5 * (m.position(m.origin((*corners)[i])) + m.position(m.origin((*corners)[i + 1])));
      double around = angle_of(mid) - bridge;
      around -= 2 * std::numbers::pi * std::floor(around / (2 * std::numbers::pi));
      longest = std::max(longest, std::abs(bridge + around - centre));
    }
  }
  return longest;
}

/// longest_spoke on a twisted cylinder (angles about its axis).
double longest_spoke(const HalfedgeMesh& m, const Tube& tube, const TwoOpenings& openings) {
  return longest_spoke(m, tube.twist, openings, [&](const Vec3& p) {
    const Vec3 d = p - tube.base;
    return std::atan2(d.dot(tube.y0), d.dot(tube.x0));
  });
}

/// The face K-gon of a twisted tube: wall_kgon on the wall opposite the middle of the bridge's
/// helix, halfway up, along the helix.
std::optional<Kgon> place_on_twisted_tube(const HalfedgeMesh& m, Face f, const Tube& tube,
                                          const TwoOpenings& openings,
                                          const std::vector<Vec3>& corner_point) {
  const auto loop = m.face_loop(f);
  double height_a = 0, height_b = 0;
  for (Corner c : openings.first) height_a += tube.height_of(corner_point[c.idx]);
  for (Corner c : openings.second) height_b += tube.height_of(corner_point[c.idx]);
  height_a /= static_cast<double>(openings.first.size());
  height_b /= static_cast<double>(openings.second.size());
  const double radius = tube.mean_radius(loop, corner_point);
  const double angle = tube.twist / 2 + std::numbers::pi;
  const Vec3 centre = tube.wall(angle, (height_a + height_b) / 2, radius);
  // The helix from the first bridge vertex to the second, at this radius, runs this way at
  // `angle` (towards the second opening).
  const Vec3 along = (height_b - height_a) * tube.length * tube.axis +
                     tube.twist * radius * tube.radial(angle + std::numbers::pi / 2);
  // The fan's spoke to the farthest rim edge leaves the centre in the K-gon's plane and has to
  // reach past the half turn by `overshoot`: seen along the axis, its cubic only passes the far
  // side of the axis if its first control point lies at least r tan(overshoot) around the tube,
  // and the K-gon cut across to r gives about r. The cube's and prism 4's half twists (45 degrees
  // past) are open with the cut as it is, only just; prism 6's (60 degrees) were not. Past 45
  // degrees the K-gon is stretched with tan(overshoot) (measured on prism 6's half twists: clean
  // and open with 1.9 to 2.1 r across and 1.6 to 1.8 times section 2's size along; more across
  // intersects, less leaves the axis blocked or folds). Measured only up to prism 6: prism 8's
  // half twists (67.5 degrees) intersect themselves when stretched by tan(overshoot), and keep
  // that of 60 degrees.
  const double overshoot = longest_spoke(m, tube, openings) - std::numbers::pi;
  double spread = 1;
  if (overshoot > std::numbers::pi / 4 + 1e-9)
    spread = std::min(std::tan(overshoot), std::tan(std::numbers::pi / 3));
  double across = 1 + 1.4 * (spread - 1);
  // Rims of more than six corners (less than 60 degrees between neighbours around the tube)
  // want the K-gon longer along the helix whatever the twist, and narrower across it unless the
  // fan reaches far past the half turn (method.md, item 6; measured on prisms 7 to 10 at
  // resolution 16): 1.8 times section 2's size along; across, 0.8 r for an overshoot up to 40
  // degrees (at 1.8 along, prism 9's three-step twists, 40 degrees, are clean and open only at
  // 0.8 r, prism 10's, 36 degrees, at 0.7 and 0.8 r), 1.8 r from 45 degrees (prism 8's
  // three-step twists, 45 degrees, at 1.7 to 1.9 r; prism 7's, 51.4 degrees, at 1.7 to 2.0 r),
  // linearly in between. Prisms 3 to 6 keep the rule above: 1.8 times along and 1.8 r across
  // fold prism 3's one-step twists, prism 4's half twists and prism 5's two-step twists.
  const double corners = rim_corners(openings);
  double turn = 0;
  if (corners > 6) {
    constexpr double degree = std::numbers::pi / 180;
    const double t = std::clamp((overshoot - 40 * degree) / (5 * degree), 0.0, 1.0);
    across = std::max(0.8 + t, spread > 1 ? across : 0.0);
    spread = std::max(spread, 1.8);
    // slide_acute_sides moves these rims' corner points on the acute sides away from the bridge,
    // and the fan then reaches less far around: half that width (method.md, items 7 and 8;
    // without the turn below, prism 10's half twists were clean and open at resolution 16 with
    // 0.667 and 0.7 of it, and folded 2 pairs each with 0.6 and 0.633, 4 with 0.733, 6 with the
    // full width). Rims of more than eight corners want the K-gon turned in its plane the way of
    // the twist as well (method.md, item 8): without it the patches of the first one or two
    // corners past the bridge on one side of each rim fold next to the face's centre (prism 11's
    // and 12's five-step twists, 12's half twists, at resolution 16). The turn grows from none at
    // eight corners to kTwistTurn at twelve (prism 8's half twists fold from 10 degrees on), and
    // is held there beyond. Measured on every pair of prisms 7 to 12: clean and open with 12
    // degrees at 0.5 of the width and with 14 degrees at 0.55 and 0.6; 14 degrees at 0.633 folds
    // prism 12's five-step twists, 12 and 16 degrees at 0.6 its half twists. 12 degrees at 0.5
    // also cleans prism 13 (14 degrees at 0.5 or 0.6 does not). Both fitted, not derived.
    across *= kSlidWidth;
    turn = kTwistTurn * std::clamp((corners - 8) / 4, 0.0, 1.0) * (tube.twist > 0 ? 1 : -1);
  }
  return wall_kgon(loop, openings, centre, tube.normal(angle), along, radius, corner_point, spread,
                   across, turn);
}

/// The helix a twisted tube's bridge stands for: from the first rim's bridge vertex (angle 0)
/// to the second's (angle twist), at the mean radius and heights of the bridge's corner points.
struct Helix {
  double radius = 0, height_a = 0, height_b = 0;

  /// Its direction (not normalized) at `angle`, from the first end towards the second.
  [[nodiscard]] Vec3 direction(const Tube& tube, double angle) const {
    return (height_b - height_a) * tube.length * tube.axis +
           tube.twist * radius * tube.radial(angle + std::numbers::pi / 2);
  }
  [[nodiscard]] double length(const Tube& tube) const {
    return std::hypot((height_b - height_a) * tube.length, tube.twist * radius);
  }
};

/// The helix of the bridge whose edge K-gon has `corners`; nothing unless two of them are at
/// each end.
std::optional<Helix> helix_of(const HalfedgeMesh& m, const Tube& tube, const TwoOpenings& openings,
                              const std::vector<Corner>& corners,
                              const std::vector<Vec3>& corner_point) {
  Helix helix;
  int na = 0, nb = 0;
  const Vertex a = m.origin(openings.first.front());
  for (Corner c : corners) {
    helix.radius += tube.radius_of(corner_point[c.idx]) / static_cast<double>(corners.size());
    const double h = tube.height_of(corner_point[c.idx]);
    if (m.origin(c) == a) {
      helix.height_a += h;
      ++na;
    } else {
      helix.height_b += h;
      ++nb;
    }
  }
  if (na != 2 || nb != 2) return std::nullopt;
  helix.height_a /= 2;
  helix.height_b /= 2;
  return helix;
}

/// The edge K-gon of a bridge that turns around a tube, as a quad in the wall's tangent plane at
/// `centre`, the middle of the curve the bridge stands for (`along` its direction there, `length`
/// its length; `normal` the wall's normal there and `normal_a`, `normal_b` at the bridge's ends;
/// a = the bridge's vertex on the first rim).
Kgon wall_quad(const HalfedgeMesh& m, const std::vector<Corner>& corners, Vertex a,
               const Vec3& centre, const Vec3& along, const Vec3& normal, const Vec3& normal_a,
               const Vec3& normal_b, double length, double twist,
               const std::vector<Vec3>& corner_point) {
  const Vec3 across = normal.cross(along);
  // Section 2 shrinks the edge's quad of corner points to half its size: its K-gon points sit a
  // quarter of the edge's length from the middle and a quarter of the corner points' spacing to
  // the side; the curve's length and that spacing give the quad here. Along a curve that turns,
  // the straight tangent at the middle leaves the wall, and the curve over the bridge overshoots
  // it: from a half twist of a cube on, a quarter of the helix folds the tube near the bridge's
  // ends (measured: at most 0.3 of a quarter is clean there, 0.35 folds). The reach shrinks from
  // section 2's quarter at no twist to a fifth of it at a half twist.
  const double reach = 1 - 0.8 * std::abs(twist) / std::numbers::pi;
  double width = 0;
  for (int i = 0; i < 4; i += 2)
    width += (corner_point[corners[i].idx] - corner_point[corners[i + 1].idx]).norm() / 2;
  Kgon g;
  g.corners = corners;
  g.centroid = centre;
  g.normal = normal;
  for (Corner c : corners) {
    const bool at_a = m.origin(c) == a;
    // The side of the bridge the corner's face region lies on: its corner point against the
    // other corner point at the same end.
    Corner other = c;
    for (Corner d : corners)
      if (d != c && m.origin(d) == m.origin(c)) other = d;
    const double side = (corner_point[c.idx] - corner_point[other.idx])
                                    .dot((at_a ? normal_a : normal_b).cross(along)) >= 0
                            ? 1.0
                            : -1.0;
    g.points.push_back(centre + (at_a ? -0.25 : 0.25) * reach * length * along +
                       side * 0.25 * width * across);
  }
  return g;
}

/// A bent tunnel: the tube between two openings that face different ways (two faces that share
/// no vertex and are not opposite each other) modelled as a section of a torus. Its centre line is
/// the circular arc that leaves the first rim's centroid along that opening's direction into the
/// tube and reaches the second rim's centroid along the second's, turning by `bend` in the plane of
/// the two directions. Positions on the wall are (sigma, angle, radius): sigma in [0, 1] along the
/// arc, the angle around the arc in the frame (outward from the bend's centre, -k), the distance
/// from the arc. A straight tube is the cylinder above.
struct BentTube {
  Vec3 centre = Vec3::Zero();  ///< of the bend
  Vec3 d = Vec3::UnitZ();      ///< the arc's direction at the first rim
  Vec3 m = Vec3::UnitX();      ///< from the first rim's centroid towards the bend's centre
  Vec3 k = Vec3::UnitY();      ///< the bend's axis
  double bend_radius = 1, bend = 0;
  bool hole = true;
  double angle_a = 0, twist = 0;  ///< the first bridge vertex's angle; the bridge's turn

  [[nodiscard]] double arc(double sigma) const { return sigma * bend; }
  [[nodiscard]] Vec3 outward(double sigma) const {
    return -std::cos(arc(sigma)) * m + std::sin(arc(sigma)) * d;
  }
  [[nodiscard]] Vec3 tangent(double sigma) const {
    return std::sin(arc(sigma)) * m + std::cos(arc(sigma)) * d;
  }
  [[nodiscard]] Vec3 line(double sigma) const { return centre + bend_radius * outward(sigma); }
  [[nodiscard]] Vec3 radial(double sigma, double angle) const {
    return std::cos(angle) * outward(sigma) - std::sin(angle) * k;
  }
  [[nodiscard]] Vec3 wall(double sigma, double angle, double radius) const {
    return line(sigma) + radius * radial(sigma, angle);
  }
  [[nodiscard]] Vec3 normal(double sigma, double angle) const {
    return hole ? -radial(sigma, angle) : radial(sigma, angle);
  }
  struct Coords {
    double sigma = 0, angle = 0, radius = 0;
  };
  [[nodiscard]] Coords coords(const Vec3& p) const {
    const Vec3 q = p - centre;
    Coords c;
    c.sigma = std::atan2(q.dot(d), -q.dot(m)) / bend;
    const Vec3 r = p - line(c.sigma);
    const Vec3 across = r - r.dot(tangent(c.sigma)) * tangent(c.sigma);
    c.radius = across.norm();
    c.angle = std::atan2(-across.dot(k), across.dot(outward(c.sigma)));
    return c;
  }
};

/// Bends below this (radians) are straight tubes.
constexpr double kNoBend = 1e-3;

/// The bent tube between the two openings, or nothing when they face straight away from (or
/// towards) each other, or no arc leaving each rim along its direction comes close to joining
/// the rims' centroids.
std::optional<BentTube> bent_tube_of(const HalfedgeMesh& m, const TwoOpenings& o) {
  const auto rim_a = rim_points(m, o.first), rim_b = rim_points(m, o.second);
  const Vec3 ca = centroid(rim_a), cb = centroid(rim_b), across = cb - ca;
  const double length = across.norm();
  if (!(length > 0)) return std::nullopt;
  const Vec3 na = newell_normal(rim_a).normalized(), nb = newell_normal(rim_b).normalized();
  const auto hole = hole_between(na, nb, across);
  if (!hole) return std::nullopt;
  BentTube t;
  t.hole = *hole;
  // Into the tube at the first opening, out of it at the second.
  const Vec3 da = t.hole ? -na : na, db = t.hole ? nb : -nb;
  t.bend = std::atan2(da.cross(db).norm(), da.dot(db));
  if (!(t.bend > kNoBend)) return std::nullopt;
  t.d = da;
  t.k = da.cross(db).normalized();
  t.m = t.k.cross(da);
  // The arc's end relative to its start, per unit bend radius; the radius that brings it
  // closest to the second centroid.
  const Vec3 w = (1 - std::cos(t.bend)) * t.m + std::sin(t.bend) * t.d;
  t.bend_radius = across.dot(w) / w.squaredNorm();
  if (!(t.bend_radius > 0) || (t.bend_radius * w - across).norm() > 0.25 * length)
    return std::nullopt;
  t.centre = ca + t.bend_radius * t.m;
  const auto ends_at = [&](Corner c, double rim_sigma) {
    const Vec3 p = m.position(m.origin(c));
    auto co = t.coords(p);
    const Vec3 q = p - t.centre;
    if (std::hypot(q.dot(t.d), q.dot(t.m)) < 1e-9 * length) {
      // On the bend's axis (a vertex of the edge the two faces share): no sigma of its own; the
      // cross-section of its rim.
      co.sigma = rim_sigma;
      const Vec3 r = p - t.line(rim_sigma);
      const Vec3 tg = t.tangent(rim_sigma);
      const Vec3 across = r - r.dot(tg) * tg;
      co.radius = across.norm();
      co.angle = std::atan2(-across.dot(t.k), across.dot(t.outward(rim_sigma)));
    }
    return co;
  };
  const auto a = ends_at(o.first.front(), 0), b = ends_at(o.second.front(), 1);
  if (!(a.radius > 1e-9 * length) || !(b.radius > 1e-9 * length)) return std::nullopt;
  t.angle_a = a.angle;
  t.twist = std::remainder(b.angle - a.angle, 2 * std::numbers::pi);
  return t;
}

/// longest_spoke on a bent tube (angles about its arc).
double longest_spoke(const HalfedgeMesh& m, const BentTube& tube, const TwoOpenings& openings) {
  return longest_spoke(m, tube.twist, openings,
                       [&](const Vec3& p) { return tube.coords(p).angle - tube.angle_a; });
}

/// Which way the face K-gon of a bent tube runs: along the curve the bridge stands for, carried
/// around the tube, or along the tube (the arc's direction).
enum class BentAxis { bridge, tube };

/// The face K-gon of a bent tube that twists: as on a twisted cylinder, a regular K-gon on the
/// wall opposite the middle of the bridge, halfway along the arc, in the wall's tangent plane,
/// its size along its axis (the bridge's curve or the arc, `axis`) times `along_scale`.
Kgon place_on_bent_tube(const HalfedgeMesh& m, Face f, const BentTube& tube,
                        const TwoOpenings& openings, const std::vector<Vec3>& corner_point,
                        double along_scale = 1, BentAxis axis = BentAxis::bridge) {
  const auto loop = m.face_loop(f);
  double radius = 0, sigma_a = 0, sigma_b = 0;
  for (Corner c : loop)
    radius += tube.coords(corner_point[c.idx]).radius / static_cast<double>(loop.size());
  for (Corner c : openings.first)
    sigma_a += tube.coords(corner_point[c.idx]).sigma / static_cast<double>(openings.first.size());
  for (Corner c : openings.second)
    sigma_b += tube.coords(corner_point[c.idx]).sigma / static_cast<double>(openings.second.size());
  const double sigma = (sigma_a + sigma_b) / 2;
  const double angle = tube.angle_a + tube.twist / 2 + std::numbers::pi;
  const Vec3 centre = tube.wall(sigma, angle, radius);
  const Vec3 normal = tube.normal(sigma, angle);
  // The curve the bridge stands for, carried around to the opposite side of the tube.
  const auto curve = [&](double t) {
    return tube.wall(sigma_a + t * (sigma_b - sigma_a), angle + (t - 0.5) * tube.twist, radius);
  };
  constexpr double kStep = 1.0 / 128;
  const Vec3 along =
      axis == BentAxis::tube ? tube.tangent(sigma) : curve(0.5 + kStep) - curve(0.5 - kStep);
  return wall_kgon(loop, openings, centre, normal, along, radius, corner_point, along_scale);
}

/// The bridge's edge K-gon on a bent tube that twists: the quad of the twisted cylinder, at the
/// middle of the curve that runs around the wall from one bridge end to the other.
std::optional<Kgon> place_bridge_on_bent_tube(const HalfedgeMesh& m, const BentTube& tube,
                                              const TwoOpenings& openings,
                                              const std::vector<Corner>& corners,
                                              const std::vector<Vec3>& corner_point) {
  const Vertex a = m.origin(openings.first.front());
  double radius = 0, sigma_a = 0, sigma_b = 0;
  int na = 0, nb = 0;
  for (Corner c : corners) {
    const auto p = tube.coords(corner_point[c.idx]);
    radius += p.radius / static_cast<double>(corners.size());
    if (m.origin(c) == a) {
      sigma_a += p.sigma / 2;
      ++na;
    } else {
      sigma_b += p.sigma / 2;
      ++nb;
    }
  }
  if (na != 2 || nb != 2) return std::nullopt;
  const auto curve = [&](double t) {
    return tube.wall(sigma_a + t * (sigma_b - sigma_a), tube.angle_a + t * tube.twist, radius);
  };
  constexpr int kSteps = 64;
  double length = 0;
  for (int i = 0; i < kSteps; ++i)
    length += (curve((i + 1.0) / kSteps) - curve(static_cast<double>(i) / kSteps)).norm();
  const Vec3 centre = curve(0.5);
  const Vec3 along = (curve(0.5 + 0.5 / kSteps) - curve(0.5 - 0.5 / kSteps)).normalized();
  const double sigma = (sigma_a + sigma_b) / 2, angle = tube.angle_a + tube.twist / 2;
  const Vec3 normal = tube.normal(sigma, angle);
  return wall_quad(m, corners, a, centre, along, normal, tube.normal(0, tube.angle_a),
                   tube.normal(1, tube.angle_a + tube.twist), length, tube.twist, corner_point);
}

/// Whether both openings' rims visit v (an end of the edge two merged faces shared).
bool on_both_rims(const HalfedgeMesh& m, const TwoOpenings& o, Vertex v) {
  const auto visits = [&](const std::vector<Corner>& corners) {
    return std::any_of(corners.begin(), corners.end(), [&](Corner c) { return m.origin(c) == v; });
  };
  return visits(o.first) && visits(o.second);
}

/// Whether the two openings' rims share a vertex: the merged faces shared an edge, and the tube
/// is pinched along it.
bool pinched(const HalfedgeMesh& m, const TwoOpenings& o) {
  for (Corner c : o.first)
    if (on_both_rims(m, o, m.origin(c))) return true;
  return false;
}

}  // namespace

std::vector<Corner> edge_kgon_corners(const HalfedgeMesh& m, Edge e) {
  // Counter-clockwise seen from the side the faces point to: h = (a -> b) has its face on the
  // left, so the order is h (left, at a), next(t) (right, at a), t (right, at b), next(h).
  const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
  return {h, m.next(t), t, m.next(h)};
}

std::optional<Kgon> place_bridge_kgon(const HalfedgeMesh& m, Face /*f*/,
                                      const TwoOpenings& openings,
                                      const std::vector<Corner>& corners,
                                      const std::vector<Vec3>& corner_point) {
  // The loop may run along a second edge twice (the edge the two faces shared): not the bridge.
  // (corners[0] is the edge's own halfedge; corners[1] and corners[3] may be the bridge's when
  // the two edges meet.)
  if (HalfedgeMesh::edge(corners[0]) != HalfedgeMesh::edge(openings.first.back()))
    return std::nullopt;
  // A bridge from one end of the shared edge to the other runs along that edge, where the tube
  // is pinched: section 2's K-gon (measured on the cube's 24 such bridges: with the bent tube's
  // quad each folds 14 pairs of triangles, with section 2's all are clean).
  if (on_both_rims(m, openings, m.origin(openings.first.front())) &&
      on_both_rims(m, openings, m.origin(openings.second.front())))
    return std::nullopt;
  if (const auto bent = bent_tube_of(m, openings); bent && std::abs(bent->twist) >= kNoTwist)
    return place_bridge_on_bent_tube(m, *bent, openings, corners, corner_point);
  const auto tube = tube_of(m, openings);
  if (!tube || std::abs(tube->twist) < kNoTwist) return std::nullopt;
  // The K-gon sits at the middle of the helix.
  const auto helix = helix_of(m, *tube, openings, corners, corner_point);
  if (!helix) return std::nullopt;
  const Vertex a = m.origin(openings.first.front());
  const double angle = tube->twist / 2, height = (helix->height_a + helix->height_b) / 2;
  const Vec3 centre = tube->wall(angle, height, helix->radius);
  return wall_quad(m, corners, a, centre, helix->direction(*tube, angle).normalized(),
                   tube->normal(angle), tube->normal(0.0), tube->normal(tube->twist),
                   helix->length(*tube), tube->twist, corner_point);
}

std::optional<Kgon> place_pinched_tube_kgon(const HalfedgeMesh& m, Face f,
                                            const TwoOpenings& openings,
                                            const std::vector<Vec3>& corner_point) {
  if (!on_both_rims(m, openings, m.origin(openings.first.front())) &&
      !on_both_rims(m, openings, m.origin(openings.second.front())))
    return std::nullopt;
  const auto bent = bent_tube_of(m, openings);
  if (!bent || !(std::abs(bent->twist) >= kNoTwist)) return std::nullopt;
  // Shortened along the bridge's curve: at full size the fan's patches next to the face's centre
  // are slivers that a grid of 16 cuts into one folded pair of triangles on the cube's 48
  // bridges across a face's diagonal; from 0.6 to 0.9 of it none of the 168 fold (0.5 and 0.95:
  // the 48 fold again), measured at resolution 16 (docs/method.md, "Bent tunnels").
  constexpr double kAlongBridge = 0.75;
  return place_on_bent_tube(m, f, *bent, openings, corner_point, kAlongBridge);
}

std::optional<Kgon> place_tube_kgon(const HalfedgeMesh& m, Face f, const TwoOpenings& openings,
                                    const std::vector<Vec3>& corner_point) {
  // Two faces that shared an edge: the tube is pinched along that edge. The placements below
  // fold the cube's quarter-turn bridges there; section 2's K-gon over the rims' own corner
  // points keeps them clean (docs/method.md).
  if (pinched(m, openings)) return std::nullopt;
  if (const auto bent = bent_tube_of(m, openings); bent && std::abs(bent->twist) >= kNoTwist) {
    // A fan that reaches far past the half turn (longest_spoke on the bent tube) wants the face
    // K-gon along the tube, 1.8 times section 2's size along it (method.md, "Fans far past the
    // half turn on a bent tube"). Measured at resolution 16 on the dodecahedron's bent tunnels,
    // whose fans reach 36 degrees past (50 of 125 pairs; the others and all of the icosahedron's
    // at most 22.2): all 125 clean from 1.5 to 2.3 times along, 20 folded at 1.45 and below
    // (and with the K-gon along the bridge's curve at 1, 1.5, 1.8 or 2.2 times), 10 at 2.35. The
    // 30 degrees is fitted to these two solids, not derived: anything between 22.2 and 36
    // degrees picks the same pairs.
    constexpr double kFarPastHalfTurn = 30 * std::numbers::pi / 180, kAlongTube = 1.8;
    if (longest_spoke(m, *bent, openings) - std::numbers::pi > kFarPastHalfTurn)
      return place_on_bent_tube(m, f, *bent, openings, corner_point, kAlongTube, BentAxis::tube);
    return place_on_bent_tube(m, f, *bent, openings, corner_point);
  }
  const auto tube = tube_of(m, openings);
  if (tube && std::abs(tube->twist) >= kNoTwist)
    return place_on_twisted_tube(m, f, *tube, openings, corner_point);
  auto points_of = [&](const std::vector<Corner>& cs) {
    std::vector<Vec3> pts;
    for (Corner c : cs) pts.push_back(corner_point[c.idx]);
    return pts;
  };
  const auto chain_a = points_of(openings.first), chain_b = points_of(openings.second);
  const auto far_a = far_point(chain_a), far_b = far_point(chain_b);
  if (!far_a || !far_b) return std::nullopt;

  const Vec3 centre = (far_a->point + far_b->point) / 2;
  const Vec3 axis = far_b->point - far_a->point;
  const Vec3 across = centroid(chain_b) - centroid(chain_a);
  const Vec3 middle = (centroid(chain_a) + centroid(chain_b)) / 2;
  const auto facing = hole_between(newell_normal(rim_points(m, openings.first)),
                                   newell_normal(rim_points(m, openings.second)), across);
  if (!facing) return std::nullopt;
  const bool hole = *facing;

  // The rims run around the tube in opposite senses, so their difference is the wall's
  // direction around the tube at the far points.
  Vec3 around = far_a->tangent - far_b->tangent;
  Vec3 normal = axis.cross(around);
  if (!(normal.norm() > 1e-12 * axis.squaredNorm())) return std::nullopt;
  normal.normalize();
  const double towards_axis = normal.dot(middle - centre);
  if (std::abs(towards_axis) < 1e-9 * axis.norm()) return std::nullopt;
  if ((towards_axis > 0) != hole) normal = -normal;

  const Vec3 e1 = (axis - axis.dot(normal) * normal).normalized();  // towards the second opening
  const Vec3 e2 = normal.cross(e1);
  // Counter-clockwise about the normal, the first opening's corners must run the way its rim
  // does at the far point; otherwise the tube is too twisted for this placement.
  if (far_a->tangent.dot(-e2) <= 0) return std::nullopt;

  // wall_kgon with the axis as the direction along the tube: section 2's regular K-gon, its
  // extent across the tube cut to the tube's radius as item 4 cuts a twisted tube's (method.md,
  // "Uneven rims"): section 2's size grows with the tube's length, and on a tube three times as
  // long as a regular prism's (height 6, unit radius) the K-gon reached 1.54 against a radius of
  // 0.50 to each side, and the straight tubes of prisms 8 and 12 folded and crossed themselves
  // (240 to 468 folded pairs at resolution 16); cut, they are clean. On the regular prisms the
  // cut takes the width from 1.2 to 1.35 r (0.60 to 0.61) to r and changes no count of
  // test_twisted_tubes.cpp.
  // Rims of more than six corners: the K-gon kStraightAlong times as long along the tube, as
  // item 6 stretches a twisted tube's (method.md, item 8). At section 2's size, 6 of prism 12's
  // 12 straight tubes folded 6 pairs of triangles each at resolution 16, next to the face's
  // centre; prisms 7 to 12's straight tubes are all clean and open from 1.3 to 2.4 times
  // (1.2: 6 of prism 12's fold; prisms 3 to 6, which keep section 2's size, fold at 1.6 and
  // more). Fitted, not derived. Those 6 folded because far_point took one edge of the far
  // corner or the other by rounding; with its chord across the corner all 12 are clean at
  // section 2's size, but the elliptic prism 10's straight tubes (test_uneven_tubes.cpp) fold 2
  // pairs each without the stretch (method.md, "Uneven rims").
  const auto loop = m.face_loop(f);
  const double radius = tube ? tube->mean_radius(loop, corner_point)
                             : std::numeric_limits<double>::infinity();  // no cut
  return wall_kgon(loop, openings, centre, normal, axis, radius, corner_point,
                   rim_corners(openings) > 6 ? kStraightAlong : 1);
}

void slide_acute_sides(const HalfedgeMesh& m, const TwoOpenings& openings,
                       std::vector<Vec3>& corner_point) {
  // Only where place_tube_kgon puts the face K-gon on a twisted cylinder, and only for rims of
  // more than six corners (place_on_twisted_tube's item 6).
  if (pinched(m, openings)) return;
  if (const auto bent = bent_tube_of(m, openings); bent && std::abs(bent->twist) >= kNoTwist)
    return;
  const auto tube = tube_of(m, openings);
  if (!tube || std::abs(tube->twist) < kNoTwist) return;
  const double corners_per_rim = rim_corners(openings);
  if (corners_per_rim <= 6) return;
  // The twist in corner steps (the mean step of the two rims), and the slide: half of it, in
  // corner positions, rounded up.
  const long steps = std::lround(std::abs(tube->twist) * corners_per_rim / (2 * std::numbers::pi));
  const double slide = static_cast<double>((steps + 1) / 2);
  if (!(slide > 0)) return;
  for (const auto* corners : {&openings.first, &openings.second}) {
    const bool first = corners == &openings.first;
    const size_t n = corners->size() - 1;
    const double rim_size = static_cast<double>(n);
    // The rim's polygon of Doo-Sabin points (the bridge vertex's once), walked by position: the
    // point of corner i at i, the bridge vertex's split points at kSplit and n - kSplit.
    const auto w = doo_sabin_shrink(rim_points(m, *corners));
    const auto at = [&](double t) {
      const double f = std::floor(t);
      const size_t i = static_cast<size_t>(f) % n;
      return Vec3(w[i] + (t - f) * (w[(i + 1) % n] - w[i]));
    };
    // The acute side: where the helix leans over the rim, the way the bridge turns at the first
    // rim and back from it at the second. Whether the rim's corners run that way from the
    // bridge: the angle of the next corner's point around the tube from the bridge vertex.
    const double bridge = first ? 0 : tube->twist;
    const double lean = (tube->twist > 0) == first ? 1 : -1;
    const Vec3 d = corner_point[(*corners)[1].idx] - tube->base;
    const double next =
        std::remainder(std::atan2(d.dot(tube->y0), d.dot(tube->x0)) - bridge, 2 * std::numbers::pi);
    const bool forward = next * lean > 0;
    // From the bridge to the far point (half the rim), corner positions t move to
    // t + k (1 - (t / half)^1.5): by almost k next to the bridge, tapering off to none at the
    // far point, and in order while k stays below two thirds of half the rim. The slide, at most
    // a quarter of the mean rim plus a half, is at most 0.6 of half of it for more than six
    // corners; the cap only matters for rims of different sizes.
    const double half = rim_size / 2;
    const double k = std::min(slide, 0.65 * half);
    for (size_t j = 0; j <= n; ++j) {
      const double t = j == 0 ? kSplit : static_cast<double>(j);
      if (t >= half) break;
      const double u = t + k * (1 - std::pow(t / half, 1.5));
      corner_point[(*corners)[forward ? j : n - j].idx] = at(forward ? u : rim_size - u);
    }
  }
}

std::vector<Vec3> rim_points(const HalfedgeMesh& m, const std::vector<Corner>& corners) {
  std::vector<Vec3> pts;
  for (size_t i = 0; i + 1 < corners.size(); ++i) pts.push_back(m.position(m.origin(corners[i])));
  return pts;
}

}  // namespace stitch::detail
