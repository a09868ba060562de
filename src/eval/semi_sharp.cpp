#include "stitch/eval/semi_sharp.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "stitch/eval/bezier_surface.hpp"
#include "topology/catmark_refinement.hpp"

namespace stitch {

namespace {

/// The largest semi-sharp tag. Boundary edges are infinitely sharp whatever they carry.
double largest_semi_sharp_tag(const HalfedgeMesh& mesh) {
  double largest = 0;
  for (Edge e : mesh.edges())
    if (!mesh.is_boundary(e) && is_semi_sharp(mesh.sharpness(e)))
      largest = std::max(largest, mesh.sharpness(e));
  for (Vertex v : mesh.vertices())
    if (is_semi_sharp(mesh.sharpness(v))) largest = std::max(largest, mesh.sharpness(v));
  return largest;
}

/// ceil(s) as OpenSubdiv counts it: Sdc takes sharpness as a float and lowers it by one per
/// level.
int levels_to_smooth(double s) {
  return static_cast<int>(std::ceil(static_cast<float>(s)));
}

/// One level of linear face-varying refinement (SemiSharpMesh::uvs). Corners that share
/// coordinates keep sharing them: a vertex corner keeps its index, an edge corner's is found by
/// the edge and its ends' indices, a face corner's by the face.
CornerUvs refine_uvs(const HalfedgeMesh& coarse, const CatmullClarkRefinement& step,
                     const CornerUvs& uvs) {
  CornerUvs out;
  out.uv = uvs.uv;
  out.index.assign(static_cast<size_t>(step.mesh.halfedge_capacity()), -1);
  std::map<std::array<int, 3>, int> edge_points;
  std::vector<int> face_point(static_cast<size_t>(coarse.face_capacity()), -1);
  auto edge_point = [&](Edge e, int a, int b) {
    const std::array<int, 3> key{e.idx, std::min(a, b), std::max(a, b)};
    const auto [it, added] = edge_points.try_emplace(key, static_cast<int>(out.uv.size()));
    if (added) out.uv.push_back(0.5 * (uvs.uv[a] + uvs.uv[b]));
    return it->second;
  };
  for (Face f : coarse.faces()) {
    const std::vector<Halfedge> loop = coarse.face_loop(f);
    // Holes, and faces --fill-holes added, have no coordinates: their quads have none either.
    if (std::any_of(loop.begin(), loop.end(), [&](Halfedge h) { return uvs.index[h.idx] < 0; }))
      continue;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (Halfedge h : loop) centre += uvs.uv[uvs.index[h.idx]];
    face_point[f.idx] = static_cast<int>(out.uv.size());
    out.uv.push_back(centre / static_cast<double>(loop.size()));
    for (Halfedge h : loop) {
      const int here = uvs.index[h.idx];
      Halfedge q = step.mesh.halfedge(step.corner_quad[h.idx]);
      // The quad runs from the vertex point to the edge point of edge(h), the face point and the
      // edge point of edge(prev(h)).
      const int indices[4] = {
          here, edge_point(HalfedgeMesh::edge(h), here, uvs.index[coarse.next(h).idx]),
          face_point[f.idx],
          edge_point(HalfedgeMesh::edge(coarse.prev(h)), here, uvs.index[coarse.prev(h).idx])};
      for (int index : indices) {
        out.index[q.idx] = index;
        q = step.mesh.next(q);
      }
    }
  }
  return out;
}

/// Refinement splits a hole into hole quads, which share edges and vertices; the surface's
/// stages take one hole face per boundary loop (halfedge_mesh.hpp). The mesh is built again from
/// its faces outside holes, as a file of it would read back: the same faces in the same order,
/// the input's vertices first with their numbers (only the points inside holes are dropped),
/// the tags; the corner maps and coordinates follow.
void one_hole_per_boundary_loop(SemiSharpMesh& refined) {
  const HalfedgeMesh& old = refined.mesh;
  bool holes = false;
  for (Face f : old.faces()) holes = holes || old.is_hole(f);
  if (!holes) return;
  BuildOptions options;
  options.allow_two_gons = true;
  options.repair = false;
  BuildReport report;
  HalfedgeMesh mesh = build_mesh(to_polygon_soup(old), options, &report);
  // Soup vertices are the live ones in index order; the build keeps the used ones in order.
  std::vector<int> soup_vertex;
  for (Vertex v : old.vertices()) soup_vertex.push_back(v.idx);
  std::vector<int> new_vertex(static_cast<size_t>(old.vertex_capacity()), -1);
  for (size_t v = 0; v < report.vertex_source.size(); ++v)
    new_vertex[static_cast<size_t>(soup_vertex[report.vertex_source[v]])] = static_cast<int>(v);
  // Surface face i of the old mesh is face i of the new one (to_polygon_soup's order, boundary
  // loops' hole faces after them); its corners are matched by their vertices.
  std::vector<Corner> new_corner(static_cast<size_t>(old.halfedge_capacity()));
  int i = 0;
  for (Face f : old.surface_faces()) {
    const std::vector<Halfedge> before = old.face_loop(f);
    const std::vector<Halfedge> after = mesh.face_loop(Face(i++));
    for (Halfedge h : before)
      for (Halfedge k : after)
        if (mesh.origin(k).idx == new_vertex[old.origin(h).idx] &&
            mesh.origin(mesh.next(k)).idx == new_vertex[old.origin(old.next(h)).idx])
          new_corner[h.idx] = k;
  }
  for (std::array<Corner, 4>& quad : refined.quad_corners.back())
    for (Corner& c : quad)
      if (c.valid()) c = new_corner[c.idx];
  if (!refined.uvs.empty()) {
    std::vector<int> index(static_cast<size_t>(mesh.halfedge_capacity()), -1);
    for (size_t h = 0; h < new_corner.size(); ++h)
      if (new_corner[h].valid()) index[new_corner[h].idx] = refined.uvs.index[h];
    refined.uvs.index = std::move(index);
  }
  refined.mesh = std::move(mesh);
}

/// Makes every semi-sharp tag smooth (boundary edges are infinitely sharp whatever they carry).
void smooth_semi_sharp_tags(HalfedgeMesh& mesh) {
  for (Edge e : mesh.edges())
    if (!mesh.is_boundary(e) && is_semi_sharp(mesh.sharpness(e))) mesh.set_sharpness(e, 0.0);
  for (Vertex v : mesh.vertices())
    if (is_semi_sharp(mesh.sharpness(v))) mesh.set_sharpness(v, 0.0);
}

/// Child `k` of a split net in the frame of quad corner k (SemiSharpMesh::point): the child
/// holding the net's corner k (in the order 00, 30, 33, 03), turned so that this corner is its
/// P[0][0] and its u runs towards corner k + 1.
ControlNet quarter(const std::array<ControlNet, 4>& children, int k) {
  static constexpr int kChild[4] = {0, 2, 3, 1};
  const ControlNet& c = children[kChild[k]];
  ControlNet r = c;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const int at[4][2] = {{a, b}, {3 - b, a}, {3 - a, 3 - b}, {b, 3 - a}};
      r.at(a, b) = c.at(at[k][0], at[k][1]);
    }
  static constexpr std::uint8_t kBit[4] = {corner00, corner30, corner33, corner03};
  r.extraordinary = 0;
  for (int i = 0; i < 4; ++i) {
    r.corner_k[i] = c.corner_k[(i + k) % 4];
    if (c.extraordinary & kBit[(i + k) % 4]) r.extraordinary |= kBit[i];
  }
  return r;
}

/// The points of a net's block at its P[0][0]: P00, P01, P10, P11.
constexpr std::array<int, 4> kCornerBlock{0, 1, 4, 5};

}  // namespace

std::string SemiSharpRefinement::summary() const {
  if (levels == 0) return "";
  std::string cut;
  if (levels < levels_to_smooth(largest_tag))
    cut = fmt::format(" (of the {} they need: smooth after them)", levels_to_smooth(largest_tag));
  return fmt::format(
      "semi-sharp tags up to {:g} honoured by {} level{} of uniform refinement{}: {} faces, {} "
      "patches",
      largest_tag, levels, levels == 1 ? "" : "s", cut, faces, patches);
}

SemiSharpRefinement semi_sharp_refinement(const HalfedgeMesh& mesh, Method method,
                                          SemiSharp semi_sharp) {
  SemiSharpRefinement r;
  if (method == Method::cc || semi_sharp != SemiSharp::refine) return r;
  r.largest_tag = largest_semi_sharp_tag(mesh);
  if (r.largest_tag <= 0) return r;
  r.levels_wanted = std::max(min_semi_sharp_levels, levels_to_smooth(r.largest_tag));
  // Level 1 has one quad per corner (hole corners too); each further level four per quad.
  const long long corners = mesh.num_halfedges();
  const long long surface_corners = static_cast<long long>(mesh.patch_corners().size());
  const int most = std::min(r.levels_wanted, max_semi_sharp_levels);
  for (int l = 1; l <= most; ++l) {
    const long long scale = 1LL << (2 * (l - 1));
    if (corners * scale > max_semi_sharp_faces) break;
    r.levels = l;
    r.faces = surface_corners * scale;
    r.patches = 4 * r.faces;
  }
  return r;
}

KgonOptions semi_sharp_kgons(KgonOptions kgons, Method method, SemiSharp semi_sharp) {
  // Honoured tags are gone from the refined mesh: only infinitely sharp ones are left there, and
  // with nothing refined (the limits) the semi-sharp ones are smooth on the input.
  if (semi_sharp == SemiSharp::refine && method != Method::cc) kgons.sharp_from = infinitely_sharp;
  return kgons;
}

SemiSharpMesh refine_semi_sharp(const HalfedgeMesh& mesh, int levels,
                                BoundaryInterpolation boundary, const CornerUvs* uvs) {
  SemiSharpMesh out{mesh, {}, uvs ? *uvs : CornerUvs{}};
  HalfedgeMesh& fine = out.mesh;
  for (int l = 0; l < levels; ++l) {
    CatmullClarkRefinement step = catmark_refinement_with_features(fine, boundary);
    if (!out.uvs.empty()) out.uvs = refine_uvs(fine, step, out.uvs);
    std::vector<std::array<Corner, 4>> quads(static_cast<size_t>(fine.halfedge_capacity()));
    for (Halfedge h : fine.halfedges()) {
      Corner q = step.mesh.halfedge(step.corner_quad[h.idx]);
      for (Corner& k : quads[h.idx]) {
        k = q;
        q = step.mesh.next(q);
      }
    }
    fine = std::move(step.mesh);
    out.quad_corners.push_back(std::move(quads));
  }
  // What the levels did not bring down (the limits cut the refinement short, or Chaikin's rule
  // lowered a tag by less than one a level) is smooth from here on, as OpenSubdiv's limit surface
  // is across a semi-sharp crease: the band it would still round is under 2^-levels of an input
  // face, and a crease the input's untagged surface lacks would not add up with it
  // (semi_sharp_nets).
  smooth_semi_sharp_tags(fine);
  if (levels > 0) one_hole_per_boundary_loop(out);
  return out;
}

SemiSharpMesh::Point SemiSharpMesh::point(Corner c, double u, double v) const {
  // Quad corner k sits at (u, v) = kQuad[k]; its own (a, b) run from there towards the
  // midpoints of its next and previous sides (CatmullClarkSurface::evaluate_refined_quad).
  static constexpr double kQuad[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Point p{c, u, v};
  for (const std::vector<std::array<Corner, 4>>& level : quad_corners) {
    const int k = p.u < 0.5 ? (p.v < 0.5 ? 0 : 3) : (p.v < 0.5 ? 1 : 2);
    const double* p0 = kQuad[k];
    const double* pn = kQuad[(k + 1) % 4];
    const double* pp = kQuad[(k + 3) % 4];
    // (u, v) - p0 = a (pn - p0) / 2 + b (pp - p0) / 2, the columns orthogonal with entries 0, +-1.
    const double du[2] = {0.5 * (pn[0] - p0[0]), 0.5 * (pn[1] - p0[1])};
    const double dv[2] = {0.5 * (pp[0] - p0[0]), 0.5 * (pp[1] - p0[1])};
    const double x = p.u - p0[0], y = p.v - p0[1];
    const double det = du[0] * dv[1] - du[1] * dv[0];
    // (a, b) = A ((u, v) - p0) with A the inverse of the columns du, dv.
    const double inv[2][2] = {{dv[1] / det, -dv[0] / det}, {-du[1] / det, du[0] / det}};
    const double a = inv[0][0] * x + inv[0][1] * y;
    const double b = inv[1][0] * x + inv[1][1] * y;
    double j[2][2];
    for (int r = 0; r < 2; ++r)
      for (int col = 0; col < 2; ++col)
        j[r][col] = inv[r][0] * p.jacobian[0][col] + inv[r][1] * p.jacobian[1][col];
    p.corner = level[p.corner.idx][k];
    p.u = a;
    p.v = b;
    std::copy(&j[0][0], &j[0][0] + 4, &p.jacobian[0][0]);
  }
  return p;
}

SurfacePoint SemiSharpMesh::Point::to_input(SurfacePoint p) const {
  // d/du of the input = sum over r of d(refined r)/du times d/d(refined r).
  const Vec3 du = jacobian[0][0] * p.du + jacobian[1][0] * p.dv;
  const Vec3 dv = jacobian[0][1] * p.du + jacobian[1][1] * p.dv;
  p.du = du;
  p.dv = dv;
  return p;
}

std::vector<Corner> SemiSharpMesh::patches_of(Corner c) const {
  std::vector<Corner> out{c};
  for (const std::vector<std::array<Corner, 4>>& level : quad_corners) {
    std::vector<Corner> next;
    next.reserve(4 * out.size());
    for (Corner x : out) next.insert(next.end(), level[x.idx].begin(), level[x.idx].end());
    out = std::move(next);
  }
  return out;
}

std::vector<Corner> SemiSharpMesh::input_corners() const {
  std::vector<Corner> of(static_cast<size_t>(quad_corners.empty() ? mesh.halfedge_capacity()
                                                                  : quad_corners.front().size()));
  for (size_t h = 0; h < of.size(); ++h) of[h] = Corner(static_cast<int>(h));
  for (const std::vector<std::array<Corner, 4>>& level : quad_corners) {
    size_t size = 0;
    for (const auto& quad : level)
      for (Corner k : quad)
        if (k.valid()) size = std::max(size, static_cast<size_t>(k.idx) + 1);
    std::vector<Corner> below(size);
    for (size_t h = 0; h < level.size(); ++h)
      for (Corner k : level[h])
        if (k.valid()) below[k.idx] = of[h];
    of = std::move(below);
  }
  return of;
}

void semi_sharp_nets(const HalfedgeMesh& input, const KgonOptions& input_options,
                     const SemiSharpMesh& refined, const KgonOptions& options, Method method,
                     std::vector<ControlNet>& nets) {
  const HalfedgeMesh& m = refined.mesh;
  // The input without its semi-sharp tags: what the surface is away from them.
  HalfedgeMesh plain = input;
  smooth_semi_sharp_tags(plain);
  const int levels = static_cast<int>(refined.quad_corners.size());
  const BezierSurface coarse = build_bezier_surface(plain, input_options);
  const SemiSharpMesh plain_refined = refine_semi_sharp(plain, levels, options.boundary);
  // Refinement's connectivity does not depend on the tags: the same corners, numbered alike.
  if (plain_refined.mesh.halfedge_capacity() != m.halfedge_capacity() ||
      nets.size() != static_cast<size_t>(m.halfedge_capacity()))
    throw std::logic_error("semi_sharp_nets: the nets are not those of the refined mesh");
  const KgonSet plain_kgons = build_kgons(plain_refined.mesh, options);
  // mdc splits extraordinary nets with the modified rule as it evaluates them; asc evaluates
  // every net as its polynomial, which the classic rule splits exactly.
  const SplitRule rule = method == Method::mdc ? SplitRule::modified : SplitRule::classic;
  std::vector<std::uint8_t> moved(nets.size(), 0);
  std::vector<std::array<Vec3, 4>> tagged_block(nets.size());
  const auto descend = [&](const auto& self, const ControlNet& net, Corner c, int level) -> void {
    if (level == levels) {
      const ControlNet untagged = build_control_net(plain_refined.mesh, plain_kgons, c);
      ControlNet& out = nets[c.idx];
      for (size_t k = 0; k < kCornerBlock.size(); ++k)
        tagged_block[c.idx][k] = out.p[kCornerBlock[k]];
      for (size_t i = 0; i < out.p.size(); ++i) {
        const Vec3 tags = out.p[i] - untagged.p[i];
        if (tags != Vec3::Zero()) moved[c.idx] = 1;
        out.p[i] = net.p[i] + tags;
      }
      return;
    }
    const std::array<ControlNet, 4> children = split(net, rule);
    const std::array<Corner, 4>& quad = refined.quad_corners[level][c.idx];
    for (int k = 0; k < 4; ++k) self(self, quarter(children, k), quad[k], level + 1);
  };
  const std::vector<Corner> corners = input.patch_corners();
  tbb::parallel_for(size_t{0}, corners.size(), [&](size_t i) {
    descend(descend, coarse.nets[corners[i].idx], corners[i], 0);
  });
  // At an extraordinary vertex the patches of the input's surface and of the refined mesh's
  // have other parameterizations, so where the tags move the nets there, the sum of their
  // corner blocks is neither flat (the K-gons are flattened, which no sum keeps) nor sure to
  // keep its patches' orientation (folding on catmark_helmet, whose creases of 7 meet its
  // boundary's extraordinary vertices, at four levels). There the blocks are the tagged refined
  // mesh's, moved by what the untagged surface adds at the vertex: flat, as a K-gon's corner,
  // C1 with the rest of the nets (all the vertex's blocks move together, so a sharp curve's
  // point moves with both its sides), and in place of the sum only within 2^-levels of the
  // vertex. Each net's block belongs to its vertex alone: vertices in parallel.
  tbb::parallel_for(0, m.vertex_capacity(), [&](int i) {
    const Vertex v(i);
    if (m.is_deleted(v)) return;
    std::vector<Corner> fan;
    bool extraordinary = false, changed = false;
    for (Halfedge h : m.vertex_fan(v)) {
      if (m.is_hole(h)) continue;
      fan.push_back(h);
      extraordinary = extraordinary || (nets[h.idx].extraordinary & corner00) != 0;
      changed = changed || moved[h.idx] != 0;
    }
    if (!extraordinary || !changed) return;
    const Vec3 added = nets[fan.front().idx].p[0] - tagged_block[fan.front().idx][0];
    for (Corner c : fan)
      for (size_t k = 0; k < kCornerBlock.size(); ++k)
        nets[c.idx].p[kCornerBlock[k]] = tagged_block[c.idx][k] + added;
  });
}

}  // namespace stitch
