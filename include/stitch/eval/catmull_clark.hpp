// The Catmull-Clark limit surface of a mesh through OpenSubdiv (Bfr), parameterized per corner
// like the Bézier patches so that the methods are compared on equal terms.
#pragma once

#include <array>
#include <memory>

#include "stitch/eval/bezier.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Corner c's patch is the quarter of a quad face at that corner, or the quad sub-face of a
/// non-quad face at that corner (OpenSubdiv's sub-face parameterization); (u, v) follow the
/// conventions of control_net.hpp: (0,0) at the vertex, u towards the midpoint of edge(c),
/// v towards the midpoint of edge(prev(c)), (1,1) at the face centre.
///
/// The mesh's feature tags are OpenSubdiv's: hole faces are left out, so their edges are the
/// surface's boundary (an OpenSubdiv hole tag would only stop the face being drawn and keep the
/// surface around it as if the face were there); edge and vertex sharpness become crease and
/// corner sharpness, semi-sharp values included; `boundary` is Sdc's boundary interpolation.
/// Only corners outside holes have patches. A vertex where the surface's boundary passes more
/// than once is refused (stitch::Error): OpenSubdiv would make it a non-manifold corner.
///
/// The constructor builds every face's Bfr surface (in parallel). OpenSubdiv cannot represent
/// every mesh this library holds (2-sided faces, faces running along one edge twice or visiting
/// a vertex twice, several edges between two vertices); on such meshes the surface is that of
/// one or two Catmull-Clark steps taken first with OpenSubdiv's rules, creases, corners and
/// boundaries included (catmull_clark_refinement for the connectivity), which is the same limit
/// surface in the same parameterization.
/// evaluate() is const and keeps no mutable state, so it may be called concurrently.
class CatmullClarkSurface {
 public:
  explicit CatmullClarkSurface(
      const HalfedgeMesh& mesh,
      BoundaryInterpolation boundary = BoundaryInterpolation::edge_and_corner);
  /// The surface of a mesh that is `steps_taken` Catmull-Clark steps from the one whose limit
  /// surface is wanted. OpenSubdiv fits Gregory patches in the smallest regions around
  /// extraordinary points, two levels below the original mesh (and refines a bounded number of
  /// levels around sharp features); counting the steps keeps those regions where they were, so
  /// the result is the original's surface up to round-off.
  CatmullClarkSurface(const HalfedgeMesh& mesh, int steps_taken,
                      BoundaryInterpolation boundary = BoundaryInterpolation::edge_and_corner);
  ~CatmullClarkSurface();
  CatmullClarkSurface(CatmullClarkSurface&&) noexcept;
  CatmullClarkSurface& operator=(CatmullClarkSurface&&) noexcept;

  /// Position, du and dv in the corner patch's own (u, v), unit normal du x dv, level 0.
  /// Throws stitch::Error for a corner that is not a live half-edge of the mesh outside holes.
  [[nodiscard]] SurfacePoint evaluate(Corner c, double u, double v) const;

 private:
  void init_from_refinement(const HalfedgeMesh& mesh, int steps_taken,
                            BoundaryInterpolation boundary);
  /// The refined surface over the whole quad of one corner, in that corner's (u, v).
  [[nodiscard]] SurfacePoint evaluate_refined_quad(const std::array<Corner, 4>& quad, double u,
                                                   double v) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stitch
