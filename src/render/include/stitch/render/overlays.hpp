// CPU-side geometry of what is drawn over (or instead of) the smooth surface: the input mesh,
// the K-gons, the control nets, the tessellation's quads, the extraordinary points and the
// surface's sharp curves (boundaries and creases). No GL here, so the modeler can rebuild these
// for the parts it edits and upload them itself.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/net/control_net.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

using Colour = Eigen::Vector3f;  ///< linear RGB in [0, 1]

/// Independent segments: segment i runs from points[2i] to points[2i+1], coloured colours[i],
/// widths[i] times the overlay's line width (an empty `widths` means 1 for every segment, so
/// sets that never widen a line pay nothing for it).
struct LineSet {
  std::vector<Vec3> points;
  std::vector<Colour> colours;
  std::vector<float> widths;

  void add(const Vec3& a, const Vec3& b, const Colour& c, float width = 1.0f) {
    points.push_back(a);
    points.push_back(b);
    colours.push_back(c);
    if (width != 1.0f && widths.empty()) widths.assign(colours.size() - 1, 1.0f);
    if (!widths.empty()) widths.push_back(width);
  }
  /// The width factor of segment i.
  [[nodiscard]] float width(int i) const {
    return static_cast<size_t>(i) < widths.size() ? widths[static_cast<size_t>(i)] : 1.0f;
  }
  /// Adds the closed polygon through `loop`.
  void add_loop(std::span<const Vec3> loop, const Colour& c);
  [[nodiscard]] int num_segments() const { return static_cast<int>(colours.size()); }
};

struct MarkerSet {
  std::vector<Vec3> positions;
  std::vector<Colour> colours;
  /// Lines shown with the markers: the surface's sharp curves (sharp_curve_lines).
  LineSet curves;
};

/// An extraordinary point of the surface: the centroid of a K-gon with K != 4 (a vertex of
/// valence != 4 or a face of degree != 4), where the surface has the K-gon's normal. At a vertex
/// on two or more sharp edges, each sector of patches has its own K (KgonSet::vertex_k) and
/// normal, so each sector with K != 4 is a point of its own (same element, same position).
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

/// Every extraordinary point, vertices first, each in index order; holes have none.
std::vector<ExtraordinaryPoint> extraordinary_points(const HalfedgeMesh& mesh,
                                                     const KgonSet& kgons);
/// The one with the largest K (ties: the first in the order above); throws UsageError
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
inline const Colour boundary{0.00f, 0.55f, 0.65f};
inline const Colour crease{0.80f, 0.05f, 0.50f};
}  // namespace palette

/// Segments along sharp features are this many times wider than the other lines of their set.
inline constexpr float sharp_line_width = 2.5f;

/// The input wireframe; boundary edges and edges with a crease tag in their own colours and
/// wider (a crease the more, the sharper its tag).
LineSet mesh_lines(const HalfedgeMesh& mesh);
/// Face K-gons red, vertex K-gons blue, edge K-gons green, each as one closed loop (for a mesh
/// without holes or sharp edges; the modeler's).
LineSet kgon_lines(const KgonSet& kgons);
/// The same for any mesh: no K-gons of holes, the vertex K-gon at a vertex on two or more sharp
/// edges (KgonSet::sharp) drawn per sector (its points closed through the curve point, where the
/// sector's ghost points would be), and an edge K-gon's points on a hole side (all at the midpoint)
/// drawn once.
LineSet kgon_lines(const HalfedgeMesh& mesh, const KgonSet& kgons);
/// The surface's curves along the edges sharp for its method (sharp_edges), `segments` per patch
/// side, boundaries and creases in their colours and wider: evaluated from `surface`, so they
/// are that method's curves.
LineSet sharp_curve_lines(const HalfedgeMesh& mesh, const Surface& surface, int segments);
/// The 4x4 grid lines of the nets of `corners`.
LineSet control_net_lines(const std::vector<ControlNet>& nets, const std::vector<Corner>& corners);
/// The edges of every quad of a tessellation (the output polygon mesh).
LineSet surface_mesh_lines(const TessellatedMesh& surface);
MarkerSet extraordinary_markers(const std::vector<ExtraordinaryPoint>& points);

/// The input polygons as a drawable TessellatedMesh: each face fanned around its centroid (one
/// degenerate quad per edge), flat normals, patch = face index, level 0. Holes are left out.
TessellatedMesh input_faces(const HalfedgeMesh& mesh);
/// Texture coordinates of input_faces' vertices: each corner's own UV, the mean of the face's
/// UVs at its centre. Throws stitch::Error when a face has none (one --fill-holes added).
std::vector<Eigen::Vector2d> input_face_texcoords(const HalfedgeMesh& mesh, const CornerUvs& uvs);

}  // namespace stitch
