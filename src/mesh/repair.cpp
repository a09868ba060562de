// Repair of polygon soups (repair.hpp). One pass reads the soup into flat loops, drops what
// cannot be a face, pairs the faces along every edge (by angle around an edge of 3 or more),
// orients each piece, splits every vertex into its fans and tags the split places sharp. A
// split can put two boundary edges on the same pair of vertices again, which the build would
// join, so passes repeat until one finds nothing (two do, in practice).
#include "stitch/mesh/repair.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <utility>

#include "mesh/repair_detail.hpp"
#include "mesh/soup_places.hpp"

namespace stitch {

namespace places = soup_places;

namespace {

constexpr int kNone = -1;
/// Passes at most; past them the build has the last word.
constexpr int kMaxPasses = 4;

constexpr std::array<Choice<RepairKind>, 7> kKinds{{
    {"repeated_vertex", RepairKind::repeated_vertex,
     "a vertex repeated at consecutive positions of a face, or a face running out along an "
     "edge and straight back: the repeated corners are removed"},
    {"degenerate_face", RepairKind::degenerate_face,
     "a face with fewer than 3 distinct vertices: dropped"},
    {"duplicate_face", RepairKind::duplicate_face,
     "a face with the loop of an earlier one, in the same direction: dropped"},
    {"flipped_face", RepairKind::flipped_face,
     "a face wound against its neighbours: reversed with its texture coordinates (the larger "
     "part of each piece keeps its winding)"},
    {"non_manifold_edge", RepairKind::non_manifold_edge,
     "an edge of 3 or more faces: pairs of faces keep a manifold edge, tagged infinitely sharp, "
     "the others get boundary edges at the same place"},
    {"non_manifold_vertex", RepairKind::non_manifold_vertex,
     "a vertex whose faces form several fans: one vertex per fan at the same position, tagged "
     "as a corner (inside a chain of split edges, a crease vertex)"},
    {"dropped_tag", RepairKind::dropped_tag,
     "a crease or corner tag on an element that only dropped faces had: dropped"},
}};

/// How the kinds read in a summary: "<action> <count> <noun>[<note>]: <places>".
struct KindWords {
  const char* action;
  const char* one;
  const char* many;
  const char* note;
};

KindWords words(RepairKind kind) {
  switch (kind) {
    case RepairKind::repeated_vertex:
      return {"removed the repeats in", "face that repeats a vertex", "faces that repeat a vertex",
              ""};
    case RepairKind::degenerate_face:
      return {"dropped", "face with fewer than 3 distinct vertices",
              "faces with fewer than 3 distinct vertices", ""};
    case RepairKind::duplicate_face:
      return {"dropped", "duplicate face", "duplicate faces", ""};
    case RepairKind::flipped_face:
      return {"flipped", "face wound against its neighbours (inconsistent orientation)",
              "faces wound against their neighbours (inconsistent orientation)",
              "; the larger part of each piece keeps its winding"};
    case RepairKind::non_manifold_edge:
      return {"split", "non-manifold edge (shared by 3 or more faces)",
              "non-manifold edges (shared by 3 or more faces)",
              " into manifold edges tagged infinitely sharp and boundary edges at the same place"};
    case RepairKind::non_manifold_vertex:
      return {"split", "non-manifold vertex (its faces form several fans)",
              "non-manifold vertices (their faces form several fans)",
              " into one vertex per fan at the same position"};
    case RepairKind::dropped_tag:
      return {"dropped", "tag on an element that only dropped faces had",
              "tags on elements that only dropped faces had", ""};
  }
  return {"", "", "", ""};
}

/// The faces a pass works on, as flat arrays: the corners of loop k are first[k] to
/// first[k + 1] - 1 in loop order, and corner c is also the side from vertex[c] to
/// vertex[next(c)].
struct Loops {
  std::vector<int> face;      // loop -> face of the soup
  std::vector<int> first{0};  // loop -> its first corner
  std::vector<int> vertex;    // corner -> vertex
  std::vector<int> slot;      // corner -> position in the soup's face loop
  std::vector<int> owner;     // corner -> loop
  [[nodiscard]] int size() const { return static_cast<int>(face.size()); }
  [[nodiscard]] int corners() const { return static_cast<int>(vertex.size()); }
  [[nodiscard]] int next(int c) const {
    return c + 1 < first[owner[c] + 1] ? c + 1 : first[owner[c]];
  }
  [[nodiscard]] int prev(int c) const {
    return c > first[owner[c]] ? c - 1 : first[owner[c] + 1] - 1;
  }
  [[nodiscard]] int end_at(int side, int v) const { return vertex[side] == v ? side : next(side); }
};

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

enum class EdgeKind : char { boundary, pair, ambiguous, split };

/// One pass over a soup: what it would change, as a plan apply() carries out.
class Pass {
 public:
  Pass(const PolygonSoup& soup, const RepairOptions& options, bool by_angle = false)
      : soup_(soup),
        options_(options),
        by_angle_(by_angle),
        nv_(static_cast<int>(soup.positions.size())) {}

  void run() {
    clean();
    group_sides();
    if (drop_duplicates()) group_sides();
    pair_sides();
    do split_fans();
    while (resolve_ambiguous() || separate_split_sides());
    orient();
    split_vertices();
    tag_split_places();
    carry_tags();
  }

  [[nodiscard]] bool changed() const { return !changes.empty(); }
  /// The soup the plan makes; vertex_from and face_from get the index in this pass's soup of
  /// each of its vertices and faces.
  PolygonSoup apply(std::vector<int>& vertex_from, std::vector<int>& face_from) const;

  std::vector<RepairChange> changes;
  std::vector<std::string> unorientable;  ///< one sentence per piece that cannot be oriented

 private:
  void clean();
  void group_sides();
  bool drop_duplicates();
  void pair_sides();
  void pair_around(int g);
  void split_fans();
  bool resolve_ambiguous();
  bool separate_split_sides();
  void orient();
  [[nodiscard]] double outward_volume(const std::vector<int>& piece,
                                      const std::vector<int>& parity) const;
  void split_vertices();
  void tag_split_places();
  void carry_tags();

  [[nodiscard]] int groups() const { return static_cast<int>(group_first_.size()) - 1; }
  [[nodiscard]] int lo(int g) const { return group_lo_[g]; }
  [[nodiscard]] int hi(int g) const {
    const int s = sides_[group_first_[g]];
    return loops_.vertex[s] == lo(g) ? loops_.vertex[loops_.next(s)] : loops_.vertex[s];
  }
  [[nodiscard]] bool same_direction(int s, int p) const {
    return loops_.vertex[s] == loops_.vertex[p];
  }
  void unite_ends(UnionFind& fans, int s, int p) const {
    for (int v : {loops_.vertex[s], loops_.vertex[loops_.next(s)]})
      fans.unite(loops_.end_at(s, v), loops_.end_at(p, v));
  }
  RepairChange& record(RepairKind kind, std::string defect, std::string action) {
    RepairChange& c = changes.emplace_back();
    c.kind = kind;
    c.defect = std::move(defect);
    c.action = std::move(action);
    return c;
  }
  void note_face(RepairChange& c, int f) const {
    c.faces.push_back(places::file_face(soup_, f));
    c.lines.push_back(f < static_cast<int>(soup_.face_lines.size()) ? soup_.face_lines[f] : 0);
  }
  void note_vertex(RepairChange& c, int v) const {
    c.vertices.push_back(places::file_vertex(soup_, v));
    c.positions.push_back(soup_.positions[v]);
  }
  [[nodiscard]] std::string face_name(int f) const { return places::face(soup_, f, false); }
  [[nodiscard]] std::string vertex_name(int v) const { return places::vertex(soup_, v, false); }
  [[nodiscard]] std::string faces_named(const std::vector<int>& loops) const {
    std::vector<std::string> names;
    for (int k : loops) names.push_back(face_name(loops_.face[k]));
    return places::listed(names);
  }

  const PolygonSoup& soup_;
  RepairOptions options_;
  bool by_angle_;  // pair every ambiguous edge by angle
  int nv_;
  Loops loops_;
  std::vector<char> dropped_face_;  // by soup face, 1 when this pass drops it
  // Sides grouped by vertex pair: group g holds sides_[group_first_[g] .. group_first_[g + 1]).
  std::vector<int> sides_, group_first_, group_lo_, group_of_;
  std::vector<EdgeKind> kind_;
  std::vector<char> cut_;     // by group: a manifold edge cut so that a split can happen
  std::vector<int> partner_;  // by side: the side it pairs with (kNone: a boundary)
  // Fans: by corner, the fan's number at its vertex; fans_at_[v] how many v has.
  std::vector<int> fan_of_, fans_at_;
  std::vector<int> corner_first_, corners_at_;  // corners by vertex
  std::vector<char> flip_;                      // by loop
  std::vector<int> final_;                      // by corner: its vertex after the split
  std::vector<int> copy_of_;                    // new vertex nv_ + i copies copy_of_[i]
  std::vector<int> vertex_change_;              // by vertex: its non_manifold_vertex change
  std::vector<SoupCrease> creases_;
  std::vector<SoupCorner> corners_;
};

/// The corners of a loop (positions in it) left once repeats (a a) and spikes (a b a: out along
/// an edge and straight back, which no face of a manifold has) are removed, read as a cycle;
/// `repeated` and `tips` get the vertices removed by each rule.
std::vector<int> without_repeats(const std::vector<int>& loop, std::vector<int>& repeated,
                                 std::vector<int>& tips) {
  std::vector<int> kept;
  for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
    const int v = loop[i];
    if (!kept.empty() && loop[kept.back()] == v) {
      repeated.push_back(v);
    } else if (kept.size() >= 2 && loop[kept[kept.size() - 2]] == v) {
      tips.push_back(loop[kept.back()]);
      kept.pop_back();
    } else {
      kept.push_back(i);
    }
  }
  // The same across the loop's end.
  for (bool again = true; again && kept.size() >= 2;) {
    const size_t n = kept.size();
    again = true;
    if (loop[kept[n - 1]] == loop[kept[0]]) {
      repeated.push_back(loop[kept[0]]);
      kept.pop_back();
    } else if (n >= 3 && loop[kept[n - 2]] == loop[kept[0]]) {
      tips.push_back(loop[kept[n - 1]]);
      kept.pop_back();  // the end now repeats the start
    } else if (n >= 3 && loop[kept[n - 1]] == loop[kept[1]]) {
      tips.push_back(loop[kept[0]]);
      kept.erase(kept.begin());  // likewise
    } else {
      again = false;
    }
  }
  return kept;
}

void Pass::clean() {
  const int nf = static_cast<int>(soup_.faces.size());
  dropped_face_.assign(nf, 0);
  std::vector<int> distinct, repeated, tips;
  auto names = [&](std::vector<int>& vertices) {
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::vector<std::string> out;
    for (int v : vertices) out.push_back(vertex_name(v));
    return places::listed(out);
  };
  for (int f = 0; f < nf; ++f) {
    const std::vector<int>& loop = soup_.faces[f];
    const int k = static_cast<int>(loop.size());
    repeated.clear();
    tips.clear();
    const std::vector<int> kept = without_repeats(loop, repeated, tips);
    const int repeats = k - static_cast<int>(kept.size());
    distinct.clear();
    for (int i : kept) distinct.push_back(loop[i]);
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const int n = static_cast<int>(distinct.size());
    if (repeats > 0) {
      std::string defect = face_name(f);
      if (!repeated.empty())
        defect += fmt::format(" repeats {} at consecutive positions", names(repeated));
      if (!tips.empty())
        defect += fmt::format("{} runs out to {} and straight back", repeated.empty() ? "" : " and",
                              names(tips));
      RepairChange& c =
          record(RepairKind::repeated_vertex, std::move(defect),
                 fmt::format("removed the {} repeated corner{}", repeats, repeats == 1 ? "" : "s"));
      note_face(c, f);
      for (const std::vector<int>* list : {&repeated, &tips})
        for (int v : *list) note_vertex(c, v);
    }
    // A face given with two vertices is a 2-gon where those are allowed; one that the removal
    // left with two had no area to begin with.
    if (n < 3 && !(n == 2 && repeats == 0 && options_.allow_two_gons)) {
      RepairChange& c = record(
          RepairKind::degenerate_face,
          repeats > 0 ? fmt::format("{} is left with {} distinct {}", face_name(f), n,
                                    n == 1 ? "vertex" : "vertices")
                      : fmt::format("{} has {} vertices; a face needs at least 3", face_name(f), n),
          "dropped it");
      note_face(c, f);
      dropped_face_[f] = 1;
      continue;
    }
    const int index = loops_.size();
    loops_.face.push_back(f);
    for (int i : kept) {
      loops_.vertex.push_back(loop[i]);
      loops_.slot.push_back(i);
      loops_.owner.push_back(index);
    }
    loops_.first.push_back(loops_.corners());
  }
}

void Pass::group_sides() {
  const int n = loops_.corners();
  auto lo_of = [&](int c) { return std::min(loops_.vertex[c], loops_.vertex[loops_.next(c)]); };
  auto hi_of = [&](int c) { return std::max(loops_.vertex[c], loops_.vertex[loops_.next(c)]); };
  // Bucketed by the lower vertex, then sorted by the other within a bucket (a vertex's few
  // sides), as build_mesh groups them.
  std::vector<int> start(static_cast<size_t>(nv_) + 1, 0);
  for (int c = 0; c < n; ++c) ++start[lo_of(c) + 1];
  for (int v = 0; v < nv_; ++v) start[v + 1] += start[v];
  sides_.assign(n, 0);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int c = 0; c < n; ++c) sides_[fill[lo_of(c)]++] = c;
  }
  for (int v = 0; v < nv_; ++v)
    std::sort(sides_.begin() + start[v], sides_.begin() + start[v + 1],
              [&](int a, int b) { return std::pair(hi_of(a), a) < std::pair(hi_of(b), b); });
  group_first_.clear();
  group_lo_.clear();
  group_of_.assign(n, kNone);
  for (int i = 0; i < n; ++i) {
    const int s = sides_[i];
    if (i == 0 || lo_of(s) != lo_of(sides_[i - 1]) || hi_of(s) != hi_of(sides_[i - 1])) {
      group_first_.push_back(i);
      group_lo_.push_back(lo_of(s));
    }
    group_of_[s] = static_cast<int>(group_first_.size()) - 1;
  }
  group_first_.push_back(n);
}

bool Pass::drop_duplicates() {
  // A duplicate runs along each of its edges in the same direction as the face it repeats, so
  // only faces with such a side are compared.
  std::vector<char> candidate(loops_.size(), 0);
  for (int g = 0; g < groups(); ++g) {
    const int b = group_first_[g], e = group_first_[g + 1];
    if (e - b < 2) continue;
    int forward = 0;
    for (int i = b; i < e; ++i) forward += loops_.vertex[sides_[i]] == lo(g);
    if (forward < 2 && e - b - forward < 2) continue;
    for (int i = b; i < e; ++i) candidate[loops_.owner[sides_[i]]] = 1;
  }
  std::map<std::vector<int>, int> seen;  // loop from its smallest rotation -> first loop
  std::vector<char> duplicate(loops_.size(), 0);
  bool any = false;
  for (int k = 0; k < loops_.size(); ++k) {
    if (!candidate[k]) continue;
    const std::vector<int> loop(loops_.vertex.begin() + loops_.first[k],
                                loops_.vertex.begin() + loops_.first[k + 1]);
    std::vector<int> best;
    for (size_t r = 0; r < loop.size(); ++r) {
      std::vector<int> rotated(loop.begin() + static_cast<long>(r), loop.end());
      rotated.insert(rotated.end(), loop.begin(), loop.begin() + static_cast<long>(r));
      if (best.empty() || rotated < best) best = std::move(rotated);
    }
    const auto [it, fresh] = seen.emplace(std::move(best), k);
    if (fresh) continue;
    duplicate[k] = 1;
    any = true;
    const int f = loops_.face[k], first = loops_.face[it->second];
    RepairChange& c =
        record(RepairKind::duplicate_face,
               fmt::format("{} repeats {}", face_name(f), face_name(first)), "dropped the repeat");
    note_face(c, f);
    note_face(c, first);
  }
  if (!any) return false;
  Loops kept;
  for (int k = 0; k < loops_.size(); ++k) {
    if (duplicate[k]) {
      dropped_face_[loops_.face[k]] = 1;
      continue;
    }
    kept.face.push_back(loops_.face[k]);
    for (int c = loops_.first[k]; c < loops_.first[k + 1]; ++c) {
      kept.vertex.push_back(loops_.vertex[c]);
      kept.slot.push_back(loops_.slot[c]);
      kept.owner.push_back(kept.size() - 1);
    }
    kept.first.push_back(kept.corners());
  }
  loops_ = std::move(kept);
  return true;
}

void Pass::pair_sides() {
  partner_.assign(loops_.corners(), kNone);
  kind_.assign(groups(), EdgeKind::boundary);
  cut_.assign(groups(), 0);
  for (int g = 0; g < groups(); ++g) {
    const int b = group_first_[g], e = group_first_[g + 1];
    if (e - b == 1) continue;
    if (e - b == 2) {
      // Running the same way, one of the two will be flipped (orient).
      partner_[sides_[b]] = sides_[b + 1];
      partner_[sides_[b + 1]] = sides_[b];
      kind_[g] = EdgeKind::pair;
      continue;
    }
    std::vector<int> forward, backward;
    for (int i = b; i < e; ++i)
      (loops_.vertex[sides_[i]] == lo(g) ? forward : backward).push_back(sides_[i]);
    if (forward.size() == backward.size() && !by_angle_) {
      // As many faces each way: several edges may join these vertices (2-gons make them), and
      // the build finds which pairs up with which. Paired in order here, for the orientation.
      kind_[g] = EdgeKind::ambiguous;
      for (size_t i = 0; i < forward.size(); ++i) {
        partner_[forward[i]] = backward[i];
        partner_[backward[i]] = forward[i];
      }
      continue;
    }
    pair_around(g);
  }
}

/// Pairs the sides of an edge of 3 or more faces by their angle around it: first the
/// neighbours whose normals point away from the wedge between them (the wedge holds a solid
/// when the faces point outward, as two cubes sharing an edge), then any neighbours running in
/// opposite directions; what is left runs one way and stays a boundary.
void Pass::pair_around(int g) {
  kind_[g] = EdgeKind::split;
  const int b = group_first_[g], e = group_first_[g + 1];
  for (int i = b; i < e; ++i) partner_[sides_[i]] = kNone;
  const Vec3& from = soup_.positions[lo(g)];
  const Vec3 axis = soup_.positions[hi(g)] - from;
  const double length = axis.norm();
  struct Around {
    double angle;
    int side;
    int direction;  // +1: from lo to hi
  };
  std::vector<Around> around;
  Vec3 r1 = Vec3::Zero(), r2 = Vec3::Zero();
  for (int i = b; i < e; ++i) {
    const int s = sides_[i];
    // Towards the face: its corners beside the edge, less their part along it.
    const Vec3 inward = 0.5 * (soup_.positions[loops_.vertex[loops_.next(loops_.next(s))]] +
                               soup_.positions[loops_.vertex[loops_.prev(s)]]) -
                        from;
    Vec3 u = inward;
    if (length > 0) u -= (u.dot(axis) / (length * length)) * axis;
    if (r1 == Vec3::Zero() && u.norm() > 0 && length > 0) {
      r1 = u.normalized();
      r2 = (axis / length).cross(r1);
    }
    const double angle = std::atan2(u.dot(r2), u.dot(r1));  // NaN only from NaN coordinates
    around.push_back({std::isfinite(angle) ? angle : 0.0, s, loops_.vertex[s] == lo(g) ? 1 : -1});
  }
  std::sort(around.begin(), around.end(), [](const Around& x, const Around& y) {
    return std::pair(x.angle, x.side) < std::pair(y.angle, y.side);
  });
  const int m = static_cast<int>(around.size());
  auto pair = [&](int i, int j) {
    partner_[around[i].side] = around[j].side;
    partner_[around[j].side] = around[i].side;
  };
  // A side running from lo to hi has its normal towards larger angles.
  for (int i = 0; i < m; ++i) {
    const int j = (i + 1) % m;
    if (around[i].direction < 0 && around[j].direction > 0) pair(i, j);
  }
  std::vector<int> open;  // unpaired, by angle: neighbours of opposite directions pair up
  for (int i = 0; i < m; ++i) {
    if (partner_[around[i].side] != kNone) continue;
    if (!open.empty() && around[open.back()].direction != around[i].direction) {
      pair(open.back(), i);
      open.pop_back();
    } else {
      open.push_back(i);
    }
  }
}

/// Fans: corners at a vertex joined through paired sides. The corners of an ambiguous edge are
/// all joined at each end, so a vertex there counts as split only if no pairing can join its
/// fans (then resolve_ambiguous pairs that edge by angle).
void Pass::split_fans() {
  const int n = loops_.corners();
  UnionFind fans(n);
  for (int g = 0; g < groups(); ++g) {
    const int b = group_first_[g], e = group_first_[g + 1];
    if (kind_[g] == EdgeKind::ambiguous) {
      for (int v : {lo(g), hi(g)})
        for (int i = b + 1; i < e; ++i)
          fans.unite(loops_.end_at(sides_[b], v), loops_.end_at(sides_[i], v));
      continue;
    }
    for (int i = b; i < e; ++i)
      if (const int s = sides_[i], p = partner_[s]; p != kNone && s < p) unite_ends(fans, s, p);
  }
  if (corner_first_.empty()) {
    corner_first_.assign(static_cast<size_t>(nv_) + 1, 0);
    for (int c = 0; c < n; ++c) ++corner_first_[loops_.vertex[c] + 1];
    for (int v = 0; v < nv_; ++v) corner_first_[v + 1] += corner_first_[v];
    corners_at_.resize(n);
    std::vector<int> fill(corner_first_.begin(), corner_first_.end() - 1);
    for (int c = 0; c < n; ++c) corners_at_[fill[loops_.vertex[c]]++] = c;
  }
  fan_of_.assign(n, kNone);
  fans_at_.assign(nv_, 0);
  std::vector<int> roots;
  for (int v = 0; v < nv_; ++v) {
    roots.clear();
    for (int i = corner_first_[v]; i < corner_first_[v + 1]; ++i) {
      const int c = corners_at_[i], root = fans.find(c);
      const auto at = std::find(roots.begin(), roots.end(), root);
      fan_of_[c] = static_cast<int>(at - roots.begin());
      if (at == roots.end()) roots.push_back(root);
    }
    fans_at_[v] = static_cast<int>(roots.size());
  }
}

/// Pairs by angle the ambiguous edges at vertices no pairing can make manifold: where the
/// joined fans stay several, or where the pieces that the other edges join around the vertex
/// (its segments) cannot chain into one fan: one of them closed among others, or more than two
/// boundary edges (pages on a spine, as OpenSubdiv's nonman_edges).
bool Pass::resolve_ambiguous() {
  const int n = loops_.corners();
  std::vector<char> ambiguous_at(nv_, 0);
  for (int g = 0; g < groups(); ++g)
    if (kind_[g] == EdgeKind::ambiguous) ambiguous_at[lo(g)] = ambiguous_at[hi(g)] = 1;
  UnionFind segments(n);
  for (int g = 0; g < groups(); ++g)
    if (kind_[g] != EdgeKind::ambiguous)
      for (int i = group_first_[g]; i < group_first_[g + 1]; ++i)
        if (const int s = sides_[i], p = partner_[s]; p != kNone && s < p)
          unite_ends(segments, s, p);
  std::vector<char> stuck(nv_, 0);
  std::vector<std::pair<int, int>> ends;  // per segment at a vertex: (root, open sides)
  for (int v = 0; v < nv_; ++v) {
    if (!ambiguous_at[v]) continue;
    if (fans_at_[v] > 1) {
      stuck[v] = 1;
      continue;
    }
    ends.clear();
    int boundary = 0;
    for (int i = corner_first_[v]; i < corner_first_[v + 1]; ++i) {
      const int c = corners_at_[i], root = segments.find(c);
      auto at =
          std::find_if(ends.begin(), ends.end(), [&](const auto& e) { return e.first == root; });
      if (at == ends.end()) at = ends.insert(ends.end(), {root, 0});
      for (int side : {c, loops_.prev(c)}) {
        const EdgeKind kind = kind_[group_of_[side]];
        at->second += kind == EdgeKind::boundary || kind == EdgeKind::ambiguous;
        boundary += kind == EdgeKind::boundary;
      }
    }
    const bool closed =
        std::any_of(ends.begin(), ends.end(), [](const auto& e) { return e.second == 0; });
    stuck[v] = ends.size() > 1 && (closed || boundary > 2);
  }
  bool any = false;
  for (int g = 0; g < groups(); ++g)
    if (kind_[g] == EdgeKind::ambiguous && (stuck[lo(g)] || stuck[hi(g)])) {
      pair_around(g);
      any = true;
    }
  return any;
}

/// A split is made by copies of the edge's vertices, one per fan, so a face leaving the edge must
/// be in other fans than the faces keeping it at one end at least. Where a face is held to them
/// through another edge at both ends (a flap folded onto the sheet), that edge is cut too: its
/// two faces get boundary edges there, and the face its own fan.
bool Pass::separate_split_sides() {
  bool any = false;
  std::map<std::pair<int, int>, std::vector<int>> on;  // fans at both ends -> sides landing there
  for (int g = 0; g < groups(); ++g) {
    if (kind_[g] != EdgeKind::split) continue;
    on.clear();
    for (int i = group_first_[g]; i < group_first_[g + 1]; ++i) {
      const int s = sides_[i];
      on[{fan_of_[loops_.end_at(s, lo(g))], fan_of_[loops_.end_at(s, hi(g))]}].push_back(s);
    }
    for (const auto& [ends, sides] : on) {
      if (sides.size() == 1 || (sides.size() == 2 && partner_[sides[0]] == sides[1])) continue;
      // The first pair there (or the first side) stays; the others leave.
      int stays = sides[0];
      for (int side : sides)
        if (partner_[side] != kNone) {
          stays = side;
          break;
        }
      for (int side : sides) {
        if (side == stays || side == partner_[stays]) continue;
        for (int v : {lo(g), hi(g)}) {
          const int c = loops_.end_at(side, v);
          const int other = c == side ? loops_.prev(c) : c;  // the corner's other side
          const int h = group_of_[other];
          if (kind_[h] == EdgeKind::ambiguous) {
            pair_around(h);
          } else if (const int p = partner_[other]; p != kNone) {
            partner_[other] = partner_[p] = kNone;
            kind_[h] = EdgeKind::split;
            cut_[h] = 1;
          } else {
            continue;
          }
          any = true;
          break;
        }
      }
    }
  }
  return any;
}

void Pass::orient() {
  const int nl = loops_.size();
  flip_.assign(nl, 0);
  std::vector<int> parity(nl, kNone), piece;
  for (int start = 0; start < nl; ++start) {
    if (parity[start] != kNone) continue;
    parity[start] = 0;
    piece.assign(1, start);
    int count[2] = {1, 0};
    int clash = kNone;  // a side where the windings cannot agree
    for (size_t q = 0; q < piece.size(); ++q) {
      const int k = piece[q];
      for (int c = loops_.first[k]; c < loops_.first[k + 1]; ++c) {
        const int p = partner_[c];
        if (p == kNone) continue;
        const int other = loops_.owner[p];
        const int want = parity[k] ^ (same_direction(c, p) ? 1 : 0);
        if (parity[other] == kNone) {
          parity[other] = want;
          ++count[want];
          piece.push_back(other);
        } else if (parity[other] != want && clash == kNone) {
          clash = c;
        }
      }
    }
    if (clash != kNone) {
      // The place to name is where the file's own windings disagree: a piece whose faces all
      // agreed would be oriented already.
      std::vector<std::pair<int, int>> twists;  // sides running along an edge the same way
      for (int k : piece)
        for (int c = loops_.first[k]; c < loops_.first[k + 1]; ++c)
          if (const int p = partner_[c]; p != kNone && c < p && same_direction(c, p))
            twists.emplace_back(c, p);
      std::sort(twists.begin(), twists.end());
      const auto [c, p] = twists.empty() ? std::pair(clash, partner_[clash]) : twists.front();
      unorientable.push_back(fmt::format(
          "the piece with {} is not orientable (like a Möbius strip): no flips make its faces "
          "agree; {} and {} run along {} in the same direction{}",
          face_name(loops_.face[start]), face_name(loops_.face[loops_.owner[c]]),
          face_name(loops_.face[loops_.owner[p]]),
          places::edge(soup_, loops_.vertex[c], loops_.vertex[loops_.next(c)]),
          twists.size() > 1 ? fmt::format(" (and {} more such edges)", twists.size() - 1) : ""));
      continue;
    }
    // The larger part keeps its winding; on a tie, the part that makes the piece point outward
    // (or, flat or open, the part with the piece's first face).
    const int flipped = count[0] != count[1] ? (count[1] > count[0] ? 0 : 1)
                                             : (outward_volume(piece, parity) < 0 ? 0 : 1);
    for (int k : piece) flip_[k] = parity[k] == flipped ? 1 : 0;
  }
  const bool uvs = !soup_.face_uvs.empty();
  for (int k = 0; k < nl; ++k) {
    if (!flip_[k]) continue;
    const int f = loops_.face[k];
    std::string defect = fmt::format("{} is wound against its neighbours", face_name(f));
    for (int c = loops_.first[k]; c < loops_.first[k + 1]; ++c)
      if (const int p = partner_[c];
          p != kNone && same_direction(c, p) && !flip_[loops_.owner[p]]) {
        defect = fmt::format("{} runs along {} in the same direction as {}", face_name(f),
                             places::edge(soup_, loops_.vertex[c], loops_.vertex[loops_.next(c)]),
                             face_name(loops_.face[loops_.owner[p]]));
        break;
      }
    RepairChange& change =
        record(RepairKind::flipped_face, std::move(defect),
               uvs ? "reversed its loop and its texture coordinates" : "reversed its loop");
    note_face(change, f);
  }
}

/// The volume a piece encloses with the parity-0 faces as they are and the others reversed,
/// each face fanned from its first corner; 0 when it is within round-off of 0.
double Pass::outward_volume(const std::vector<int>& piece, const std::vector<int>& parity) const {
  const Vec3& origin = soup_.positions[loops_.vertex[loops_.first[piece.front()]]];
  double volume = 0, scale = 0;
  for (int k : piece) {
    const int b = loops_.first[k], e = loops_.first[k + 1];
    const Vec3 a = soup_.positions[loops_.vertex[b]] - origin;
    for (int c = b + 1; c + 1 < e; ++c) {
      const Vec3 p = soup_.positions[loops_.vertex[c]] - origin;
      const Vec3 q = soup_.positions[loops_.vertex[c + 1]] - origin;
      const double v = a.dot(p.cross(q));
      volume += parity[k] == 0 ? v : -v;
      scale += a.norm() * p.norm() * q.norm();
    }
  }
  return std::abs(volume) <= 1e-9 * scale ? 0 : volume;
}

void Pass::split_vertices() {
  final_ = loops_.vertex;
  vertex_change_.assign(nv_, kNone);
  copy_of_.clear();
  for (int v = 0; v < nv_; ++v) {
    const int fans = fans_at_[v];
    if (fans < 2) continue;
    // The first fan (the one with the earliest corner) keeps the vertex.
    std::vector<int> id(fans, v);
    for (int i = 1; i < fans; ++i) {
      id[i] = nv_ + static_cast<int>(copy_of_.size());
      copy_of_.push_back(v);
    }
    std::vector<int> faces;
    for (int i = corner_first_[v]; i < corner_first_[v + 1]; ++i) {
      const int c = corners_at_[i];
      final_[c] = id[fan_of_[c]];
      faces.push_back(loops_.owner[c]);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    vertex_change_[v] = static_cast<int>(changes.size());
    RepairChange& change =
        record(RepairKind::non_manifold_vertex,
               fmt::format("{} is non-manifold: its faces ({}) form {} fans", vertex_name(v),
                           faces_named(faces), fans),
               fmt::format("split it into {} vertices at the same position", fans));
    note_vertex(change, v);
    for (int k : faces) note_face(change, loops_.face[k]);
  }
}

/// The sharp tags that keep split places together: the pairs on a split edge become an
/// infinitely sharp edge (the others are boundaries), and the vertices there corners, as
/// OpenSubdiv tags non-manifold vertices, except inside a chain of split edges: a vertex with
/// two of them, no boundary and every copy along both stays a crease vertex of the one curve.
void Pass::tag_split_places() {
  std::vector<int> split_at(nv_, 0), boundary_at(nv_, 0);
  for (int g = 0; g < groups(); ++g) {
    if (kind_[g] == EdgeKind::boundary) {
      ++boundary_at[lo(g)];
      ++boundary_at[hi(g)];
    }
    if (kind_[g] != EdgeKind::split) continue;
    ++split_at[lo(g)];
    ++split_at[hi(g)];
    const int b = group_first_[g], e = group_first_[g + 1];
    std::vector<int> faces;
    std::vector<std::string> kept, alone;
    for (int i = b; i < e; ++i) {
      const int s = sides_[i], p = partner_[s];
      faces.push_back(loops_.owner[s]);
      if (p == kNone) {
        alone.push_back(face_name(loops_.face[loops_.owner[s]]));
      } else if (s < p) {
        creases_.push_back({final_[s], final_[loops_.next(s)], infinitely_sharp, 0});
        kept.push_back(fmt::format("{} with {}", face_name(loops_.face[loops_.owner[s]]),
                                   face_name(loops_.face[loops_.owner[p]])));
      }
    }
    const bool cut = cut_[g] && e - b == 2;  // a manifold edge, cut for a split beside it
    std::string action = cut ? "cut it" : "split it";
    if (!kept.empty())
      action += fmt::format(": {} keep{} it, tagged infinitely sharp", places::listed(kept),
                            kept.size() == 1 ? "s" : "");
    if (!alone.empty())
      action +=
          fmt::format("{} {} get{} a boundary edge at the same place", kept.empty() ? ":" : ";",
                      places::listed(alone), alone.size() == 1 ? "s" : "");
    RepairChange& change = record(
        RepairKind::non_manifold_edge,
        cut ? fmt::format("{} joins {}, one of which leaves the other at a split edge beside it "
                          "(a flap folded onto a sheet)",
                          places::edge(soup_, lo(g), hi(g)), faces_named(faces))
            : fmt::format("non-manifold {}: it is shared by {} faces ({})",
                          places::edge(soup_, lo(g), hi(g)), e - b, faces_named(faces)),
        std::move(action));
    note_vertex(change, lo(g));
    note_vertex(change, hi(g));
    for (int k : faces) note_face(change, loops_.face[k]);
  }
  for (int v = 0; v < nv_; ++v) {
    if (fans_at_[v] < 2 && split_at[v] == 0) continue;
    bool crease = split_at[v] == 2 && boundary_at[v] == 0;
    if (crease) {
      // Each fan must run along both split edges, or its copy would end the curve.
      std::vector<std::array<int, 2>> along;  // per fan: the split groups it touches
      along.assign(std::max(fans_at_[v], 1), {kNone, kNone});
      for (int i = corner_first_[v]; crease && i < corner_first_[v + 1]; ++i) {
        const int c = corners_at_[i];
        for (int g : {group_of_[c], group_of_[loops_.prev(c)]}) {
          if (kind_[g] != EdgeKind::split) continue;
          auto& seen = along[fan_of_[c]];
          if (seen[0] == kNone || seen[0] == g)
            seen[0] = g;
          else
            seen[1] = g;
        }
      }
      for (const auto& seen : along) crease = crease && seen[1] != kNone;
    }
    if (const int i = vertex_change_[v]; i != kNone)
      changes[i].action += crease ? ", crease vertices of the one sharp curve along the split edges"
                                  : ", each tagged as an infinitely sharp corner";
    if (crease) continue;
    std::vector<char> done(fans_at_[v], 0);
    for (int i = corner_first_[v]; i < corner_first_[v + 1]; ++i) {
      const int c = corners_at_[i];
      if (done[fan_of_[c]]) continue;
      done[fan_of_[c]] = 1;
      corners_.push_back({final_[c], infinitely_sharp, 0});
    }
  }
}

/// The soup's own tags, moved with the repairs: a split vertex's tags go to every copy, a
/// crease to every edge joining copies of its two vertices; tags on what only dropped faces had
/// are dropped and named. Tags that were wrong before are left for the build to refuse.
void Pass::carry_tags() {
  const auto in_range = [&](int v) { return v >= 0 && v < nv_; };
  // What the soup's faces had before this pass dropped some, found when first needed.
  std::vector<char> used_before;
  std::vector<std::pair<int, int>> edges_before;
  auto find_before = [&] {
    if (!used_before.empty()) return;
    used_before.assign(nv_, 0);
    for (const auto& loop : soup_.faces)
      for (size_t i = 0; i < loop.size(); ++i) {
        used_before[loop[i]] = 1;
        const int a = loop[i], b = loop[(i + 1) % loop.size()];
        edges_before.emplace_back(std::min(a, b), std::max(a, b));
      }
    std::sort(edges_before.begin(), edges_before.end());
  };
  auto dropped = [&](const char* what, const char* element, int line) -> RepairChange& {
    return record(RepairKind::dropped_tag,
                  fmt::format("the {} tag{} names {} that only dropped faces had", what,
                              line > 0 ? fmt::format(" on line {}", line) : "", element),
                  "dropped the tag");
  };
  for (const SoupCorner& t : soup_.corners) {
    if (!in_range(t.vertex)) {
      corners_.push_back(t);  // the build refuses it
      continue;
    }
    if (corner_first_[t.vertex] < corner_first_[t.vertex + 1]) {
      std::vector<char> done(fans_at_[t.vertex], 0);
      for (int i = corner_first_[t.vertex]; i < corner_first_[t.vertex + 1]; ++i)
        if (const int c = corners_at_[i]; !done[fan_of_[c]]) {
          done[fan_of_[c]] = 1;
          corners_.push_back({final_[c], t.sharpness, t.line});
        }
      continue;
    }
    find_before();
    if (used_before[t.vertex])
      note_vertex(dropped("corner", "a vertex", t.line), t.vertex);
    else
      corners_.push_back(t);  // no face had it: the build refuses it as before
  }
  for (const SoupCrease& t : soup_.creases) {
    if (!in_range(t.a) || !in_range(t.b)) {
      creases_.push_back(t);
      continue;
    }
    // Every edge between copies of the two vertices takes the tag.
    std::vector<std::pair<int, int>> edges;
    for (int i = corner_first_[t.a]; i < corner_first_[t.a + 1]; ++i) {
      const int c = corners_at_[i];
      for (int d : {loops_.next(c), loops_.prev(c)})
        if (loops_.vertex[d] == t.b) edges.emplace_back(final_[c], final_[d]);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [a, b] : edges) creases_.push_back({a, b, t.sharpness, t.line});
    if (!edges.empty()) continue;
    find_before();
    if (std::binary_search(edges_before.begin(), edges_before.end(),
                           std::pair(std::min(t.a, t.b), std::max(t.a, t.b)))) {
      RepairChange& change = dropped("crease", "an edge", t.line);
      note_vertex(change, t.a);
      note_vertex(change, t.b);
    } else {
      creases_.push_back(t);
    }
  }
}

PolygonSoup Pass::apply(std::vector<int>& vertex_from, std::vector<int>& face_from) const {
  PolygonSoup out;
  out.source = soup_.source;
  out.numbering = soup_.numbering;
  out.positions = soup_.positions;
  vertex_from.resize(nv_ + copy_of_.size());
  std::iota(vertex_from.begin(), vertex_from.begin() + nv_, 0);
  std::copy(copy_of_.begin(), copy_of_.end(), vertex_from.begin() + nv_);
  for (int v : copy_of_) out.positions.push_back(soup_.positions[v]);
  if (!soup_.vertex_lines.empty())
    for (int v : vertex_from)
      out.vertex_lines.push_back(
          v < static_cast<int>(soup_.vertex_lines.size()) ? soup_.vertex_lines[v] : 0);
  for (int v : vertex_from) out.vertex_origin.push_back(places::file_vertex(soup_, v));
  // Texture coordinates follow the corners when they match the faces; otherwise the build
  // drops them with its own warning.
  bool uvs = soup_.face_uvs.size() == soup_.faces.size();
  for (size_t f = 0; uvs && f < soup_.faces.size(); ++f)
    uvs = soup_.face_uvs[f].size() == soup_.faces[f].size();
  out.uvs = soup_.uvs;
  if (!uvs) out.face_uvs = soup_.face_uvs;
  face_from.clear();
  for (int k = 0; k < loops_.size(); ++k) {
    const int f = loops_.face[k], b = loops_.first[k], d = loops_.first[k + 1] - b;
    std::vector<int> loop, uv;
    for (int i = 0; i < d; ++i) {
      // Reversed, a loop keeps its first corner: a b c d becomes a d c b.
      const int c = b + (flip_[k] ? (d - i) % d : i);
      loop.push_back(final_[c]);
      if (uvs) uv.push_back(soup_.face_uvs[f][loops_.slot[c]]);
    }
    out.faces.push_back(std::move(loop));
    if (uvs) out.face_uvs.push_back(std::move(uv));
    if (f < static_cast<int>(soup_.face_lines.size()))
      out.face_lines.push_back(soup_.face_lines[f]);
    out.face_origin.push_back(places::file_face(soup_, f));
    face_from.push_back(f);
  }
  out.creases = creases_;
  out.corners = corners_;
  return out;
}

/// One sentence per kind of change, the first few defects named: what was done to how many
/// (`done`: a summary line), or only how many are wrong (a refusal).
std::vector<std::string> sentences(const std::vector<RepairChange>& changes, bool done) {
  std::vector<std::string> lines;
  for (const Choice<RepairKind>& row : kKinds) {
    std::vector<std::string> defects;
    for (const RepairChange& c : changes)
      if (c.kind == row.value) defects.push_back(c.defect);
    if (defects.empty()) continue;
    const KindWords w = words(row.value);
    const std::string counted =
        fmt::format("{} {}", defects.size(), defects.size() == 1 ? w.one : w.many);
    lines.push_back(
        done ? fmt::format("{} {}{}: {}", w.action, counted, w.note, places::listed(defects))
             : fmt::format("{}: {}", counted, places::listed(defects)));
  }
  return lines;
}

}  // namespace

ChoiceTable<RepairKind> repair_kind_table() {
  return kKinds;
}

int RepairReport::count(RepairKind kind) const {
  return static_cast<int>(std::count_if(changes.begin(), changes.end(),
                                        [kind](const RepairChange& c) { return c.kind == kind; }));
}

std::vector<std::pair<std::string_view, int>> RepairReport::counts() const {
  std::vector<std::pair<std::string_view, int>> out;
  for (const Choice<RepairKind>& row : repair_kind_table())
    if (const int n = count(row.value); n > 0) out.emplace_back(row.name, n);
  return out;
}

std::vector<std::string> RepairReport::summary() const {
  return sentences(changes, true);
}

std::string to_json(const RepairReport& report) {
  using json = nlohmann::ordered_json;  // the fields in the order written
  const int base = report.numbering == Numbering::from_one ? 1 : 0;
  json j;
  j["file"] = report.source;
  j["numbered_from"] = report.numbering == Numbering::none ? json(nullptr) : json(base);
  j["counts"] = json::object();
  for (const auto& [name, n] : report.counts()) j["counts"][std::string(name)] = n;
  j["changes"] = json::array();
  for (const RepairChange& c : report.changes) {
    json change;
    change["kind"] = choice_name(repair_kind_table(), c.kind);
    std::vector<int> faces = c.faces, vertices = c.vertices;
    for (int& f : faces) f += base;
    for (int& v : vertices) v += base;
    change["faces"] = faces;
    change["lines"] = c.lines;
    if (report.numbering != Numbering::none) change["vertices"] = vertices;
    json positions = json::array();
    for (const Vec3& p : c.positions) positions.push_back({p.x(), p.y(), p.z()});
    change["positions"] = positions;
    change["defect"] = c.defect;
    change["action"] = c.action;
    j["changes"].push_back(change);
  }
  return j.dump(2);
}

namespace detail {

std::optional<Repaired> repaired(const PolygonSoup& soup, const RepairOptions& options,
                                 RepairReport& report, bool by_angle) {
  report.source = soup.source;
  report.numbering = soup.numbering;
  places::check_face_indices(soup);
  std::optional<Repaired> out;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    Pass plan(out ? out->soup : soup, options, by_angle);
    plan.run();
    if (!plan.unorientable.empty())
      throw InputError(fmt::format(
          "{}{} cannot be oriented consistently, so no flip repairs {}: {}",
          soup.source.empty() ? "" : soup.source + ": ",
          plan.unorientable.size() == 1
              ? "a piece of the mesh"
              : fmt::format("{} pieces of the mesh", plan.unorientable.size()),
          plan.unorientable.size() == 1 ? "it" : "them", places::listed(plan.unorientable)));
    if (!plan.changed()) break;
    std::vector<int> vertex_from, face_from;
    PolygonSoup next = plan.apply(vertex_from, face_from);
    const PolygonSoup& before = out ? out->soup : soup;
    // A pass that changes nothing would only say the same again; the build decides then.
    if (next.faces == before.faces && next.positions.size() == before.positions.size() &&
        next.creases.size() == before.creases.size() &&
        next.corners.size() == before.corners.size())
      break;
    report.changes.insert(report.changes.end(), plan.changes.begin(), plan.changes.end());
    if (out) {
      // Back through the earlier passes to the soup given.
      for (int& v : vertex_from) v = out->vertex_from[v];
      for (int& f : face_from) f = out->face_from[f];
    }
    out = Repaired{std::move(next), std::move(vertex_from), std::move(face_from)};
  }
  return out;
}

std::string describe_defects(const PolygonSoup& soup, const RepairOptions& options) {
  places::check_face_indices(soup);
  Pass plan(soup, options);
  plan.run();
  std::vector<std::string> parts = sentences(plan.changes, false);
  if (!plan.unorientable.empty())
    parts.push_back(fmt::format("{} non-orientable piece{}: {}", plan.unorientable.size(),
                                plan.unorientable.size() == 1 ? "" : "s",
                                places::listed(plan.unorientable)));
  if (parts.empty()) return "";
  std::string text;
  for (const std::string& p : parts) text += (text.empty() ? "" : "; ") + p;
  return text;
}

}  // namespace detail

RepairReport repair(PolygonSoup& soup, const RepairOptions& options) {
  RepairReport report;
  if (auto out = detail::repaired(soup, options, report)) soup = std::move(out->soup);
  return report;
}

}  // namespace stitch
