// CPU-side geometry of what is drawn over (or instead of) the smooth surface: the input mesh,
// the K-gons, the control nets, the tessellation's quads and the extraordinary points. No GL
// here, so the modeler can rebuild these for the parts it edits and upload them itself.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/net/control_net.hpp"
#include "stitch/tess/surface_mesh.hpp"

namespace stitch {

using Colour = Eigen::Vector3f;  ///< linear RGB in [0, 1]

/// Independent segments: segment i runs from points[2i] to points[2i+1], coloured colours[i].
struct LineSet {
  std::vector<Vec3> points;
  std::vector<Colour> colours;

  void add(const Vec3& a, const Vec3& b, const Colour& c) {
    points.push_back(a);
    points.push_back(b);
    colours.push_back(c);
  }
  /// Adds the closed polygon through `loop`.
  void add_loop(const std::vector<Vec3>& loop, const Colour& c);
  [[nodiscard]] int num_segments() const { return static_cast<int>(colours.size()); }
};

struct MarkerSet {
  std::vector<Vec3> positions;
  std::vector<Colour> colours;
};

/// An extraordinary point of the surface: the centroid of a K-gon with K != 4 (a vertex of
/// valence != 4 or a face of degree != 4), where the surface has the K-gon's normal.
struct ExtraordinaryPoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  int k = 4;
  KgonKind kind = KgonKind::vertex;
  int element = -1;  ///< vertex or face index
  /// Size of the patches meeting there: the mean distance from the point to their opposite
  /// corners (a scale for close-ups).
  double extent = 0.0;
};

/// Every extraordinary point, vertices first, each in index order.
std::vector<ExtraordinaryPoint> extraordinary_points(const HalfedgeMesh& mesh,
                                                     const KgonSet& kgons);
/// The one with the largest K (ties: the first in the order above); throws std::invalid_argument
/// when there is none (a mesh of quads with every valence 4, e.g. a torus).
const ExtraordinaryPoint& highest_valence_point(const std::vector<ExtraordinaryPoint>& points);

/// Colours used by the overlays, also listed in docs/gallery.md.
namespace palette {
inline const Colour mesh{0.10f, 0.10f, 0.12f};
inline const Colour face_kgon{0.85f, 0.20f, 0.15f};
inline const Colour vertex_kgon{0.15f, 0.35f, 0.90f};
inline const Colour edge_kgon{0.15f, 0.65f, 0.25f};
inline const Colour net{0.55f, 0.20f, 0.65f};
inline const Colour tessellation{0.20f, 0.20f, 0.25f};
inline const Colour extraordinary{0.95f, 0.55f, 0.05f};
}  // namespace palette

LineSet mesh_lines(const HalfedgeMesh& mesh);
/// Face K-gons red, vertex K-gons blue, edge K-gons green.
LineSet kgon_lines(const KgonSet& kgons);
/// The 4x4 grid lines of the nets of `corners`.
LineSet control_net_lines(const std::vector<ControlNet>& nets, const std::vector<Corner>& corners);
/// The edges of every quad of a tessellation (the output polygon mesh).
LineSet surface_mesh_lines(const SurfaceMesh& surface);
MarkerSet extraordinary_markers(const std::vector<ExtraordinaryPoint>& points);

/// The input polygons as a drawable SurfaceMesh: each face fanned around its centroid (one
/// degenerate quad per edge), flat normals, patch = face index, level 0.
SurfaceMesh input_faces(const HalfedgeMesh& mesh);

}  // namespace stitch
