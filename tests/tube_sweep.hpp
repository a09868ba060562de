// The sweep of the tube tests (test_twisted_tubes.cpp, test_uneven_tubes.cpp): an edge inserted
// between every corner of one face and every corner of another, each smooth surface checked at
// resolution 16 (issue 13; docs/method.md, "K-gons of faces that run around two openings").
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "stitch/analysis/continuity.hpp"
#include "stitch/analysis/surface_check.hpp"
#include "stitch/analysis/unfold_tubes.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/tess/adaptive.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch::test {

struct PairResult {
  int steps = 0;  ///< corner steps between the two bridge ends around the tube (opposite faces)
  bool clean = false, open = false;
  int folds = 0, self_intersections = 0;  ///< check_surface's pairs of triangles
  std::string op, problems;
};

inline Vec3 face_centre(const HalfedgeMesh& m, Face f) {
  return centroid(face_points(m, f));
}

/// Corner steps around the axis between vertices va and vb of two opposite n-gons (0 when vb is
/// straight above va, up to n / 2 for a half twist).
inline int twist_steps(const HalfedgeMesh& m, Vertex va, Vertex vb, const Vec3& centre_a,
                       const Vec3& centre_b, int n) {
  const Vec3 axis = (centre_b - centre_a).normalized();
  auto flat = [&](const Vec3& p, const Vec3& c) {
    const Vec3 d = p - c;
    return Vec3(d - d.dot(axis) * axis);
  };
  const Vec3 ra = flat(m.position(va), centre_a), rb = flat(m.position(vb), centre_b);
  const double angle = std::atan2(ra.cross(rb).norm(), ra.dot(rb));
  return static_cast<int>(std::lround(angle / (2 * std::numbers::pi / n)));
}

enum class C1Check { none, every_pair, clean_pairs };
enum class SweepTessellation { resolution_16, adaptive };
enum class SweepScope { every_pair, first_corner_of_a };
/// The tube's K-gons as the openings construction fits them, or with the controls unfold_tubes
/// chooses where those fold (what stitch smooth and the modeler build by default).
enum class TubeKgons { fitted, unfolded };

/// `op` (an insert-edge between faces a and b of `solid`, whose centres are ca and cb) applied to
/// a copy of `solid`, smoothed with `kgon` and checked: clean, and `open` when the segment between
/// the two faces' centres, extended 3 times beyond them, misses the surface (meaningful for
/// opposite faces). C1 along every edge is checked too, always or when clean. `tessellation`:
/// the welded grid at resolution 16, or the adaptive triangles at the default tolerance (1e-3).
inline PairResult check_tube(const HalfedgeMesh& solid, const std::string& op, const Vec3& ca,
                             const Vec3& cb, C1Check c1 = C1Check::none,
                             SweepTessellation tessellation = SweepTessellation::resolution_16,
                             const KgonOptions& kgon = {},
                             TubeKgons tube_kgons = TubeKgons::fitted) {
  PairResult r;
  r.op = op;
  HalfedgeMesh mesh = solid;
  apply_operation(mesh, r.op);
  KgonOptions options = kgon;
  if (tube_kgons == TubeKgons::unfolded) unfold_tubes(mesh, options);
  const Surface surface(mesh, Method::mdc, options);
  const TriangleSoup tris = tessellation == SweepTessellation::adaptive
                                ? triangulate(tessellate_adaptive(mesh, surface))
                                : triangulate(tessellate(mesh, surface, {16, true}));
  const SurfaceCheckReport check = check_surface(tris);
  r.clean = check.clean();
  r.folds = check.folds;
  r.self_intersections = check.self_intersections;
  if (!r.clean) r.problems = check.describe(tris);
  r.open = segment_hits(tris, ca + 3 * (ca - cb), cb + 3 * (cb - ca)).empty();
  // The construction keeps C1 along every edge (see test_surface.cpp for the tolerance).
  if (c1 == C1Check::every_pair || (c1 == C1Check::clean_pairs && r.clean)) {
    EXPECT_LT(analyze_continuity(mesh, surface).touching_ev.max_deg, 1e-7) << r.op;
  }
  return r;
}

/// check_tube for an edge inserted between every corner of face a and every corner of face b of
/// `solid` (1-based face numbers; pairs at one vertex are skipped), or between the first corner
/// of face a and every corner of face b (`scope`; on a regular prism, each twist once). The
/// twist steps are measured on `steps_on` when given (a mesh with the same connectivity, e.g.
/// the regular prism a variant's vertices were moved from), else on `solid`.
inline std::vector<PairResult> sweep(
    const HalfedgeMesh& solid, int a, int b, C1Check c1 = C1Check::none,
    const HalfedgeMesh* steps_on = nullptr,
    SweepTessellation tessellation = SweepTessellation::resolution_16,
    SweepScope scope = SweepScope::every_pair, TubeKgons tube_kgons = TubeKgons::fitted) {
  std::vector<PairResult> out;
  const Face fa(a - 1), fb(b - 1);
  const Vec3 ca = face_centre(solid, fa), cb = face_centre(solid, fb);
  const HalfedgeMesh& reference = steps_on ? *steps_on : solid;
  std::vector<Halfedge> corners_of_a = solid.face_loop(fa);
  if (scope == SweepScope::first_corner_of_a) corners_of_a.resize(1);
  for (Halfedge ha : corners_of_a) {
    for (Halfedge hb : solid.face_loop(fb)) {
      const Vertex va = solid.origin(ha), vb = solid.origin(hb);
      if (va == vb) continue;
      const std::string op = "insert-edge " + std::to_string(va.idx + 1) + "@" + std::to_string(a) +
                             " " + std::to_string(vb.idx + 1) + "@" + std::to_string(b);
      PairResult r = check_tube(solid, op, ca, cb, c1, tessellation, {}, tube_kgons);
      r.steps = twist_steps(reference, va, vb, face_centre(reference, fa),
                            face_centre(reference, fb), solid.degree(fa));
      out.push_back(std::move(r));
    }
  }
  return out;
}

struct Counts {
  int total = 0, clean = 0, open = 0;
  bool operator==(const Counts&) const = default;
};

inline std::ostream& operator<<(std::ostream& os, const Counts& c) {
  return os << c.total << " pairs, " << c.clean << " clean, " << c.open << " open";
}

/// Counts by twist (corner steps), and all together under key -1.
inline std::map<int, Counts> count(const std::vector<PairResult>& results) {
  std::map<int, Counts> out;
  for (const PairResult& r : results)
    for (int key : {r.steps, -1}) {
      ++out[key].total;
      out[key].clean += r.clean ? 1 : 0;
      out[key].open += r.open ? 1 : 0;
    }
  return out;
}

inline void expect_clean_and_open(const std::vector<PairResult>& results, int max_steps) {
  for (const PairResult& r : results)
    if (r.steps <= max_steps) {
      EXPECT_TRUE(r.clean) << r.op << " (twist of " << r.steps << " steps)\n" << r.problems;
      EXPECT_TRUE(r.open) << r.op << " (twist of " << r.steps << " steps): the axis is blocked";
    }
}

}  // namespace stitch::test
