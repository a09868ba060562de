// Control nets: one 4x4 bicubic Bézier net per corner of the input mesh (method.md, section 3).
//
// The patch of corner c (the half-edge of face f leaving vertex v) is the quad of one
// vertex-insertion step at c. Its parameterization:
//   P[0][0] at vertex v (vertex K-gon centroid),   u runs towards the midpoint of edge(c),
//   P[3][0] at the middle of edge(c),              v runs towards the midpoint of edge(prev(c)),
//   P[3][3] at the centre of face f,
//   P[0][3] at the middle of edge(prev(c)).
// so du x dv points to the side the input face points to.
//
// Sides (a is the u index, b the v index) and the patch across each:
//   side 0 (b = 0): point (t, 0) of c  = point (0, t) of rotate_cw(c)  (its side 3)
//   side 1 (a = 3): point (1, t) of c  = point (t, 1) of next(c)       (its side 2)
//   side 2 (b = 3): point (t, 1) of c  = point (1, t) of prev(c)       (its side 1)
//   side 3 (a = 0): point (0, t) of c  = point (t, 0) of rotate_ccw(c) (its side 0)
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Patch corners in the order used by ControlNet::extraordinary.
enum PatchCorner : std::uint8_t {
  corner00 = 1,  ///< P[0][0] (the mesh vertex)
  corner30 = 2,  ///< P[3][0] (edge(c))
  corner33 = 4,  ///< P[3][3] (the face centre)
  corner03 = 8,  ///< P[0][3] (edge(prev(c)))
};

struct ControlNet {
  std::array<Vec3, 16> p;          ///< P[a][b] = p[4 * a + b]
  std::uint8_t extraordinary = 0;  ///< PatchCorner bits of the corners whose K != 4
  /// K of the K-gon at each patch corner, in the order 00, 30, 33, 03.
  std::array<int, 4> corner_k{4, 4, 4, 4};

  Vec3& at(int a, int b) { return p[4 * a + b]; }
  [[nodiscard]] const Vec3& at(int a, int b) const { return p[4 * a + b]; }
  [[nodiscard]] bool regular() const { return extraordinary == 0; }
  bool operator==(const ControlNet&) const = default;
};

/// The net kept at an index that makes no patch (a deleted half-edge, a hole's corner): all
/// points at the origin.
ControlNet unused_net();

/// The net of one corner.
ControlNet build_control_net(const HalfedgeMesh& mesh, const KgonSet& kgons, Corner c);

/// The nets of every corner, indexed by half-edge (unused_net() where there is no patch).
std::vector<ControlNet> build_control_nets(const HalfedgeMesh& mesh, const KgonSet& kgons);
/// The same into `nets`, whose storage is kept when it is large enough (rebuilding a surface
/// without fresh memory for its largest array).
void build_control_nets(const HalfedgeMesh& mesh, const KgonSet& kgons,
                        std::vector<ControlNet>& nets);

/// The dependency rule of the nets: the corners whose nets read a K-gon of `kgons` (a net reads
/// the K-gons of its face, its vertex, its edge and its previous edge), sorted, without repeats
/// and without the corners of holes (they make no patch).
std::vector<Corner> nets_reading(const HalfedgeMesh& mesh, const KgonElements& kgons);

/// The patch across `side` of the patch of corner c, and the side of that patch it meets.
struct PatchNeighbour {
  Corner corner;
  int side;
};
PatchNeighbour neighbour_across(const HalfedgeMesh& mesh, Corner c, int side);

/// (u, v) of the point at parameter t along `side` (t runs from the side's first corner in the
/// order listed above: sides 0 and 3 start at the vertex, sides 1 and 2 at the edge midpoint).
std::array<double, 2> side_point(int side, double t);

}  // namespace stitch
