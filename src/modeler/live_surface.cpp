#include "stitch/modeler/live_surface.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

namespace stitch::modeler {

namespace {

template <class H>
void sort_unique(std::vector<H>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

class Stopwatch {
 public:
  [[nodiscard]] double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

AffectedSet affected_by(const HalfedgeMesh& m, const Change& change) {
  AffectedSet a;
  if (change.kind == Change::Kind::geometry) {
    // A moved vertex moves the corner points of its faces (and their normals). K-gons built on
    // those corner points: the faces' own, those of their vertices and edges. Face K-gons across
    // an edge also read the faces' normals (the fallback for K-gons without a plane).
    std::vector<Face> moved_faces;
    for (Vertex v : change.moved)
      for (Halfedge h : m.vertex_fan(v)) moved_faces.push_back(m.face(h));
    sort_unique(moved_faces);
    for (Face f : moved_faces)
      for (Halfedge h : m.face_loop(f)) {
        a.vertices.push_back(m.origin(h));
        a.edges.push_back(HalfedgeMesh::edge(h));
        a.faces.push_back(m.face(HalfedgeMesh::twin(h)));
      }
    a.faces.insert(a.faces.end(), moved_faces.begin(), moved_faces.end());
  } else if (change.kind == Change::Kind::kgons) {
    a.faces = change.faces;
    a.vertices = change.vertices;
    a.edges = change.edges;
  }
  sort_unique(a.faces);
  sort_unique(a.vertices);
  sort_unique(a.edges);
  // A net reads the K-gons of its face, its vertex, its edge and its previous edge.
  for (Face f : a.faces)
    for (Halfedge h : m.face_loop(f)) a.corners.push_back(h);
  for (Vertex v : a.vertices)
    for (Halfedge h : m.vertex_fan(v)) a.corners.push_back(h);
  for (Edge e : a.edges)
    for (int side = 0; side < 2; ++side) {
      const Halfedge h = HalfedgeMesh::halfedge(e, side);
      a.corners.push_back(h);
      a.corners.push_back(m.next(h));
    }
  sort_unique(a.corners);
  return a;
}

void LiveSurface::layout(const HalfedgeMesh& mesh) {
  corners_ = mesh.halfedges();
  slot_.assign(mesh.halfedge_capacity(), -1);
  for (size_t k = 0; k < corners_.size(); ++k) slot_[corners_[k].idx] = static_cast<int>(k);
  const int n = resolution_, per_patch = vertices_per_patch();
  const size_t nv = corners_.size() * per_patch;
  tess_ = SurfaceMesh{};
  tess_.positions.resize(nv);
  tess_.normals.resize(nv);
  tess_.uv.resize(nv);
  tess_.patch.resize(nv);
  tess_.level.resize(nv);
  tess_.quads.reserve(corners_.size() * n * n);
  // The same vertex and quad order as tessellate(..., welded = false).
  for (size_t k = 0; k < corners_.size(); ++k) {
    const int base = static_cast<int>(k) * per_patch;
    for (int s = 0; s < per_patch; ++s) {
      tess_.uv[base + s] = {static_cast<double>(s / (n + 1)) / n, static_cast<double>(s % (n + 1)) / n};
      tess_.patch[base + s] = corners_[k].idx;
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        tess_.quads.push_back({base + i * (n + 1) + j, base + (i + 1) * (n + 1) + j,
                               base + (i + 1) * (n + 1) + j + 1, base + i * (n + 1) + j + 1});
  }
}

namespace {

/// The Catmull-Clark limit surface (built for the whole mesh), or null for the Bezier methods.
/// Built before anything changes, since OpenSubdiv refuses some meshes (2-sided faces, faces
/// along one edge twice).
std::unique_ptr<Surface> cc_surface(const HalfedgeMesh& mesh, const KgonOptions& options, Method method) {
  return method == Method::cc ? std::make_unique<Surface>(mesh, Method::cc, options) : nullptr;
}

}  // namespace

void LiveSurface::tessellate_patches(const std::vector<int>& patches, const Surface* cc) {
  const int n = resolution_, per_patch = vertices_per_patch();
  const BezierRule rule = method_ == Method::asc ? BezierRule::asc : BezierRule::mdc;
  tbb::parallel_for(size_t{0}, patches.size(), [&](size_t q) {
    const int k = patches[q];
    const Corner c = corners_[k];
    for (int s = 0; s < per_patch; ++s) {
      const double u = static_cast<double>(s / (n + 1)) / n, v = static_cast<double>(s % (n + 1)) / n;
      const SurfacePoint sp = cc ? cc->evaluate(c, u, v) : evaluate_patch(nets_[c.idx], u, v, rule);
      const size_t at = static_cast<size_t>(k) * per_patch + s;
      tess_.positions[at] = sp.position;
      tess_.normals[at] = sp.normal;
      tess_.level[at] = sp.level;
    }
  });
  recomputed_.clear();
  for (int k : patches) recomputed_.push_back(corners_[k]);
}

UpdateStats LiveSurface::rebuild(const HalfedgeMesh& mesh, const KgonOptions& options,
                                 Method method, int resolution) {
  if (resolution < 1) throw MeshError("the resolution must be at least 1");
  const Stopwatch watch;
  const auto cc = cc_surface(mesh, options, method);
  method_ = method;
  resolution_ = resolution;
  kgons_ = build_kgons(mesh, options);
  nets_ = build_control_nets(mesh, kgons_);
  layout(mesh);
  std::vector<int> all(corners_.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  tessellate_patches(all, cc.get());
  UpdateStats stats;
  stats.full = true;
  stats.candidate_patches = stats.recomputed_patches = static_cast<int>(all.size());
  stats.milliseconds = watch.ms();
  return stats;
}

UpdateStats LiveSurface::update(const HalfedgeMesh& mesh, const KgonOptions& options,
                                const Change& change) {
  if (change.kind == Change::Kind::none) {
    recomputed_.clear();
    return {};
  }
  if (change.kind == Change::Kind::topology) return rebuild(mesh, options, method_, resolution_);
  const Stopwatch watch;
  std::vector<Corner> candidates;
  if (change.all_kgons) {
    kgons_ = build_kgons(mesh, options);
    candidates = corners_;
  } else {
    AffectedSet a = affected_by(mesh, change);
    update_kgons(mesh, options, kgons_, a.faces, a.vertices, a.edges);
    candidates = std::move(a.corners);
  }
  std::vector<int> changed;
  for (Corner c : candidates) {
    ControlNet net = build_control_net(mesh, kgons_, c);
    if (net != nets_[c.idx]) {
      nets_[c.idx] = net;
      changed.push_back(slot_[c.idx]);
    }
  }
  if (method_ == Method::cc) {
    // The limit surface ignores K-gons, and OpenSubdiv rebuilds it whole after a move.
    changed.clear();
    if (change.kind == Change::Kind::geometry)
      for (size_t k = 0; k < corners_.size(); ++k) changed.push_back(static_cast<int>(k));
  }
  std::sort(changed.begin(), changed.end());
  tessellate_patches(changed, changed.empty() ? nullptr : cc_surface(mesh, options, method_).get());
  UpdateStats stats;
  stats.full = method_ == Method::cc && !changed.empty();
  stats.candidate_patches = static_cast<int>(candidates.size());
  stats.recomputed_patches = static_cast<int>(changed.size());
  stats.milliseconds = watch.ms();
  return stats;
}

UpdateStats LiveSurface::set_method(const HalfedgeMesh& mesh, const KgonOptions& options,
                                    Method method) {
  const Stopwatch watch;
  const auto cc = cc_surface(mesh, options, method);
  method_ = method;
  std::vector<int> all(corners_.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  tessellate_patches(all, cc.get());
  UpdateStats stats;
  stats.full = true;
  stats.recomputed_patches = static_cast<int>(all.size());
  stats.milliseconds = watch.ms();
  return stats;
}

UpdateStats LiveSurface::set_resolution(const HalfedgeMesh& mesh, const KgonOptions& options,
                                        int resolution) {
  if (resolution < 1) throw MeshError("the resolution must be at least 1");
  const Stopwatch watch;
  const auto cc = cc_surface(mesh, options, method_);
  resolution_ = resolution;
  layout(mesh);
  UpdateStats stats = set_method(mesh, options, method_);
  stats.milliseconds = watch.ms();
  return stats;
}

}  // namespace stitch::modeler
