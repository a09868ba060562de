#include "stitch/analysis/local_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "analysis/triangle_check.hpp"
#include "eval/patch_sampler.hpp"
#include "mesh/sort_unique.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/topology/operation.hpp"
#include "support/scratch.hpp"

namespace stitch {

namespace {

using detail::ScratchVector;
using detail::sort_unique;

bool has_patch(const HalfedgeMesh& m, Corner c) {
  return c.idx >= 0 && c.idx < m.halfedge_capacity() && !m.is_deleted(c) && !m.is_hole(c);
}

// Grid indices get 14 bits each in a weld key, element numbers 32.
static_assert(limits::max_resolution < (1 << 14));

/// What a grid sample lies on, so that every patch sharing it finds the same key (the rules of
/// TessellationLayout::vertex, which numbers the welded tessellation the same way).
enum class On : std::uint64_t { vertex, face, edge, half, boundary_half, spoke, interior };

std::uint64_t key(On on, int element, int a = 0, int b = 0) {
  return (static_cast<std::uint64_t>(on) << 60) |
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(element)) << 28) |
         (static_cast<std::uint64_t>(a) << 14) | static_cast<std::uint64_t>(b);
}

/// Sample (i, j) of corner c's grid: (0, 0) is its vertex, (n, n) its face's centre, (n, 0) the
/// middle of edge(c), (0, n) the middle of edge(prev(c)). Side j = 0 is the half of edge(c) at
/// the vertex, which the patch of rotate_cw(c) has as its side i = 0; side i = n is the spoke
/// to the face centre, which next(c) has as its side j = n.
std::uint64_t sample_key(const HalfedgeMesh& m, Corner c, int i, int j, int n) {
  if (i == 0 && j == 0) return key(On::vertex, m.origin(c).idx);
  if (i == n && j == n) return key(On::face, m.face(c).idx);
  if (i == n && j == 0) return key(On::edge, HalfedgeMesh::edge(c).idx);
  if (i == 0 && j == n) return key(On::edge, HalfedgeMesh::edge(m.prev(c)).idx);
  if (j == 0) return key(On::half, c.idx, i);
  if (i == 0) {
    const Corner across = m.rotate_ccw(c);
    return m.is_hole(across) ? key(On::boundary_half, c.idx, j) : key(On::half, across.idx, j);
  }
  if (i == n) return key(On::spoke, c.idx, j);
  if (j == n) return key(On::spoke, m.prev(c).idx, i);
  return key(On::interior, c.idx, i, j);
}

/// The triangles of the patches checked, in scratch storage: a search checks one setting after
/// another, and fresh arrays each time cost more than the check (support/scratch.hpp).
struct LocalTriangles {
  ScratchVector<Vec3> positions;
  ScratchVector<std::array<int, 3>> triangles;
  ScratchVector<int> source;  ///< the corner whose patch each triangle samples
  ScratchVector<char> focus;

  void add(int a, int b, int c, int corner, bool focused) {
    // A grid cell at a collapsed side repeats a vertex: no triangle (as triangulate does).
    if (a == b || b == c || a == c) return;
    triangles.push_back({a, b, c});
    source.push_back(corner);
    focus.push_back(focused ? 1 : 0);
  }
};

}  // namespace

std::vector<Corner> patch_neighbourhood(const HalfedgeMesh& m, const std::vector<Corner>& changed) {
  std::vector<Corner> out;
  for (Corner c : changed) {
    if (!has_patch(m, c)) continue;
    out.push_back(c);
    for (Halfedge h : m.face_loop(m.face(c))) out.push_back(h);
    for (Halfedge h : m.vertex_fan(m.origin(c))) out.push_back(h);
    // The patches across the corner's two edges touch it at their midpoints.
    out.push_back(HalfedgeMesh::twin(c));
    out.push_back(HalfedgeMesh::twin(m.prev(c)));
  }
  std::erase_if(out, [&](Corner c) { return !has_patch(m, c); });
  sort_unique(out);
  return out;
}

LocalCheckReport check_patches(const HalfedgeMesh& m, const std::vector<Corner>& changed,
                               const PatchGridSampler& sample, const LocalCheckOptions& options) {
  const int n = options.resolution;
  limits::check_resolution(n, "check_patches: the resolution");
  std::vector<Corner> focus_corners;
  for (Corner c : changed)
    if (has_patch(m, c)) focus_corners.push_back(c);
  sort_unique(focus_corners);
  const std::vector<Corner> local = patch_neighbourhood(m, focus_corners);

  LocalCheckReport report;
  report.changed_patches = static_cast<int>(focus_corners.size());
  report.patches = static_cast<int>(local.size());
  if (local.empty()) return report;

  LocalTriangles soup;
  const std::size_t samples = local.size() * (n + 1) * (n + 1);
  soup.positions.reserve(samples);
  const std::size_t triangles = 2 * local.size() * n * n;
  soup.triangles.reserve(triangles);
  soup.source.reserve(triangles);
  soup.focus.reserve(triangles);
  std::unordered_map<std::uint64_t, int> welded;
  welded.reserve(samples);
  const int side = n + 1;
  std::vector<int> grid(static_cast<size_t>(side) * side);
  for (Corner c : local) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const auto [it, fresh] =
            welded.emplace(sample_key(m, c, i, j, n), static_cast<int>(soup.positions.size()));
        if (fresh) soup.positions.push_back(sample(c, i, j));
        grid[i * side + j] = it->second;
      }
    const bool focused = std::binary_search(focus_corners.begin(), focus_corners.end(), c);
    // The quads of tessellate() (counter-clockwise from the normal side), split as
    // triangulate(TessellatedMesh) splits them, so the triangles are the whole check's.
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const int q0 = grid[i * side + j], q1 = grid[(i + 1) * side + j],
                  q2 = grid[(i + 1) * side + j + 1], q3 = grid[i * side + j + 1];
        for (const auto& t : quad_triangles(std::array{q0, q1, q2, q3}, soup.positions))
          soup.add(t[0], t[1], t[2], c.idx, focused);
      }
  }

  SurfaceCheckOptions check = options.surface;
  check.max_listed = std::numeric_limits<int>::max();
  const SurfaceCheckReport r =
      detail::check_triangles(soup.positions, soup.triangles, soup.focus, check);
  report.triangles = r.triangles;
  report.self_intersections = r.self_intersections;
  report.folds = r.folds;
  report.degenerate = r.degenerate;
  for (const auto* pairs : {&r.intersecting_pairs, &r.folded_pairs})
    for (const auto& p : *pairs) {
      report.problem_corners.emplace_back(soup.source[p[0]]);
      report.problem_corners.emplace_back(soup.source[p[1]]);
    }
  sort_unique(report.problem_corners);
  return report;
}

LocalCheckReport check_patches(const HalfedgeMesh& mesh, const Surface& surface,
                               const std::vector<Corner>& changed,
                               const LocalCheckOptions& options) {
  // Samples come patch after patch, which is the order the sampler keeps its splits for.
  PatchSampler sampler(surface, options.resolution);
  return check_patches(
      mesh, changed,
      [&](Corner c, int i, int j) { return sampler.evaluate_grid(c, i, j).position; }, options);
}

std::vector<Corner> patches_touched(const HalfedgeMesh& m, const std::vector<Vertex>& vertices,
                                    const std::vector<Edge>& edges,
                                    const std::vector<Face>& faces) {
  // Faces whose loops or corner positions changed: their K-gons and the K-gons of their
  // vertices, edges and the faces across (which read their normals) may change, and with them
  // every net that reads one of those (kgons_reading and nets_reading).
  std::vector<Face> moved;
  for (Edge e : edges) {
    if (e.idx >= m.edge_capacity() || m.is_deleted(e)) continue;
    for (int s = 0; s < 2; ++s) moved.push_back(m.face(HalfedgeMesh::halfedge(e, s)));
  }
  for (Vertex v : vertices) {
    if (v.idx >= m.vertex_capacity() || m.is_deleted(v)) continue;
    for (Halfedge h : m.vertex_fan(v)) moved.push_back(m.face(h));
  }
  for (Face f : faces)
    if (f.idx < m.face_capacity() && !m.is_deleted(f)) moved.push_back(f);
  return nets_reading(m, kgons_reading(m, std::move(moved)));
}

std::vector<std::string> corner_names(const HalfedgeMesh& m, const std::vector<Corner>& corners,
                                      bool as_written) {
  std::vector<int> vertex_number, face_number;
  if (as_written) {
    // The writer's numbering (to_polygon_soup): ranks among live vertices and surface faces.
    vertex_number.assign(static_cast<size_t>(m.vertex_capacity()), 0);
    face_number.assign(static_cast<size_t>(m.face_capacity()), 0);
    int next = 0;
    for (Vertex v : m.vertices()) vertex_number[v.idx] = ++next;
    next = 0;
    for (Face f : m.surface_faces()) face_number[f.idx] = ++next;
  }
  std::vector<std::string> names;
  for (Corner c : corners) {
    std::string name = corner_name(m, c);  // V@F or V@F#k in the mesh's own numbers
    if (as_written) {
      // The same corner in the file's numbers; the occurrence does not depend on numbering.
      const size_t hash = name.find('#');
      name = fmt::format("{}@{}{}", vertex_number[m.origin(c).idx], face_number[m.face(c).idx],
                         hash == std::string::npos ? "" : name.substr(hash));
    }
    names.push_back(std::move(name));
  }
  return names;
}

}  // namespace stitch
