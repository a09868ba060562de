// The half-edge mesh every stage works on.
//
// Index-based handles and plain arrays (after pmp-library): connectivity lives in this class,
// every other attribute (K-gon settings, colours, ...) lives in arrays beside it, indexed by the
// handle's idx. The mesh is always closed: every half-edge has a face, so there are no boundary
// half-edges. It can hold everything the topology operators create: 2-sided faces, several edges
// between the same two vertices, and faces whose loop runs along the same edge twice.
//
// Half-edges come in pairs: the two half-edges of edge e are 2e and 2e+1, so twin(h) = h ^ 1.
// A *corner* (a face and one position in its loop) is the half-edge of that face leaving the
// corner's vertex; everything downstream is defined per corner, never per vertex id.
//
// Feature tags live in arrays beside the connectivity, as OpenSubdiv's Sdc tags do: a face can be
// a *hole* (a boundary loop of the surface: it makes no patches, and its edges are the surface's
// boundary), an edge or a vertex can carry a sharpness (creases and corners; sharpness >=
// infinitely_sharp is infinite, as in OpenSubdiv). A mesh read with boundaries holds one hole face
// per boundary loop, so navigation never meets a missing face.
//
// Elements are removed by marking them deleted, so the numbers of untouched elements stay stable
// while a sequence of operators runs; garbage_collection() compacts the arrays, keeping order.
//
// A MeshJournal (mesh_journal.hpp) may observe the mesh: every editing call then reports the
// element it is about to change, so a sequence of edits yields a delta that undoes or redoes them
// and says where they touched. The mesh itself holds only a pointer to that observer.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // Vec3::cross
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stitch/error.hpp"
#include "stitch/mesh/element_range.hpp"

namespace stitch {

using Vec3 = Eigen::Vector3d;

/// OpenSubdiv's infinite sharpness: tags at or above it make a crease or corner (method.md).
inline constexpr double infinitely_sharp = 10.0;
/// A tag sharp for a few levels of refinement and then smooth: 0 < s < infinitely_sharp.
constexpr bool is_semi_sharp(double s) {
  return s > 0 && s < infinitely_sharp;
}

// The K-gon methods honour semi-sharp tags by refining the mesh (eval/semi_sharp.hpp) for
// ceil(largest tag) levels, within these two bounds (docs/method.md measures them).

/// At least two levels: after one the tags' part of the K-gon surface is still far from
/// Catmull-Clark's (50% of the crease response off on OpenSubdiv's catmark_cube_corner0, a
/// corner of 0.7 at a valence-3 vertex), after two at most 14.1% on OpenSubdiv's shapes.
inline constexpr int min_semi_sharp_levels = 2;
/// At most four: a sharper tag is smooth after them, rounded over less than 2^-4 of the faces
/// beside it where OpenSubdiv rounds it over 2^-s, a sharp-looking rim either way (OpenSubdiv's
/// chess pieces have creases of 6 and 7.9). Where such tags decide the response it is within
/// 5.6% of Catmull-Clark's (catmark_helmet, 7), and each level more costs four times the
/// patches.
inline constexpr int max_semi_sharp_levels = 4;

/// How semi-sharp creases lose sharpness level by level (OpenSubdiv's Sdc::Options::
/// CreasingMethod, an OBJ file's `t creasemethod`): by one per level (uniform), or by Chaikin's
/// rule, which blends the sharpness of each half of a crease with that of the crease's other
/// edges at the vertex, so that a crease's sharpness varies smoothly along it.
enum class CreaseMethod { uniform, chaikin };

/// How the surface treats boundary vertices with a single face (OpenSubdiv's
/// Sdc::Options::VtxBoundaryInterpolation): interpolated as corners, or smoothed along the
/// boundary curve like every other boundary vertex.
enum class BoundaryInterpolation { edge_and_corner, edge_only };

template <class Tag>
struct Handle {
  int idx = -1;
  constexpr Handle() = default;
  constexpr explicit Handle(int i) : idx(i) {}
  [[nodiscard]] constexpr bool valid() const { return idx >= 0; }
  constexpr auto operator<=>(const Handle&) const = default;
};

struct VertexTag {};
struct HalfedgeTag {};
struct EdgeTag {};
struct FaceTag {};
using Vertex = Handle<VertexTag>;
using Halfedge = Handle<HalfedgeTag>;
using Edge = Handle<EdgeTag>;
using Face = Handle<FaceTag>;
/// A corner is identified with the half-edge of its face that leaves its vertex.
using Corner = Halfedge;

class MeshJournal;
struct MeshDelta;

class HalfedgeMesh {
 public:
  // --- navigation -------------------------------------------------------------------------
  [[nodiscard]] Halfedge next(Halfedge h) const { return Halfedge(he_next_[h.idx]); }
  [[nodiscard]] Halfedge prev(Halfedge h) const { return Halfedge(he_prev_[h.idx]); }
  [[nodiscard]] static Halfedge twin(Halfedge h) { return Halfedge(h.idx ^ 1); }
  [[nodiscard]] static Edge edge(Halfedge h) { return Edge(h.idx >> 1); }
  [[nodiscard]] static Halfedge halfedge(Edge e, int side) { return Halfedge(2 * e.idx + side); }
  [[nodiscard]] Vertex origin(Halfedge h) const { return Vertex(he_origin_[h.idx]); }
  [[nodiscard]] Vertex target(Halfedge h) const { return origin(twin(h)); }
  [[nodiscard]] Face face(Halfedge h) const { return Face(he_face_[h.idx]); }
  /// One half-edge of the face's loop.
  [[nodiscard]] Halfedge halfedge(Face f) const { return Halfedge(face_he_[f.idx]); }
  /// One outgoing half-edge of the vertex (invalid for an isolated vertex).
  [[nodiscard]] Halfedge halfedge(Vertex v) const { return Halfedge(vertex_he_[v.idx]); }
  /// The next outgoing half-edge counter-clockwise around origin(h) (seen from the side the
  /// faces point to).
  [[nodiscard]] Halfedge rotate_ccw(Halfedge h) const { return twin(prev(h)); }
  /// The inverse of rotate_ccw.
  [[nodiscard]] Halfedge rotate_cw(Halfedge h) const { return next(twin(h)); }

  [[nodiscard]] const Vec3& position(Vertex v) const { return positions_[v.idx]; }
  /// Writable position; counts as a change of v for an observing journal.
  Vec3& position(Vertex v) {
    note(v);
    return positions_[v.idx];
  }
  [[nodiscard]] const std::vector<Vec3>& positions() const { return positions_; }

  // --- feature tags ----------------------------------------------------------------------
  [[nodiscard]] bool is_hole(Face f) const { return face_hole_[f.idx] != 0; }
  void set_hole(Face f, bool hole) {
    note(f);
    face_hole_[f.idx] = hole ? 1 : 0;
  }
  /// Whether the corner h (a half-edge) lies in a hole, i.e. makes no patch.
  [[nodiscard]] bool is_hole(Halfedge h) const { return is_hole(face(h)); }
  /// An edge of a hole: on the surface's boundary.
  [[nodiscard]] bool is_boundary(Edge e) const {
    return is_hole(halfedge(e, 0)) || is_hole(halfedge(e, 1));
  }
  [[nodiscard]] double sharpness(Edge e) const { return edge_sharpness_[e.idx]; }
  void set_sharpness(Edge e, double s) {
    note(e);
    edge_sharpness_[e.idx] = s;
  }
  [[nodiscard]] double sharpness(Vertex v) const { return vertex_sharpness_[v.idx]; }
  void set_sharpness(Vertex v, double s) {
    note(v);
    vertex_sharpness_[v.idx] = s;
  }
  /// A boundary edge or an infinitely sharp crease: the surface has a curve there that only the
  /// vertices along it shape, and is C0 across it.
  [[nodiscard]] bool is_sharp(Edge e) const {
    return is_boundary(e) || edge_sharpness_[e.idx] >= infinitely_sharp;
  }
  [[nodiscard]] CreaseMethod crease_method() const { return crease_method_; }
  /// The whole mesh's, as OpenSubdiv's option is: not an element edit, so no journal sees it.
  void set_crease_method(CreaseMethod m) { crease_method_ = m; }
  /// Whether any face is a hole or any edge or vertex carries a sharpness tag.
  [[nodiscard]] bool has_features() const;
  /// The corners that make patches (not in holes), in index order.
  [[nodiscard]] std::vector<Corner> patch_corners() const;
  /// The faces that are not holes, in index order.
  [[nodiscard]] std::vector<Face> surface_faces() const;

  // --- sizes and iteration ----------------------------------------------------------------
  // *_capacity() counts deleted elements too (handles index arrays of that size);
  // num_*() counts live elements.
  [[nodiscard]] int vertex_capacity() const { return static_cast<int>(positions_.size()); }
  [[nodiscard]] int halfedge_capacity() const { return static_cast<int>(he_next_.size()); }
  [[nodiscard]] int edge_capacity() const { return halfedge_capacity() / 2; }
  [[nodiscard]] int face_capacity() const { return static_cast<int>(face_he_.size()); }
  [[nodiscard]] int num_vertices() const { return vertex_capacity() - deleted_vertices_; }
  [[nodiscard]] int num_edges() const { return edge_capacity() - deleted_edges_; }
  [[nodiscard]] int num_halfedges() const { return 2 * num_edges(); }
  [[nodiscard]] int num_faces() const { return face_capacity() - deleted_faces_; }
  [[nodiscard]] bool has_garbage() const {
    return deleted_vertices_ + deleted_edges_ + deleted_faces_ > 0;
  }

  [[nodiscard]] bool is_deleted(Vertex v) const { return vertex_deleted_[v.idx] != 0; }
  [[nodiscard]] bool is_deleted(Edge e) const { return edge_deleted_[e.idx] != 0; }
  [[nodiscard]] bool is_deleted(Halfedge h) const { return is_deleted(edge(h)); }
  [[nodiscard]] bool is_deleted(Face f) const { return face_deleted_[f.idx] != 0; }

  /// Live elements in index order, as ranges that build no list (see element_range.hpp for
  /// what they see when the mesh changes during the loop; to_vector() takes a copy).
  [[nodiscard]] ElementRange<Vertex> vertices() const {
    return {vertex_deleted_, vertex_capacity(), num_vertices()};
  }
  [[nodiscard]] ElementRange<Edge> edges() const {
    return {edge_deleted_, edge_capacity(), num_edges()};
  }
  [[nodiscard]] ElementRange<Halfedge> halfedges() const {
    return {edge_deleted_, halfedge_capacity(), num_halfedges(), 1};
  }
  [[nodiscard]] ElementRange<Face> faces() const {
    return {face_deleted_, face_capacity(), num_faces()};
  }

  /// The half-edges of the face's loop, starting at halfedge(f), in loop order.
  [[nodiscard]] std::vector<Halfedge> face_loop(Face f) const;
  /// The half-edges of the loop starting at h, in loop order.
  [[nodiscard]] std::vector<Halfedge> loop_from(Halfedge h) const;
  /// The outgoing half-edges (= corners) around v, counter-clockwise, starting at halfedge(v).
  [[nodiscard]] std::vector<Halfedge> vertex_fan(Vertex v) const;
  [[nodiscard]] int degree(Face f) const;
  [[nodiscard]] int valence(Vertex v) const;
  /// The position of h in its face's loop counted from halfedge(face(h)).
  [[nodiscard]] int index_in_face(Halfedge h) const;

  // --- low-level editing, for the builders and the topology operators ---------------------
  // These do not keep the mesh valid on their own; callers finish with a valid mesh
  // (validate() checks).
  Vertex add_vertex(const Vec3& p);
  Face add_face();
  /// Adds edge (a, b): returns the half-edge a->b; its twin is b->a. next/prev/face unset.
  Halfedge add_edge(Vertex a, Vertex b);
  /// Links h -> n (sets next(h) = n and prev(n) = h).
  void link(Halfedge h, Halfedge n) {
    note(edge(h));
    note(edge(n));
    he_next_[h.idx] = n.idx;
    he_prev_[n.idx] = h.idx;
  }
  void set_face(Halfedge h, Face f) {
    note(edge(h));
    he_face_[h.idx] = f.idx;
  }
  void set_origin(Halfedge h, Vertex v) {
    note(edge(h));
    he_origin_[h.idx] = v.idx;
  }
  void set_halfedge(Face f, Halfedge h) {
    note(f);
    face_he_[f.idx] = h.idx;
  }
  void set_halfedge(Vertex v, Halfedge h) {
    note(v);
    vertex_he_[v.idx] = h.idx;
  }
  /// Sets face(h) = f for every half-edge of the loop through h and makes h the face's start.
  void assign_loop(Halfedge h, Face f);
  void delete_vertex(Vertex v);
  void delete_edge(Edge e);
  void delete_face(Face f);

  /// Maps from old to new indices produced by garbage_collection() (-1 for removed).
  struct Remap {
    std::vector<int> vertex, edge, face;
  };
  /// Removes deleted elements, keeping the relative order of the rest. Not allowed while a
  /// journal observes the mesh (it renumbers everything).
  Remap garbage_collection();

  /// Whether a MeshJournal observes the mesh (mesh_journal.hpp).
  [[nodiscard]] bool observed() const { return observer_.journal != nullptr; }

  /// Exact equality of connectivity and positions (element numbering included); an observing
  /// journal is bookkeeping, not part of the mesh's value.
  [[nodiscard]] bool operator==(const HalfedgeMesh& o) const = default;

 private:
  friend class MeshJournal;
  friend void apply_delta(HalfedgeMesh& mesh, const MeshDelta& delta, bool forward);
  /// The journal observing the mesh, if any. A copy or a move starts unobserved; a mesh that is
  /// destroyed, assigned to or moved from loses its journal, whose record no longer describes
  /// it (mesh_journal.hpp). Never part of equality.
  struct ObserverSlot {
    MeshJournal* journal = nullptr;
    ObserverSlot() = default;
    ObserverSlot(const ObserverSlot& /*other*/) noexcept {}
    ObserverSlot(ObserverSlot&& other) noexcept { other.lose(); }
    ObserverSlot& operator=(const ObserverSlot& other) noexcept {
      if (this != &other) lose();
      return *this;
    }
    ObserverSlot& operator=(ObserverSlot&& other) noexcept {
      if (this != &other) {
        lose();
        other.lose();
      }
      return *this;
    }
    ~ObserverSlot() { lose(); }
    void lose() noexcept;
    bool operator==(const ObserverSlot& /*other*/) const { return true; }
  };
  // One null test per editing call; the reports are out of line, in mesh_journal.cpp.
  void note(Vertex v) {
    if (observer_.journal) report(v);
  }
  void note(Edge e) {
    if (observer_.journal) report(e);
  }
  void note(Face f) {
    if (observer_.journal) report(f);
  }
  void report(Vertex v);
  void report(Edge e);
  void report(Face f);

  std::vector<Vec3> positions_;
  std::vector<int> vertex_he_;
  std::vector<std::uint8_t> vertex_deleted_;
  std::vector<double> vertex_sharpness_;
  std::vector<int> he_next_, he_prev_, he_origin_, he_face_;
  std::vector<std::uint8_t> edge_deleted_;
  std::vector<double> edge_sharpness_;
  std::vector<int> face_he_;
  std::vector<std::uint8_t> face_deleted_, face_hole_;
  int deleted_vertices_ = 0, deleted_edges_ = 0, deleted_faces_ = 0;
  CreaseMethod crease_method_ = CreaseMethod::uniform;
  ObserverSlot observer_;
};

}  // namespace stitch

template <class Tag>
struct std::hash<stitch::Handle<Tag>> {
  size_t operator()(const stitch::Handle<Tag>& h) const noexcept { return std::hash<int>()(h.idx); }
};
