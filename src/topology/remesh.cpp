#include "stitch/topology/remesh.hpp"

#include <fmt/format.h>
#include <opensubdiv/sdc/catmarkScheme.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "mesh/opensubdiv_topology.hpp"
#include "topology/raw_mesh.hpp"

namespace stitch {

namespace {

// None of these schemes has a rule for a boundary or a crease that this library implements
// (dual and vertex insertion have none at all), and dropping the tags would quietly change the
// surface, so a mesh with any is refused. Numbers are the input's, as the user wrote them.
Verdict features_allowed(const HalfedgeMesh& mesh, const char* op) {
  if (!mesh.has_features()) return {};
  constexpr const char* kWhy = "the remeshings do not carry holes or sharpness tags";
  for (Face f : mesh.faces())
    if (mesh.is_hole(f))
      return Verdict::refused(fmt::format(
          "{}: face {} is a hole (a boundary loop of the surface) and {} (fill-hole {} closes it)",
          op, f.idx + 1, kWhy, f.idx + 1));
  for (Edge e : mesh.edges())
    if (mesh.sharpness(e) > 0) {
      const Halfedge h = HalfedgeMesh::halfedge(e, 0);
      const int a = mesh.origin(h).idx + 1, b = mesh.target(h).idx + 1;
      return Verdict::refused(
          fmt::format("{}: edge {} has sharpness {} and {} (crease {} {} 0 makes it "
                      "smooth)",
                      op, e.idx + 1, mesh.sharpness(e), kWhy, std::min(a, b), std::max(a, b)));
    }
  for (Vertex v : mesh.vertices())
    if (mesh.sharpness(v) > 0)
      return Verdict::refused(
          fmt::format("{}: vertex {} has sharpness {} and {} (corner {} 0 makes it "
                      "smooth)",
                      op, v.idx + 1, mesh.sharpness(v), kWhy, v.idx + 1));
  return {};
}

/// The dual edge of an edge that a face runs along twice would be a loop.
Verdict dual_allowed(const HalfedgeMesh& mesh) {
  if (Verdict v = features_allowed(mesh, "dual"); !v) return v;
  for (Halfedge h : mesh.halfedges())
    if (mesh.face(h) == mesh.face(HalfedgeMesh::twin(h)))
      return Verdict::refused(
          fmt::format("dual: face {} runs along edge {} twice; its dual edge would be a loop",
                      mesh.face(h).idx + 1, HalfedgeMesh::edge(h).idx + 1));
  return {};
}

}  // namespace

HalfedgeMesh dual(const HalfedgeMesh& input) {
  dual_allowed(input).throw_if_refused();
  const HalfedgeMesh m = detail::compacted(input);
  detail::RawMesh raw;
  for (Face f : m.faces()) raw.positions.push_back(detail::face_centroid(m, f));
  raw.num_faces = m.num_vertices();
  const int nh = m.halfedge_capacity();
  raw.origin.resize(nh);
  raw.next.resize(nh);
  raw.face.resize(nh);
  for (Halfedge h : m.halfedges()) {
    raw.origin[h.idx] = m.face(HalfedgeMesh::twin(h)).idx;
    raw.next[h.idx] = m.rotate_ccw(h).idx;
    raw.face[h.idx] = m.origin(h).idx;
  }
  return detail::build_raw(raw, "dual");
}

HalfedgeMesh vertex_insertion(const HalfedgeMesh& input) {
  features_allowed(input, "vertex-insertion").throw_if_refused();
  const HalfedgeMesh m = detail::compacted(input);
  const int nv = m.num_vertices(), nh = m.halfedge_capacity();
  detail::RawMesh raw;
  raw.positions = m.positions();
  for (Face f : m.faces()) raw.positions.push_back(detail::face_centroid(m, f));
  raw.num_faces = m.num_edges();
  raw.origin.resize(2 * nh);
  raw.next.resize(2 * nh);
  raw.face.resize(2 * nh);
  // Spoke of corner c: half-edge 2c runs origin(c) -> face point, 2c+1 back.
  auto out = [](Halfedge c) { return 2 * c.idx; };
  auto back = [](Halfedge c) { return 2 * c.idx + 1; };
  for (Halfedge c : m.halfedges()) {
    raw.origin[out(c)] = m.origin(c).idx;
    raw.origin[back(c)] = nv + m.face(c).idx;
  }
  // Quad of edge e (h: a -> b on face F, t: b -> a on face G): a -> G point -> b -> F point.
  for (Edge e : m.edges()) {
    const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
    const int loop[4] = {out(m.next(t)), back(t), out(m.next(h)), back(h)};
    for (int i = 0; i < 4; ++i) {
      raw.next[loop[i]] = loop[(i + 1) % 4];
      raw.face[loop[i]] = e.idx;
    }
  }
  return detail::build_raw(raw, "vertex-insertion");
}

HalfedgeMesh doo_sabin(const HalfedgeMesh& input) {
  features_allowed(input, "doo-sabin").throw_if_refused();
  const HalfedgeMesh m = detail::compacted(input);
  const int nh = m.halfedge_capacity(), nf = m.num_faces(), ne = m.num_edges();
  detail::RawMesh raw;
  std::vector<Vec3> centroid;
  for (Face f : m.faces()) centroid.push_back(detail::face_centroid(m, f));
  for (Halfedge c : m.halfedges()) {
    const Vec3& p = m.position(m.origin(c));
    const Vec3 m_next = 0.5 * (p + m.position(m.target(c)));
    const Vec3 m_prev = 0.5 * (p + m.position(m.origin(m.prev(c))));
    raw.positions.push_back(0.25 * (p + centroid[m.face(c).idx] + m_next + m_prev));
  }
  raw.num_faces = nf + ne + m.num_vertices();
  // 2H edges: a face edge and a vertex edge per old half-edge.
  raw.origin.resize(4 * nh);
  raw.next.resize(4 * nh);
  raw.face.resize(4 * nh);
  // Face edge of corner c (edge c): 2c runs corner c -> corner next(c) in the shrunken face,
  // 2c+1 back, in the quad of edge(c). Vertex edge of corner x (edge H + x): 2(H+x) runs
  // corner x -> corner rotate_cw(x) in the quad of edge(x), 2(H+x)+1 back, in x's vertex face.
  auto f_fwd = [](Halfedge c) { return 2 * c.idx; };
  auto f_back = [](Halfedge c) { return 2 * c.idx + 1; };
  auto v_fwd = [nh](Halfedge x) { return 2 * (nh + x.idx); };
  auto v_back = [nh](Halfedge x) { return 2 * (nh + x.idx) + 1; };
  for (Halfedge c : m.halfedges()) {
    raw.origin[f_fwd(c)] = c.idx;
    raw.origin[f_back(c)] = m.next(c).idx;
    raw.next[f_fwd(c)] = f_fwd(m.next(c));
    raw.face[f_fwd(c)] = m.face(c).idx;
    raw.origin[v_fwd(c)] = c.idx;
    raw.origin[v_back(c)] = m.rotate_cw(c).idx;
    // Around the vertex face the loop goes from corner rotate_cw(x) to corner x, then on to
    // rotate_ccw(x)'s back half-edge.
    raw.next[v_back(c)] = v_back(m.rotate_ccw(c));
    raw.face[v_back(c)] = nf + ne + m.origin(c).idx;
  }
  for (Edge e : m.edges()) {
    const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
    const int loop[4] = {f_back(h), v_fwd(h), f_back(t), v_fwd(t)};
    for (int i = 0; i < 4; ++i) {
      raw.next[loop[i]] = loop[(i + 1) % 4];
      raw.face[loop[i]] = nf + e.idx;
    }
  }
  return detail::build_raw(raw, "doo-sabin");
}

namespace {

// The neighbourhoods OpenSubdiv's Sdc::Scheme asks about to compute its refinement masks (the
// interfaces of Vtr's componentInterfaces.h). The mesh is closed and carries no creases, so
// every edge has two faces and every sharpness is zero.
struct FaceNeighbourhood {
  int degree = 0;
  [[nodiscard]] int GetNumVertices() const { return degree; }
};

struct EdgeNeighbourhood {
  int degrees[2] = {0, 0};  // of the faces on either side
  [[nodiscard]] static int GetNumFaces() { return 2; }
  [[nodiscard]] static float GetSharpness() { return 0.0F; }
  static void GetChildSharpnesses(const OpenSubdiv::Sdc::Crease& /*crease*/, float s[2]) {
    s[0] = s[1] = 0.0F;
  }
  void GetNumVerticesPerFace(int out[]) const {
    out[0] = degrees[0];
    out[1] = degrees[1];
  }
};

struct VertexNeighbourhood {
  int valence = 0;
  [[nodiscard]] int GetNumEdges() const { return valence; }
  [[nodiscard]] int GetNumFaces() const { return valence; }
  [[nodiscard]] static float GetSharpness() { return 0.0F; }
  [[nodiscard]] static float GetChildSharpness(const OpenSubdiv::Sdc::Crease& /*crease*/) {
    return 0.0F;
  }
  float* GetSharpnessPerEdge(float out[]) const {
    std::fill(out, out + valence, 0.0F);
    return out;
  }
  float* GetChildSharpnessPerEdge(const OpenSubdiv::Sdc::Crease& /*crease*/, float out[]) const {
    return GetSharpnessPerEdge(out);
  }
};

}  // namespace

// OpenSubdiv's Far refiner would need the mesh as a face-vertex list, which cannot express a
// face running along one edge twice or several edges between two vertices; its Sdc layer gives
// the same rules for any neighbourhood, and the half-edge mesh supplies the neighbourhoods.
CatmullClarkRefinement catmull_clark_refinement(const HalfedgeMesh& m) {
  using namespace OpenSubdiv;
  const Sdc::Scheme<Sdc::SCHEME_CATMARK> scheme(catmark_options());
  constexpr Sdc::Crease::Rule kSmooth = Sdc::Crease::RULE_SMOOTH;

  // Dense numbers of the live elements; corner c of edge k and side s is number 2k + s.
  std::vector<int> vid(m.vertex_capacity(), -1), fid(m.face_capacity(), -1),
      eid(m.edge_capacity(), -1);
  const auto vertices = m.vertices().to_vector();
  const auto faces = m.faces().to_vector();
  const auto edges = m.edges().to_vector();
  for (size_t i = 0; i < vertices.size(); ++i) vid[vertices[i].idx] = static_cast<int>(i);
  for (size_t i = 0; i < faces.size(); ++i) fid[faces[i].idx] = static_cast<int>(i);
  for (size_t i = 0; i < edges.size(); ++i) eid[edges[i].idx] = static_cast<int>(i);
  const int nv = m.num_vertices(), nf = m.num_faces(), nh = m.num_halfedges();
  auto corner_id = [&](Halfedge c) { return 2 * eid[HalfedgeMesh::edge(c).idx] + (c.idx & 1); };
  auto face_point = [&](Face f) { return nv + fid[f.idx]; };
  auto edge_point = [&](Halfedge c) { return nv + nf + eid[HalfedgeMesh::edge(c).idx]; };

  detail::RawMesh raw;
  raw.positions.resize(static_cast<size_t>(nv + nf) + edges.size());
  int max_size = 2;
  for (Face f : faces) max_size = std::max(max_size, m.degree(f));
  for (Vertex v : vertices) max_size = std::max(max_size, m.valence(v));
  SdcMask mask(max_size);

  for (Face f : faces) {
    const auto loop = m.face_loop(f);
    scheme.ComputeFaceVertexMask(FaceNeighbourhood{static_cast<int>(loop.size())}, mask);
    Vec3 p = Vec3::Zero();
    for (size_t i = 0; i < loop.size(); ++i) p += mask.vertex[i] * m.position(m.origin(loop[i]));
    raw.positions[face_point(f)] = p;
  }
  for (Edge e : edges) {
    const Halfedge h = HalfedgeMesh::halfedge(e, 0), t = HalfedgeMesh::twin(h);
    scheme.ComputeEdgeVertexMask(EdgeNeighbourhood{{m.degree(m.face(h)), m.degree(m.face(t))}},
                                 mask, kSmooth, kSmooth);
    require_face_centre_weights(mask);
    Vec3 p = mask.vertex[0] * m.position(m.origin(h)) + mask.vertex[1] * m.position(m.origin(t));
    if (mask.num_face > 0)
      p += mask.face[0] * raw.positions[face_point(m.face(h))] +
           mask.face[1] * raw.positions[face_point(m.face(t))];
    raw.positions[edge_point(h)] = p;
  }
  for (Vertex v : vertices) {
    const auto fan = m.vertex_fan(v);
    scheme.ComputeVertexVertexMask(VertexNeighbourhood{static_cast<int>(fan.size())}, mask, kSmooth,
                                   kSmooth);
    require_face_centre_weights(mask);
    // Smaller weights first, as OpenSubdiv's PrimvarRefiner adds them, for the same round-off.
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < mask.num_face; ++i)
      p += mask.face[i] * raw.positions[face_point(m.face(fan[i]))];
    for (int i = 0; i < mask.num_edge; ++i) p += mask.edge[i] * m.position(m.target(fan[i]));
    raw.positions[vid[v.idx]] = p + mask.vertex[0] * m.position(v);
  }

  // Each old half-edge c gives two edges of the refined mesh: the half of its edge at
  // origin(c) (edge corner_id(c), refined half-edge first(c) leaving the vertex point), and the
  // spoke from its edge point to its face point (edge nh + corner_id(c), half-edge in(c) towards
  // the face point, out(c) back).
  auto first = [&](Halfedge c) { return 2 * corner_id(c); };
  auto second = [&](Halfedge c) { return 2 * (corner_id(c) ^ 1) + 1; };
  auto in = [&](Halfedge c) { return 2 * (nh + corner_id(c)); };
  auto out = [&](Halfedge c) { return 2 * (nh + corner_id(c)) + 1; };
  raw.origin.resize(4 * static_cast<size_t>(nh));
  raw.next.resize(raw.origin.size());
  raw.face.resize(raw.origin.size());
  CatmullClarkRefinement result;
  result.corner_quad.assign(static_cast<size_t>(m.halfedge_capacity()), Face());
  std::vector<int> quad_start;
  for (Face f : faces) {
    for (Halfedge c : m.face_loop(f)) {
      const int quad = static_cast<int>(quad_start.size());
      const Halfedge p = m.prev(c);
      raw.origin[first(c)] = vid[m.origin(c).idx];
      raw.origin[second(c)] = edge_point(c);
      raw.origin[in(c)] = edge_point(c);
      raw.origin[out(c)] = face_point(f);
      const int loop[4] = {first(c), in(c), out(p), second(p)};
      for (int i = 0; i < 4; ++i) {
        raw.next[loop[i]] = loop[(i + 1) % 4];
        raw.face[loop[i]] = quad;
      }
      quad_start.push_back(first(c));
      result.corner_quad[c.idx] = Face(quad);
    }
  }
  raw.num_faces = static_cast<int>(quad_start.size());
  result.mesh = detail::build_raw(raw, "catmull-clark");
  for (size_t q = 0; q < quad_start.size(); ++q)
    result.mesh.set_halfedge(Face(static_cast<int>(q)), Halfedge(quad_start[q]));
  return result;
}

HalfedgeMesh catmull_clark_step(const HalfedgeMesh& mesh) {
  features_allowed(mesh, "catmull-clark").throw_if_refused();
  return catmull_clark_refinement(mesh).mesh;
}

Verdict can_remesh(const HalfedgeMesh& mesh, Remeshing scheme) {
  return scheme == Remeshing::dual ? dual_allowed(mesh)
                                   : features_allowed(mesh, remeshing_name(scheme));
}

HalfedgeMesh remesh(const HalfedgeMesh& mesh, Remeshing scheme) {
  switch (scheme) {
    case Remeshing::doo_sabin:
      return doo_sabin(mesh);
    case Remeshing::vertex_insertion:
      return vertex_insertion(mesh);
    case Remeshing::catmull_clark:
      return catmull_clark_step(mesh);
    case Remeshing::dual:
      return dual(mesh);
  }
  throw UsageError("remesh: unknown scheme");
}

const char* remeshing_name(Remeshing scheme) {
  switch (scheme) {
    case Remeshing::doo_sabin:
      return "doo-sabin";
    case Remeshing::vertex_insertion:
      return "vertex-insertion";
    case Remeshing::catmull_clark:
      return "catmull-clark";
    case Remeshing::dual:
      return "dual";
  }
  return "?";
}

}  // namespace stitch
