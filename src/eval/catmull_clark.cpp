#include "stitch/eval/catmull_clark.hpp"

#include <fmt/format.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/surfaceFactoryCache.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <utility>
#include <vector>

#include "mesh/opensubdiv_topology.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/topology/remesh.hpp"
#include "topology/catmark_refinement.hpp"

namespace stitch {
namespace {

namespace Osd = OpenSubdiv;

// Messages number vertices, edges and faces from 1, as the command line and files do.
//
// The live elements of a half-edge mesh's surface (outside holes) numbered densely, as
// OpenSubdiv wants them. Face f's vertices are given in the order of face_loop(f), so corner c is
// face vertex index_in_face(c). Hole faces are left out, so their edges have one face: that is
// how OpenSubdiv represents a boundary. (Its hole tag would not do: it only stops a face being
// drawn, and the surface around it stays the one of the mesh with the face.) Edges between two
// holes and vertices with only holes around them are not part of the surface.
struct OsdTopology {
  const HalfedgeMesh* mesh = nullptr;
  std::vector<Vertex> vertices;
  std::vector<SurfaceRing> rings;  // per dense vertex
  std::vector<Edge> edges;
  std::vector<Face> faces;
  std::vector<int> vertex_id, edge_id, face_id;  // mesh index -> dense index (-1: not on surface)
  mutable std::vector<std::string> problems;     // filled by OpenSubdiv's topology validation

  explicit OsdTopology(const HalfedgeMesh& m) : mesh(&m) {
    vertex_id.assign(static_cast<size_t>(m.vertex_capacity()), -1);
    edge_id.assign(static_cast<size_t>(m.edge_capacity()), -1);
    face_id.assign(static_cast<size_t>(m.face_capacity()), -1);
    for (Vertex v : m.vertices()) {
      SurfaceRing ring = surface_ring(m, v);
      if (ring.faces.empty()) continue;
      vertex_id[v.idx] = static_cast<int>(vertices.size());
      vertices.push_back(v);
      rings.push_back(std::move(ring));
    }
    for (Edge e : m.edges()) {
      if (m.is_hole(HalfedgeMesh::halfedge(e, 0)) && m.is_hole(HalfedgeMesh::halfedge(e, 1)))
        continue;
      edge_id[e.idx] = static_cast<int>(edges.size());
      edges.push_back(e);
    }
    faces = m.surface_faces();
    for (size_t i = 0; i < faces.size(); ++i) face_id[faces[i].idx] = static_cast<int>(i);
  }
  [[nodiscard]] int id(Vertex v) const { return vertex_id[v.idx]; }
  [[nodiscard]] int id(Edge e) const { return edge_id[e.idx]; }
  [[nodiscard]] int id(Face f) const { return face_id[f.idx]; }
};

}  // namespace
}  // namespace stitch

// The half-edge mesh knows every relation OpenSubdiv needs, so the topology is given in full
// (with explicit edges): inferring edges from face-vertices would merge the several edges
// between one pair of vertices that the topology operators create into one non-manifold edge.
namespace OpenSubdiv {
namespace OPENSUBDIV_VERSION {
namespace Far {

using stitch::OsdTopology;

template <>
bool TopologyRefinerFactory<OsdTopology>::resizeComponentTopology(TopologyRefiner& refiner,
                                                                  const OsdTopology& topo) {
  const stitch::HalfedgeMesh& mesh = *topo.mesh;
  setNumBaseVertices(refiner, static_cast<int>(topo.vertices.size()));
  for (size_t i = 0; i < topo.vertices.size(); ++i) {
    setNumBaseVertexFaces(refiner, static_cast<Index>(i),
                          static_cast<int>(topo.rings[i].faces.size()));
    setNumBaseVertexEdges(refiner, static_cast<Index>(i),
                          static_cast<int>(topo.rings[i].edges.size()));
  }
  setNumBaseFaces(refiner, static_cast<int>(topo.faces.size()));
  for (size_t i = 0; i < topo.faces.size(); ++i) {
    setNumBaseFaceVertices(refiner, static_cast<Index>(i), mesh.degree(topo.faces[i]));
  }
  setNumBaseEdges(refiner, static_cast<int>(topo.edges.size()));
  for (size_t i = 0; i < topo.edges.size(); ++i) {
    const stitch::Edge e = topo.edges[i];
    const bool boundary = mesh.is_boundary(e);
    setNumBaseEdgeFaces(refiner, static_cast<Index>(i), boundary ? 1 : 2);
  }
  return true;
}

template <>
bool TopologyRefinerFactory<OsdTopology>::assignComponentTopology(TopologyRefiner& refiner,
                                                                  const OsdTopology& topo) {
  using stitch::HalfedgeMesh;
  const HalfedgeMesh& mesh = *topo.mesh;
  for (size_t i = 0; i < topo.faces.size(); ++i) {
    IndexArray face_vertices = getBaseFaceVertices(refiner, static_cast<Index>(i));
    IndexArray face_edges = getBaseFaceEdges(refiner, static_cast<Index>(i));
    const auto loop = mesh.face_loop(topo.faces[i]);
    for (size_t j = 0; j < loop.size(); ++j) {
      face_vertices[static_cast<int>(j)] = topo.id(mesh.origin(loop[j]));
      face_edges[static_cast<int>(j)] = topo.id(HalfedgeMesh::edge(loop[j]));
    }
  }
  for (size_t i = 0; i < topo.edges.size(); ++i) {
    IndexArray edge_vertices = getBaseEdgeVertices(refiner, static_cast<Index>(i));
    IndexArray edge_faces = getBaseEdgeFaces(refiner, static_cast<Index>(i));
    LocalIndexArray edge_in_face = getBaseEdgeFaceLocalIndices(refiner, static_cast<Index>(i));
    int num_faces = 0;
    for (int side = 0; side < 2; ++side) {
      const stitch::Halfedge h = HalfedgeMesh::halfedge(topo.edges[i], side);
      edge_vertices[side] = topo.id(mesh.origin(h));
      if (mesh.is_hole(h)) continue;
      edge_faces[num_faces] = topo.id(mesh.face(h));
      edge_in_face[num_faces++] = static_cast<LocalIndex>(mesh.index_in_face(h));
    }
  }
  // surface_ring gives OpenSubdiv's order around a vertex: counter-clockwise, edge k leading out
  // of face k, face k+1 across the trailing edge of face k, and on the boundary the first edge
  // and the last one the two boundary edges.
  for (size_t i = 0; i < topo.vertices.size(); ++i) {
    const auto v = static_cast<Index>(i);
    IndexArray vertex_faces = getBaseVertexFaces(refiner, v);
    IndexArray vertex_edges = getBaseVertexEdges(refiner, v);
    LocalIndexArray in_face = getBaseVertexFaceLocalIndices(refiner, v);
    LocalIndexArray in_edge = getBaseVertexEdgeLocalIndices(refiner, v);
    const stitch::SurfaceRing& ring = topo.rings[i];
    for (size_t k = 0; k < ring.faces.size(); ++k) {
      const auto kk = static_cast<int>(k);
      vertex_faces[kk] = topo.id(mesh.face(ring.faces[k]));
      in_face[kk] = static_cast<LocalIndex>(mesh.index_in_face(ring.faces[k]));
    }
    for (size_t k = 0; k < ring.edges.size(); ++k) {
      const auto kk = static_cast<int>(k);
      vertex_edges[kk] = topo.id(HalfedgeMesh::edge(ring.edges[k]));
      // Side 1 of an edge starts at its v1.
      in_edge[kk] = static_cast<LocalIndex>(ring.edges[k].idx & 1);
    }
  }
  return true;
}

// Boundary edges (one face) and corners of the boundary are sharpened by OpenSubdiv itself,
// from the topology and the boundary interpolation option; only the user's tags are given.
template <>
bool TopologyRefinerFactory<OsdTopology>::assignComponentTags(TopologyRefiner& refiner,
                                                              const OsdTopology& topo) {
  const stitch::HalfedgeMesh& mesh = *topo.mesh;
  for (size_t i = 0; i < topo.edges.size(); ++i) {
    const double s = mesh.sharpness(topo.edges[i]);
    if (s > 0.0 && !mesh.is_boundary(topo.edges[i]))
      setBaseEdgeSharpness(refiner, static_cast<Index>(i),
                           static_cast<float>(std::min(s, stitch::infinitely_sharp)));
  }
  for (size_t i = 0; i < topo.vertices.size(); ++i) {
    const double s = mesh.sharpness(topo.vertices[i]);
    if (s > 0.0)
      setBaseVertexSharpness(refiner, static_cast<Index>(i),
                             static_cast<float>(std::min(s, stitch::infinitely_sharp)));
  }
  return true;
}

template <>
void TopologyRefinerFactory<OsdTopology>::reportInvalidTopology(TopologyError /*code*/,
                                                                const char* msg,
                                                                const OsdTopology& topo) {
  topo.problems.emplace_back(msg);
}

}  // namespace Far
}  // namespace OPENSUBDIV_VERSION
}  // namespace OpenSubdiv

namespace stitch {
namespace {

using SurfaceCache =
    Osd::Bfr::SurfaceFactoryCacheThreaded<std::shared_mutex, std::shared_lock<std::shared_mutex>,
                                          std::unique_lock<std::shared_mutex>>;
using SurfaceFactory = Osd::Bfr::RefinerSurfaceFactory<SurfaceCache>;

// OpenSubdiv's (s, t) of the four vertices of a quad face, in face order.
constexpr std::array<std::array<double, 2>, 4> kQuadVertexCoord{
    {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};

// Topology that Vtr cannot represent (a face running along one edge twice: "the same edge
// cannot appear twice in a face", far/topologyRefinerFactory.h), that Bfr mishandles (2-sided
// faces: no limit surface for the faces around them, and writes past its own buffers under
// valgrind), or on which Bfr's surfaces come apart without an error (a face visiting a vertex
// twice, several edges between two vertices: gaps of a fifth of a cube's size were measured), or
// that OpenSubdiv 3.5's Bfr reads past its own crease list on (a face with a valence-2 interior
// vertex and a boundary vertex: IrregularPatchBuilder::sharpenBoundaryControlEdges, fixed in
// 3.6.0). One Catmull-Clark step removes all of these (see CatmullClarkSurface; after it no face
// holds both a valence-2 interior vertex and a boundary vertex), so the first one found is only
// the reason to take it. Only the surface counts: holes are not given to OpenSubdiv.
std::string topology_needing_a_step(const HalfedgeMesh& mesh) {
  enum : char { inside, on_boundary, valence_two };
  std::vector<char> kind(static_cast<size_t>(mesh.vertex_capacity()), inside);
  for (Vertex v : mesh.vertices()) {
    const SurfaceRing ring = surface_ring(mesh, v);
    kind[v.idx] = ring.boundary() ? on_boundary : ring.edges.size() == 2 ? valence_two : inside;
    std::vector<Vertex> seen;
    for (Halfedge h : ring.edges) {
      if (std::find(seen.begin(), seen.end(), mesh.target(h)) != seen.end())
        return fmt::format("vertices {} and {} are joined by more than one edge", v.idx + 1,
                           mesh.target(h).idx + 1);
      seen.push_back(mesh.target(h));
    }
  }
  for (Face f : mesh.surface_faces()) {
    if (mesh.degree(f) == 2) return fmt::format("face {} has 2 sides", f.idx + 1);
    std::vector<Vertex> seen;
    int two = -1;
    bool boundary = false;
    for (Halfedge h : mesh.face_loop(f)) {
      boundary = boundary || kind[mesh.origin(h).idx] == on_boundary;
      if (kind[mesh.origin(h).idx] == valence_two) two = mesh.origin(h).idx;
      if (mesh.face(HalfedgeMesh::twin(h)) == f)
        return fmt::format("face {} runs along edge {} twice", f.idx + 1,
                           HalfedgeMesh::edge(h).idx + 1);
      if (std::find(seen.begin(), seen.end(), mesh.origin(h)) != seen.end())
        return fmt::format("face {} visits vertex {} twice", f.idx + 1, mesh.origin(h).idx + 1);
      seen.push_back(mesh.origin(h));
    }
    if (two >= 0 && boundary)
      return fmt::format("face {} has a valence-2 interior vertex ({}) and a boundary vertex",
                         f.idx + 1, two + 1);
  }
  return {};
}

/// "cc (Catmull-Clark ...) cannot handle WHAT; use mdc or asc", the names from the table.
std::string refusal(const std::string& what) {
  const Choice<Method>& cc = choice_of(method_table(), Method::cc);
  return fmt::format("{} ({}) cannot handle {}; use {} or {}", cc.name, cc.help, what,
                     to_string(Method::mdc), to_string(Method::asc));
}

[[noreturn]] void throw_no_limit_surface(Face f) {
  throw InputError(
      refusal(fmt::format("face {}: OpenSubdiv gives it no limit surface", f.idx + 1)));
}

}  // namespace

struct CatmullClarkSurface::Impl {
  std::vector<Osd::Bfr::Surface<double>> surfaces;  // per dense face
  std::vector<double> patch_points;                 // xyz, all faces one after the other
  std::vector<size_t> patch_offset;                 // per dense face, into patch_points
  std::vector<int> corner_face;                     // per half-edge: dense face, -1 if none
  std::vector<int> corner_index;                    // per half-edge: index in its face's loop

  // When the mesh needed a Catmull-Clark step first: the refined mesh's surface, and per
  // half-edge of this mesh the four corners of its quad there (from its vertex point on).
  std::unique_ptr<CatmullClarkSurface> refined;
  std::vector<std::array<Corner, 4>> quad_corners;  // invalid for deleted half-edges and holes

  [[nodiscard]] bool live(Corner c) const {
    if (c.idx < 0) return false;
    const auto i = static_cast<size_t>(c.idx);
    return refined ? i < quad_corners.size() && quad_corners[i][0].valid()
                   : i < corner_face.size() && corner_face[i] >= 0;
  }
};

CatmullClarkSurface::CatmullClarkSurface(const HalfedgeMesh& mesh, BoundaryInterpolation boundary)
    : CatmullClarkSurface(mesh, 0, boundary) {}

CatmullClarkSurface::CatmullClarkSurface(const HalfedgeMesh& mesh, int steps_taken,
                                         BoundaryInterpolation boundary)
    : impl_(std::make_unique<Impl>()) {
  if (mesh.surface_faces().empty())
    throw InputError(refusal("this mesh: it has no faces outside holes"));
  // A vertex where boundary loops meet stays so under refinement: refused here, where the
  // vertex still has the number the user knows.
  for (Vertex v : mesh.vertices()) {
    try {
      (void)surface_ring(mesh, v);
    } catch (const Error& e) {
      throw_with_message(e, refusal(fmt::format("this mesh: {}", e.what())));
    }
  }
  if (!topology_needing_a_step(mesh).empty()) {
    init_from_refinement(mesh, steps_taken, boundary);
    return;
  }

  const OsdTopology topo(mesh);
  using RefinerFactory = Osd::Far::TopologyRefinerFactory<OsdTopology>;
  RefinerFactory::Options options(Osd::Sdc::SCHEME_CATMARK,
                                  catmark_options(boundary, mesh.crease_method()));
  options.validateFullTopology = true;
  const std::unique_ptr<Osd::Far::TopologyRefiner> refiner(RefinerFactory::Create(topo, options));
  if (!refiner || !topo.problems.empty()) {
    throw InputError(refusal(fmt::format("this mesh: OpenSubdiv refused its topology{}{}",
                                         topo.problems.empty() ? "" : ": ",
                                         topo.problems.empty() ? "" : topo.problems.front())));
  }
  // OpenSubdiv accepts some topology only by tagging it non-manifold (then sharpened) or as a
  // hole: the result would not be the Catmull-Clark limit surface of the mesh's surface.
  const Osd::Far::TopologyLevel& level = refiner->GetLevel(0);
  for (int v = 0; v < level.GetNumVertices(); ++v) {
    if (level.IsVertexNonManifold(v)) {
      throw InputError(
          refusal(fmt::format("vertex {}: OpenSubdiv treats its neighbourhood as non-manifold",
                              topo.vertices[v].idx + 1)));
    }
  }
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    if (level.IsFaceHole(f)) {
      throw InputError(refusal(fmt::format("face {} of degree {}: OpenSubdiv makes it a hole",
                                           topo.faces[f].idx + 1, mesh.degree(topo.faces[f]))));
    }
  }

  // Bfr represents the surface exactly except in the smallest regions around extraordinary
  // points, where it fits Gregory patches after a number of refinement levels (2 by default),
  // and around irregular sharp features (6 levels by default; semi-sharp creases and corners
  // of up to that sharpness are resolved exactly). Counting the steps already taken keeps those
  // regions the same whatever the route, so the surface of a refined mesh is that of the mesh,
  // not only close to it.
  constexpr int kApproxLevelSmooth = 2;
  constexpr int kApproxLevelSharp = 6;
  SurfaceFactory::Options factory_options;
  factory_options.SetApproxLevelSmooth(std::max(0, kApproxLevelSmooth - steps_taken));
  factory_options.SetApproxLevelSharp(std::max(0, kApproxLevelSharp - steps_taken));
  // OpenSubdiv 3.5's Bfr shares a cached irregular patch between faces around a valence-2 vertex
  // that it built from one face's own vertex indices (fixed upstream in 2025, OpenSubdiv pull
  // request 1353): the surfaces then change from run to run by 1% of the size on
  // catmark_val2_interior. Such meshes are built uncached.
  const auto vertices = mesh.vertices();
  factory_options.EnableCaching(std::none_of(vertices.begin(), vertices.end(),
                                             [&](Vertex v) { return mesh.valence(v) == 2; }));
  const SurfaceFactory factory(*refiner, factory_options);
  const int num_faces = static_cast<int>(topo.faces.size());
  Impl& impl = *impl_;
  impl.surfaces.resize(static_cast<size_t>(num_faces));
  std::vector<char> ok(static_cast<size_t>(num_faces), 0);
  tbb::parallel_for(0, num_faces, [&](int f) {
    ok[f] = factory.InitVertexSurface(f, &impl.surfaces[f]) ? 1 : 0;
  });
  for (int f = 0; f < num_faces; ++f) {
    if (ok[f] == 0) throw_no_limit_surface(topo.faces[f]);
  }

  impl.patch_offset.resize(static_cast<size_t>(num_faces) + 1);
  impl.patch_offset[0] = 0;
  for (int f = 0; f < num_faces; ++f) {
    impl.patch_offset[f + 1] =
        impl.patch_offset[f] + 3 * static_cast<size_t>(impl.surfaces[f].GetNumPatchPoints());
  }
  impl.patch_points.resize(impl.patch_offset.back());
  std::vector<double> mesh_points(3 * topo.vertices.size());
  for (size_t i = 0; i < topo.vertices.size(); ++i) {
    const Vec3& p = mesh.position(topo.vertices[i]);
    for (int k = 0; k < 3; ++k) mesh_points[3 * i + k] = p[k];
  }
  const Osd::Bfr::Surface<double>::PointDescriptor xyz(3);
  tbb::parallel_for(0, num_faces, [&](int f) {
    impl.surfaces[f].PreparePatchPoints(mesh_points.data(), xyz,
                                        impl.patch_points.data() + impl.patch_offset[f], xyz);
  });

  impl.corner_face.assign(static_cast<size_t>(mesh.halfedge_capacity()), -1);
  impl.corner_index.assign(static_cast<size_t>(mesh.halfedge_capacity()), -1);
  for (int f = 0; f < num_faces; ++f) {
    const auto loop = mesh.face_loop(topo.faces[f]);
    for (size_t k = 0; k < loop.size(); ++k) {
      impl.corner_face[loop[k].idx] = f;
      impl.corner_index[loop[k].idx] = static_cast<int>(k);
    }
  }
}

// The limit surface of a mesh is that of its Catmull-Clark refinement, and corner c's patch is
// exactly the refined quad of c (the quarter of a quad face, or the quad sub-face of another
// face, in OpenSubdiv's parameterization too). The refined mesh is all quads with one edge per
// pair of vertices, except where a face ran along an edge twice: its two spokes to that edge's
// point join the same two vertices, so there a second step follows (by recursion), after which
// none of this topology is left. The step places creases, corners and the boundary with
// OpenSubdiv's rules and hands the subdivided tags and the holes on, so the refined surface is
// the one OpenSubdiv would give the mesh with its features.
void CatmullClarkSurface::init_from_refinement(const HalfedgeMesh& mesh, int steps_taken,
                                               BoundaryInterpolation boundary) {
  const CatmullClarkRefinement step = catmark_refinement_with_features(mesh, boundary);
  Impl& impl = *impl_;
  impl.quad_corners.assign(static_cast<size_t>(mesh.halfedge_capacity()), {});
  for (Corner c : mesh.patch_corners()) {
    const auto loop = step.mesh.face_loop(step.corner_quad[c.idx]);
    std::copy(loop.begin(), loop.end(), impl.quad_corners[c.idx].begin());
  }
  impl.refined = std::make_unique<CatmullClarkSurface>(step.mesh, steps_taken + 1, boundary);
}

CatmullClarkSurface::~CatmullClarkSurface() = default;
CatmullClarkSurface::CatmullClarkSurface(CatmullClarkSurface&&) noexcept = default;
CatmullClarkSurface& CatmullClarkSurface::operator=(CatmullClarkSurface&&) noexcept = default;

SurfacePoint CatmullClarkSurface::evaluate(Corner c, double u, double v) const {
  const Impl& impl = *impl_;
  if (!impl.live(c)) {
    throw InputError(
        fmt::format("{}: half-edge {} (0-based) is not a live corner of the mesh outside holes",
                    to_string(Method::cc), c.idx));
  }
  if (impl.refined) return evaluate_refined_quad(impl.quad_corners[c.idx], u, v);
  const int f = impl.corner_face[c.idx];
  const int k = impl.corner_index[c.idx];
  const Osd::Bfr::Surface<double>& surface = impl.surfaces[f];
  const Osd::Bfr::Parameterization param = surface.GetParameterization();

  // (s, t) in OpenSubdiv's domain of the face and the Jacobian d(s, t)/d(u, v) (columns
  // ds_du, ds_dv). Corner patches are half the size of the face's domain on each side.
  double st[2];
  std::array<double, 2> st_du{}, st_dv{};
  if (param.GetType() == Osd::Bfr::Parameterization::QUAD) {
    const auto& p0 = kQuadVertexCoord[k];
    const auto& pn = kQuadVertexCoord[(k + 1) % 4];
    const auto& pp = kQuadVertexCoord[(k + 3) % 4];
    for (int i = 0; i < 2; ++i) {
      st_du[i] = 0.5 * (pn[i] - p0[i]);
      st_dv[i] = 0.5 * (pp[i] - p0[i]);
      st[i] = p0[i] + u * st_du[i] + v * st_dv[i];
    }
  } else {
    // A sub-face's normalized (0,0) is at its face vertex, its first coordinate runs towards
    // the next vertex of the face (checked by the patch-side tests).
    const double sub[2] = {u, v};
    param.ConvertNormalizedSubFaceToCoord(k, sub, st);
    st_du = {0.5, 0.0};
    st_dv = {0.0, 0.5};
  }

  double pos[3], ds[3], dt[3];
  surface.Evaluate(st, impl.patch_points.data() + impl.patch_offset[f],
                   Osd::Bfr::Surface<double>::PointDescriptor(3), pos, ds, dt);
  SurfacePoint out;
  out.position = Vec3(pos[0], pos[1], pos[2]);
  const Vec3 d_s(ds[0], ds[1], ds[2]), d_t(dt[0], dt[1], dt[2]);
  out.du = st_du[0] * d_s + st_du[1] * d_t;
  out.dv = st_dv[0] * d_s + st_dv[1] * d_t;
  const Vec3 n = out.du.cross(out.dv);
  const double len = n.norm();
  // Catmull-Clark limit surfaces are regular everywhere (the tangent plane is defined at
  // extraordinary points too), so a vanishing cross product means a degenerate input.
  out.normal = len > 0.0 ? Vec3(n / len) : Vec3::UnitZ();
  out.level = 0;
  return out;
}

// (u, v) over the whole quad: the quarter at quad corner k is that corner's patch, whose own
// (a, b) run from the corner towards the midpoints of its next and previous sides; the chain
// rule carries its derivatives back to (u, v).
SurfacePoint CatmullClarkSurface::evaluate_refined_quad(const std::array<Corner, 4>& quad, double u,
                                                        double v) const {
  const int k = u < 0.5 ? (v < 0.5 ? 0 : 3) : (v < 0.5 ? 1 : 2);
  const auto& p0 = kQuadVertexCoord[k];
  const auto& pn = kQuadVertexCoord[(k + 1) % 4];
  const auto& pp = kQuadVertexCoord[(k + 3) % 4];
  Eigen::Matrix2d to_uv;  // columns: d(u, v)/da and d(u, v)/db
  to_uv << 0.5 * (pn[0] - p0[0]), 0.5 * (pp[0] - p0[0]), 0.5 * (pn[1] - p0[1]),
      0.5 * (pp[1] - p0[1]);
  const Eigen::Matrix2d to_ab = to_uv.inverse();  // exact: entries 0, +-2
  const Eigen::Vector2d ab = to_ab * Eigen::Vector2d(u - p0[0], v - p0[1]);
  SurfacePoint point = impl_->refined->evaluate(quad[k], ab[0], ab[1]);
  const Vec3 da = point.du, db = point.dv;
  point.du = to_ab(0, 0) * da + to_ab(1, 0) * db;
  point.dv = to_ab(0, 1) * da + to_ab(1, 1) * db;
  const Vec3 n = point.du.cross(point.dv);
  const double len = n.norm();
  point.normal = len > 0.0 ? Vec3(n / len) : point.normal;
  return point;
}

}  // namespace stitch
