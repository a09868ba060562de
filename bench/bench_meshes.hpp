// The generated meshes the benchmarks share: quad tori and tori with some quads split into
// triangles, of about a given number of faces, built once per process.
#pragma once

#include <sys/resource.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::bench {

enum MeshKind : int { quad_torus = 0, mixed_torus = 1, triangle_torus = 2 };

// The process's peak resident size so far, in GB (getrusage): a benchmark's own when it is the
// only one the process runs (--benchmark_filter matching one case).
inline double peak_rss_gb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024 / 1e9;  // ru_maxrss is in kB on Linux
}

// A torus of m x n quads, all vertices regular.
inline HalfedgeMesh make_quad_torus(int m, int n) {
  return make_torus(m, n);
}

// The same torus with the diagonal of every fourth quad inserted (a quarter of the quads become
// two triangles): half of the vertices get valence 5, and two fifths of the faces are triangles,
// where the hierarchical evaluation of mdc and the irregular patches of Bfr do extra work.
inline HalfedgeMesh make_mixed_torus(int m, int n) {
  HalfedgeMesh mesh = make_torus(m, n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      if ((i + 2 * j) % 4 != 0) continue;
      const Corner a = mesh.halfedge(Face(i * n + j));
      insert_edge(mesh, a, mesh.next(mesh.next(a)));
    }
  }
  return mesh;
}

// The torus with every quad split along the same diagonal: all triangles, every vertex of
// valence 6 and every face centre of valence 3, so every patch has extraordinary corners.
inline HalfedgeMesh make_triangle_torus(int m, int n) {
  HalfedgeMesh mesh = make_torus(m, n);
  for (int f = 0; f < m * n; ++f) {
    const Corner a = mesh.halfedge(Face(f));
    insert_edge(mesh, a, mesh.next(mesh.next(a)));
  }
  return mesh;
}

// Grid sizes giving about 1k, 10k and 100k faces.
inline std::pair<int, int> torus_grid(MeshKind kind, int target_faces) {
  const double quads = kind == quad_torus    ? target_faces
                       : kind == mixed_torus ? target_faces / 1.25
                                             : target_faces / 2.0;
  const int side = static_cast<int>(std::lround(std::sqrt(quads)));
  return {side, side};
}

inline const HalfedgeMesh& bench_mesh(MeshKind kind, int target_faces) {
  static std::map<std::pair<int, int>, HalfedgeMesh> cache;
  const auto key = std::make_pair(static_cast<int>(kind), target_faces);
  auto it = cache.find(key);
  if (it == cache.end()) {
    const auto [m, n] = torus_grid(kind, target_faces);
    it = cache
             .emplace(key, kind == quad_torus    ? make_quad_torus(m, n)
                           : kind == mixed_torus ? make_mixed_torus(m, n)
                                                 : make_triangle_torus(m, n))
             .first;
  }
  return it->second;
}

inline std::string mesh_label(MeshKind kind, const HalfedgeMesh& mesh) {
  return std::string(kind == quad_torus    ? "quad torus"
                     : kind == mixed_torus ? "tris+quads torus"
                                           : "triangle torus") +
         ", " + std::to_string(mesh.num_faces()) + " faces";
}

}  // namespace stitch::bench
