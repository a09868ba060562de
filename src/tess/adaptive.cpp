#include "tess/adaptive.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "eval/patch_sampler.hpp"
#include "mesh/mesh_writer.hpp"
#include "stitch/tess/adaptive.hpp"
#include "tess/write_stream.hpp"

namespace stitch {

namespace detail {

int side_rate(const ControlNet& net, int side, double tolerance, int max_rate) {
  // Sides 0 and 2 run along u (index a), 1 and 3 along v; the row on the side and the next one
  // inwards both shape the triangles of the strip along it.
  const bool along_u = side == 0 || side == 2;
  const int edge_row = side == 0 || side == 3 ? 0 : 3;
  const int inner_row = edge_row == 0 ? 1 : 2;
  double largest = 0;
  for (const int row : {edge_row, inner_row}) {
    const auto at = [&](int t) -> const Vec3& { return along_u ? net.at(t, row) : net.at(row, t); };
    for (int k = 0; k < 2; ++k)
      largest = std::max(largest, (at(k + 2) - 2 * at(k + 1) + at(k)).norm());
  }
  // In doubles first: a huge net or a tiny tolerance must clamp, not overflow an int.
  const double n = std::ceil(std::sqrt(0.75 * largest / tolerance));
  if (!(n >= 1)) return 1;  // also NaN
  return static_cast<int>(std::min(n, static_cast<double>(max_rate)));
}

std::vector<std::array<StripCorner, 3>> zip_strip(int outer, int inner) {
  std::vector<std::array<StripCorner, 3>> out;
  out.reserve(static_cast<size_t>(outer + inner - 1));
  const std::int64_t r = outer, n = inner + 1;  // the inner chain is a grid of n segments
  int k = 0, m = 0;
  while (k < outer || m < inner - 1) {
    // Of the two possible next triangles take the one whose new diagonal is shorter along the
    // strip (all diagonals span the same distance across it), in units of 1 / (r n).
    bool advance_outer = m == inner - 1;
    if (k < outer && !advance_outer) {
      const std::int64_t via_outer = std::llabs((k + 1) * n - (m + 1) * r);
      const std::int64_t via_inner = std::llabs(k * n - (m + 2) * r);
      advance_outer = via_outer <= via_inner;
    }
    if (advance_outer) {
      out.push_back({StripCorner{0, k}, StripCorner{0, k + 1}, StripCorner{1, m}});
      ++k;
    } else {
      out.push_back({StripCorner{0, k}, StripCorner{1, m + 1}, StripCorner{1, m}});
      ++m;
    }
  }
  return out;
}

}  // namespace detail

namespace {

using detail::side_rate;
using detail::zip_strip;

struct Sample {
  int vertex = -1;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

/// Numbers output vertices as patches ask for them and evaluates each sample of each patch, so a
/// vertex takes the position of the first patch that meets it and the mean of all their normals.
class Builder {
 public:
  Builder(const HalfedgeMesh& mesh, const Surface& surface, AdaptiveMesh& out)
      : mesh_(mesh),
        surface_(surface),
        out_(out),
        sampler_(surface),
        vertex_(mesh.vertex_capacity(), -1),
        face_(mesh.face_capacity(), -1),
        edge_(mesh.edge_capacity(), -1),
        half_(mesh.halfedge_capacity(), -1),
        spoke_(mesh.halfedge_capacity(), -1),
        half_rate_(mesh.halfedge_capacity(), 0),
        spoke_rate_(mesh.halfedge_capacity(), 0) {}

  /// The rate of every side, the larger of what the two patches sharing it ask for.
  void choose_rates(double tolerance, int max_rate) {
    for (const Corner c : surface_.corners())
      for (int side = 0; side < 4; ++side) {
        int& rate = rate_of(c, side);
        rate = std::max(rate, side_rate(surface_.bezier().nets[c.idx], side, tolerance, max_rate));
      }
  }

  void add_patch(Corner c) {
    int n = 1;
    for (int side = 0; side < 4; ++side) {
      const int r = rate_of(c, side);
      n = std::max(n, r);
      out_.min_rate = out_.min_rate == 0 ? r : std::min(out_.min_rate, r);
      out_.max_rate = std::max(out_.max_rate, r);
    }
    // Patch corners 00, 30, 33, 03 (control_net.hpp), each sampled once for this patch.
    std::array<Sample, 4> corners;
    for (int at = 0; at < 4; ++at)
      corners[at] =
          sample(c, corner_vertex(c, at), {at == 1 || at == 2 ? 1.0 : 0.0, at >= 2 ? 1.0 : 0.0});
    static constexpr std::array<std::array<int, 2>, 4> kEnds{{{0, 1}, {1, 2}, {3, 2}, {0, 3}}};
    std::array<std::vector<Sample>, 4> sides;
    for (int side = 0; side < 4; ++side) {
      const int r = rate_of(c, side);
      sides[side].push_back(corners[kEnds[side][0]]);
      for (int m = 1; m < r; ++m) {
        const auto [u, v] = side_point(side, static_cast<double>(m) / r);
        sides[side].push_back(sample(c, side_vertex(c, side, m), {u, v}));
      }
      sides[side].push_back(corners[kEnds[side][1]]);
    }
    if (n == 1) {  // every side is one segment: the patch is one quad
      triangle(sides[0][0], sides[0][1], sides[1][1]);
      triangle(sides[0][0], sides[1][1], sides[3][1]);
      return;
    }
    // The (n - 1)^2 grid points inside, row-major in i.
    const int first = reserve((n - 1) * (n - 1));
    std::vector<Sample> grid;
    grid.reserve(static_cast<size_t>(n - 1) * (n - 1));
    for (int i = 1; i < n; ++i)
      for (int j = 1; j < n; ++j)
        grid.push_back(sample(c, first + static_cast<int>(grid.size()),
                              {static_cast<double>(i) / n, static_cast<double>(j) / n}));
    const auto inner = [&](int i, int j) -> const Sample& {
      return grid[static_cast<size_t>(i - 1) * (n - 1) + (j - 1)];
    };
    for (int i = 1; i + 1 < n; ++i)
      for (int j = 1; j + 1 < n; ++j) {
        triangle(inner(i, j), inner(i + 1, j), inner(i + 1, j + 1));
        triangle(inner(i, j), inner(i + 1, j + 1), inner(i, j + 1));
      }
    // One strip per side between its samples and the grid's outermost row along it; the strips
    // of neighbouring sides share the segment from the patch corner to the grid's corner point.
    for (int side = 0; side < 4; ++side) {
      std::vector<const Sample*> row;
      for (int a = 1; a < n; ++a) {
        switch (side) {
          case 0:
            row.push_back(&inner(a, 1));
            break;
          case 1:
            row.push_back(&inner(n - 1, a));
            break;
          case 2:
            row.push_back(&inner(a, n - 1));
            break;
          default:
            row.push_back(&inner(1, a));
            break;
        }
      }
      const int r = static_cast<int>(sides[side].size()) - 1;
      for (const auto& t : zip_strip(r, n - 1)) {
        const auto at = [&](const detail::StripCorner& s) -> const Sample& {
          return s[0] == 0 ? sides[side][s[1]] : *row[s[1]];
        };
        triangle(at(t[0]), at(t[1]), at(t[2]));
      }
    }
  }

  void finish() {
    for (size_t v = 0; v < out_.normals.size(); ++v)
      if (shared_[v] > 1) out_.normals[v].normalize();
  }

 private:
  /// Sides are keyed by the mesh element they lie on (control_net.hpp): the half of edge(h) at
  /// origin(h), or the spoke from edge(h)'s middle to face(h)'s centre.
  int& rate_of(Corner c, int side) {
    switch (side) {
      case 0:
        return half_rate_[c.idx];
      case 1:
        return spoke_rate_[c.idx];
      case 2:
        return spoke_rate_[mesh_.prev(c).idx];
      default:
        return half_rate_[mesh_.rotate_ccw(c).idx];
    }
  }

  /// The output vertex of patch corner `at` of c: 0 the mesh vertex, 1 the middle of edge(c),
  /// 2 the face centre, 3 the middle of edge(prev(c)).
  int corner_vertex(Corner c, int at) {
    int* slot = nullptr;
    switch (at) {
      case 0:
        slot = &vertex_[mesh_.origin(c).idx];
        break;
      case 1:
        slot = &edge_[HalfedgeMesh::edge(c).idx];
        break;
      case 2:
        slot = &face_[mesh_.face(c).idx];
        break;
      default:
        slot = &edge_[HalfedgeMesh::edge(mesh_.prev(c)).idx];
        break;
    }
    if (*slot < 0) *slot = reserve(1);
    return *slot;
  }

  /// The output vertex of sample 0 < m < rate of `side` of c's patch (parameter m / rate along
  /// the side, which runs the same way in both patches sharing it).
  int side_vertex(Corner c, int side, int m) {
    int* first = nullptr;
    switch (side) {
      case 0:
        first = &half_[c.idx];
        break;
      case 1:
        first = &spoke_[c.idx];
        break;
      case 2:
        first = &spoke_[mesh_.prev(c).idx];
        break;
      default:
        first = &half_[mesh_.rotate_ccw(c).idx];
        break;
    }
    if (*first < 0) *first = reserve(rate_of(c, side) - 1);
    return *first + (m - 1);
  }

  int reserve(int count) {
    const auto first = static_cast<std::int64_t>(out_.positions.size());
    if (first + count > std::numeric_limits<int>::max())
      throw UsageError(
          "the adaptive tessellation has more than 2^31 - 1 vertices: raise --tolerance");
    const auto size = static_cast<size_t>(first + count);
    out_.positions.resize(size);
    out_.normals.resize(size, Vec3::Zero());
    out_.uv.resize(size);
    out_.patch.resize(size, -1);
    shared_.resize(size, 0);
    return static_cast<int>(first);
  }

  Sample sample(Corner c, int vertex, const Eigen::Vector2d& uv) {
    const SurfacePoint p = sampler_.evaluate(c, uv.x(), uv.y());
    if (!p.position.allFinite() || !p.normal.allFinite())
      throw InputError(
          fmt::format("the surface is not finite at ({}, {}) on the patch of corner "
                      "half-edge {}",
                      uv.x(), uv.y(), c.idx));
    if (shared_[vertex]++ == 0) {
      out_.positions[vertex] = p.position;
      out_.uv[vertex] = uv;
      out_.patch[vertex] = c.idx;
    }
    out_.normals[vertex] += p.normal;
    return {vertex, uv};
  }

  /// Ordered counter-clockwise in (u, v): du x dv is the normal side (control_net.hpp).
  void triangle(const Sample& a, const Sample& b, const Sample& c) {
    const Eigen::Vector2d ab = b.uv - a.uv, ac = c.uv - a.uv;
    if (ab.x() * ac.y() - ab.y() * ac.x() >= 0)
      out_.triangles.push_back({a.vertex, b.vertex, c.vertex});
    else
      out_.triangles.push_back({a.vertex, c.vertex, b.vertex});
  }

  const HalfedgeMesh& mesh_;
  const Surface& surface_;
  AdaptiveMesh& out_;
  PatchSampler sampler_;
  std::vector<int> vertex_, face_, edge_;  ///< output vertex by element index (-1: none yet)
  std::vector<int> half_, spoke_;          ///< first output vertex inside each side, by half-edge
  std::vector<int> half_rate_, spoke_rate_;
  std::vector<int> shared_;  ///< samples that met each output vertex
};

}  // namespace

AdaptiveMesh tessellate_adaptive(const HalfedgeMesh& mesh, const Surface& surface,
                                 const AdaptiveOptions& options) {
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    throw UsageError(fmt::format("the tolerance must be positive, not {}", options.tolerance));
  if (options.max_rate < 1) throw UsageError("the largest rate must be at least 1");
  Eigen::AlignedBox3d box;
  for (int v = 0; v < mesh.vertex_capacity(); ++v)
    if (!mesh.is_deleted(Vertex(v))) box.extend(mesh.position(Vertex(v)));
  const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
  if (!(diagonal > 0)) throw InputError("the mesh has no extent to measure the tolerance against");
  AdaptiveMesh out;
  Builder builder(mesh, surface, out);
  builder.choose_rates(options.tolerance * diagonal, options.max_rate);
  for (const Corner c : surface.corners()) builder.add_patch(c);
  builder.finish();
  return out;
}

void write_adaptive_mesh(const std::string& path, MeshFileFormat format, const AdaptiveMesh& mesh,
                         const SurfaceFileOptions& options) {
  if (is_gltf(format))
    throw OutputError(
        fmt::format("cannot write {}: an adaptive tessellation is not written as glTF", path));
  const bool normals = has_vertex_normals(format);
  detail::write_stream(
      path, format,
      detail::stream_arrays(mesh.positions, normals ? &mesh.normals : nullptr, mesh.triangles),
      mesh.positions, options, "stitch surface (bicubic Bezier patches, adaptive tessellation)");
}

}  // namespace stitch
