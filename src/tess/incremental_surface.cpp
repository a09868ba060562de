#include "stitch/tess/incremental_surface.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <numeric>

#include "eval/patch_sampler.hpp"
#include "mesh/sort_unique.hpp"
#include "stitch/error.hpp"

namespace stitch {

namespace {

using detail::sort_unique;

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

SurfaceUpdateStats update_stats(size_t candidates, size_t recomputed, bool full,
                                const Stopwatch& watch) {
  SurfaceUpdateStats stats;
  stats.full = full;
  stats.candidate_patches = static_cast<int>(candidates);
  stats.recomputed_patches = static_cast<int>(recomputed);
  stats.milliseconds = watch.ms();
  return stats;
}

template <class T>
void resize_to(std::vector<T>& v, int n) {
  v.resize(static_cast<size_t>(n));
}

}  // namespace

std::vector<Corner> IncrementalSurface::corners() const {
  std::vector<Corner> out;
  out.reserve(static_cast<size_t>(num_patches_));
  for (size_t h = 0; h < live_.size(); ++h)
    if (live_[h]) out.emplace_back(static_cast<int>(h));
  return out;
}

void IncrementalSurface::layout(int slots, const std::vector<int>& changed_slots) {
  const int per_patch = vertices_per_patch(), per_quads = quads_per_patch();
  const size_t nv = static_cast<size_t>(slots) * per_patch;
  tess_.positions.resize(nv, Vec3::Zero());
  tess_.normals.resize(nv, Vec3::Zero());
  tess_.uv.resize(nv, Eigen::Vector2d::Zero());
  tess_.patch.resize(nv, -1);
  tess_.level.resize(nv, 0);
  tess_.quads.resize(static_cast<size_t>(slots) * per_quads);
  relaid_ = changed_slots;
  for (const int h : changed_slots) {
    const bool live = live_[h] != 0;
    // The same vertex and quad order as tessellate(..., welded = false); dead slots draw nothing.
    const int base = h * per_patch;
    for (int s = 0; s < per_patch; ++s) {
      tess_.uv[base + s] = grid_.uv(s);
      tess_.patch[base + s] = live ? h : -1;
      if (!live) {
        tess_.positions[base + s] = tess_.normals[base + s] = Vec3::Zero();
        tess_.level[base + s] = 0;
      }
    }
    auto* q = &tess_.quads[static_cast<size_t>(h) * per_quads];
    if (live)
      grid_.quads(base, q);
    else
      std::fill(q, q + per_quads, std::array<int, 4>{base, base, base, base});
  }
}

std::vector<Corner> IncrementalSurface::changed_nets(const HalfedgeMesh& mesh,
                                                     const std::vector<Corner>& candidates,
                                                     const std::vector<ControlNet>* fresh) {
  std::vector<std::uint8_t> changed(candidates.size(), 0);
  tbb::parallel_for(size_t{0}, candidates.size(), [&](size_t q) {
    const Corner c = candidates[q];
    ControlNet net = fresh ? (*fresh)[c.idx] : build_control_net(mesh, kgons_, c);
    if (net != nets_[c.idx]) {
      nets_[c.idx] = net;  // each candidate's own slot: no two threads write the same one
      changed[q] = 1;
    }
  });
  std::vector<Corner> out;
  for (size_t q = 0; q < candidates.size(); ++q)
    if (changed[q]) out.push_back(candidates[q]);
  return out;
}

void IncrementalSurface::evaluate(const std::vector<Corner>& patches, const Surface* cc) {
  const int per_patch = vertices_per_patch();
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, patches.size(), 16),
      [&](const tbb::blocked_range<size_t>& range) {
        // As tessellate samples: a patch's grid at once, the same numbers as
        // evaluating each point on its own.
        PatchSampler sampler =
            cc ? PatchSampler(*cc, resolution()) : PatchSampler(method_, nets_, resolution());
        const int n = resolution();
        for (size_t q = range.begin(); q < range.end(); ++q) {
          const Corner c = patches[q];
          const size_t at = static_cast<size_t>(c.idx) * per_patch;
          sampler.evaluate_block(c, 0, n, 0, n,
                                 {tess_.positions.data() + at, tess_.normals.data() + at,
                                  tess_.level.data() + at, n + 1});
        }
      });
  recomputed_ = patches;
}

void IncrementalSurface::reserve_room(const HalfedgeMesh& mesh) {
  const auto room = [](int n) { return static_cast<size_t>(slot_capacity_for(n)); };
  const size_t halfedges = room(mesh.halfedge_capacity());
  for (auto* v : {&kgons_.in_face, &kgons_.in_vertex, &kgons_.in_next_edge, &kgons_.in_prev_edge,
                  &kgons_.vertex_k})
    v->reserve(halfedges);
  kgons_.corner_point.reserve(halfedges);
  if (!kgons_.sharp_curve.empty()) kgons_.sharp_curve.reserve(halfedges);
  if (!kgons_.cone.empty()) kgons_.cone.reserve(halfedges);
  if (!kgons_.sharp_edge.empty()) kgons_.sharp_edge.reserve(room(mesh.edge_capacity()));
  kgons_.face.reserve(room(mesh.face_capacity()));
  kgons_.vertex.reserve(room(mesh.vertex_capacity()));
  kgons_.edge.reserve(room(mesh.edge_capacity()));
  nets_.reserve(halfedges);
  live_.reserve(halfedges);
  fresh_tessellation(static_cast<int>(halfedges));
}

void IncrementalSurface::fresh_tessellation(int room_slots) {
  // A fresh one: reserve on a smaller one would keep its old, smaller room.
  tess_ = TessellatedMesh{};
  const auto halfedges = static_cast<size_t>(room_slots);
  const size_t samples = halfedges * static_cast<size_t>(vertices_per_patch());
  tess_.positions.reserve(samples);
  tess_.normals.reserve(samples);
  tess_.uv.reserve(samples);
  tess_.patch.reserve(samples);
  tess_.level.reserve(samples);
  tess_.quads.reserve(halfedges * static_cast<size_t>(quads_per_patch()));
}

SurfaceUpdateStats IncrementalSurface::rebuild_on(const HalfedgeMesh& mesh,
                                                  const KgonOptions& options, Method method,
                                                  int resolution, const HalfedgeMesh* input) {
  const Stopwatch watch;
  PatchGrid grid(resolution);  // may refuse the resolution: nothing has changed yet
  const auto cc = cc_surface(mesh, options, method);
  method_ = method;
  grid_ = std::move(grid);
  kgon_topology_.reset();
  kgons_ = build_kgons(mesh, options);
  nets_ = build_control_nets(mesh, kgons_);
  if (input != nullptr && refined_ && method != Method::cc)
    semi_sharp_nets(*input, options, *refined_, options, method, nets_);
  const int slots = mesh.halfedge_capacity();
  reserve_room(mesh);
  live_.assign(static_cast<size_t>(slots), 0);
  const std::vector<Corner> patch_corners = mesh.patch_corners();
  for (Corner c : patch_corners) live_[c.idx] = 1;
  num_patches_ = static_cast<int>(patch_corners.size());
  std::vector<int> all(static_cast<size_t>(slots));
  std::iota(all.begin(), all.end(), 0);
  layout(slots, all);
  evaluate(corners(), cc.get());
  SurfaceUpdateStats stats = update_stats(num_patches_, num_patches_, true, watch);
  stats.layout_changed = true;
  return stats;
}

SurfaceUpdateStats IncrementalSurface::update_topology(const HalfedgeMesh& m,
                                                       const KgonOptions& options,
                                                       const SurfaceChange& change) {
  if (change.whole) return rebuild_on(m, options, method_, resolution());
  const Stopwatch watch;
  const auto cc = cc_surface(m, options, method_);  // may refuse: nothing has changed yet
  const int nh = m.halfedge_capacity(), old_nh = static_cast<int>(live_.size());
  kgon_topology_.reset();

  // Arrays to the new capacities (an undo can shrink them back); the K-gons and nets of removed
  // elements are emptied below, as build_kgons and build_control_nets leave them.
  resize_to(kgons_.corner_point, nh);
  resize_to(kgons_.in_face, nh);
  resize_to(kgons_.in_vertex, nh);
  resize_to(kgons_.in_next_edge, nh);
  resize_to(kgons_.in_prev_edge, nh);
  kgons_.vertex_k.resize(static_cast<size_t>(nh), 4);
  if (!kgons_.sharp_curve.empty()) kgons_.sharp_curve.resize(static_cast<size_t>(nh));
  if (!kgons_.cone.empty()) kgons_.cone.resize(static_cast<size_t>(nh));
  if (!kgons_.sharp_edge.empty()) kgons_.sharp_edge.resize(static_cast<size_t>(m.edge_capacity()));
  resize_to(kgons_.face, m.face_capacity());
  resize_to(kgons_.vertex, m.vertex_capacity());
  resize_to(kgons_.edge, m.edge_capacity());
  nets_.resize(static_cast<size_t>(nh), unused_net());
  for (int h = nh; h < old_nh; ++h) num_patches_ -= live_[h];
  live_.resize(static_cast<size_t>(nh), 0);

  // The touched elements seed the update: every touched half-edge's face, vertex and edge, the
  // fans of touched vertices, and touched faces (their loops may start elsewhere, which orders
  // their K-gon points).
  std::vector<Face> moved_faces;
  AffectedSet seeds;
  std::vector<Corner> fresh;  // live corners that had no live patch before
  std::vector<int> relaid;    // slots whose liveness changed
  // A corner has a patch while its edge lives and its face is not a hole; a face that became
  // or stopped being a hole changes its corners' liveness without touching their edges.
  auto refresh = [&](Halfedge h) {
    const bool now = !m.is_deleted(h) && !m.is_hole(h);
    if (now != (live_[h.idx] != 0)) {
      relaid.push_back(h.idx);
      num_patches_ += now ? 1 : -1;
      live_[h.idx] = now ? 1 : 0;
      if (now) fresh.push_back(h);
    }
    if (!m.is_deleted(h) && !now) nets_[h.idx].p.fill(Vec3::Zero());
  };
  for (Edge e : change.edges) {
    if (e.idx >= m.edge_capacity()) continue;  // removed again by an undo: truncated above
    for (int side = 0; side < 2; ++side) {
      const Halfedge h = HalfedgeMesh::halfedge(e, side);
      refresh(h);
      if (m.is_deleted(h)) {
        nets_[h.idx].p.fill(Vec3::Zero());  // what's left of a removed corner: never read
        kgons_.corner_point[h.idx] = Vec3::Zero();
        kgons_.in_face[h.idx] = kgons_.in_vertex[h.idx] = kgons_.in_next_edge[h.idx] =
            kgons_.in_prev_edge[h.idx] = -1;
        kgons_.edge[e.idx] = Kgon{};
        continue;
      }
      moved_faces.push_back(m.face(h));
      seeds.vertices.push_back(m.origin(h));
      seeds.edges.push_back(e);
    }
  }
  for (Face f : change.faces)
    if (f.idx < m.face_capacity() && !m.is_deleted(f))
      for (Halfedge h : m.face_loop(f)) {
        refresh(h);
        seeds.vertices.push_back(m.origin(h));
        seeds.edges.push_back(HalfedgeMesh::edge(h));
      }
  for (Vertex v : change.vertices) {
    if (v.idx >= m.vertex_capacity()) continue;
    if (m.is_deleted(v)) {
      kgons_.vertex[v.idx] = Kgon{};
      continue;
    }
    seeds.vertices.push_back(v);
    for (Halfedge h : m.vertex_fan(v)) moved_faces.push_back(m.face(h));
  }
  for (Face f : change.faces) {
    if (f.idx >= m.face_capacity()) continue;
    if (m.is_deleted(f)) {
      kgons_.face[f.idx] = Kgon{};
      continue;
    }
    moved_faces.push_back(f);
  }
  for (int h = old_nh; h < nh; ++h)  // new slots born dead still need their empty quads
    if (!live_[h]) relaid.push_back(h);
  AffectedSet a = affected_by(m, std::move(moved_faces), std::move(seeds));

  update_kgons(m, options, kgons_, a.faces, a.vertices, a.edges);
  std::vector<Corner> changed = fresh;
  std::sort(fresh.begin(), fresh.end());
  for (Corner c : a.corners) {
    ControlNet net = build_control_net(m, kgons_, c);
    const bool is_fresh = std::binary_search(fresh.begin(), fresh.end(), c);
    if (is_fresh || net != nets_[c.idx]) {
      nets_[c.idx] = net;
      if (!is_fresh) changed.push_back(c);
    }
  }
  for (Corner c : fresh)  // not all fresh corners need be candidates (e.g. after an undo)
    nets_[c.idx] = build_control_net(m, kgons_, c);

  layout(nh, relaid);
  if (cc) {
    evaluate(corners(), cc.get());
  } else {
    sort_unique(changed);
    evaluate(changed, nullptr);
  }
  SurfaceUpdateStats stats =
      update_stats(a.corners.size(), recomputed_.size(), cc != nullptr, watch);
  stats.layout_changed = !relaid.empty() || nh != old_nh;
  return stats;
}

SurfaceUpdateStats IncrementalSurface::update_on(const HalfedgeMesh& mesh,
                                                 const KgonOptions& options,
                                                 const SurfaceChange& change) {
  if (change.kind == SurfaceChange::Kind::topology) return update_topology(mesh, options, change);
  relaid_.clear();
  if (change.kind == SurfaceChange::Kind::none) {
    recomputed_.clear();
    return {};
  }
  const Stopwatch watch;
  std::vector<Corner> candidates;
  if (change.all_kgons) {
    kgons_ = build_kgons(mesh, options);
    candidates = corners();
  } else {
    AffectedSet a = affected_by(mesh, change);
    update_kgons(mesh, options, kgons_, a.faces, a.vertices, a.edges);
    candidates = std::move(a.corners);
  }
  std::vector<Corner> changed = changed_nets(mesh, candidates);
  std::unique_ptr<Surface> cc;
  if (method_ == Method::cc) {
    // The limit surface ignores K-gons, and OpenSubdiv rebuilds it whole after a move.
    changed.clear();
    if (change.kind == SurfaceChange::Kind::geometry) {
      changed = corners();
      cc = cc_surface(mesh, options, method_);
    }
  }
  std::sort(changed.begin(), changed.end());
  evaluate(changed, cc.get());
  return update_stats(candidates.size(), changed.size(), cc != nullptr, watch);
}

SurfaceUpdateStats IncrementalSurface::update_positions_on(const HalfedgeMesh& mesh,
                                                           const KgonOptions& options,
                                                           const HalfedgeMesh* input,
                                                           const SemiSharpMesh* refined) {
  const auto slots = static_cast<int>(live_.size());
  if (mesh.halfedge_capacity() != slots ||
      mesh.face_capacity() != static_cast<int>(kgons_.face.size()) ||
      mesh.vertex_capacity() != static_cast<int>(kgons_.vertex.size()) ||
      mesh.edge_capacity() != static_cast<int>(kgons_.edge.size()))
    throw UsageError(fmt::format(
        "IncrementalSurface::update_positions: the mesh has {} half-edge, {} face, {} vertex and "
        "{} edge slots, the surface was built for {}, {}, {} and {}: after a topology edit call "
        "update with its SurfaceChange",
        mesh.halfedge_capacity(), mesh.face_capacity(), mesh.vertex_capacity(),
        mesh.edge_capacity(), slots, kgons_.face.size(), kgons_.vertex.size(), kgons_.edge.size()));
  const Stopwatch watch;
  const auto cc = cc_surface(mesh, options, method_);  // may refuse: nothing has changed yet
  relaid_.clear();
  // Everything that depends on point data, from scratch; the layout stays, and so does the
  // K-gons' topology once prepared (options it depends on may have changed: then again).
  if (!kgon_topology_ || !kgon_topology_->fits(mesh, options)) {
    kgon_topology_ = prepare_kgons(mesh, options);
    kgons_ = kgon_topology_->skeleton;
  }
  place_kgons(mesh, options, *kgon_topology_, kgons_);
  const std::vector<Corner> candidates = corners();
  std::vector<ControlNet> fresh;
  if (input != nullptr && refined != nullptr && !cc) {
    fresh = build_control_nets(mesh, kgons_);
    semi_sharp_nets(*input, options, *refined, options, method_, fresh);
  }
  std::vector<Corner> changed = changed_nets(mesh, candidates, fresh.empty() ? nullptr : &fresh);
  if (cc) changed = candidates;  // the limit surface ignores the nets
  evaluate(changed, cc.get());
  return update_stats(candidates.size(), changed.size(), cc != nullptr, watch);
}

SurfaceUpdateStats IncrementalSurface::set_method(const HalfedgeMesh& mesh,
                                                  const KgonOptions& options, Method method) {
  // A method that takes the tags otherwise (cc honours them itself) needs other K-gons, or
  // another mesh.
  // On a refined mesh the nets depend on the method too (semi_sharp_nets).
  if (semi_sharp_refinement(mesh, method, semi_sharp_).levels != refinement_.levels ||
      on(options, method).sharp_from != on(options, method_).sharp_from || refined_)
    return rebuild(mesh, options, method, resolution(), semi_sharp_);
  const Stopwatch watch;
  const auto cc = cc_surface(this->mesh(mesh), on(options, method), method);
  method_ = method;
  evaluate(corners(), cc.get());
  return update_stats(0, num_patches_, true, watch);
}

SurfaceUpdateStats IncrementalSurface::set_resolution(const HalfedgeMesh& mesh,
                                                      const KgonOptions& options, int resolution) {
  const Stopwatch watch;
  PatchGrid grid(resolution);
  const auto cc = cc_surface(this->mesh(mesh), on(options, method_), method_);
  grid_ = std::move(grid);
  std::vector<int> all(live_.size());
  std::iota(all.begin(), all.end(), 0);
  // Room as after a rebuild, so the next topology edit does not move every sample either.
  fresh_tessellation(slot_capacity_for(static_cast<int>(live_.size())));
  layout(static_cast<int>(live_.size()), all);
  evaluate(corners(), cc.get());
  SurfaceUpdateStats stats = update_stats(0, num_patches_, true, watch);
  stats.layout_changed = true;
  return stats;
}

KgonOptions IncrementalSurface::on(const KgonOptions& options, Method method) const {
  KgonOptions k = semi_sharp_kgons(options, method, semi_sharp_);
  if (refined_) {
    k.face.clear();
    k.edge.clear();
  }
  return k;
}

SemiSharpMesh IncrementalSurface::refine_again(const HalfedgeMesh& input,
                                               const KgonOptions& options) const {
  if (input.halfedge_capacity() != input_halfedges_ || input.vertex_capacity() != input_vertices_)
    throw UsageError(fmt::format(
        "IncrementalSurface: the mesh has {} half-edge and {} vertex slots, the surface was "
        "refined from {} and {}: after a topology edit call update with its SurfaceChange",
        input.halfedge_capacity(), input.vertex_capacity(), input_halfedges_, input_vertices_));
  return refine_semi_sharp(input, refinement_.levels, options.boundary);
}

SurfaceUpdateStats IncrementalSurface::rebuild(const HalfedgeMesh& mesh, const KgonOptions& options,
                                               Method method, int resolution,
                                               SemiSharp semi_sharp) {
  const Stopwatch watch;
  // Everything that can refuse (the refinement, OpenSubdiv's, the resolution) before anything
  // changes.
  const SemiSharpRefinement refinement = semi_sharp_refinement(mesh, method, semi_sharp);
  std::optional<SemiSharpMesh> refined;
  if (refinement.levels > 0)
    refined.emplace(refine_semi_sharp(mesh, refinement.levels, options.boundary));
  const PatchGrid grid(resolution);
  semi_sharp_ = semi_sharp;
  refinement_ = refinement;
  refined_ = std::move(refined);
  input_halfedges_ = mesh.halfedge_capacity();
  input_vertices_ = mesh.vertex_capacity();
  SurfaceUpdateStats stats =
      rebuild_on(this->mesh(mesh), on(options, method), method, resolution, &mesh);
  stats.milliseconds = watch.ms();
  return stats;
}

SurfaceUpdateStats IncrementalSurface::update(const HalfedgeMesh& mesh, const KgonOptions& options,
                                              const SurfaceChange& change) {
  if (!refined_) {
    // A tag edit can make tags to refine for: then refined from here on.
    if (change.kind != SurfaceChange::Kind::topology ||
        semi_sharp_refinement(mesh, method_, semi_sharp_).levels == 0)
      return update_on(mesh, on(options, method_), change);
    return rebuild(mesh, options, method_, resolution(), semi_sharp_);
  }
  // The refined mesh's numbers follow no edit of the input's connectivity or tags: refined again
  // and rebuilt.
  if (change.kind == SurfaceChange::Kind::topology)
    return rebuild(mesh, options, method_, resolution(), semi_sharp_);
  if (change.kind == SurfaceChange::Kind::none) {
    recomputed_.clear();
    relaid_.clear();
    return {};
  }
  return update_positions(mesh, options);
}

SurfaceUpdateStats IncrementalSurface::update_positions(const HalfedgeMesh& mesh,
                                                        const KgonOptions& options) {
  if (!refined_) return update_positions_on(mesh, on(options, method_));
  const Stopwatch watch;
  // The same connectivity refined again gives the same numbers: only the points differ, and
  // the nets compared tell which patches to evaluate again.
  SemiSharpMesh refined = refine_again(mesh, options);
  SurfaceUpdateStats stats =
      update_positions_on(refined.mesh, on(options, method_), &mesh, &refined);
  refined_ = std::move(refined);
  stats.milliseconds = watch.ms();
  return stats;
}

}  // namespace stitch
