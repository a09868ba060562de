// The surface as plain bicubic Bézier patches, for CAD and other tools that know only
// polynomials: regular patches as they are, patches at extraordinary points as their hierarchy
// of modified de Casteljau children (docs/formats.md, "The patch set").
#pragma once

#include <vector>

#include "stitch/eval/surface.hpp"

namespace stitch {

/// One bicubic polynomial patch: a cell of the hierarchy under the patch of one mesh corner.
struct BezierPatch {
  /// The control points, P[a][b] = net.p[4 * a + b] (a is the u index); `extraordinary` is 0,
  /// since the patch is meant as the plain polynomial of its net.
  ControlNet net;
  Corner corner;   ///< the root patch: the mesh corner (half-edge) it lies in
  int face = 0;    ///< face of that corner (0-based index)
  int vertex = 0;  ///< vertex of that corner (0-based index)
  int level = 0;   ///< modified de Casteljau splits from the root (0: the root itself)
  int cell_u = 0;  ///< the cell covers u in [cell_u, cell_u + 1] / 2^level of the root
  int cell_v = 0;  ///< and v in [cell_v, cell_v + 1] / 2^level
  /// True when the polynomial is the surface (regular root or regular child). False for the
  /// innermost cell at an extraordinary point, whose polynomial only approximates the surface.
  bool exact = true;
};

struct PatchSetOptions {
  /// Largest distance of an inexact cell from the surface, relative to the model size (the
  /// diagonal of the bounding box of the control points). > 0.
  double tolerance = 1e-6;
  /// Largest angle between an inexact cell's normal and the surface's, in degrees. > 0.
  double angle_tolerance_deg = 0.1;
  /// Depth at which a tolerance that cannot be reached is refused.
  int max_depth = 30;
};

struct PatchSet {
  Method method = Method::mdc;
  std::vector<BezierPatch> patches;  ///< root corner order, each root's cells depth first
  int depth = 0;                     ///< splits at extraordinary points (0: none needed)
  double model_size = 0;             ///< bounding box diagonal of the control points
  double tolerance = 0, angle_tolerance_deg = 0;  ///< as asked
  /// Largest deviation of an inexact cell from Surface::evaluate, measured on a grid of samples
  /// in every innermost cell: distance in model units and normal angle in degrees.
  double max_position_deviation = 0, max_normal_deviation_deg = 0;

  [[nodiscard]] int num_exact() const;
};

/// The patches of the surface: for mdc, every extraordinary root split to the smallest depth at
/// which the innermost cells are within the tolerances; for asc, the roots as they are. Throws
/// UsageError for cc (not a set of Bézier patches), a tolerance <= 0 or not finite,
/// and stitch::Error when max_depth does not reach the tolerance.
PatchSet bezier_patches(const HalfedgeMesh& mesh, const Surface& surface,
                        const PatchSetOptions& options = {});

/// The plain polynomial of one patch at (u, v) of its own cell, in the root's scale of
/// derivatives (du, dv multiplied by 2^level) so it can be compared with Surface::evaluate.
SurfacePoint evaluate_cell(const BezierPatch& patch, double u, double v);

/// (u, v) of the root patch for (s, t) of the cell.
std::array<double, 2> cell_to_root(const BezierPatch& patch, double s, double t);

}  // namespace stitch
