#include "stitch/tess/tessellate.hpp"

#include <tbb/parallel_for.h>

#include <cstdint>

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
  const size_t per_patch = static_cast<size_t>(n + 1) * (n + 1);
  const size_t samples = corners.size() * per_patch;

  // Where every sample goes: its own slot (unwelded) or its mesh element's (welded), and
  // whether it is the first sample to claim that slot (then it writes the slot's attributes).
  std::vector<int> id(samples);
  std::vector<std::uint8_t> first(samples, 1);
  int slots = 0;
  if (options.welded) {
    WeldIndex weld(mesh, n);
    for (size_t k = 0; k < corners.size(); ++k)
      for (size_t s = 0; s < per_patch; ++s) {
        const int before = slots;
        id[k * per_patch + s] = weld.slot(corners[k], static_cast<int>(s) / (n + 1),
                                          static_cast<int>(s) % (n + 1), slots);
        first[k * per_patch + s] = slots > before;
      }
  } else {
    for (size_t i = 0; i < samples; ++i) id[i] = static_cast<int>(i);
    slots = static_cast<int>(samples);
  }

  SurfaceMesh out;
  out.positions.resize(slots);
  out.normals.assign(slots, Vec3::Zero());
  out.uv.resize(slots);
  out.patch.resize(slots);
  out.level.resize(slots);
  // A shared sample's normal is the mean over the patches sharing it: each patch's normal is
  // kept here and summed afterwards, in a fixed order, so the result does not depend on timing.
  std::vector<Vec3> normal(options.welded ? samples : 0);

  // Every patch evaluates its own grid independently, in parallel.
  tbb::parallel_for(size_t{0}, corners.size(), [&](size_t k) {
    for (size_t s = 0; s < per_patch; ++s) {
      const int i = static_cast<int>(s) / (n + 1), j = static_cast<int>(s) % (n + 1);
      const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
      const SurfacePoint sp = surface.evaluate(corners[k], u, v);
      const size_t at = k * per_patch + s;
      if (options.welded) normal[at] = sp.normal;
      if (!first[at]) continue;
      const int slot = id[at];
      out.positions[slot] = sp.position;
      out.uv[slot] = Eigen::Vector2d(u, v);
      out.patch[slot] = corners[k].idx;
      out.level[slot] = sp.level;
      if (!options.welded) out.normals[slot] = sp.normal;
    }
  });
  if (options.welded) {
    for (size_t at = 0; at < samples; ++at) out.normals[id[at]] += normal[at];
    for (Vec3& nrm : out.normals) nrm.normalize();
  }

  out.quads.reserve(corners.size() * n * n);
  for (size_t k = 0; k < corners.size(); ++k) {
    const int* g = &id[k * per_patch];
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        out.quads.push_back({g[i * (n + 1) + j], g[(i + 1) * (n + 1) + j],
                             g[(i + 1) * (n + 1) + j + 1], g[i * (n + 1) + j + 1]});
  }
  return out;
}

}  // namespace stitch
