// The K-gons' topology apart from their point data, as OpenSubdiv's Bfr separates a surface's
// topology-dependent preparation from the points it is evaluated with.
//
// What a K-gon is made of (its corners and their order, which construction builds it, how its
// vertex meets the sharp edges, the Doo-Sabin weights of its size) follows from the mesh's
// connectivity, holes and tags and from the options' construction, boundary rule and sharp_from.
// Only its points, centroid and normal follow from the vertex positions. prepare_kgons works out
// the first once; place_kgons fills in the second, so a mesh whose vertices move while its
// connectivity stays (a deformation) re-runs only place_kgons. build_kgons is the two in one.
//
// Left in the position pass because they read positions: which faces with two openings get
// their tube placement (a placement needs a usable tube, decided by where the rims are), and the
// whole K-gon of a crease or corner vertex (its sectors' cone test) and of a sharp edge.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "stitch/kgon/kgon.hpp"

namespace stitch {

/// The corners of a face whose loop runs along one edge twice (an edge inserted between two
/// faces), split by opening: each list runs in loop order from the corner after a bridge to the
/// bridge corner that leaves the opening (src/kgon/openings.hpp).
struct TwoOpenings {
  std::vector<Corner> first, second;
};

/// The two openings of f when the options' construction is `openings` and f's loop runs around
/// two openings (src/kgon/openings.hpp); nothing otherwise.
std::optional<TwoOpenings> two_openings(const HalfedgeMesh& mesh, Face f,
                                        const KgonOptions& options);

/// Everything of a mesh's K-gons that does not depend on the vertex positions.
struct KgonTopology {
  /// The options' fields it was prepared for (the controls are applied with the points).
  KgonConstruction construction = KgonConstruction::openings;
  BoundaryInterpolation boundary = BoundaryInterpolation::edge_and_corner;
  double sharp_from = 0;
  /// The set as build_kgons leaves it, but for the point data: every array sized, every K-gon's
  /// corners and per-corner index, vertex_k outside crease and corner vertices, sharp_edge.
  KgonSet skeleton;
  /// The live elements, in index order.
  std::vector<Face> faces;
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  /// By vertex: its kind, and how many sharp edges leave it.
  std::vector<VertexKind> vertex_kind;
  std::vector<int> sharp_spokes;
  /// By edge: is_sharp under the options (skeleton.sharp_edge is kept only for meshes with
  /// features).
  std::vector<std::uint8_t> sharp;
  /// By face: its two openings where the openings construction applies.
  std::vector<std::optional<TwoOpenings>> openings;
  /// doo_sabin_weights(k) for every k up to the largest K-gon: index k.
  std::vector<std::vector<double>> doo_sabin;

  /// Whether it describes this mesh's element capacities and these options (the connectivity
  /// and tags themselves are the caller's to keep).
  [[nodiscard]] bool fits(const HalfedgeMesh& mesh, const KgonOptions& options) const;
};

/// The topology-only preparation of build_kgons(mesh, options).
KgonTopology prepare_kgons(const HalfedgeMesh& mesh, const KgonOptions& options);

/// The position pass: fills the points, centroids, normals, corner points, sharp curves and
/// cone flags of `set` for the mesh's current positions and options' controls. `set` is a copy
/// of topology.skeleton or a set this function filled from the same topology; the mesh has the
/// connectivity and tags `topology` was prepared from. The result equals build_kgons(mesh,
/// options) bit for bit.
void place_kgons(const HalfedgeMesh& mesh, const KgonOptions& options, const KgonTopology& topology,
                 KgonSet& set);

}  // namespace stitch
