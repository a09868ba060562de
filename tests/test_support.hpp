// Shared helpers of the test suite: where the test meshes are, and small meshes built in code.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"

namespace stitch::test {

inline std::string opensubdiv_shape(const std::string& name) {
  return std::string(STITCH_OPENSUBDIV_SHAPES_DIR) + "/" + name;
}
/// The file names of the OpenSubdiv shapes ("catmark_cube.obj", ...), sorted.
inline std::vector<std::string> opensubdiv_shape_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(STITCH_OPENSUBDIV_SHAPES_DIR))
    if (entry.path().extension() == ".obj") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}
inline std::string example_path(const std::string& name) {
  return std::string(STITCH_EXAMPLES_DIR) + "/" + name;
}

/// The message of the Error `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
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

/// An axis-aligned unit cube centred at the origin, faces pointing outward: vertex i at
/// ((i & 1) - 0.5, (i & 2) / 2 - 0.5, (i & 4) / 4 - 0.5).
inline PolygonSoup cube_soup() {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i)
    s.positions.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
  s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return s;
}

inline HalfedgeMesh cube_mesh() {
  return build_mesh(cube_soup());
}

/// A regular tetrahedron, faces pointing outward.
inline HalfedgeMesh tetrahedron_mesh() {
  PolygonSoup s;
  s.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  s.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  return build_mesh(s);
}

/// Doubles edge(h) with a 2-sided face, as the topology operators make them: h stays in its
/// face and lends its twin t to the 2-gon; a new edge gives t's old face a half-edge in t's place
/// and the 2-gon its other half-edge. Returns the 2-gon.
inline Face double_with_two_gon(HalfedgeMesh& mesh, Halfedge h) {
  const Halfedge t = HalfedgeMesh::twin(h);
  const Face other = mesh.face(t);
  const Halfedge before = mesh.prev(t), after = mesh.next(t);
  const Halfedge h2 = mesh.add_edge(mesh.origin(h), mesh.target(h));
  const Halfedge t2 = HalfedgeMesh::twin(h2);
  mesh.link(before, t2);
  mesh.link(t2, after);
  mesh.set_face(t2, other);
  mesh.set_halfedge(other, t2);
  const Face two_gon = mesh.add_face();
  mesh.link(t, h2);
  mesh.link(h2, t);
  mesh.assign_loop(t, two_gon);
  return two_gon;
}

/// Signed volume enclosed by the faces, each fanned from its first corner: positive when the
/// faces are oriented outward.
inline double signed_volume(const HalfedgeMesh& mesh) {
  double volume = 0;
  for (Face f : mesh.faces()) {
    const auto loop = mesh.face_loop(f);
    const Vec3& a = mesh.position(mesh.origin(loop[0]));
    for (size_t i = 1; i + 1 < loop.size(); ++i)
      volume +=
          a.dot(mesh.position(mesh.origin(loop[i])).cross(mesh.position(mesh.origin(loop[i + 1]))));
  }
  return volume / 6;
}

/// The diagonal of the bounding box of the live vertices: the model size tolerances scale with.
inline double mesh_size(const HalfedgeMesh& mesh) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Vertex v : mesh.vertices()) {
    lo = lo.cwiseMin(mesh.position(v));
    hi = hi.cwiseMax(mesh.position(v));
  }
  return (hi - lo).norm();
}

}  // namespace stitch::test
