#include "stitch/modeler/surface_health.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>

#include "sort_unique.hpp"

namespace stitch::modeler {

std::string SurfaceProblems::summary() const {
  if (empty()) return {};
  const char* what = folds > 0 && self_intersections > 0 ? "folds and intersects itself"
                     : folds > 0                         ? "folds"
                                                         : "intersects itself";
  return fmt::format("surface {} at {} patch{}", what, corners.size(),
                     corners.size() == 1 ? "" : "es");
}

std::string describe_problems(const HalfedgeMesh& mesh, const SurfaceProblems& problems) {
  if (problems.empty()) return {};
  // Enough to find the place; the outlines in the view show them all.
  constexpr size_t kMostNamed = 8;
  const size_t named = std::min(problems.corners.size(), kMostNamed);
  const std::vector<Corner> first(problems.corners.begin(), problems.corners.begin() + named);
  return fmt::format("{} (corners {}{}; {} folded and {} crossing pairs of triangles)",
                     problems.summary(), fmt::join(corner_names(mesh, first), ", "),
                     named < problems.corners.size() ? ", ..." : "", problems.folds,
                     problems.self_intersections);
}

SurfaceProblems check_live_surface(const HalfedgeMesh& mesh, const IncrementalSurface& surface,
                                   const std::vector<Corner>& changed) {
  SurfaceProblems out;
  if (surface.method() == Method::cc || changed.empty()) return out;
  const auto start = std::chrono::steady_clock::now();
  const int n = kHealthResolution;
  PatchGridSampler sample;
  if (surface.resolution() == n) {
    // The drawn samples: the same evaluate_patch at the same (i / n, j / n).
    const TessellatedMesh& tess = surface.tessellation();
    const int per_patch = surface.vertices_per_patch();
    sample = [&tess, per_patch, n](Corner c, int i, int j) {
      return tess.positions[static_cast<size_t>(c.idx) * per_patch + i * (n + 1) + j];
    };
  } else {
    const BezierRule rule = surface.method() == Method::asc ? BezierRule::asc : BezierRule::mdc;
    sample = [&surface, rule, n](Corner c, int i, int j) {
      return evaluate_patch(surface.nets()[c.idx], static_cast<double>(i) / n,
                            static_cast<double>(j) / n, rule)
          .position;
    };
  }
  std::vector<Corner> corners = changed;
  detail::sort_unique(corners);
  const LocalCheckReport r = check_patches(mesh, corners, sample);
  out.corners = r.problem_corners;
  out.folds = r.folds;
  out.self_intersections = r.self_intersections;
  out.checked_patches = r.changed_patches;
  out.triangles = r.triangles;
  out.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<TubeUnfolding> unfold_live_tubes(const HalfedgeMesh& mesh, KgonOptions& options,
                                             const IncrementalSurface& surface,
                                             const std::vector<Face>& tubes) {
  if (tubes.empty() || surface.method() == Method::cc) return {};  // no copy for nothing
  // A copy rather than build_bezier_surface: copying costs a pass over memory, building the
  // K-gons and nets of the whole mesh again far more. unfold_tubes reads and rebuilds only the
  // tubes' K-gons and the nets around them.
  BezierSurface copy{surface.kgons(), surface.nets(), {}};
  UnfoldTubesOptions unfold;
  unfold.check.resolution = kHealthResolution;
  unfold.method = surface.method();
  return unfold_tubes(mesh, options, copy, tubes, unfold);
}

std::string describe_unfoldings(const HalfedgeMesh& mesh,
                                const std::vector<TubeUnfolding>& unfoldings) {
  std::vector<std::string> parts;
  for (const TubeUnfolding& u : unfoldings) parts.push_back(describe(mesh, u));
  return fmt::format("{}", fmt::join(parts, "; "));
}

void add_problem_outlines(const IncrementalSurface& surface, const std::vector<Corner>& corners,
                          LineSet& lines) {
  const TessellatedMesh& tess = surface.tessellation();
  const int n = surface.resolution(), per_patch = surface.vertices_per_patch();
  auto at = [&](Corner c, int i, int j) -> const Vec3& {
    return tess.positions[static_cast<size_t>(c.idx) * per_patch + i * (n + 1) + j];
  };
  for (Corner c : corners) {
    if (static_cast<size_t>(c.idx + 1) * per_patch > tess.positions.size()) continue;
    for (int k = 0; k < n; ++k) {
      lines.add(at(c, k, 0), at(c, k + 1, 0), problem_colour, 2.0f);
      lines.add(at(c, k, n), at(c, k + 1, n), problem_colour, 2.0f);
      lines.add(at(c, 0, k), at(c, 0, k + 1), problem_colour, 2.0f);
      lines.add(at(c, n, k), at(c, n, k + 1), problem_colour, 2.0f);
    }
  }
}

}  // namespace stitch::modeler
