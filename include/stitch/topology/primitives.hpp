// Primitive solids, each a closed oriented mesh with outward counter-clockwise faces, centred at
// the origin. Numbering (0-based here, 1-based in files) is documented in docs/editing.md.
#pragma once

#include <string>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Vertices at the alternate corners (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1).
HalfedgeMesh make_tetrahedron();
/// The cube [-1,1]^3. Vertices: 1 (-1,-1,-1), 2 (1,-1,-1), 3 (1,1,-1), 4 (-1,1,-1),
/// 5 (-1,-1,1), 6 (1,-1,1), 7 (1,1,1), 8 (-1,1,1). Faces: 1 bottom (z=-1) 1 4 3 2,
/// 2 top (z=1) 5 6 7 8, 3 front (y=-1) 1 2 6 5, 4 right (x=1) 2 3 7 6, 5 back (y=1) 3 4 8 7,
/// 6 left (x=-1) 4 1 5 8. Faces 1 and 2, 3 and 5, 4 and 6 are opposite.
HalfedgeMesh make_cube();
/// Vertices at +-1 on the axes: +x, -x, +y, -y, +z, -z.
HalfedgeMesh make_octahedron();
/// 20 vertices, 12 pentagons, circumradius sqrt(3).
HalfedgeMesh make_dodecahedron();
/// 12 vertices (0, +-1, +-phi) and cyclic permutations, 20 triangles.
HalfedgeMesh make_icosahedron();
/// An n-sided prism (n >= 2): bottom ring 1..n at z=-1, top ring n+1..2n at z=1, on the unit
/// circle; faces: 1 bottom, 2 top, then side i+2 on edge (i, i+1) of the rings.
HalfedgeMesh make_prism(int n);
/// A torus of m segments around the main axis (z) and n around the tube (m, n >= 3), major
/// radius 2, minor radius 0.5 (scaled by R, r). Vertex i*n + j (0-based) is ring i, tube step j;
/// face i*n + j is the quad from (i, j) to (i+1, j+1).
HalfedgeMesh make_torus(int m, int n, double major_radius = 2.0, double minor_radius = 0.5);

/// Builds a primitive by name with integer parameters (prism: n; torus: m n), as the command
/// line and the operation lines spell them. Throws stitch::Error for an unknown name or bad params.
HalfedgeMesh make_primitive(const std::string& name, const std::vector<int>& params);

/// The names make_primitive() accepts, with their parameters, for help texts.
std::vector<std::string> primitive_names();

}  // namespace stitch
