#include "stitch/mesh/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <span>
#include <tuple>
#include <utility>

#include "mesh/repair_detail.hpp"
#include "mesh/soup_places.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"

namespace stitch {

namespace {

std::string where_face(const PolygonSoup& soup, int f) {
  return soup_places::face(soup, f);
}

std::string where_vertex(const PolygonSoup& soup, int v) {
  return soup_places::vertex(soup, v);
}

void check_soup(const PolygonSoup& soup, const BuildOptions& options) {
  const int nv = static_cast<int>(soup.positions.size());
  for (int v = 0; v < nv; ++v)
    if (const std::string problem = limits::coordinate_problem(soup.positions[v]); !problem.empty())
      throw InputError(fmt::format("{} {}", where_vertex(soup, v), problem));
  if (soup.faces.empty()) throw InputError("the mesh has no faces");
  soup_places::check_face_indices(soup);
  const size_t min_degree = options.allow_two_gons ? 2 : 3;
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const auto& loop = soup.faces[f];
    if (loop.size() < min_degree)
      throw InputError(fmt::format("{} has {} vertices; a face needs at least {}",
                                   where_face(soup, f), loop.size(), min_degree));
    for (size_t i = 0; i < loop.size(); ++i)
      if (loop[i] == loop[(i + 1) % loop.size()])
        throw InputError(fmt::format("{} repeats {} at consecutive positions", where_face(soup, f),
                                     soup_places::vertex(soup, loop[i], false)));
  }
}

struct DirectedEdge {
  int face;
  int slot;  // position in the face loop; the edge runs from slot to slot+1
};

/// The directed edges of a file joining two vertices, and which of them are twins: ranges
/// [first, first + count) of EdgeGroups' flat lists (one allocation for all edges, not several
/// per edge: a mesh has hundreds of thousands).
struct Group {
  int a, b;                      // mesh vertices, a < b in soup order
  int first = 0, count = 0;      // fwd[first + i] pairs with bwd[first + perm[first + i]]
  DirectedEdge unpaired{-1, 0};  // an edge with no partner (face -1: none)
  [[nodiscard]] bool has_unpaired() const { return unpaired.face >= 0; }
};

struct EdgeGroups {
  std::vector<Group> groups;
  std::vector<DirectedEdge> fwd, bwd;  // a -> b and b -> a, group by group
  std::vector<int> perm;
  [[nodiscard]] auto perm_range(const Group& g) {
    return std::pair(perm.begin() + g.first, perm.begin() + g.first + g.count);
  }
};

/// Corner steps the pairing search may take in all (a fraction of a second); beyond it the mesh is
/// refused rather than searched for longer.
constexpr long long kSearchBudget = 20'000'000;

/// Where several edges join the same two vertices a file cannot say which directed edge is the
/// twin of which. This chooses the pairings (Group::perm) so that every vertex gets a single
/// fan, by a depth-first search over the ambiguous groups that checks a vertex as soon as all
/// groups around it are chosen. A vertex is checked on its own corners only, so the search costs
/// in proportion to the corners it touches, not to the mesh. Every valid pairing is reachable, so
/// a mesh written from a valid half-edge mesh always reads back. When there is no valid pairing
/// the groups keep their first pairing and the caller reports a vertex with several fans.
class PairingSearch {
 public:
  PairingSearch(const PolygonSoup& soup, const std::vector<int>& remap, int num_vertices,
                EdgeGroups& edges)
      : edges_(edges), groups_(edges.groups), num_vertices_(num_vertices) {
    // Corner c = offset[f] + i of face f is also the directed edge leaving it.
    std::vector<int> offset(soup.faces.size() + 1, 0);
    for (size_t f = 0; f < soup.faces.size(); ++f)
      offset[f + 1] = offset[f] + static_cast<int>(soup.faces[f].size());
    const int corners = offset.back();
    next_.resize(corners);
    vertex_.resize(corners);
    twin_.assign(corners, -1);
    for (size_t f = 0; f < soup.faces.size(); ++f) {
      const int k = static_cast<int>(soup.faces[f].size());
      for (int i = 0; i < k; ++i) {
        next_[offset[f] + i] = offset[f] + (i + 1) % k;
        vertex_[offset[f] + i] = remap[soup.faces[f][i]];
      }
    }
    auto id = [&](const DirectedEdge& d) { return offset[d.face] + d.slot; };
    fwd_.resize(edges.fwd.size());
    bwd_.resize(edges.bwd.size());
    for (size_t i = 0; i < edges.fwd.size(); ++i) {
      fwd_[i] = id(edges.fwd[i]);
      bwd_[i] = id(edges.bwd[i]);
    }
    boundary_in_.assign(num_vertices, -1);
    for (size_t g = 0; g < groups_.size(); ++g) {
      if (groups_[g].has_unpaired()) {
        // An unpaired edge u -> v: the hole's loop leaves v where this edge arrives.
        const int c = id(groups_[g].unpaired);
        int& in = boundary_in_[vertex_[next_[c]]];
        in = in == -1 ? c : -2;  // -2: several holes meet there (build_mesh refuses it)
      }
      set_twins(static_cast<int>(g));
    }
    // Corners per vertex, as one array sliced by vertex.
    first_corner_.assign(num_vertices + 1, 0);
    for (int c = 0; c < corners; ++c) ++first_corner_[vertex_[c] + 1];
    for (int v = 0; v < num_vertices; ++v) first_corner_[v + 1] += first_corner_[v];
    corners_at_.resize(corners);
    std::vector<int> fill(first_corner_.begin(), first_corner_.end() - 1);
    for (int c = 0; c < corners; ++c) corners_at_[fill[vertex_[c]]++] = c;
  }

  /// Searches; returns false when the budget ran out before an answer.
  bool run() {
    std::vector<int> open;  // ambiguous groups
    std::vector<std::vector<int>> around(num_vertices_);
    for (size_t g = 0; g < groups_.size(); ++g)
      if (groups_[g].count >= 2) {
        open.push_back(static_cast<int>(g));
        around[groups_[g].a].push_back(static_cast<int>(g));
        around[groups_[g].b].push_back(static_cast<int>(g));
      }
    if (open.empty()) return true;
    pending_.assign(num_vertices_, 0);
    for (int v = 0; v < num_vertices_; ++v) pending_[v] = static_cast<int>(around[v].size());
    // A vertex no choice can change decides the answer on its own.
    for (int v = 0; v < num_vertices_; ++v)
      if (pending_[v] == 0 && !single_fan(v)) return true;
    // Groups linked through shared vertices are searched together, each cluster on its own, in
    // breadth-first order so every vertex is checked soon after its first group is chosen.
    std::vector<char> placed(groups_.size(), 0), seen(num_vertices_, 0);
    for (int start : open) {
      if (placed[start]) continue;
      std::vector<int> order{start}, queue;
      placed[start] = 1;
      for (size_t i = 0; i < order.size(); ++i)
        for (int v : {groups_[order[i]].a, groups_[order[i]].b}) {
          if (seen[v]) continue;
          seen[v] = 1;
          for (int g : around[v])
            if (!placed[g]) {
              placed[g] = 1;
              order.push_back(g);
            }
        }
      if (!search(order)) return false;
    }
    return true;
  }

 private:
  void set_twins(int g) {
    const Group& grp = groups_[g];
    for (int i = grp.first; i < grp.first + grp.count; ++i) {
      const int back = grp.first + edges_.perm[i];
      twin_[fwd_[i]] = bwd_[back];
      twin_[bwd_[back]] = fwd_[i];
    }
  }

  /// Whether the corners at v form one cycle under "next corner around v".
  bool single_fan(int v) {
    const int count = first_corner_[v + 1] - first_corner_[v];
    const int start = corners_at_[first_corner_[v]];
    int c = start, steps = 0;
    do {
      const int t = twin_[c];
      if (t >= 0) {
        c = next_[t];
      } else {  // through the hole: on along the unpaired edge that arrives at v
        if (boundary_in_[v] < 0) break;
        c = next_[boundary_in_[v]];
      }
      ++steps;
    } while (c != start && steps <= count);
    work_ += steps;
    return steps == count && c == start;
  }

  /// Chooses the pairings of the groups in `order`; false when the budget is spent.
  bool search(const std::vector<int>& order) {
    const int n = static_cast<int>(order.size());
    std::vector<char> started(n, 0);
    int pos = 0;
    while (pos >= 0 && pos < n) {
      const int g = order[pos];
      Group& grp = groups_[g];
      if (!started[pos]) {
        started[pos] = 1;
      } else {
        ++pending_[grp.a];
        ++pending_[grp.b];
        if (const auto [begin, end] = edges_.perm_range(grp); !std::next_permutation(begin, end)) {
          // Every pairing of this group failed: back to the previous group's next choice.
          started[pos] = 0;
          set_twins(g);
          --pos;
          continue;
        }
      }
      // A choice costs its group's size (next_permutation and set_twins), not one step: with a
      // group of thousands of faces on one vertex pair, counting one would let the budget run
      // for minutes.
      work_ += grp.count;
      if (work_ > kSearchBudget) return false;
      set_twins(g);
      --pending_[grp.a];
      --pending_[grp.b];
      if ((pending_[grp.a] > 0 || single_fan(grp.a)) && (pending_[grp.b] > 0 || single_fan(grp.b)))
        ++pos;
    }
    if (pos < 0) {
      // No pairing works (next_permutation left every group at its first pairing): the caller
      // names a vertex with several fans under the first pairings.
      for (int g : order) set_twins(g);
    }
    return true;
  }

  EdgeGroups& edges_;
  std::vector<Group>& groups_;
  int num_vertices_;
  std::vector<int> next_, vertex_, twin_, boundary_in_;
  std::vector<int> fwd_, bwd_;  // EdgeGroups::fwd and bwd as corner numbers
  std::vector<int> first_corner_, corners_at_, pending_;
  long long work_ = 0;
};

}  // namespace

namespace {

std::string where_tag(const PolygonSoup& soup, int line, const char* what) {
  if (line > 0) return fmt::format("the {} tag on line {} of {}", what, line, soup.source);
  return fmt::format("a {} tag", what);
}

/// Messages number vertices from 1, as everywhere in stitch, but a file's tags (OpenSubdiv's)
/// count from 0: a tag from a file is also quoted with its own numbers, so it can be found.
std::string tag_numbers(int line, int a, int b = -1) {
  if (line <= 0) return "";
  return fmt::format(" (numbered from 1; the tag counts from 0: {}{})", a,
                     b < 0 ? "" : fmt::format(" {}", b));
}

/// One warning for each kind of element whose sharpness is finite but not zero: the K-gon
/// methods honour them only by refining the mesh first (build_surface), which multiplies the
/// patches, or round them when asked (KgonOptions::sharp_from), so the user should know where
/// they are.
void warn_semi_sharp(const HalfedgeMesh& mesh, const PolygonSoup& soup,
                     const std::vector<int>& vertex_source, std::vector<std::string>& warnings) {
  auto number = [&](Vertex v) {
    return soup_places::quoted(soup, soup_places::file_vertex(soup, vertex_source[v.idx]));
  };
  std::vector<std::string> edges, vertices;
  for (Edge e : mesh.edges())
    if (!mesh.is_boundary(e) && is_semi_sharp(mesh.sharpness(e))) {
      const Halfedge h = HalfedgeMesh::halfedge(e, 0);
      edges.push_back(fmt::format("({}, {})", number(mesh.origin(h)), number(mesh.target(h))));
    }
  for (Vertex v : mesh.vertices())
    if (is_semi_sharp(mesh.sharpness(v))) vertices.push_back(std::to_string(number(v)));
  const char* numbered = soup.numbering == Numbering::from_zero ? "from 0" : "from 1";
  // The first few are enough to find them in the file; the count says the rest.
  if (!edges.empty())
    warnings.push_back(fmt::format(
        "{} {} finite sharpness (semi-sharp): the K-gon methods honour them by refining the "
        "mesh ceil(sharpness) levels, from {} to {}, before the patches, or with --sharp-from S "
        "make those of sharpness >= S infinitely sharp and the others smooth (vertices "
        "numbered {}): {}",
        edges.size(), edges.size() == 1 ? "edge has" : "edges have", min_semi_sharp_levels,
        max_semi_sharp_levels, numbered, soup_places::listed(edges)));
  if (!vertices.empty())
    warnings.push_back(fmt::format(
        "{} {} finite corner sharpness (semi-sharp): the K-gon methods honour them by refining "
        "the mesh ceil(sharpness) levels, from {} to {}, before the patches, or with "
        "--sharp-from S make those of sharpness >= S corners and ignore the others (numbered "
        "{}): {}",
        vertices.size(), vertices.size() == 1 ? "vertex has" : "vertices have",
        min_semi_sharp_levels, max_semi_sharp_levels, numbered, soup_places::listed(vertices)));
}

/// Puts the soup's crease and corner tags on the mesh's edges and vertices. A crease names two
/// vertices; every edge joining them takes it (a file cannot tell such edges apart).
void apply_tags(const PolygonSoup& soup, const std::vector<int>& remap, BuildReport& report,
                HalfedgeMesh& mesh) {
  const std::vector<int>& vertex_source = report.vertex_source;
  auto check = [&](double s, int line, const char* what) {
    if (!std::isfinite(s) || s < 0)
      throw InputError(fmt::format("{} has sharpness {}: it must be a finite number >= 0",
                                   where_tag(soup, line, what), s));
  };
  const int nv = static_cast<int>(soup.positions.size());
  auto vertex = [&](int i, int line, const char* what) {
    if (i < 0 || i >= nv)
      throw InputError(fmt::format("{} names vertex {}{}, but there are {} vertices",
                                   where_tag(soup, line, what), i + 1, tag_numbers(line, i), nv));
    if (remap[i] < 0)
      throw InputError(fmt::format("{} names vertex {}{}, which no face uses",
                                   where_tag(soup, line, what), i + 1, tag_numbers(line, i)));
    return Vertex(remap[i]);
  };
  for (const SoupCorner& c : soup.corners) {
    check(c.sharpness, c.line, "corner");
    const Vertex v = vertex(c.vertex, c.line, "corner");
    mesh.set_sharpness(v, std::max(mesh.sharpness(v), c.sharpness));
  }
  for (const SoupCrease& c : soup.creases) {
    check(c.sharpness, c.line, "crease");
    const Vertex a = vertex(c.a, c.line, "crease"), b = vertex(c.b, c.line, "crease");
    bool found = false;
    for (Halfedge h : mesh.vertex_fan(a))
      if (mesh.target(h) == b) {
        const Edge e = HalfedgeMesh::edge(h);
        mesh.set_sharpness(e, std::max(mesh.sharpness(e), c.sharpness));
        found = true;
      }
    if (!found)
      throw InputError(fmt::format("{} names edge ({}, {}){}, but no face has that edge",
                                   where_tag(soup, c.line, "crease"), vertex_source[a.idx] + 1,
                                   vertex_source[b.idx] + 1, tag_numbers(c.line, c.a, c.b)));
  }
  warn_semi_sharp(mesh, soup, vertex_source, report.warnings);
}

/// build_mesh without the repair.
HalfedgeMesh build_as_is(const PolygonSoup& soup, const BuildOptions& options, BuildReport& rep) {
  check_soup(soup, options);

  // Unused vertices are dropped: they have no place on a surface.
  const int nv_in = static_cast<int>(soup.positions.size());
  std::vector<int> used(nv_in, 0);
  for (const auto& loop : soup.faces)
    for (int v : loop) used[v] = 1;
  std::vector<int> remap(nv_in, -1);
  HalfedgeMesh mesh;
  for (int v = 0; v < nv_in; ++v) {
    if (!used[v]) {
      ++rep.dropped_vertices;
      continue;
    }
    remap[v] = mesh.add_vertex(soup.positions[v]).idx;
    rep.vertex_source.push_back(v);
  }
  if (rep.dropped_vertices > 0)
    rep.warnings.push_back(fmt::format("dropped {} unused vertices (not referenced by any face)",
                                       rep.dropped_vertices));

  // Directed edges grouped by their unordered vertex pair (lo, hi), the groups in (lo, hi) order
  // and each group's edges in face order: the order in which the edges are numbered. Bucketed by
  // lo, then sorted by (hi, face, slot) within a bucket (a vertex's few edges).
  std::vector<int> first_at(static_cast<size_t>(nv_in) + 1, 0);
  for (const auto& loop : soup.faces)
    for (size_t i = 0; i < loop.size(); ++i)
      ++first_at[std::min(loop[i], loop[(i + 1) % loop.size()]) + 1];
  for (int v = 0; v < nv_in; ++v) first_at[v + 1] += first_at[v];
  struct EdgeAt {
    int hi;
    DirectedEdge d;
  };
  std::vector<EdgeAt> by_lo(static_cast<size_t>(first_at[nv_in]));
  {
    std::vector<int> fill(first_at.begin(), first_at.end() - 1);
    for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
      const auto& loop = soup.faces[f];
      for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
        const int a = loop[i], b = loop[(i + 1) % loop.size()];
        by_lo[fill[std::min(a, b)]++] = {std::max(a, b), {f, i}};
      }
    }
  }
  auto before = [](const EdgeAt& x, const EdgeAt& y) {
    return std::tie(x.hi, x.d.face, x.d.slot) < std::tie(y.hi, y.d.face, y.d.slot);
  };
  for (int v = 0; v < nv_in; ++v)
    std::sort(by_lo.begin() + first_at[v], by_lo.begin() + first_at[v + 1], before);

  // Pairing: an edge seen once per direction pairs itself. Where several edges join the same two
  // vertices the file cannot say which directed edge is the twin of which, so the pairings of
  // those groups are searched for one under which every vertex has a single fan.
  EdgeGroups pairs;
  pairs.fwd.reserve(by_lo.size() / 2);
  pairs.bwd.reserve(by_lo.size() / 2);
  pairs.perm.reserve(by_lo.size() / 2);
  for (int lo = 0; lo < nv_in; ++lo)
    for (int run = first_at[lo], end = 0; run < first_at[lo + 1]; run = end) {
      const int hi = by_lo[run].hi;
      end = run;
      while (end < first_at[lo + 1] && by_lo[end].hi == hi) ++end;
      // lo -> hi and hi -> lo, in face order.
      auto forward = [&](const EdgeAt& e) { return soup.faces[e.d.face][e.d.slot] == lo; };
      const auto edges = std::span(by_lo).subspan(run, end - run);
      const auto fwd = static_cast<size_t>(std::count_if(edges.begin(), edges.end(), forward));
      const size_t bwd = edges.size() - fwd;
      auto first_of = [&](bool forward_edge) {
        for (const EdgeAt& e : edges)
          if (forward(e) == forward_edge) return e.d;
        return edges[0].d;
      };
      Group grp{remap[lo], remap[hi]};
      if (fwd != bwd) {
        if (edges.size() == 1) {
          grp.unpaired = edges[0].d;
          pairs.groups.push_back(grp);
          continue;
        }
        if (edges.size() == 2) {
          throw InputError(fmt::format(
              "inconsistent orientation: {} and {} both run along {} in the same direction (one of "
              "them must be flipped)",
              where_face(soup, edges[0].d.face), where_face(soup, edges[1].d.face),
              soup_places::edge(soup, lo, hi)));
        }
        throw InputError(fmt::format("non-manifold {}: it is shared by {} faces, e.g. {}",
                                     soup_places::edge(soup, lo, hi), edges.size(),
                                     where_face(soup, first_of(fwd > 0).face)));
      }
      grp.first = static_cast<int>(pairs.fwd.size());
      grp.count = static_cast<int>(fwd);
      for (const EdgeAt& e : edges) (forward(e) ? pairs.fwd : pairs.bwd).push_back(e.d);
      for (int i = 0; i < grp.count; ++i) pairs.perm.push_back(i);
      pairs.groups.push_back(grp);
    }

  // Builds the connectivity for the chosen pairings; returns the vertices with several fans.
  auto assemble = [&](HalfedgeMesh& out) {
    // The half-edge of each face's slot, face after face.
    std::vector<int> slot_first(soup.faces.size() + 1, 0);
    for (size_t f = 0; f < soup.faces.size(); ++f)
      slot_first[f + 1] = slot_first[f] + static_cast<int>(soup.faces[f].size());
    std::vector<Halfedge> slot_he(static_cast<size_t>(slot_first.back()));
    auto slot = [&](const DirectedEdge& d) -> Halfedge& {
      return slot_he[static_cast<size_t>(slot_first[d.face] + d.slot)];
    };
    std::vector<Halfedge> boundary;  // half-edges with no face: twins of unpaired edges
    for (const Group& g : pairs.groups) {
      if (g.has_unpaired()) {
        const DirectedEdge& d = g.unpaired;
        const bool forward = soup.faces[d.face][d.slot] == rep.vertex_source[g.a];
        const Halfedge h = forward ? out.add_edge(Vertex(g.a), Vertex(g.b))
                                   : out.add_edge(Vertex(g.b), Vertex(g.a));
        slot(d) = h;
        boundary.push_back(HalfedgeMesh::twin(h));
      }
      for (int i = g.first; i < g.first + g.count; ++i) {
        const Halfedge h = out.add_edge(Vertex(g.a), Vertex(g.b));
        slot(pairs.fwd[i]) = h;
        slot(pairs.bwd[g.first + pairs.perm[i]]) = HalfedgeMesh::twin(h);
      }
    }
    for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
      const Face face = out.add_face();
      const std::span hs(slot_he.data() + slot_first[f], soup.faces[f].size());
      for (size_t i = 0; i < hs.size(); ++i) {
        out.link(hs[i], hs[(i + 1) % hs.size()]);
        out.set_face(hs[i], face);
        out.set_halfedge(out.origin(hs[i]), hs[i]);
      }
      out.set_halfedge(face, hs[0]);
    }
    if (!boundary.empty()) {
      // Boundary half-edge b->a continues with the boundary half-edge leaving a.
      std::map<int, std::vector<Halfedge>> leaving;
      for (Halfedge h : boundary) leaving[out.origin(h).idx].push_back(h);
      for (const auto& [v, hs] : leaving)
        if (hs.size() > 1)
          throw InputError(fmt::format(
              "{} is non-manifold: {} boundary loops touch there (a surface may meet itself "
              "only along edges)",
              where_vertex(soup, rep.vertex_source[v]), hs.size()));
      for (Halfedge h : boundary) out.link(h, leaving.at(out.target(h).idx)[0]);
      rep.filled_holes = 0;
      for (Halfedge h : boundary) {
        if (out.face(h).valid()) continue;
        const Face hole = out.add_face();
        out.assign_loop(h, hole);
        if (!options.fill_holes) out.set_hole(hole, true);
        ++rep.filled_holes;
      }
    }
    // A vertex is manifold when its outgoing half-edges form a single fan.
    std::vector<int> outgoing(out.vertex_capacity(), 0);
    for (Halfedge h : out.halfedges()) ++outgoing[out.origin(h).idx];
    std::vector<std::pair<Vertex, int>> bad;  // vertex, size of the fan found
    for (Vertex v : out.vertices()) {
      const int fan = static_cast<int>(out.vertex_fan(v).size());
      if (fan != outgoing[v.idx]) bad.emplace_back(v, fan);
    }
    return bad;
  };

  const bool ambiguous = std::any_of(pairs.groups.begin(), pairs.groups.end(),
                                     [](const Group& g) { return g.count >= 2; });
  if (ambiguous && !PairingSearch(soup, remap, mesh.vertex_capacity(), pairs).run())
    throw InputError(
        fmt::format("too many faces run along the same pairs of vertices to tell which of them are "
                    "neighbours (gave up after {} steps); give each face its own vertices",
                    kSearchBudget));
  const auto bad = assemble(mesh);
  if (!bad.empty()) {
    const auto [v, fan] = bad.front();
    int outgoing = 0;
    for (Halfedge h : mesh.halfedges()) outgoing += mesh.origin(h) == v;
    throw InputError(fmt::format(
        "{} is non-manifold: its faces form more than one fan ({} of its {} corners are "
        "connected around it)",
        where_vertex(soup, rep.vertex_source[v.idx]), fan, outgoing));
  }
  if (rep.filled_holes > 0 && options.fill_holes)
    rep.warnings.push_back(fmt::format("filled {} hole(s), each with one face", rep.filled_holes));
  apply_tags(soup, remap, rep, mesh);
  mesh.set_crease_method(soup.crease_method);
  validate(mesh);
  // Soup face f is Face(f), its loop starting at slot 0 (assemble), so texture coordinates go to
  // the corners by position. Faces edited after reading (code that does not know about UVs) no
  // longer match them: they are dropped, with a warning. Bad values are the data's fault.
  if (!soup.face_uvs.empty() || !soup.uvs.empty()) {
    bool match = soup.face_uvs.size() == soup.faces.size();
    for (size_t f = 0; match && f < soup.faces.size(); ++f)
      match = soup.face_uvs[f].size() == soup.faces[f].size();
    if (!match) {
      rep.warnings.push_back(
          "texture coordinates dropped: their face lists do not match the faces (the faces were "
          "changed after reading)");
    } else {
      const int nuv = static_cast<int>(soup.uvs.size());
      for (int u = 0; u < nuv; ++u)
        if (!soup.uvs[u].allFinite())
          throw InputError(fmt::format("texture coordinate {} is not finite", u + 1));
      CornerUvs& out = rep.corner_uvs;
      out.uv = soup.uvs;
      out.index.assign(mesh.halfedge_capacity(), -1);
      for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
        Halfedge h = mesh.halfedge(Face(f));
        for (int i : soup.face_uvs[f]) {
          if (i < 0 || i >= nuv)
            throw InputError(fmt::format("{} refers to texture coordinate {}, but there are {}",
                                         where_face(soup, f), i + 1, nuv));
          out.index[h.idx] = i;
          h = mesh.next(h);
        }
      }
    }
  }
  // Soup face f is Face(f); boundary loops and the faces that fill them come after.
  rep.face_source.assign(mesh.face_capacity(), -1);
  std::iota(rep.face_source.begin(), rep.face_source.begin() + soup.faces.size(), 0);
  return mesh;
}

}  // namespace

HalfedgeMesh build_mesh(const PolygonSoup& soup, const BuildOptions& options, BuildReport* report) {
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  const RepairOptions repair_options{options.allow_two_gons};
  // A soup that builds as it is is taken as it is, repairing on or off: the repair only ever
  // sees what the build refuses, so it never changes a mesh that reads (one stitch wrote).
  std::optional<InputError> refusal;
  try {
    BuildReport as_is;
    HalfedgeMesh mesh = build_as_is(soup, options, as_is);
    rep = std::move(as_is);
    return mesh;
  } catch (const InputError& e) {
    refusal = e;
  }
  if (!options.repair) {
    // What repair() would fix, all of it at once: the user has to fix it all.
    const std::string defects = detail::describe_defects(soup, repair_options);
    if (defects.empty()) throw *refusal;
    throw InputError(fmt::format("{}refused as it is (repairing is off): {}",
                                 soup.source.empty() ? "" : soup.source + ": ", defects));
  }
  // Where several faces each way share an edge, the repair leaves the pairing to the build's
  // search unless the vertices there cannot be manifold; should the build still refuse, every
  // such edge is paired by angle instead.
  std::optional<InputError> failure;
  for (const bool by_angle : {false, true}) {
    RepairReport repairs;
    const auto fixed = detail::repaired(soup, repair_options, repairs, by_angle);
    if (!fixed) continue;
    if (fixed->soup.faces.empty()) {
      std::string dropped;
      for (const std::string& line : repairs.summary()) dropped += "; " + line;
      throw InputError(fmt::format("{}no faces are left{}",
                                   soup.source.empty() ? "" : soup.source + ": ", dropped));
    }
    BuildReport attempt;
    HalfedgeMesh mesh;
    try {
      mesh = build_as_is(fixed->soup, options, attempt);
    } catch (const InputError& e) {
      if (!failure) failure = e;
      continue;
    }
    rep = std::move(attempt);
    // Back to the soup given.
    for (int& v : rep.vertex_source) v = fixed->vertex_from[v];
    for (int& f : rep.face_source)
      if (f >= 0) f = fixed->face_from[f];
    const std::vector<std::string> summary = repairs.summary();
    rep.warnings.insert(rep.warnings.begin(), summary.begin(), summary.end());
    rep.repair = std::move(repairs);
    return mesh;
  }
  throw failure ? *failure : *refusal;
}

PolygonSoup to_polygon_soup(const HalfedgeMesh& mesh) {
  PolygonSoup soup;
  std::vector<int> index(mesh.vertex_capacity(), -1);
  for (Vertex v : mesh.vertices()) {
    index[v.idx] = static_cast<int>(soup.positions.size());
    soup.positions.push_back(mesh.position(v));
  }
  for (Face f : mesh.surface_faces()) {
    std::vector<int> loop;
    for (Halfedge h : mesh.face_loop(f)) loop.push_back(index[mesh.origin(h).idx]);
    soup.faces.push_back(std::move(loop));
  }
  for (Edge e : mesh.edges())
    if (mesh.sharpness(e) > 0) {
      const Halfedge h = HalfedgeMesh::halfedge(e, 0);
      soup.creases.push_back(
          {index[mesh.origin(h).idx], index[mesh.target(h).idx], mesh.sharpness(e), 0});
    }
  for (Vertex v : mesh.vertices())
    if (mesh.sharpness(v) > 0) soup.corners.push_back({index[v.idx], mesh.sharpness(v), 0});
  soup.crease_method = mesh.crease_method();
  return soup;
}

void check_reads_back(const HalfedgeMesh& mesh) {
  BuildOptions options;
  options.allow_two_gons = true;
  options.repair = false;
  const TopologyStats before = topology_stats(mesh);
  const TopologyStats after = topology_stats(build_mesh(to_polygon_soup(mesh), options));
  if (after.vertices != before.vertices || after.edges != before.edges ||
      after.faces != before.faces || after.components != before.components ||
      after.genus != before.genus)
    throw InputError(fmt::format(
        "written to a file, the mesh would read back as another surface ({} components of genus "
        "{} instead of {} of genus {})",
        after.components, after.genus, before.components, before.genus));
}

}  // namespace stitch
