// The Catmull-Clark limit surface of a mesh through OpenSubdiv (Bfr), parameterized per corner
// like the Bézier patches so that the methods are compared on equal terms.
#pragma once

#include <memory>
#include <string>

#include "stitch/eval/bezier.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Corner c's patch is the quarter of a quad face at that corner, or the quad sub-face of a
/// non-quad face at that corner (OpenSubdiv's sub-face parameterization); (u, v) follow the
/// conventions of control_net.hpp: (0,0) at the vertex, u towards the midpoint of edge(c),
/// v towards the midpoint of edge(prev(c)), (1,1) at the face centre.
///
/// The constructor builds every face's Bfr surface (in parallel). OpenSubdiv cannot represent
/// every mesh this library can hold: a face whose loop runs along the same edge twice, and
/// 2-sided faces (Bfr gives the faces around them no limit surface), are refused with a
/// MeshError saying so. Faces visiting a vertex twice and several edges between two vertices
/// are passed on as they are, but Bfr's surface can come apart around them, so on such meshes
/// the constructor checks that neighbouring patches meet and refuses the mesh if they do not.
/// evaluate() is const and keeps no mutable state, so it may be called concurrently.
class CatmullClarkSurface {
 public:
  explicit CatmullClarkSurface(const HalfedgeMesh& mesh);
  ~CatmullClarkSurface();
  CatmullClarkSurface(CatmullClarkSurface&&) noexcept;
  CatmullClarkSurface& operator=(CatmullClarkSurface&&) noexcept;

  /// Position, du and dv in the corner patch's own (u, v), unit normal du x dv, level 0.
  /// Throws MeshError for a corner that is not a live half-edge of the mesh.
  [[nodiscard]] SurfacePoint evaluate(Corner c, double u, double v) const;

 private:
  void check_patch_sides(const HalfedgeMesh& mesh, const std::string& unusual) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stitch
