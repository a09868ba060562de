// The exact surface as tensor-product B-spline faces, for CAD. The cells under one mesh corner
// tile its root patch's square dyadically (cell [k, k + 1] / 2^level), so the whole hierarchy of
// one corner is one bicubic B-spline with knots at the cells' sides; the four corner patches of a
// quad tile the quad's square the same way (docs/formats.md, "B-spline faces").
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "stitch/eval/semi_sharp.hpp"
#include "stitch/tess/patches.hpp"

namespace stitch {

enum class FacePacking {
  quads,    ///< the corner patches of each quad of the mesh in one face; K != 4: K faces
  corners,  ///< one face per corner patch
};
/// The packings by name (quads first: the default).
ChoiceTable<FacePacking> face_packing_table();

/// Where a root patch lies in its face: the face's (s, t) of the root's (u, v) is origin + size *
/// the quarter turn of (u, v) about the unit square's centre (origin 0, size 1 and rotation 0
/// for a face of one corner patch).
struct FaceQuadrant {
  Corner corner;
  int rotation =
      0;  ///< quarter turns of (u, v): 0 (u, v), 1 (1 - v, u), 2 (1 - u, 1 - v), 3 (v, 1 - u)
  double size = 1;  ///< 1; 1/2 in a packed quad; smaller for a refined mesh (ControlMesh)
  std::array<double, 2> origin{0, 0};
};

/// The mesh a surface's faces are packed and named after when the surface was built on a
/// refinement of it (for semi-sharp tags, SemiSharpMesh): the refined patches of one control
/// corner tile its patch's square dyadically, as the cells of a hierarchy do, so a control quad
/// is still one face. `roots`, by half-edge of the refined mesh: the control corner whose patch
/// holds that corner's patch, and where (FaceQuadrant's rule, in the control patch's square).
struct ControlMesh {
  const HalfedgeMesh* mesh = nullptr;
  std::vector<FaceQuadrant> roots;
};
/// `input` as the control mesh of a surface built on its semi-sharp refinement `refined`.
ControlMesh control_mesh(const HalfedgeMesh& input, const SemiSharpMesh& refined);

/// One bicubic B-spline face. Its knots are clamped (multiplicity 4 at 0 and 1) and its interior
/// knots have multiplicity 3, so the poles are the Bézier nets of the grid's rectangles sharing
/// their sides: exact for any piecewise polynomial that is continuous. A CAD writer lowers the
/// multiplicities where the surface is smoother (cad/cad.hpp).
struct BsplineFace {
  int face = 0;     ///< the (control) mesh face (0-based)
  int vertex = -1;  ///< the corner's vertex for a face of one corner patch; -1 for a packed quad
  Corner corner;    ///< that corner of the (control) mesh; invalid for a packed quad
  std::vector<FaceQuadrant> quadrants;   ///< 1, or 4 in the order of the face's corners
  std::vector<double> u_knots, v_knots;  ///< distinct, from 0 to 1 (u is s, v is t)
  std::vector<Vec3> poles;               ///< u major: poles[i * num_v_poles() + j]
  /// Whether each side lies on a sharp edge of the mesh (a boundary or an infinitely sharp
  /// crease), where the surface is only continuous. Sides in the order t = 0, s = 1, t = 1, s = 0.
  std::array<bool, 4> sharp_side{};

  [[nodiscard]] int num_u_poles() const { return 3 * static_cast<int>(u_knots.size()) - 2; }
  [[nodiscard]] int num_v_poles() const { return 3 * static_cast<int>(v_knots.size()) - 2; }
  [[nodiscard]] const Vec3& pole(int i, int j) const { return poles[i * num_v_poles() + j]; }
};

/// A point of a face as a point of the surface: the root patch and its (u, v).
struct RootPoint {
  Corner corner;
  double u = 0, v = 0;
};
RootPoint root_point(const BsplineFace& face, double s, double t);

/// The face's name, after its control elements (numbered from 1 as in the input file):
/// "face F" for a packed quad, "corner V@F" (as `stitch edit` writes corners) for one corner.
/// `mesh` is the control mesh when the faces were laid out after one.
std::string face_name(const HalfedgeMesh& mesh, const BsplineFace& face);

/// The faces' quadrants, sides and knots, without poles: what a writer can tell before the work.
std::vector<BsplineFace> bspline_face_layout(const HalfedgeMesh& mesh, const Surface& surface,
                                             const PatchSet& patches, FacePacking packing,
                                             const ControlMesh* control = nullptr);

/// The faces of the patch set: for `quads`, one per quad of the mesh and one per corner of every
/// other face, in face order; for `corners`, one per corner patch. With a control mesh, its
/// faces and corners are the ones packed. `progress` (optional) is told the fraction done.
std::vector<BsplineFace> bspline_faces(const HalfedgeMesh& mesh, const Surface& surface,
                                       const PatchSet& patches, FacePacking packing,
                                       const std::function<void(double)>& progress = {},
                                       const ControlMesh* control = nullptr);

}  // namespace stitch
