// K-gons: the shape handles of the surface (method.md, section 2).
//
// One K-gon per face (K = degree), per vertex (K = valence) and per edge (K = 4). Point k of a
// K-gon belongs to one corner of the input mesh, and every corner has exactly four K-gon points:
// one in its face's K-gon, one in its vertex's K-gon, and one in each of the edge K-gons of the
// two face edges that meet at the corner.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "stitch/choices.hpp"
#include "stitch/kgon/kgon_control.hpp"
#include "stitch/kgon/small_vector.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

enum class KgonKind { face, vertex, edge };

/// Where the K-gons of faces come from.
enum class KgonConstruction {
  /// Section 2 as it stands: corner points of one Doo-Sabin step, shrunk once more.
  doo_sabin,
  /// Section 2, except for faces whose loop runs along one edge twice (made by inserting an
  /// edge between two faces): their corner points come from each opening's own loop and their
  /// K-gon sits on the wall of the tube joining the openings (see src/kgon/openings.hpp).
  /// Faces where that placement does not apply keep section 2's K-gon.
  openings,
};

/// The constructions by name (openings first: the default).
ChoiceTable<KgonConstruction> kgon_construction_table();
/// The boundary rules by name (edge-and-corner first: the default).
ChoiceTable<BoundaryInterpolation> boundary_table();

struct KgonOptions {
  KgonConstruction construction = KgonConstruction::openings;
  /// Whether boundary vertices with one face are corners of the surface (the default, as in
  /// OpenSubdiv) or lie on a smooth boundary curve. Also used by --method cc.
  BoundaryInterpolation boundary = BoundaryInterpolation::edge_and_corner;
  /// Sharpness from which an edge or vertex tag counts as infinitely sharp; below it a tag is
  /// smooth. The construction has no subdivision levels to round a crease over (method.md):
  /// OpenSubdiv rounds a crease of sharpness s over about 2^-s of the faces beside it, so from
  /// 4 on the difference is a sliver, and below it the crease is soft. --method cc honours the
  /// exact values.
  double sharp_from = 4.0;
  /// Applies to every face and vertex K-gon with K != 4 (the extraordinary ones); quads and
  /// edge K-gons keep their shape unless a per-element control names them.
  KgonControl global;
  /// Per-element controls, keyed by element index; they replace `global` for that element.
  std::unordered_map<int, KgonControl> face, vertex, edge;
};

/// How a vertex meets the sharp edges (boundary edges and infinitely sharp creases) around it
/// (method.md, "Boundaries, creases and corners").
enum class VertexKind {
  smooth,  ///< no sharp edge: one K-gon over the whole fan
  dart,    ///< one sharp edge, which fades out here: one K-gon over the whole fan
  crease,  ///< two sharp edges: the sharp curve runs smoothly through, one K-gon per sector
  corner,  ///< three or more sharp edges, a corner tag, or (edge-and-corner) a boundary
           ///< vertex with one face: interpolated, one K-gon per sector
};
VertexKind vertex_kind(const HalfedgeMesh& mesh, Vertex v, const KgonOptions& options);
/// A boundary edge, or a crease whose sharpness reaches options.sharp_from: the surface has a
/// sharp curve there, C0 across it.
bool is_sharp(const HalfedgeMesh& mesh, Edge e, const KgonOptions& options);

struct Kgon {
  /// Up to this many points and corners are held in the K-gon itself (no heap block).
  static constexpr int kInPlace = 4;
  SmallVector<Vec3, kInPlace> points;  ///< in the order of `corners`
  SmallVector<Corner, kInPlace> corners;
  Vec3 centroid = Vec3::Zero();
  /// Unit normal of the least-squares plane, oriented like the surface. A 4-gon is not
  /// flattened and no plane is fitted: its normal is its Newell normal, normalized (the same
  /// plane when the 4-gon is planar). A triangle is its own plane: its normal is its Newell
  /// normal too, and it is not moved. For K = 2 there is no plane: the normal is the average of
  /// the adjacent faces' normals (see build_kgons).
  Vec3 normal = Vec3::UnitZ();
  [[nodiscard]] int size() const { return static_cast<int>(points.size()); }
};

/// All K-gons of a mesh, indexed by element index, plus per-corner look-ups.
struct KgonSet {
  std::vector<Kgon> face, vertex, edge;  ///< empty Kgon for deleted elements
  /// Doo-Sabin corner point w(f, i) of every corner, indexed by half-edge.
  std::vector<Vec3> corner_point;
  /// Index of the corner's point in its face, vertex, next-edge (edge(h)) and
  /// previous-edge (edge(prev(h))) K-gon, indexed by half-edge.
  std::vector<int> in_face, in_vertex, in_next_edge, in_prev_edge;
  /// K of the vertex K-gon the corner's patch sees at its vertex, indexed by half-edge: the
  /// valence, or at a crease or corner vertex the size of the corner's sector closed by its
  /// ghost points (4 where the surface is regular there).
  std::vector<int> vertex_k;
  /// Along a sharp edge, the first two Bézier points of the sharp curve from origin(h) (the
  /// patch corner at the vertex and at the edge midpoint are the K-gon centroids), indexed by
  /// half-edge h; unset for other edges.
  std::vector<std::array<Vec3, 2>> sharp_curve;
  /// By half-edge: 1 where the corner's sector at a crease or corner vertex wraps around too far
  /// to be flattened, so the surface has a cone point there (method.md); 0 elsewhere.
  std::vector<std::uint8_t> cone;
  /// Whether each edge is sharp under the options the set was built with (is_sharp), by edge.
  std::vector<std::uint8_t> sharp_edge;
  [[nodiscard]] bool sharp(Edge e) const { return !sharp_edge.empty() && sharp_edge[e.idx] != 0; }

  [[nodiscard]] const Vec3& face_point(const HalfedgeMesh& m, Corner c) const {
    return face[m.face(c).idx].points[in_face[c.idx]];
  }
  [[nodiscard]] const Vec3& vertex_point(const HalfedgeMesh& m, Corner c) const {
    return vertex[m.origin(c).idx].points[in_vertex[c.idx]];
  }
  [[nodiscard]] const Vec3& next_edge_point(Corner c) const {
    return edge[HalfedgeMesh::edge(c).idx].points[in_next_edge[c.idx]];
  }
  [[nodiscard]] const Vec3& prev_edge_point(const HalfedgeMesh& m, Corner c) const {
    return edge[HalfedgeMesh::edge(m.prev(c)).idx].points[in_prev_edge[c.idx]];
  }
};

/// Doo-Sabin weights for an n-sided loop: a0 = 1/4 + 5/(4n), ak = (3 + 2cos(2 pi k/n))/(4n).
std::vector<double> doo_sabin_weights(int n);
/// The DS point of every corner of the loop (point i = sum_j a_((j-i) mod n) p_j).
std::vector<Vec3> doo_sabin_shrink(const std::vector<Vec3>& loop);

/// Builds every K-gon of a valid mesh. Default options reproduce method.md section 2 exactly.
KgonSet build_kgons(const HalfedgeMesh& mesh, const KgonOptions& options = {});
/// The same into `into`, whatever it held, keeping its storage where it is large enough (a
/// surface rebuilt for a moved mesh allocates nothing new for its K-gons).
void build_kgons(const HalfedgeMesh& mesh, const KgonOptions& options, KgonSet& into);

/// Elements of a mesh whose K-gons are meant: each list sorted, without repeats.
struct KgonElements {
  std::vector<Face> faces;
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  /// Adds `other`'s elements (keeping the lists sorted and free of repeats).
  void merge(const KgonElements& other);
};

/// The dependency rule of the K-gons (what an incremental update must rebuild): the elements
/// whose K-gons can read the corner points or normals of `faces` (faces whose vertices moved or
/// whose loops changed). Those are the faces themselves, their vertices and edges, and the faces
/// across their edges, whose K-gons read the faces' normals when they have no plane of their
/// own. Faces that are deleted are skipped.
KgonElements kgons_reading(const HalfedgeMesh& mesh, std::vector<Face> faces);

/// Local update of a set that build_kgons made for this mesh's connectivity (IncrementalSurface's
/// update): recomputes the corner points of `faces`, then the K-gons of `faces`,
/// `vertices` and `edges`, exactly as build_kgons would. The caller lists every element whose
/// K-gon can change (e.g. after a vertex moved: its faces and their vertices and edges).
void update_kgons(const HalfedgeMesh& mesh, const KgonOptions& options, KgonSet& set,
                  const std::vector<Face>& faces, const std::vector<Vertex>& vertices,
                  const std::vector<Edge>& edges);

}  // namespace stitch
