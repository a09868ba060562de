// The second stage of unfold_tubes (docs/method.md, "Tubes that still fold"): where no setting
// of the grid (tube_settings()) is clean and open, the same controls taken as continuous, plus
// the stretch's direction and an offset of the face K-gon, are moved downhill from the fitted
// placement (NLopt's Nelder-Mead) on a score that counts folds, crossings and hits of the axis
// and, unlike those counts, also falls as a fold is about to open: the sharp turns of the grid.
// Internal.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "stitch/analysis/local_check.hpp"
#include "stitch/kgon/kgon.hpp"

namespace stitch::detail {

/// Positions of some patches on the grid of one resolution n: patch k's sample (i, j) is
/// positions[(k * (n + 1) + i) * (n + 1) + j].
struct PatchGrids {
  int n = 0;
  std::vector<Corner> corners;
  std::vector<Vec3> positions;
  [[nodiscard]] const Vec3& at(size_t k, int i, int j) const {
    return positions[(k * (n + 1) + i) * (n + 1) + j];
  }
};

/// How sharply the grids turn: over neighbouring cells of one patch, the angle between the
/// cells' normals beyond 30 degrees, in units of 60 degrees, summed. A fold of the triangles
/// is a turn beyond 90 degrees; this grows continuously while one forms, so a search can follow
/// it down where the count of folds stays the same.
double sharp_turns(const PatchGrids& grids);

/// Where the tube lies, for the directions and sizes the controls are taken in.
struct TubeFrame {
  Vec3 along;         ///< unit, from the first rim's centre to the second's
  Vec3 face_normal;   ///< unit, of the face's fitted K-gon
  Vec3 across;        ///< unit, face_normal x along (or any direction across `along`)
  double length = 1;  ///< between the rims' centres
  double radius = 1;  ///< the first rim's mean distance from its centre
};

/// What one setting of the face's and the bridge's K-gon controls gives.
struct TubeScore {
  LocalCheckReport report;  ///< the local check of the patches the two K-gons reach
  double sharp_turns = 0;   ///< of those patches
  int axis_hits = 0;        ///< where the line through the rims' centres meets them
  [[nodiscard]] bool clean_and_open() const { return report.clean() && axis_hits == 0; }
};

struct TubeControls {
  KgonControl face, bridge;
};

/// Sets the two K-gons' controls, rebuilds what they reach and scores it.
using TubeScorer = std::function<TubeScore(const TubeControls&)>;

/// Minimises folds + 3 crossings + 2 axis hits + sharp turns / 5 over the face K-gon's scale
/// (0.22 to 4.5 times `base`'s), rotation (±90 degrees), stretch (0.3 to 3.3) and its direction
/// (within ±92 degrees of the tube's), offset (a quarter of the tube's length along it, half its
/// radius along the K-gon's normal) and the bridge's scale (0.3 to 3.3), from the fitted placement
/// and then three fixed other starts, at most `max_evaluations` settings in all. Returns the
/// first setting scored clean and open, or nothing; `evaluations` counts the settings scored.
std::optional<TubeControls> tube_descent(const TubeFrame& frame, const KgonControl& base,
                                         const TubeScorer& score, int max_evaluations,
                                         int& evaluations);

}  // namespace stitch::detail
