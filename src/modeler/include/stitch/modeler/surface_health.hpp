// Whether the live surface folds or meets itself near what was edited: the local check of
// include/stitch/analysis/local_check.hpp on the patches an edit recomputed and their neighbours,
// at a cost that follows the edit, not the mesh. The session runs it after every topology edit
// (Session::surface_problems); the modeler shows the result in its status bar and outlines the
// patches.
#pragma once

#include <string>
#include <vector>

#include "stitch/analysis/local_check.hpp"
#include "stitch/analysis/unfold_tubes.hpp"
#include "stitch/render/overlays.hpp"
#include "stitch/tess/incremental_surface.hpp"

namespace stitch::modeler {

struct SurfaceProblems {
  std::vector<Corner> corners;  ///< patches with a folded or crossing triangle, in index order
  int folds = 0, self_intersections = 0;  ///< pairs of triangles, as check_surface counts them
  int checked_patches = 0;                ///< the last check's patches in focus
  int triangles = 0;                      ///< and the triangles it tessellated
  double milliseconds = 0.0;              ///< its wall time
  [[nodiscard]] bool empty() const { return corners.empty(); }
  /// "surface folds at 2 patches" (or "intersects itself", or both); empty when clean.
  [[nodiscard]] std::string summary() const;
};

/// summary() and the patches' corners, `V@F` as script lines number them (the first few).
std::string describe_problems(const HalfedgeMesh& mesh, const SurfaceProblems& problems);

/// The check's resolution: the tests' (LocalCheckOptions), finer than the display's default 8,
/// at which the clean hole through a cube shows folds (README).
inline constexpr int kHealthResolution = local_check_resolution;

/// Checks the patches of `changed` (e.g. IncrementalSurface::recomputed() and the corners of
/// earlier problems, which an edit may have fixed) with their neighbours on the live surface: its
/// tessellation when that has kHealthResolution, else its nets evaluated at it (so the answer
/// does not depend on the display resolution). Nothing is checked for the Catmull-Clark method,
/// which has no nets of its own.
SurfaceProblems check_live_surface(const HalfedgeMesh& mesh, const IncrementalSurface& surface,
                                   const std::vector<Corner>& changed);

/// unfold_tubes (include/stitch/analysis/unfold_tubes.hpp) on `tubes` of the live surface, which
/// must be up to date with `mesh` and `options`, judged with the surface's method (mdc or asc;
/// nothing for cc, which has no nets of its own). The search runs on a copy of the surface's
/// K-gons and nets, so nothing is built or evaluated for the rest of the mesh; the chosen
/// controls go to `options`, and the live surface is left as it was (the caller applies them).
std::vector<TubeUnfolding> unfold_live_tubes(const HalfedgeMesh& mesh, KgonOptions& options,
                                             const IncrementalSurface& surface,
                                             const std::vector<Face>& tubes);

/// What unfold_live_tubes found, for the status bar: describe (unfold_tubes.hpp) of each, joined
/// by "; ", empty for none.
std::string describe_unfoldings(const HalfedgeMesh& mesh,
                                const std::vector<TubeUnfolding>& unfoldings);

/// Colour of the outlines of problem patches.
inline const Colour problem_colour{0.90f, 0.05f, 0.05f};

/// Adds the four sides of each listed patch on the live tessellation to `lines`, wider than
/// other lines.
void add_problem_outlines(const IncrementalSurface& surface, const std::vector<Corner>& corners,
                          LineSet& lines);

}  // namespace stitch::modeler
