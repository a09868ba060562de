// Where every grid sample of every patch goes in a tessellation, from the mesh's topology and the
// resolution alone: welding by construction. A sample on a patch's side belongs to the mesh
// element it lies on (vertex, face centre, edge midpoint, the half of an edge at a vertex, the
// spoke from an edge midpoint to a face centre), so every patch that shares it computes the same
// output vertex number without hashing, searching or a sequential pass, and any range of output
// vertices or quads can be produced on its own (in parallel, or streamed to a file). Internal.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/tess/patch_grid.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch {

class PatchSampler;

/// Sample (i, j) of the k-th corner's (n + 1)^2 grid, u = i / n, v = j / n.
struct GridSample {
  int corner = 0;  ///< index into the surface's corner list
  int i = 0, j = 0;
};

/// Where TessellationLayout::evaluate puts the attributes of each output vertex (null: skip).
struct SampleAttributes {
  Eigen::Vector2d* uv = nullptr;
  int* patch = nullptr;
  int* level = nullptr;
};

/// Output vertices, in order: mesh vertices, face centres, edge midpoints, then corner after
/// corner the n - 1 samples of its edge half, the n - 1 of its spoke and its (n - 1)^2 interior
/// samples (so a range of them stays on a few patches at a time), then the n - 1 samples of each
/// boundary half that no corner's block holds. Holes have no samples.
/// Unwelded: every corner's own grid, corner after corner, each laid out by PatchGrid.
class TessellationLayout {
 public:
  TessellationLayout(const HalfedgeMesh& mesh, const std::vector<Corner>& corners, int resolution,
                     bool welded);

  [[nodiscard]] int resolution() const { return n_; }
  [[nodiscard]] bool welded() const { return welded_; }
  [[nodiscard]] std::int64_t num_vertices() const { return num_vertices_; }
  [[nodiscard]] std::int64_t num_quads() const {
    return static_cast<std::int64_t>(corners_.size()) * n_ * n_;
  }

  /// The output vertex of sample (i, j) of corner k.
  [[nodiscard]] std::int64_t vertex(int k, int i, int j) const;
  /// Quad q = (corner k, cell (i, j)), counter-clockwise seen from the normal side.
  [[nodiscard]] std::array<std::int64_t, 4> quad(std::int64_t q) const;
  /// Quads [begin, end) as quad(q) gives them, four vertex numbers each into `out` (as int, as
  /// the files store them), walking the cells without a division each.
  void quads(std::int64_t begin, std::int64_t end, int* out) const;
  /// The samples that make output vertex `vertex`, the one whose position it takes first.
  /// At most max(valence, face degree, 4) samples.
  void samples(std::int64_t vertex, std::vector<GridSample>& out) const;

  /// Whether output vertex `vertex`, if shared, takes the normalized sum of its samples'
  /// normals rather than its first sample's normal. The sum is taken at mesh vertices, face
  /// centres and edge midpoints (few, and where patches of a merged face can meet at an angle),
  /// on sharp edges (C0 there), and everywhere under asc (AS&C's patches are not C1 along edges
  /// from an extraordinary vertex). Elsewhere (the spokes inside faces and the smooth edges'
  /// halves under mdc and cc) the patches meet with C1 and their normals agree up to round-off
  /// (test PatchesThatShareASmoothSampleAgreeOnItsNormal).
  [[nodiscard]] bool averages_normals(std::int64_t vertex, const Surface& surface) const;
  /// vertex(k, i, j) of every sample of corner k's grid, at i * (n + 1) + j.
  void grid_vertices(int k, std::int64_t* out) const;
  /// The position of the output vertex of every sample of corner k's grid, at i * (n + 1) + j:
  /// evaluate()'s, to the bit (the samples of its sides that neighbouring patches own are
  /// evaluated from those patches). `scratch` is working storage.
  void grid_positions(PatchSampler& sampler, int k, Vec3* positions,
                      std::vector<Vec3>& scratch) const;
  /// Quads [begin, end) as two triangles each, split along the shorter diagonal of their output
  /// vertices' positions (quad_triangles), as a writer of triangles splits quad(q) of a whole
  /// tessellation: six vertex numbers per quad into `indices` and, if not null, the positions of
  /// those corners into `corners`. Each corner's grid is evaluated with the samples its
  /// neighbours own (evaluate()'s positions, to the bit), so no position has to be held.
  void triangles(const Surface& surface, std::int64_t begin, std::int64_t end, int* indices,
                 Vec3* corners) const;
  /// Positions and unit normals of output vertices [begin, end): the position of the first
  /// sample; the normal of the first sample, or where averages_normals, the normalized sum of all
  /// sharing samples' normals in a fixed order (the result does not depend on threads). With
  /// `attributes`, also the first sample's (u, v), corner half-edge and level into the
  /// TessellatedMesh-like arrays (null to skip).
  void evaluate(const Surface& surface, std::int64_t begin, std::int64_t end, Vec3* positions,
                Vec3* normals, const SampleAttributes& attributes = {}) const;

 private:
  [[nodiscard]] int corner_index(Corner c) const { return corner_index_[c.idx]; }
  /// The vertices of corner k's block (welded) or grid (unwelded).
  [[nodiscard]] std::int64_t block_size() const {
    return welded_ ? static_cast<std::int64_t>(n_) * n_ - 1 : grid_.num_samples();
  }
  struct BlockScratch {
    std::vector<Vec3> positions, normals;  ///< a block cut by the range
    std::vector<int> levels;
    std::vector<Vec3> grid_positions, grid_normals;  ///< a corner's own samples
    std::vector<int> grid_levels;
    std::vector<Vec3> shared_positions, shared_normals;  ///< a neighbour's side
  };
  /// Positions, normals and levels (if not null) of corner k's block, in its order.
  void evaluate_block(PatchSampler& sampler, const Surface& surface, int k, Vec3* positions,
                      Vec3* normals, int* levels, BlockScratch& scratch) const;
  /// Sample (i, j) of corner k's grid that is vertex r of its block (welded: edge half, spoke,
  /// interior) or of its grid (unwelded).
  [[nodiscard]] GridSample block_sample(int k, int r) const;
  /// The uv and patch attributes of output vertices [from, to) of corner k's block, at
  /// vertex - begin.
  void fill_block_attributes(int k, std::int64_t from, std::int64_t to, std::int64_t begin,
                             const SampleAttributes& attributes) const;
  /// evaluate() vertex by vertex for [from, to), written at vertex - begin.
  void evaluate_each(PatchSampler& sampler, const Surface& surface, std::int64_t from,
                     std::int64_t to, std::int64_t begin, Vec3* positions, Vec3* normals,
                     const SampleAttributes& attributes) const;
  /// The point of the sample `g` as evaluate() computes it: `grid`, through the sampler's grid
  /// tables (corner blocks and boundary halves); otherwise directly (the patch corners).
  SurfacePoint sample_point(PatchSampler& sampler, const GridSample& g, bool grid) const;
  /// The quad of cell (i, j) of corner k.
  [[nodiscard]] std::array<std::int64_t, 4> cell_quad(int k, int i, int j) const;

  const HalfedgeMesh& mesh_;
  const std::vector<Corner>& corners_;
  int n_;
  PatchGrid grid_;
  bool welded_;
  std::vector<int> corner_index_;                         ///< by half-edge
  std::vector<int> vertex_slot_, face_slot_, edge_slot_;  ///< by element index (compacted)
  std::vector<Vertex> vertices_;
  std::vector<Face> faces_;
  std::vector<Edge> edges_;
  /// Where each group of output vertices starts; per corner, a block of n^2 - 1: its edge half
  /// (n - 1), its spoke (n - 1), its interior ((n - 1)^2).
  std::int64_t first_face_ = 0, first_edge_ = 0, first_block_ = 0, first_extra_ = 0,
               num_vertices_ = 0;
  /// Boundary halves: by half-edge, the number of the extra block of corner c's side i = 0
  /// (-1: owned by rotate_ccw(c)'s block); by that number, the corner's index.
  std::vector<int> extra_half_, extra_corner_;
  /// The (u, v) of each place in a block: the same for every corner's block.
  std::vector<Eigen::Vector2d> block_uv_;
  [[nodiscard]] std::int64_t block(int k) const {
    return first_block_ + static_cast<std::int64_t>(k) * block_size();
  }
};

}  // namespace stitch
