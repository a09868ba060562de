#include "stitch/topology/remesh.hpp"

#include <fmt/format.h>
#include <opensubdiv/far/primvarRefiner.h>

#include <memory>

#include "raw_mesh.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/opensubdiv_topology.hpp"

namespace stitch {

namespace td = topology_detail;

HalfedgeMesh dual(const HalfedgeMesh& input) {
  const HalfedgeMesh m = td::compacted(input);
  for (Halfedge h : m.halfedges())
    if (m.face(h) == m.face(HalfedgeMesh::twin(h)))
      throw MeshError(
          fmt::format("dual: face {} runs along edge {} twice; its dual edge would be a loop",
                      m.face(h).idx + 1, HalfedgeMesh::edge(h).idx + 1));
  td::RawMesh raw;
  for (Face f : m.faces()) raw.positions.push_back(td::face_centroid(m, f));
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
  return td::build_raw(raw, "dual");
}

HalfedgeMesh vertex_insertion(const HalfedgeMesh& input) {
  const HalfedgeMesh m = td::compacted(input);
  const int nv = m.num_vertices(), nh = m.halfedge_capacity();
  td::RawMesh raw;
  raw.positions = m.positions();
  for (Face f : m.faces()) raw.positions.push_back(td::face_centroid(m, f));
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
  return td::build_raw(raw, "vertex-insertion");
}

HalfedgeMesh doo_sabin(const HalfedgeMesh& input) {
  const HalfedgeMesh m = td::compacted(input);
  const int nh = m.halfedge_capacity(), nf = m.num_faces(), ne = m.num_edges();
  td::RawMesh raw;
  std::vector<Vec3> centroid;
  for (Face f : m.faces()) centroid.push_back(td::face_centroid(m, f));
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
  return td::build_raw(raw, "doo-sabin");
}

HalfedgeMesh catmull_clark_step(const HalfedgeMesh& input) {
  using namespace OpenSubdiv;
  const HalfedgeMesh m = td::compacted(input);
  for (Face f : m.faces())
    if (m.degree(f) < 3)
      throw MeshError(fmt::format(
          "catmull-clark: face {} has 2 sides, which OpenSubdiv does not accept", f.idx + 1));
  for (Halfedge h : m.halfedges())
    if (td::edges_between(m, m.origin(h), m.target(h)).size() > 1)
      throw MeshError(fmt::format(
          "catmull-clark: vertices {} and {} are joined by several edges, which OpenSubdiv's "
          "face-vertex input cannot express",
          m.origin(h).idx + 1, m.target(h).idx + 1));

  const auto refiner = catmark_refiner(m);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(1));

  struct Point {
    double p[3] = {0, 0, 0};
    void Clear() { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const Point& s, double w) {
      for (int i = 0; i < 3; ++i) p[i] += w * s.p[i];
    }
  };
  const Far::TopologyLevel& fine = refiner->GetLevel(1);
  std::vector<Point> points(m.num_vertices() + fine.GetNumVertices());
  for (Vertex v : m.vertices())
    for (int i = 0; i < 3; ++i) points[v.idx].p[i] = m.position(v)[i];
  Point* coarse = points.data();
  Point* refined = points.data() + m.num_vertices();
  // Double-precision weights: the float default would cost ~1e-8 relative accuracy.
  Far::PrimvarRefinerReal<double>(*refiner).Interpolate(1, coarse, refined);

  PolygonSoup soup;
  for (int v = 0; v < fine.GetNumVertices(); ++v) {
    const Point& q = points[m.num_vertices() + v];
    soup.positions.emplace_back(q.p[0], q.p[1], q.p[2]);
  }
  for (int f = 0; f < fine.GetNumFaces(); ++f) {
    const Far::ConstIndexArray fv = fine.GetFaceVertices(f);
    soup.faces.emplace_back(fv.begin(), fv.end());
  }
  return build_mesh(soup);
}

}  // namespace stitch
