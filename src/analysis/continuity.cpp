#include "stitch/analysis/continuity.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "stitch/analysis/sectors.hpp"

namespace stitch {

double angle_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
}

namespace {

enum class SideKind { interior, boundary, crease };

struct SideResult {
  SideKind kind = SideKind::interior;
  double max_deg = 0, sum_deg = 0, max_gap = 0;
  long count = 0;
  bool touches_ev = false;
  std::vector<std::pair<double, double>> by_distance;  // (distance from the EV, jump)
};

/// Whether a side of the patch of c lies on a sharp edge, and which kind. Only sides 0 and 3 run
/// along a mesh edge (sides 1 and 2 are spokes inside the face); a patch across in a hole makes
/// the side a boundary whatever the edge's tags say, because there is nothing to sample there.
SideKind side_kind(const HalfedgeMesh& mesh, const std::vector<std::uint8_t>& sharp, Corner c,
                   int side) {
  const PatchNeighbour nb = neighbour_across(mesh, c, side);
  if (mesh.is_hole(nb.corner)) return SideKind::boundary;
  if (side == 1 || side == 2) return SideKind::interior;
  const Edge e = HalfedgeMesh::edge(side == 0 ? c : mesh.prev(c));
  if (mesh.is_boundary(e)) return SideKind::boundary;
  return sharp[static_cast<size_t>(e.idx)] != 0 ? SideKind::crease : SideKind::interior;
}

/// The largest angle between the normals of the patches at (u, v) and their mean.
double normal_spread(const Surface& surface,
                     const std::vector<std::pair<Corner, std::array<double, 2>>>& at) {
  Vec3 mean = Vec3::Zero();
  std::vector<Vec3> normals;
  for (const auto& [c, uv] : at) normals.push_back(surface.evaluate(c, uv[0], uv[1]).normal);
  for (const Vec3& n : normals) mean += n;
  double worst = 0;
  for (const Vec3& n : normals) worst = std::max(worst, angle_deg(n, mean.normalized()));
  return worst;
}

/// A corner tag that every method makes a corner of (mdc also from KgonOptions::sharp_from on,
/// which the surface does not record; such a vertex is then checked as an extraordinary point,
/// over its whole fan, which is its one sector).
bool corner_tag(const HalfedgeMesh& mesh, Vertex v) {
  return mesh.sharpness(v) >= infinitely_sharp;
}

}  // namespace

ContinuityReport analyze_continuity(const HalfedgeMesh& mesh, const Surface& surface,
                                    const ContinuityOptions& options) {
  std::vector<double> ts;
  for (int k = 0; k < options.samples_per_side; ++k)
    ts.push_back((k + 0.5) / options.samples_per_side);
  for (int k = 2; k <= options.max_halvings; ++k) {
    ts.push_back(std::ldexp(1.0, -k));
    ts.push_back(1.0 - std::ldexp(1.0, -k));
  }
  std::sort(ts.begin(), ts.end());

  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Vertex v : mesh.vertices()) {
    lo = lo.cwiseMin(mesh.position(v));
    hi = hi.cwiseMax(mesh.position(v));
  }
  const double diagonal = std::max((hi - lo).norm(), 1e-300);
  // The K each patch sees at its vertex: at a crease or corner that of its sector, which is
  // what makes the patch extraordinary there (equal to the valence elsewhere).
  const std::vector<int>& vertex_k = surface.bezier().kgons.vertex_k;
  const std::vector<std::uint8_t> sharp = sharp_edges(mesh, surface);

  ContinuityReport rep;
  rep.method = surface.method();
  FeatureReport& feat = rep.features;
  std::map<double, double> by_distance;
  double sum_ev = 0, sum_reg = 0;
  // Sides 0 and 1 of every patch cover every interior boundary and every crease once (sides 3
  // and 2 are their partners). A boundary side has no partner, so side 3 is needed to count
  // those on the far half of each boundary edge. The patches are measured a chunk at a time on
  // every core and each chunk's sides are summed in patch order, so memory holds one chunk and
  // the sums do not depend on the threads.
  const auto& corners = surface.corners();
  constexpr size_t kChunk = 1 << 14;
  std::vector<SideResult> results(std::min(corners.size(), kChunk) * 2);
  for (size_t chunk = 0; chunk < corners.size(); chunk += kChunk) {
    const size_t chunk_end = std::min(corners.size(), chunk + kChunk);
    tbb::parallel_for(chunk, chunk_end, [&](size_t k) {
      const Corner c = corners[k];
      for (int side = 0; side < 2; ++side) {
        SideResult& r = results[2 * (k - chunk) + side];
        r = SideResult{.by_distance = std::move(r.by_distance)};  // its storage kept
        r.by_distance.clear();
        r.kind = side_kind(mesh, sharp, c, side);
        if (r.kind == SideKind::boundary) continue;
        // Side 0 starts at the mesh vertex, side 1 ends at the face centre; the other ends are
        // edge midpoints, where K = 4 always.
        const int ev_k = side == 0 ? vertex_k[c.idx] : mesh.degree(mesh.face(c));
        r.touches_ev = ev_k != 4;
        const PatchNeighbour nb = neighbour_across(mesh, c, side);
        for (double t : ts) {
          const auto [u0, v0] = side_point(side, t);
          const auto [u1, v1] = side_point(nb.side, t);
          const SurfacePoint a = surface.evaluate(c, u0, v0);
          const SurfacePoint b = surface.evaluate(nb.corner, u1, v1);
          r.max_gap = std::max(r.max_gap, (a.position - b.position).norm() / diagonal);
          ++r.count;
          // Across a crease the surface is C0 by design: only the gap means something there.
          if (r.kind == SideKind::crease) continue;
          const double jump = angle_deg(a.normal, b.normal);
          r.max_deg = std::max(r.max_deg, jump);
          r.sum_deg += jump;
          if (r.touches_ev) r.by_distance.emplace_back(side == 0 ? t : 1.0 - t, jump);
        }
      }
    });
    for (size_t i = 0; i < 2 * (chunk_end - chunk); ++i) {
      const SideResult& r = results[i];
      if (r.kind == SideKind::boundary) {
        ++feat.boundary_sides;
        continue;
      }
      if (r.kind == SideKind::crease) {
        ++feat.crease_sides;
        feat.crease_gap = std::max(feat.crease_gap, r.max_gap);
        continue;
      }
      JumpStats& s = r.touches_ev ? rep.touching_ev : rep.away_from_ev;
      s.max_deg = std::max(s.max_deg, r.max_deg);
      s.samples += r.count;
      (r.touches_ev ? sum_ev : sum_reg) += r.sum_deg;
      rep.max_gap = std::max(rep.max_gap, r.max_gap);
      for (const auto& [d, j] : r.by_distance) by_distance[d] = std::max(by_distance[d], j);
    }
  }
  for (const Corner c : corners)
    if (side_kind(mesh, sharp, c, 3) == SideKind::boundary) ++feat.boundary_sides;
  if (rep.touching_ev.samples) rep.touching_ev.mean_deg = sum_ev / rep.touching_ev.samples;
  if (rep.away_from_ev.samples) rep.away_from_ev.mean_deg = sum_reg / rep.away_from_ev.samples;
  rep.jump_by_distance.assign(by_distance.begin(), by_distance.end());

  // G1 at extraordinary points: one tangent plane shared by every patch meeting there. At a
  // vertex on a sharp feature, one per sector instead.
  for (Vertex v : mesh.vertices()) {
    if (sharp_spokes(mesh, v, sharp) > 0 || corner_tag(mesh, v)) {
      ++feat.sector_vertices;
      const auto& cone = surface.bezier().kgons.cone;
      const bool cc_corner = surface.method() == Method::cc &&
                             vertex_kind(mesh, v, KgonOptions{}) == VertexKind::corner;
      for (const std::vector<Corner>& sector : vertex_sectors(mesh, v, sharp)) {
        if (sector.size() < 2) continue;
        // Cone points have no tangent plane by design: sectors the construction could not
        // flatten (KgonSet::cone), and OpenSubdiv's corners.
        if (cc_corner || (surface.method() != Method::cc && !cone.empty() && cone[sector[0].idx])) {
          ++feat.cone_points;
          continue;
        }
        std::vector<std::pair<Corner, std::array<double, 2>>> at;
        for (Corner c : sector) at.push_back({c, {0.0, 0.0}});
        feat.sector_normal_spread_deg =
            std::max(feat.sector_normal_spread_deg, normal_spread(surface, at));
        ++feat.sectors_compared;
      }
      continue;
    }
    if (mesh.valence(v) == 4) continue;
    std::vector<std::pair<Corner, std::array<double, 2>>> at;
    for (Corner c : mesh.vertex_fan(v)) at.push_back({c, {0.0, 0.0}});
    rep.ev_normal_spread_deg = std::max(rep.ev_normal_spread_deg, normal_spread(surface, at));
    ++rep.extraordinary_points;
  }
  rep.has_sharp_features = feat.sector_vertices > 0;
  for (Face f : mesh.surface_faces()) {
    if (mesh.degree(f) == 4) continue;
    std::vector<std::pair<Corner, std::array<double, 2>>> at;
    for (Corner c : mesh.face_loop(f)) at.push_back({c, {1.0, 1.0}});
    rep.ev_normal_spread_deg = std::max(rep.ev_normal_spread_deg, normal_spread(surface, at));
    ++rep.extraordinary_points;
  }
  // analyze prints these and compare writes them: a NaN must stop both, not pass as a number.
  bool finite = std::isfinite(rep.touching_ev.max_deg) && std::isfinite(rep.touching_ev.mean_deg) &&
                std::isfinite(rep.away_from_ev.max_deg) &&
                std::isfinite(rep.away_from_ev.mean_deg) && std::isfinite(rep.max_gap) &&
                std::isfinite(rep.ev_normal_spread_deg) && std::isfinite(feat.crease_gap) &&
                std::isfinite(feat.sector_normal_spread_deg);
  for (const auto& [t, jump] : rep.jump_by_distance) finite = finite && std::isfinite(jump);
  if (!finite)
    throw Error(fmt::format("the continuity measures of the {} surface are not finite",
                            to_string(rep.method)));
  return rep;
}

}  // namespace stitch
