// Shared helpers of the test suite: where the test meshes are, and small meshes built in code.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"

namespace stitch::test {

inline std::string opensubdiv_shape(const std::string& name) {
  return std::string(STITCH_OPENSUBDIV_SHAPES_DIR) + "/" + name;
}
inline std::string example_path(const std::string& name) {
  return std::string(STITCH_EXAMPLES_DIR) + "/" + name;
}

/// The message of the MeshError `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

/// The closed orientable meshes of the OpenSubdiv regression shapes (tests/data/opensubdiv-shapes,
/// see its README).
inline const std::vector<std::string>& closed_opensubdiv_shapes() {
  static const std::vector<std::string> names{
      "bilinear_cube.obj",          "catmark_cube.obj",       "catmark_torus.obj",
      "catmark_torus_creases0.obj", "catmark_pyramid.obj",    "catmark_smoothtris0.obj",
      "catmark_righthanded.obj",    "catmark_chaikin0.obj",   "catmark_cubes_semisharp.obj",
      "loop_icosahedron.obj",       "loop_tetrahedron.obj",   "loop_cube.obj",
      "loop_cubes_infsharp.obj",    "loop_icos_semisharp.obj"};
  return names;
}

/// An axis-aligned unit cube centred at the origin, faces pointing outward.
inline HalfedgeMesh cube_mesh() {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i)
    s.positions.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
  s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return build_mesh(s);
}

/// A regular tetrahedron, faces pointing outward.
inline HalfedgeMesh tetrahedron_mesh() {
  PolygonSoup s;
  s.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  s.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  return build_mesh(s);
}

}  // namespace stitch::test
