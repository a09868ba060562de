#include "openings.hpp"

#include <cmath>
#include <numbers>

#include "stitch/mesh/polygon.hpp"

namespace stitch::detail {

std::optional<TwoOpenings> find_two_openings(const HalfedgeMesh& m, Face f) {
  const auto loop = m.face_loop(f);
  std::vector<Halfedge> bridges;
  for (Halfedge h : loop)
    if (m.face(HalfedgeMesh::twin(h)) == f) bridges.push_back(h);
  if (bridges.size() != 2) return std::nullopt;
  const Halfedge b1 = bridges[0], b2 = HalfedgeMesh::twin(b1);
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
  // Two separate rims: each opening visits its bridge vertex at its two ends and every other
  // vertex once, and the openings share no vertex. Anything else (random edits make such
  // faces) is not a tube between two openings, and keeps section 2's K-gon.
  std::vector<int> seen(m.vertex_capacity(), 0);
  for (const auto* corners : {&o.first, &o.second}) {
    const Vertex bridge_end = m.origin(corners->front());
    if (m.origin(corners->back()) != bridge_end) return std::nullopt;
    for (size_t i = 1; i < corners->size(); ++i)
      if (seen[m.origin((*corners)[i]).idx]++) return std::nullopt;
  }
  return o;
}

void set_opening_corner_points(const HalfedgeMesh& m, const TwoOpenings& openings,
                               std::vector<Vec3>& corner_point) {
  for (const auto* corners : {&openings.first, &openings.second}) {
    std::vector<Vec3> loop;
    for (Corner c : *corners) loop.push_back(m.position(m.origin(c)));
    const auto w = doo_sabin_shrink(loop);
    for (size_t i = 0; i < corners->size(); ++i) corner_point[(*corners)[i].idx] = w[i];
  }
}

namespace {

struct RimSample {
  Vec3 point, tangent;
};

/// The point halfway along the chain of an opening's corner points, and the chain's direction
/// there: the part of the rim farthest from the bridge.
std::optional<RimSample> far_point(const std::vector<Vec3>& chain) {
  double length = 0;
  for (size_t i = 0; i + 1 < chain.size(); ++i) length += (chain[i + 1] - chain[i]).norm();
  if (!(length > 0)) return std::nullopt;
  double left = length / 2;
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    const Vec3 d = chain[i + 1] - chain[i];
    const double l = d.norm();
    if (l >= left && l > 0) return RimSample{chain[i] + d * (left / l), d / l};
    left -= l;
  }
  return RimSample{chain.back(), (chain.back() - chain[chain.size() - 2]).normalized()};
}

}  // namespace

std::optional<Kgon> place_tube_kgon(const HalfedgeMesh& m, Face f, const TwoOpenings& openings,
                                    const std::vector<Vec3>& corner_point) {
  auto points_of = [&](const std::vector<Corner>& cs) {
    std::vector<Vec3> pts;
    for (Corner c : cs) pts.push_back(corner_point[c.idx]);
    return pts;
  };
  auto rim_of = [&](const std::vector<Corner>& cs) {
    std::vector<Vec3> pts;
    for (Corner c : cs) pts.push_back(m.position(m.origin(c)));
    return pts;
  };
  const auto chain_a = points_of(openings.first), chain_b = points_of(openings.second);
  const auto far_a = far_point(chain_a), far_b = far_point(chain_b);
  if (!far_a || !far_b) return std::nullopt;

  const Vec3 centre = (far_a->point + far_b->point) / 2;
  const Vec3 axis = far_b->point - far_a->point;
  const Vec3 across = centroid(chain_b) - centroid(chain_a);
  const Vec3 middle = (centroid(chain_a) + centroid(chain_b)) / 2;
  // The openings face away from each other around a hole through the solid (the surface's
  // outside is the tube's inside) and towards each other across a handle joining two solids.
  const double sa = newell_normal(rim_of(openings.first)).dot(across);
  const double sb = newell_normal(rim_of(openings.second)).dot(across);
  const bool hole = sa < 0 && sb > 0, handle = sa > 0 && sb < 0;
  if (!hole && !handle) return std::nullopt;

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

  const auto loop = m.face_loop(f);
  const int k = static_cast<int>(loop.size());
  // Turn the polygon so that the middle of the first opening's corners faces that opening.
  double s = 0, c = 0;
  for (int i = 0; i < k; ++i)
    for (Corner a : openings.first)
      if (loop[i] == a) {
        s += std::sin(2 * std::numbers::pi * i / k);
        c += std::cos(2 * std::numbers::pi * i / k);
      }
  const double phase = std::numbers::pi - std::atan2(s, c);
  // Size: half the mean distance to the corner points, as section 2 gives a regular polygon
  // (each Doo-Sabin shrink halves its first harmonic: corner points at 1/2 of the vertices'
  // radius, K-gon points at 1/4).
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

}  // namespace stitch::detail
