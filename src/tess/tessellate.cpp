#include "stitch/tess/tessellate.hpp"

#include <tbb/parallel_for.h>

namespace stitch {

namespace {

/// Where each grid sample of a corner's patch goes in the welded mesh. Samples on a patch's
/// sides belong to the mesh element they lie on (vertex, edge half, face spoke, edge midpoint,
/// face centre), so every patch sharing them finds the same slot.
class WeldIndex {
 public:
  WeldIndex(const HalfedgeMesh& m, int n) : m_(m), n_(n) {
    const int nh = m.halfedge_capacity();
    vertex_.assign(m.vertex_capacity(), -1);
    face_.assign(m.face_capacity(), -1);
    edge_mid_.assign(m.edge_capacity(), -1);
    half_.assign(static_cast<size_t>(nh) * std::max(n - 1, 0), -1);
    spoke_.assign(static_cast<size_t>(nh) * std::max(n - 1, 0), -1);
  }

  /// The slot of sample (i, j) of corner c, claiming a new one when `next` is the first to ask.
  int slot(Corner c, int i, int j, int& next) {
    int& s = ref(c, i, j);
    if (s < 0) s = next++;
    return s;
  }

 private:
  int& ref(Corner c, int i, int j) {
    const int n = n_;
    if (i == 0 && j == 0) return vertex_[m_.origin(c).idx];
    if (i == n && j == n) return face_[m_.face(c).idx];
    if (i == n && j == 0) return edge_mid_[HalfedgeMesh::edge(c).idx];
    if (i == 0 && j == n) return edge_mid_[HalfedgeMesh::edge(m_.prev(c)).idx];
    // Side 0 is the half of edge(c) at the vertex; side 3 the same for rotate_ccw(c).
    if (j == 0) return half_[static_cast<size_t>(c.idx) * (n - 1) + (i - 1)];
    if (i == 0) return half_[static_cast<size_t>(m_.rotate_ccw(c).idx) * (n - 1) + (j - 1)];
    // Side 1 runs from the middle of edge(c) to the face centre; side 2 is prev(c)'s side 1.
    if (i == n) return spoke_[static_cast<size_t>(c.idx) * (n - 1) + (j - 1)];
    if (j == n) return spoke_[static_cast<size_t>(m_.prev(c).idx) * (n - 1) + (i - 1)];
    interior_ = -1;
    return interior_;
  }

  const HalfedgeMesh& m_;
  int n_;
  std::vector<int> vertex_, face_, edge_mid_, half_, spoke_;
  int interior_ = -1;  // interior samples are never shared
};

}  // namespace

SurfaceMesh tessellate(const HalfedgeMesh& mesh, const Surface& surface,
                       const TessellationOptions& options) {
  const int n = options.resolution;
  if (n < 1) throw MeshError("the resolution must be at least 1");
  const auto& corners = surface.corners();
  const int per_patch = (n + 1) * (n + 1);

  // Every patch evaluates its own grid independently, in parallel.
  std::vector<SurfacePoint> samples(corners.size() * per_patch);
  tbb::parallel_for(size_t{0}, corners.size(), [&](size_t k) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        samples[k * per_patch + i * (n + 1) + j] =
            surface.evaluate(corners[k], static_cast<double>(i) / n, static_cast<double>(j) / n);
  });

  SurfaceMesh out;
  auto push = [&](const SurfacePoint& sp, Corner c, int i, int j) {
    out.positions.push_back(sp.position);
    out.normals.push_back(sp.normal);
    out.uv.emplace_back(static_cast<double>(i) / n, static_cast<double>(j) / n);
    out.patch.push_back(c.idx);
    out.level.push_back(sp.level);
  };
  std::vector<int> id(per_patch);
  auto emit_quads = [&] {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        out.quads.push_back({id[i * (n + 1) + j], id[(i + 1) * (n + 1) + j],
                             id[(i + 1) * (n + 1) + j + 1], id[i * (n + 1) + j + 1]});
  };

  if (!options.welded) {
    for (size_t k = 0; k < corners.size(); ++k) {
      for (int s = 0; s < per_patch; ++s) {
        id[s] = out.num_vertices();
        push(samples[k * per_patch + s], corners[k], s / (n + 1), s % (n + 1));
      }
      emit_quads();
    }
    return out;
  }

  WeldIndex weld(mesh, n);
  int next = 0;
  for (size_t k = 0; k < corners.size(); ++k) {
    for (int s = 0; s < per_patch; ++s) {
      const int i = s / (n + 1), j = s % (n + 1);
      const SurfacePoint& sp = samples[k * per_patch + s];
      id[s] = weld.slot(corners[k], i, j, next);
      if (id[s] == out.num_vertices()) {
        push(sp, corners[k], i, j);
      } else {
        out.normals[id[s]] += sp.normal;  // normalized below: the mean of the patches' normals
      }
    }
    emit_quads();
  }
  for (Vec3& nrm : out.normals) nrm.normalize();
  return out;
}

}  // namespace stitch
