#include "stitch/topology/primitives.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch {

namespace {

HalfedgeMesh from_one_based(std::vector<Vec3> positions,
                            const std::vector<std::vector<int>>& faces) {
  PolygonSoup soup;
  soup.positions = std::move(positions);
  for (const auto& f : faces) {
    soup.faces.emplace_back();
    for (int v : f) soup.faces.back().push_back(v - 1);
  }
  return build_mesh(soup);
}

}  // namespace

HalfedgeMesh make_tetrahedron() {
  return from_one_based({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                        {{1, 2, 3}, {1, 4, 2}, {1, 3, 4}, {2, 4, 3}});
}

HalfedgeMesh make_cube() {
  return from_one_based(
      {{-1, -1, -1},
       {1, -1, -1},
       {1, 1, -1},
       {-1, 1, -1},
       {-1, -1, 1},
       {1, -1, 1},
       {1, 1, 1},
       {-1, 1, 1}},
      {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}});
}

HalfedgeMesh make_octahedron() {
  return from_one_based(
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
      {{1, 3, 5}, {3, 2, 5}, {2, 4, 5}, {4, 1, 5}, {3, 1, 6}, {2, 3, 6}, {4, 2, 6}, {1, 4, 6}});
}

HalfedgeMesh make_icosahedron() {
  const double p = std::numbers::phi;
  return from_one_based(
      {{-1, p, 0},
       {1, p, 0},
       {-1, -p, 0},
       {1, -p, 0},
       {0, -1, p},
       {0, 1, p},
       {0, -1, -p},
       {0, 1, -p},
       {p, 0, -1},
       {p, 0, 1},
       {-p, 0, -1},
       {-p, 0, 1}},
      {{1, 12, 6},  {1, 6, 2},  {1, 2, 8},  {1, 8, 11}, {1, 11, 12}, {2, 6, 10}, {6, 12, 5},
       {12, 11, 3}, {11, 8, 7}, {8, 2, 9},  {4, 10, 5}, {4, 5, 3},   {4, 3, 7},  {4, 7, 9},
       {4, 9, 10},  {5, 10, 6}, {3, 5, 12}, {7, 3, 11}, {9, 7, 8},   {10, 9, 2}});
}

HalfedgeMesh make_dodecahedron() {
  // The dual of the icosahedron, with vertices pushed out to a common radius: face centroids of
  // a regular icosahedron are the vertices of a regular dodecahedron.
  const HalfedgeMesh ico = make_icosahedron();
  PolygonSoup soup;
  for (Face f : ico.faces()) {
    Vec3 c = Vec3::Zero();
    for (Halfedge h : ico.face_loop(f)) c += ico.position(ico.origin(h));
    soup.positions.push_back(c.normalized() * std::sqrt(3.0));
  }
  for (Vertex v : ico.vertices()) {
    soup.faces.emplace_back();
    // Faces around v counter-clockwise: each outgoing half-edge's face, in fan order.
    for (Halfedge h : ico.vertex_fan(v)) soup.faces.back().push_back(ico.face(h).idx);
  }
  // The fan runs counter-clockwise around v, so its faces' points run counter-clockwise too.
  return build_mesh(soup);
}

HalfedgeMesh make_prism(int n) {
  if (n < 2) throw UsageError(fmt::format("prism: needs n >= 2 sides, got {}", n));
  if (n > limits::max_primitive_faces - 2)
    throw UsageError(
        fmt::format("prism: at most {} sides (a primitive has at most {} faces), got {}",
                    limits::max_primitive_faces - 2, limits::max_primitive_faces, n));
  std::vector<Vec3> pos;
  for (int z : {-1, 1})
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      pos.emplace_back(std::cos(a), std::sin(a), z);
    }
  std::vector<std::vector<int>> faces(2);
  for (int i = n; i >= 1; --i) faces[0].push_back(i);
  for (int i = 1; i <= n; ++i) faces[1].push_back(n + i);
  for (int i = 1; i <= n; ++i) {
    const int j = i % n + 1;
    faces.push_back({i, j, n + j, n + i});
  }
  PolygonSoup soup;
  soup.positions = pos;
  for (const auto& f : faces) {
    soup.faces.emplace_back();
    for (int v : f) soup.faces.back().push_back(v - 1);
  }
  BuildOptions options;
  options.allow_two_gons = true;  // a 2-prism has 2-sided caps
  return build_mesh(soup, options);
}

HalfedgeMesh make_torus(int m, int n, double major_radius, double minor_radius) {
  if (m < 3 || n < 3)
    throw UsageError(fmt::format("torus: needs m, n >= 3 segments, got {} x {}", m, n));
  if (static_cast<long long>(m) * n > limits::max_primitive_faces)
    throw UsageError(fmt::format("torus: at most {} faces (m x n), got {} x {}",
                                 limits::max_primitive_faces, m, n));
  PolygonSoup soup;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * std::numbers::pi * i / m, v = 2 * std::numbers::pi * j / n;
      const double r = major_radius + minor_radius * std::cos(v);
      soup.positions.emplace_back(r * std::cos(u), r * std::sin(u), minor_radius * std::sin(v));
    }
  auto id = [&](int i, int j) { return (i % m) * n + (j % n); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j)
      soup.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return build_mesh(soup);
}

HalfedgeMesh make_primitive(const std::string& name, const std::vector<int>& params) {
  auto expect = [&](size_t count, const char* usage) {
    if (params.size() != count)
      throw UsageError(
          fmt::format("primitive {}: expected {} parameter(s): {}", name, count, usage));
  };
  if (name == "tetrahedron") return expect(0, "none"), make_tetrahedron();
  if (name == "cube") return expect(0, "none"), make_cube();
  if (name == "octahedron") return expect(0, "none"), make_octahedron();
  if (name == "dodecahedron") return expect(0, "none"), make_dodecahedron();
  if (name == "icosahedron") return expect(0, "none"), make_icosahedron();
  if (name == "prism") return expect(1, "N (sides, >= 2)"), make_prism(params[0]);
  if (name == "torus")
    return expect(2, "M N (segments around and across, each >= 3)"),
           make_torus(params[0], params[1]);
  throw UsageError(
      fmt::format("unknown primitive '{}' (known: tetrahedron, cube, octahedron, "
                  "dodecahedron, icosahedron, prism N, torus M N)",
                  name));
}

std::vector<std::string> primitive_names() {
  return {"tetrahedron", "cube",    "octahedron", "dodecahedron",
          "icosahedron", "prism N", "torus M N"};
}

}  // namespace stitch
