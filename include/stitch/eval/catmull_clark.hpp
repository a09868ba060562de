// The Catmull-Clark limit surface of a mesh through OpenSubdiv (Bfr), parameterized per corner
// like the Bézier patches so that the methods are compared on equal terms.
#pragma once

#include <memory>

#include "stitch/eval/bezier.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Corner c's patch is the quarter of a quad face at that corner, or the quad sub-face of a
/// non-quad face at that corner (OpenSubdiv's sub-face parameterization); (u, v) follow the
/// conventions of control_net.hpp: (0,0) at the vertex, u towards the midpoint of edge(c),
/// v towards the midpoint of edge(prev(c)), (1,1) at the face centre.
class CatmullClarkSurface {
 public:
  explicit CatmullClarkSurface(const HalfedgeMesh& mesh);
  ~CatmullClarkSurface();
  CatmullClarkSurface(CatmullClarkSurface&&) noexcept;
  CatmullClarkSurface& operator=(CatmullClarkSurface&&) noexcept;

  [[nodiscard]] SurfacePoint evaluate(Corner c, double u, double v) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stitch
