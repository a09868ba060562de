#include "analysis/tube_descent.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <nlopt.hpp>
#include <numbers>

namespace stitch::detail {

namespace {

constexpr int dimensions = 7;
using Point = std::array<double, dimensions>;

/// The coordinates: log face scale, face rotation / 30 degrees, log stretch, the stretch's angle
/// from the tube's direction towards `across` (radians), log bridge scale, the face K-gon's
/// offset along the tube (quarters of its length) and along the K-gon's normal (quarters of the
/// radius). Logs so that halving and doubling are as far; all of order 1, so one initial step
/// fits them all.
constexpr Point lower = {-1.5, -3, -1.2, -1.6, -1.2, -1, -2};
constexpr Point upper = {1.5, 3, 1.2, 1.6, 1.2, 1, 2};
/// The fitted placement, then three others spread over the signs (fixed, so the search is
/// repeatable): where the first descent stalls in a fold it cannot get out of.
constexpr std::array<Point, 4> starts = {{{0, 0, 0, 0, 0, 0, 0},
                                          {-0.3, 0.5, 0.4, 0, 0.3, 0, 0.5},
                                          {0.3, -0.5, 0.4, 0.5, -0.3, 0.2, -0.5},
                                          {-0.3, -0.5, 0, -0.5, 0.3, -0.2, 1}}};

TubeControls controls_at(const TubeFrame& frame, const KgonControl& base, const Point& x) {
  TubeControls out;
  out.face = base;
  out.face.scale *= std::exp(x[0]);
  out.face.rotate_deg += 30 * x[1];
  out.face.stretch = std::exp(x[2]);
  out.face.stretch_along = std::cos(x[3]) * frame.along + std::sin(x[3]) * frame.across;
  out.face.offset +=
      x[5] * frame.length / 4 * frame.along + x[6] * frame.radius / 4 * frame.face_normal;
  out.bridge.scale = std::exp(x[4]);
  return out;
}

double objective(const TubeScore& s) {
  return s.report.folds + 3.0 * s.report.self_intersections + 2.0 * s.axis_hits +
         0.2 * s.sharp_turns;
}

}  // namespace

double sharp_turns(const PatchGrids& grids) {
  const int n = grids.n;
  const double from = std::cos(30 * std::numbers::pi / 180);
  std::vector<Vec3> normals(static_cast<size_t>(n) * n);
  double sum = 0;
  auto turn = [&](const Vec3& a, const Vec3& b) {
    const double c = a.dot(b);
    if (c >= from) return 0.0;
    return (std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi - 30) / 60;
  };
  for (size_t k = 0; k < grids.corners.size(); ++k) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        // The cell's normal from its diagonals: defined for a cell with a collapsed side too.
        const Vec3 d = (grids.at(k, i + 1, j + 1) - grids.at(k, i, j))
                           .cross(grids.at(k, i, j + 1) - grids.at(k, i + 1, j));
        const double length = d.norm();
        normals[i * n + j] = length > 0 ? Vec3(d / length) : Vec3::Zero();
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec3& a = normals[i * n + j];
        if (a.isZero()) continue;
        if (i + 1 < n && !normals[(i + 1) * n + j].isZero())
          sum += turn(a, normals[(i + 1) * n + j]);
        if (j + 1 < n && !normals[i * n + j + 1].isZero()) sum += turn(a, normals[i * n + j + 1]);
      }
  }
  return sum;
}

std::optional<TubeControls> tube_descent(const TubeFrame& frame, const KgonControl& base,
                                         const TubeScorer& score, int max_evaluations,
                                         int& evaluations) {
  struct State {
    const TubeFrame& frame;
    const KgonControl& base;
    const TubeScorer& score;
    int& evaluations;
    std::optional<TubeControls> found;
    nlopt::opt* opt = nullptr;
    // NLopt turns an exception thrown by the objective into its own "nlopt failure": kept here
    // and thrown again after, with its message.
    std::exception_ptr error;
  } state{frame, base, score, evaluations, std::nullopt, nullptr, nullptr};
  for (const Point& start : starts) {
    if (state.found || evaluations >= max_evaluations) break;
    nlopt::opt opt(nlopt::LN_NELDERMEAD, dimensions);
    state.opt = &opt;
    opt.set_lower_bounds(std::vector<double>(lower.begin(), lower.end()));
    opt.set_upper_bounds(std::vector<double>(upper.begin(), upper.end()));
    opt.set_initial_step(0.3);
    // Each start its share: a descent that has not found a clean setting in that many has
    // settled in a fold it does not leave (measured: most tubes took 17 to 85 scores, the half
    // twist of prism 6 half as high about 110).
    const int share = max_evaluations / static_cast<int>(starts.size());
    opt.set_maxeval(std::min(share, max_evaluations - evaluations));
    opt.set_xtol_abs(1e-3);
    opt.set_min_objective(
        [](const std::vector<double>& x, std::vector<double>& /*gradient*/, void* data) {
          auto& s = *static_cast<State*>(data);
          Point p;
          std::copy(x.begin(), x.end(), p.begin());
          const TubeControls controls = controls_at(s.frame, s.base, p);
          try {
            const TubeScore result = s.score(controls);
            ++s.evaluations;
            if (result.clean_and_open()) {
              s.found = controls;
              s.opt->force_stop();
            }
            return objective(result);
          } catch (...) {
            s.error = std::current_exception();
            s.opt->force_stop();
            return 0.0;
          }
        },
        &state);
    std::vector<double> x(start.begin(), start.end());
    double value = 0;
    // A forced stop (found) and a stop at the evaluation limit are results, not errors; NLopt
    // reports the first by the return code or, in some versions, by nlopt::forced_stop.
    try {
      opt.optimize(x, value);
    } catch (const nlopt::forced_stop&) {
    } catch (const nlopt::roundoff_limited&) {
    }
    if (state.error) std::rethrow_exception(state.error);
  }
  return state.found;
}

}  // namespace stitch::detail
