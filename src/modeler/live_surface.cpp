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

/// The Catmull-Clark limit surface (built for the whole mesh), or null for the Bezier methods.
/// Built before anything changes, since it is the one surface that can refuse a mesh (should
/// OpenSubdiv reject it).
std::unique_ptr<Surface> cc_surface(const HalfedgeMesh& mesh, const KgonOptions& options,
                                    Method method) {
  return method == Method::cc ? std::make_unique<Surface>(mesh, Method::cc, options) : nullptr;
}

/// The K-gons that can read the corner points or normals of `moved_faces` (faces whose vertices
/// moved or whose loops changed): the faces' own, those of their vertices and edges, and the
/// face K-gons across their edges (which read the faces' normals when they have no plane).
/// Then the corners whose nets read one of those K-gons: a net reads the K-gons of its face,
/// its vertex, its edge and its previous edge.
AffectedSet expand(const HalfedgeMesh& m, std::vector<Face> moved_faces, AffectedSet a) {
  sort_unique(moved_faces);
  for (Face f : moved_faces)
    for (Halfedge h : m.face_loop(f)) {
      a.vertices.push_back(m.origin(h));
      a.edges.push_back(HalfedgeMesh::edge(h));
      a.faces.push_back(m.face(HalfedgeMesh::twin(h)));
    }
  a.faces.insert(a.faces.end(), moved_faces.begin(), moved_faces.end());
  sort_unique(a.faces);
  sort_unique(a.vertices);
  sort_unique(a.edges);
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

template <class T>
void resize_to(std::vector<T>& v, int n) {
  v.resize(static_cast<size_t>(n));
}

}  // namespace

AffectedSet affected_by(const HalfedgeMesh& m, const Change& change) {
  AffectedSet a;
  std::vector<Face> moved_faces;
  if (change.kind == Change::Kind::geometry) {
    for (Vertex v : change.moved)
      for (Halfedge h : m.vertex_fan(v)) moved_faces.push_back(m.face(h));
  } else if (change.kind == Change::Kind::kgons) {
    a.faces = change.faces;
    a.vertices = change.vertices;
    a.edges = change.edges;
  }
  return expand(m, std::move(moved_faces), std::move(a));
}

bool LiveSurface::layout(const HalfedgeMesh& mesh, const std::vector<bool>& was_live) {
  const int n = resolution_, per_patch = vertices_per_patch(), per_quads = quads_per_patch();
  const int slots = mesh.halfedge_capacity();
  const int old_slots = static_cast<int>(tess_.quads.size()) / std::max(per_quads, 1);
  const size_t nv = static_cast<size_t>(slots) * per_patch;
  tess_.positions.resize(nv, Vec3::Zero());
  tess_.normals.resize(nv, Vec3::Zero());
  tess_.uv.resize(nv, Eigen::Vector2d::Zero());
  tess_.patch.resize(nv, -1);
  tess_.level.resize(nv, 0);
  tess_.quads.resize(static_cast<size_t>(slots) * per_quads);
  corners_ = mesh.halfedges();
  bool changed = slots != old_slots;
  for (int h = 0; h < slots; ++h) {
    const bool live = !mesh.is_deleted(Halfedge(h));
    if (h < old_slots && h < static_cast<int>(was_live.size()) && was_live[h] == live) continue;
    changed = true;
    // The same vertex and quad order as tessellate(..., welded = false); dead slots draw nothing.
    const int base = h * per_patch;
    for (int s = 0; s < per_patch; ++s) {
      tess_.uv[base + s] = {static_cast<double>(s / (n + 1)) / n,
                            static_cast<double>(s % (n + 1)) / n};
      tess_.patch[base + s] = live ? h : -1;
      if (!live) {
        tess_.positions[base + s] = tess_.normals[base + s] = Vec3::Zero();
        tess_.level[base + s] = 0;
      }
    }
    auto* q = &tess_.quads[static_cast<size_t>(h) * per_quads];
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        *q++ =
            live ? std::array<int, 4>{base + i * (n + 1) + j, base + (i + 1) * (n + 1) + j,
                                      base + (i + 1) * (n + 1) + j + 1, base + i * (n + 1) + j + 1}
                 : std::array<int, 4>{base, base, base, base};
  }
  return changed;
}

void LiveSurface::evaluate(const std::vector<Corner>& patches, const Surface* cc) {
  const int n = resolution_, per_patch = vertices_per_patch();
  const BezierRule rule = method_ == Method::asc ? BezierRule::asc : BezierRule::mdc;
  tbb::parallel_for(size_t{0}, patches.size(), [&](size_t q) {
    const Corner c = patches[q];
    for (int s = 0; s < per_patch; ++s) {
      const double u = static_cast<double>(s / (n + 1)) / n,
                   v = static_cast<double>(s % (n + 1)) / n;
      const SurfacePoint sp = cc ? cc->evaluate(c, u, v) : evaluate_patch(nets_[c.idx], u, v, rule);
      const size_t at = static_cast<size_t>(c.idx) * per_patch + s;
      tess_.positions[at] = sp.position;
      tess_.normals[at] = sp.normal;
      tess_.level[at] = sp.level;
    }
  });
  recomputed_ = patches;
}

UpdateStats LiveSurface::rebuild(const HalfedgeMesh& mesh, const KgonOptions& options,
                                 Method method, int resolution) {
  if (resolution < 1) throw MeshError("the resolution must be at least 1");
  const Stopwatch watch;
  const auto cc = cc_surface(mesh, options, method);
  method_ = method;
  resolution_ = resolution;
  mesh_ = mesh;
  kgons_ = build_kgons(mesh, options);
  nets_ = build_control_nets(mesh, kgons_);
  tess_ = SurfaceMesh{};
  layout(mesh, {});
  evaluate(corners_, cc.get());
  UpdateStats stats;
  stats.full = stats.layout_changed = true;
  stats.candidate_patches = stats.recomputed_patches = static_cast<int>(corners_.size());
  stats.milliseconds = watch.ms();
  return stats;
}

UpdateStats LiveSurface::update_topology(const HalfedgeMesh& m, const KgonOptions& options) {
  const Stopwatch watch;
  const auto cc = cc_surface(m, options, method_);  // may refuse: nothing has changed yet
  const HalfedgeMesh& old = mesh_;
  const int nh = m.halfedge_capacity(), old_nh = old.halfedge_capacity();

  // What differs from the previous mesh. Untouched elements keep their numbers under the
  // operators, so this is an element-by-element comparison.
  std::vector<Face> moved_faces;
  AffectedSet seeds;
  std::vector<Corner> fresh;  // live corners that had no live patch before
  std::vector<bool> was_live(old_nh);
  for (int h = 0; h < old_nh; ++h) was_live[h] = !old.is_deleted(Halfedge(h));
  for (int i = 0; i < nh; ++i) {
    const Halfedge h(i);
    if (m.is_deleted(h)) continue;
    const bool existed = i < old_nh && was_live[i];
    if (!existed) fresh.push_back(h);
    if (existed && old.next(h) == m.next(h) && old.prev(h) == m.prev(h) &&
        old.origin(h) == m.origin(h) && old.face(h) == m.face(h))
      continue;
    moved_faces.push_back(m.face(h));
    seeds.vertices.push_back(m.origin(h));
    seeds.edges.push_back(HalfedgeMesh::edge(h));
  }
  for (Vertex v : m.vertices()) {
    const bool same = v.idx < old.vertex_capacity() && !old.is_deleted(v) &&
                      old.halfedge(v) == m.halfedge(v) && old.position(v) == m.position(v);
    if (same) continue;
    seeds.vertices.push_back(v);  // its fan starts elsewhere or it moved
    for (Halfedge h : m.vertex_fan(v)) moved_faces.push_back(m.face(h));
  }
  for (Face f : m.faces()) {
    const bool same =
        f.idx < old.face_capacity() && !old.is_deleted(f) && old.halfedge(f) == m.halfedge(f);
    if (!same) moved_faces.push_back(f);  // its loop starts elsewhere (K-gon point order)
  }
  AffectedSet a = expand(m, std::move(moved_faces), std::move(seeds));

  // Arrays to the new capacities; K-gons and nets of removed elements emptied (as build_kgons
  // and build_control_nets leave them).
  resize_to(kgons_.corner_point, nh);
  resize_to(kgons_.in_face, nh);
  resize_to(kgons_.in_vertex, nh);
  resize_to(kgons_.in_next_edge, nh);
  resize_to(kgons_.in_prev_edge, nh);
  resize_to(kgons_.face, m.face_capacity());
  resize_to(kgons_.vertex, m.vertex_capacity());
  resize_to(kgons_.edge, m.edge_capacity());
  ControlNet unused;
  unused.p.fill(Vec3::Zero());
  nets_.resize(static_cast<size_t>(nh), unused);
  for (int i = 0; i < old_nh && i < nh; ++i)
    if (was_live[i] && m.is_deleted(Halfedge(i))) {
      nets_[i].p.fill(Vec3::Zero());  // what's left of a removed corner: never read
      kgons_.corner_point[i] = Vec3::Zero();
      kgons_.in_face[i] = kgons_.in_vertex[i] = kgons_.in_next_edge[i] = kgons_.in_prev_edge[i] =
          -1;
      if (i % 2 == 0) kgons_.edge[i / 2] = Kgon{};
    }
  for (int v = 0; v < std::min(old.vertex_capacity(), m.vertex_capacity()); ++v)
    if (!old.is_deleted(Vertex(v)) && m.is_deleted(Vertex(v))) kgons_.vertex[v] = Kgon{};
  for (int f = 0; f < std::min(old.face_capacity(), m.face_capacity()); ++f)
    if (!old.is_deleted(Face(f)) && m.is_deleted(Face(f))) kgons_.face[f] = Kgon{};

  update_kgons(m, options, kgons_, a.faces, a.vertices, a.edges);
  std::vector<Corner> changed = fresh;
  std::vector<bool> is_fresh(nh, false);
  for (Corner c : fresh) is_fresh[c.idx] = true;
  for (Corner c : a.corners) {
    ControlNet net = build_control_net(m, kgons_, c);
    if (is_fresh[c.idx] || net != nets_[c.idx]) {
      nets_[c.idx] = net;
      if (!is_fresh[c.idx]) changed.push_back(c);
    }
  }
  for (Corner c : fresh)  // not all fresh corners need be candidates (e.g. after an undo)
    nets_[c.idx] = build_control_net(m, kgons_, c);

  const bool layout_changed = layout(m, was_live);
  mesh_ = m;
  UpdateStats stats;
  stats.layout_changed = layout_changed;
  stats.candidate_patches = static_cast<int>(a.corners.size());
  if (cc) {
    stats.full = true;
    evaluate(corners_, cc.get());
  } else {
    sort_unique(changed);
    evaluate(changed, nullptr);
  }
  stats.recomputed_patches = static_cast<int>(recomputed_.size());
  stats.milliseconds = watch.ms();
  return stats;
}

UpdateStats LiveSurface::update(const HalfedgeMesh& mesh, const KgonOptions& options,
                                const Change& change) {
  if (change.kind == Change::Kind::none) {
    recomputed_.clear();
    return {};
  }
  if (change.kind == Change::Kind::topology) return update_topology(mesh, options);
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
  for (Vertex v : change.moved) mesh_.position(v) = mesh.position(v);
  std::vector<Corner> changed;
  for (Corner c : candidates) {
    ControlNet net = build_control_net(mesh, kgons_, c);
    if (net != nets_[c.idx]) {
      nets_[c.idx] = net;
      changed.push_back(c);
    }
  }
  std::unique_ptr<Surface> cc;
  if (method_ == Method::cc) {
    // The limit surface ignores K-gons, and OpenSubdiv rebuilds it whole after a move.
    changed.clear();
    if (change.kind == Change::Kind::geometry) {
      changed = corners_;
      cc = cc_surface(mesh, options, method_);
    }
  }
  std::sort(changed.begin(), changed.end());
  evaluate(changed, cc.get());
  UpdateStats stats;
  stats.full = cc != nullptr;
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
  evaluate(corners_, cc.get());
  UpdateStats stats;
  stats.full = true;
  stats.recomputed_patches = static_cast<int>(corners_.size());
  stats.milliseconds = watch.ms();
  return stats;
}

UpdateStats LiveSurface::set_resolution(const HalfedgeMesh& mesh, const KgonOptions& options,
                                        int resolution) {
  if (resolution < 1) throw MeshError("the resolution must be at least 1");
  const Stopwatch watch;
  const auto cc = cc_surface(mesh, options, method_);
  resolution_ = resolution;
  tess_ = SurfaceMesh{};
  layout(mesh, {});
  evaluate(corners_, cc.get());
  UpdateStats stats;
  stats.full = stats.layout_changed = true;
  stats.recomputed_patches = static_cast<int>(corners_.size());
  stats.milliseconds = watch.ms();
  return stats;
}

}  // namespace stitch::modeler
