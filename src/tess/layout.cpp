#include "tess/layout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "eval/patch_sampler.hpp"
#include "stitch/mesh/polygon.hpp"

namespace stitch {

TessellationLayout::TessellationLayout(const HalfedgeMesh& mesh, const std::vector<Corner>& corners,
                                       int resolution, bool welded)
    : mesh_(mesh), corners_(corners), n_(resolution), grid_(resolution), welded_(welded) {
  const auto num_corners = static_cast<std::int64_t>(corners.size());
  const std::int64_t per_side = n_ - 1;
  if (!welded_) {
    num_vertices_ = num_corners * grid_.num_samples();
  } else {
    corner_index_.assign(mesh.halfedge_capacity(), -1);
    for (size_t k = 0; k < corners.size(); ++k) corner_index_[corners[k].idx] = static_cast<int>(k);
    vertex_slot_.assign(mesh.vertex_capacity(), -1);
    face_slot_.assign(mesh.face_capacity(), -1);
    edge_slot_.assign(mesh.edge_capacity(), -1);
    for (int v = 0; v < mesh.vertex_capacity(); ++v)
      if (!mesh.is_deleted(Vertex(v))) {
        vertex_slot_[v] = static_cast<int>(vertices_.size());
        vertices_.push_back(Vertex(v));
      }
    for (int f = 0; f < mesh.face_capacity(); ++f)
      if (!mesh.is_deleted(Face(f)) && !mesh.is_hole(Face(f))) {
        face_slot_[f] = static_cast<int>(faces_.size());
        faces_.push_back(Face(f));
      }
    for (int e = 0; e < mesh.edge_capacity(); ++e)
      if (!mesh.is_deleted(Edge(e))) {
        edge_slot_[e] = static_cast<int>(edges_.size());
        edges_.push_back(Edge(e));
      }
    // On a boundary, the half of edge(prev(c)) at c's vertex has no patch across to own it;
    // those halves get blocks of their own after the corners' blocks.
    extra_half_.assign(mesh.halfedge_capacity(), -1);
    int extra = 0;
    for (Corner c : corners)
      if (mesh.is_hole(mesh.rotate_ccw(c))) {
        extra_half_[c.idx] = extra++;
        extra_corner_.push_back(corner_index(c));
      }
    first_face_ = static_cast<std::int64_t>(vertices_.size());
    first_edge_ = first_face_ + static_cast<std::int64_t>(faces_.size());
    first_block_ = first_edge_ + static_cast<std::int64_t>(edges_.size());
    first_extra_ = first_block_ + num_corners * (per_side * per_side + 2 * per_side);
    num_vertices_ = first_extra_ + static_cast<std::int64_t>(extra) * per_side;
  }
  block_uv_.resize(static_cast<size_t>(block_size()));
  for (size_t r = 0; r < block_uv_.size(); ++r) {
    const GridSample g = block_sample(0, static_cast<int>(r));
    block_uv_[r] = grid_.uv(grid_.sample(g.i, g.j));
  }
  // Output files and TessellatedMesh number vertices with 32-bit ints.
  if (num_vertices_ > std::numeric_limits<int>::max())
    throw UsageError(
        fmt::format("{} corners at resolution {} make {} surface vertices, more than 2^31 - 1: use "
                    "a lower resolution",
                    num_corners, n_, num_vertices_));
}

std::int64_t TessellationLayout::vertex(int k, int i, int j) const {
  const int n = n_;
  if (!welded_) return static_cast<std::int64_t>(k) * grid_.num_samples() + grid_.sample(i, j);
  const Corner c = corners_[k];
  if (i == 0 && j == 0) return vertex_slot_[mesh_.origin(c).idx];
  if (i == n && j == n) return first_face_ + face_slot_[mesh_.face(c).idx];
  if (i == n && j == 0) return first_edge_ + edge_slot_[HalfedgeMesh::edge(c).idx];
  if (i == 0 && j == n) return first_edge_ + edge_slot_[HalfedgeMesh::edge(mesh_.prev(c)).idx];
  const std::int64_t side = n - 1;
  // Side j = 0 is the half of edge(c) at the corner's vertex; side i = 0 the same half of
  // rotate_ccw(c)'s edge. Side i = n runs from the middle of edge(c) to the face centre; side
  // j = n is prev(c)'s.
  if (j == 0) return block(k) + (i - 1);
  if (i == 0) {
    if (const int x = extra_half_[c.idx]; x >= 0) return first_extra_ + x * side + (j - 1);
    return block(corner_index(mesh_.rotate_ccw(c))) + (j - 1);
  }
  if (i == n) return block(k) + side + (j - 1);
  if (j == n) return block(corner_index(mesh_.prev(c))) + side + (i - 1);
  return block(k) + 2 * side + (i - 1) * side + (j - 1);
}

std::array<std::int64_t, 4> TessellationLayout::quad(std::int64_t q) const {
  const std::int64_t cells = static_cast<std::int64_t>(n_) * n_;
  const auto cell = static_cast<int>(q % cells);
  return cell_quad(static_cast<int>(q / cells), cell / n_, cell % n_);
}

void TessellationLayout::quads(std::int64_t begin, std::int64_t end, int* out) const {
  // Corner by corner: the numbers of its (n + 1)^2 grid samples once, its cells from them.
  const int n = n_;
  const std::int64_t cells = static_cast<std::int64_t>(n) * n;
  std::vector<std::int64_t> grid(static_cast<size_t>(n + 1) * (n + 1));
  // Cell j of the grid row that starts at `row`, counter-clockwise.
  const auto put_cell = [&out, n](const std::int64_t* row, int j) {
    out[0] = static_cast<int>(row[j]);
    out[1] = static_cast<int>(row[j + n + 1]);
    out[2] = static_cast<int>(row[j + n + 2]);
    out[3] = static_cast<int>(row[j + 1]);
    out += 4;
  };
  for (std::int64_t q = begin; q < end;) {
    const auto k = static_cast<int>(q / cells);
    grid_vertices(k, grid.data());
    const std::int64_t last = std::min(end, (k + 1) * cells);
    if (q == k * cells && last == q + cells) {  // the whole corner, as nearly always
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          put_cell(grid.data() + static_cast<std::ptrdiff_t>(i) * (n + 1), j);
      q = last;
      continue;
    }
    const auto cell = static_cast<int>(q - k * cells);
    for (int i = cell / n, j = cell % n; q < last; ++i, j = 0)
      for (; j < n && q < last; ++j, ++q)
        put_cell(grid.data() + static_cast<std::ptrdiff_t>(i) * (n + 1), j);
  }
}

void TessellationLayout::grid_vertices(int k, std::int64_t* out) const {
  const int n = n_, stride = n + 1;
  if (!welded_) {
    const std::int64_t first = static_cast<std::int64_t>(k) * grid_.num_samples();
    for (int s = 0; s < grid_.num_samples(); ++s) out[s] = first + s;
    return;
  }
  // vertex(k, i, j) a side at a time: the mesh is asked once per side, not once per sample.
  const Corner c = corners_[k];
  const std::int64_t side = n - 1, own = block(k);
  out[0] = vertex(k, 0, 0);
  out[n * stride] = vertex(k, n, 0);
  out[n * stride + n] = vertex(k, n, n);
  out[n] = vertex(k, 0, n);
  const int x = extra_half_[c.idx];
  const std::int64_t side_i0 =
      x >= 0 ? first_extra_ + x * side : block(corner_index(mesh_.rotate_ccw(c)));
  const std::int64_t side_jn = block(corner_index(mesh_.prev(c))) + side;
  for (int m = 1; m < n; ++m) {
    out[m * stride] = own + (m - 1);             // j = 0
    out[m] = side_i0 + (m - 1);                  // i = 0
    out[n * stride + m] = own + side + (m - 1);  // i = n
    out[m * stride + n] = side_jn + (m - 1);     // j = n
  }
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) out[i * stride + j] = own + 2 * side + (i - 1) * side + (j - 1);
}

std::array<std::int64_t, 4> TessellationLayout::cell_quad(int k, int i, int j) const {
  if (!welded_) return grid_.quad(i * n_ + j, static_cast<std::int64_t>(k) * grid_.num_samples());
  if (i >= 1 && j >= 1 && i + 1 < n_ && j + 1 < n_) {
    // All four corners interior: consecutive rows of this corner's interior block.
    const std::int64_t side = n_ - 1;
    const std::int64_t at = block(k) + 2 * side + (i - 1) * side + (j - 1);
    return {at, at + side, at + side + 1, at + 1};
  }
  return {vertex(k, i, j), vertex(k, i + 1, j), vertex(k, i + 1, j + 1), vertex(k, i, j + 1)};
}

void TessellationLayout::samples(std::int64_t vertex, std::vector<GridSample>& out) const {
  out.clear();
  const int n = n_;
  if (!welded_) {
    const std::int64_t per_patch = grid_.num_samples();
    out.push_back(
        block_sample(static_cast<int>(vertex / per_patch), static_cast<int>(vertex % per_patch)));
    return;
  }
  if (vertex < first_face_) {
    // Every corner around the mesh vertex, counter-clockwise from halfedge(v).
    const Corner start = mesh_.halfedge(vertices_[vertex]);
    Corner c = start;
    do {
      if (corner_index(c) >= 0) out.push_back({corner_index(c), 0, 0});
      c = mesh_.rotate_ccw(c);
    } while (c != start);
  } else if (vertex < first_edge_) {
    const Corner start = mesh_.halfedge(faces_[vertex - first_face_]);
    Corner c = start;
    do {
      out.push_back({corner_index(c), n, n});
      c = mesh_.next(c);
    } while (c != start);
  } else if (vertex < first_block_) {
    // The edge's midpoint: side i = n of both half-edges' corners, and side j = n of the corners
    // that follow them.
    const Edge e = edges_[vertex - first_edge_];
    for (int side = 0; side < 2; ++side) {
      const Corner h = HalfedgeMesh::halfedge(e, side);
      if (corner_index(h) < 0) continue;  // a hole
      out.push_back({corner_index(h), n, 0});
      out.push_back({corner_index(mesh_.next(h)), 0, n});
    }
  } else if (vertex >= first_extra_) {
    const std::int64_t at = vertex - first_extra_;
    const auto x = static_cast<int>(at / (n - 1));
    out.push_back({extra_corner_[x], 0, static_cast<int>(at % (n - 1)) + 1});
  } else {
    const std::int64_t at = vertex - first_block_;
    const std::int64_t per_corner = static_cast<std::int64_t>(n) * n - 1;
    const auto k = static_cast<int>(at / per_corner);
    const auto r = static_cast<int>(at % per_corner);
    const int side = n - 1;
    const GridSample own = block_sample(k, r);
    out.push_back(own);
    if (r < side) {  // the half of edge(c) at the vertex, shared with rotate_cw(c)'s side i = 0
      if (const int across = corner_index(mesh_.rotate_cw(corners_[k])); across >= 0)
        out.push_back({across, 0, own.i});
    } else if (r < 2 * side) {  // the spoke, shared with next(c)'s side j = n
      out.push_back({corner_index(mesh_.next(corners_[k])), own.j, n});
    }
  }
}

void TessellationLayout::evaluate(const Surface& surface, std::int64_t begin, std::int64_t end,
                                  Vec3* positions, Vec3* normals,
                                  const SampleAttributes& attributes) const {
  PatchSampler sampler(surface, n_);
  BlockScratch scratch;
  // Corner blocks (and unwelded grids) are evaluated a block at a time; the mesh vertices, face
  // centres, edge midpoints and boundary halves, shared by varying numbers of patches, one by
  // one.
  const std::int64_t blocks_begin = welded_ ? first_block_ : 0;
  const std::int64_t blocks_end = welded_ ? first_extra_ : num_vertices_;
  const std::int64_t per_block = block_size();
  evaluate_each(sampler, surface, begin, std::min(end, blocks_begin), begin, positions, normals,
                attributes);
  const std::int64_t lo = std::max(begin, blocks_begin), hi = std::min(end, blocks_end);
  if (lo < hi && per_block > 0) {
    for (std::int64_t k = (lo - blocks_begin) / per_block; blocks_begin + k * per_block < hi; ++k) {
      const std::int64_t first = blocks_begin + k * per_block;
      const auto corner = static_cast<int>(k);
      if (first >= begin && first + per_block <= end) {
        const std::int64_t at = first - begin;
        evaluate_block(sampler, surface, corner, positions + at, normals + at,
                       attributes.level ? attributes.level + at : nullptr, scratch);
        fill_block_attributes(corner, first, first + per_block, begin, attributes);
        continue;
      }
      // A block cut by the range: evaluated whole aside, its part in the range copied.
      scratch.positions.resize(static_cast<size_t>(per_block));
      scratch.normals.resize(static_cast<size_t>(per_block));
      scratch.levels.resize(static_cast<size_t>(per_block));
      evaluate_block(sampler, surface, corner, scratch.positions.data(), scratch.normals.data(),
                     scratch.levels.data(), scratch);
      const std::int64_t from = std::max(first, begin), to = std::min(first + per_block, end);
      for (std::int64_t vertex = from; vertex < to; ++vertex) {
        positions[vertex - begin] = scratch.positions[vertex - first];
        normals[vertex - begin] = scratch.normals[vertex - first];
        if (attributes.level) attributes.level[vertex - begin] = scratch.levels[vertex - first];
      }
      fill_block_attributes(corner, from, to, begin, attributes);
    }
  }
  evaluate_each(sampler, surface, std::max(begin, blocks_end), end, begin, positions, normals,
                attributes);
}

void TessellationLayout::evaluate_block(PatchSampler& sampler, const Surface& surface, int k,
                                        Vec3* positions, Vec3* normals, int* levels,
                                        BlockScratch& scratch) const {
  const int n = n_;
  const Corner c = corners_[k];
  if (!welded_) {
    sampler.evaluate_block(c, 0, n, 0, n, {positions, normals, levels, n + 1});
    return;
  }
  const int side = n - 1;
  if (side == 0) return;
  // The corner's own samples in one call (one descent of an extraordinary net): rows i = 1..n,
  // columns j = 0..n - 1, i.e. the interior, the edge half (j = 0), the spoke (i = n) and the
  // edge midpoint (n, 0), which is not the block's; then laid out in the block's order.
  const auto own = static_cast<size_t>(n) * n;
  scratch.grid_positions.resize(own);
  scratch.grid_normals.resize(own);
  scratch.grid_levels.resize(own);
  sampler.evaluate_block(c, 1, n, 0, side,
                         {scratch.grid_positions.data(), scratch.grid_normals.data(),
                          levels ? scratch.grid_levels.data() : nullptr, n});
  const auto place = [&](std::int64_t to, int i, int j) {
    const size_t from = static_cast<size_t>(i - 1) * n + j;
    positions[to] = scratch.grid_positions[from];
    normals[to] = scratch.grid_normals[from];
    if (levels) levels[to] = scratch.grid_levels[from];
  };
  for (int m = 1; m < n; ++m) {
    place(m - 1, m, 0);         // edge half
    place(side + m - 1, n, m);  // spoke
  }
  // The interior row by row, each a contiguous run both here and in the grid, in one pass.
  for (int i = 1; i < n; ++i) {
    const size_t from = static_cast<size_t>(i - 1) * n + 1;
    const std::int64_t to = 2 * side + static_cast<std::int64_t>(i - 1) * side;
    std::copy_n(scratch.grid_positions.data() + from, side, positions + to);
    std::copy_n(scratch.grid_normals.data() + from, side, normals + to);
    if (levels) std::copy_n(scratch.grid_levels.data() + from, side, levels + to);
  }
  // The edge half (i, 0) is shared with (0, i) of the corner across it (none on a boundary), the
  // spoke (n, j) with (j, n) of the next corner: where averages_normals, their normals are the
  // normalized sums, this patch's first; elsewhere this patch's normals.
  scratch.shared_positions.resize(static_cast<size_t>(side));
  scratch.shared_normals.resize(static_cast<size_t>(side));
  const auto shared = [&](Vec3* normal, int other, bool mean, int i0, int i1, int j0, int j1) {
    if (other < 0 || !mean) return;
    sampler.evaluate_block(
        corners_[other], i0, i1, j0, j1,
        {scratch.shared_positions.data(), scratch.shared_normals.data(), nullptr, 1});
    for (int s = 0; s < side; ++s) normal[s] = (normal[s] + scratch.shared_normals[s]).normalized();
  };
  shared(normals, corner_index(mesh_.rotate_cw(c)), averages_normals(block(k), surface), 0, 0, 1,
         side);
  shared(normals + side, corner_index(mesh_.next(c)), averages_normals(block(k) + side, surface), 1,
         side, n, n);
}

bool TessellationLayout::averages_normals(std::int64_t vertex, const Surface& surface) const {
  if (!welded_) return false;
  if (vertex < first_block_) return true;    // mesh vertices, face centres, edge midpoints
  if (vertex >= first_extra_) return false;  // boundary halves: one patch
  if (surface.method() == Method::asc) return true;
  const std::int64_t per_corner = block_size();
  const std::int64_t at = vertex - first_block_;
  // The edge half (the first n - 1 of a corner's block) lies on a mesh edge, the spoke and the
  // interior inside a face.
  return at % per_corner < n_ - 1 && surface.bezier().kgons.sharp(HalfedgeMesh::edge(
                                         corners_[static_cast<size_t>(at / per_corner)]));
}

GridSample TessellationLayout::block_sample(int k, int r) const {
  if (!welded_) return {k, grid_.row(r), grid_.column(r)};
  const int n = n_, side = n - 1;
  if (r < side) return {k, r + 1, 0};
  if (r < 2 * side) return {k, n, r - side + 1};
  const int interior = r - 2 * side;
  return {k, interior / side + 1, interior % side + 1};
}

void TessellationLayout::fill_block_attributes(int k, std::int64_t from, std::int64_t to,
                                               std::int64_t begin,
                                               const SampleAttributes& attributes) const {
  if (!attributes.uv && !attributes.patch) return;
  const std::int64_t first = welded_ ? block(k) : static_cast<std::int64_t>(k) * block_size();
  if (attributes.uv)
    std::copy(block_uv_.begin() + (from - first), block_uv_.begin() + (to - first),
              attributes.uv + (from - begin));
  if (attributes.patch)
    std::fill(attributes.patch + (from - begin), attributes.patch + (to - begin), corners_[k].idx);
}

void TessellationLayout::evaluate_each(PatchSampler& sampler, const Surface& surface,
                                       std::int64_t from, std::int64_t to, std::int64_t begin,
                                       Vec3* positions, Vec3* normals,
                                       const SampleAttributes& attributes) const {
  std::vector<GridSample> sharing;
  for (std::int64_t vertex = from; vertex < to; ++vertex) {
    samples(vertex, sharing);
    const bool grid = !welded_ || vertex >= first_block_;
    const bool mean = sharing.size() > 1 && averages_normals(vertex, surface);
    Vec3 normal = Vec3::Zero();  // set from the first patch: a mean starts from its normal
    for (size_t s = 0; s < (mean ? sharing.size() : 1); ++s) {
      const GridSample& g = sharing[s];
      const Eigen::Vector2d& uv = grid_.uv(grid_.sample(g.i, g.j));
      const SurfacePoint point = sample_point(sampler, g, grid);
      if (s > 0) {
        normal += point.normal;
        continue;
      }
      normal = point.normal;
      const std::int64_t at = vertex - begin;
      positions[at] = point.position;
      if (attributes.uv) attributes.uv[at] = uv;
      if (attributes.patch) attributes.patch[at] = corners_[g.corner].idx;
      if (attributes.level) attributes.level[at] = point.level;
    }
    // One patch's unit normal as evaluated, or the mean direction of its patches' normals.
    normals[vertex - begin] = mean ? normal.normalized() : normal;
  }
}

SurfacePoint TessellationLayout::sample_point(PatchSampler& sampler, const GridSample& g,
                                              bool grid) const {
  if (grid) return sampler.evaluate_grid(corners_[g.corner], g.i, g.j);
  // The mesh vertices, face centres and edge midpoints are patch corners, evaluated directly:
  // the sampler's tables would not pay off there.
  const Eigen::Vector2d& uv = grid_.uv(grid_.sample(g.i, g.j));
  return sampler.evaluate(corners_[g.corner], uv.x(), uv.y());
}

void TessellationLayout::grid_positions(PatchSampler& sampler, int k, Vec3* positions,
                                        std::vector<Vec3>& scratch) const {
  const int n = n_, stride = n + 1, side = n - 1;
  const Corner c = corners_[k];
  scratch.resize(static_cast<size_t>(stride) * (stride + 1));
  Vec3* const normals = scratch.data();  // not needed, but always computed
  Vec3* const spoke = normals + static_cast<std::ptrdiff_t>(stride) * stride;
  // The whole grid from this patch, then the samples other patches own from those: every sample
  // is a function of its patch and (i, j) alone, to the bit (PatchSampler::evaluate_block
  // equals evaluate_grid and Surface::evaluate), so a sample evaluated here from the patch that
  // owns it has the position evaluate() gives its vertex.
  sampler.evaluate_block(c, 0, n, 0, n, {positions, normals, nullptr, stride});
  if (!welded_) return;
  if (side > 0) {
    // Side i = 0: rotate_ccw(c)'s edge half, its samples (m, 0), which land at (0, m) with a
    // stride of 1 (on a boundary, this patch's own: already there).
    if (extra_half_[c.idx] < 0)
      sampler.evaluate_block(corners_[corner_index(mesh_.rotate_ccw(c))], 1, side, 0, 0,
                             {positions + 1, normals + 1, nullptr, 1});
    // Side j = n: prev(c)'s spoke, its samples (n, m), a row there and a column here.
    sampler.evaluate_block(corners_[corner_index(mesh_.prev(c))], n, n, 1, side,
                           {spoke, normals, nullptr, 0});
    for (int m = 1; m < n; ++m) positions[m * stride + n] = spoke[m - 1];
  }
  // The patch corners: each vertex's first sample.
  std::vector<GridSample> sharing;
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{n, 0}, std::pair{n, n}, std::pair{0, n}}) {
    samples(vertex(k, i, j), sharing);
    const GridSample& g = sharing[0];
    if (g.corner != k || g.i != i || g.j != j)
      sampler.evaluate_block(corners_[g.corner], g.i, g.i, g.j, g.j,
                             {positions + i * stride + j, normals, nullptr, 0});
  }
}

void TessellationLayout::triangles(const Surface& surface, std::int64_t begin, std::int64_t end,
                                   int* indices, Vec3* corners) const {
  const int n = n_, stride = n + 1;
  const std::int64_t cells = static_cast<std::int64_t>(n) * n;
  PatchSampler sampler(surface, n);
  const auto samples = static_cast<size_t>(stride) * stride;
  std::vector<Vec3> positions(samples), scratch;
  std::vector<std::int64_t> numbers(samples);
  for (std::int64_t q = begin; q < end;) {
    const auto k = static_cast<int>(q / cells);
    grid_positions(sampler, k, positions.data(), scratch);
    grid_vertices(k, numbers.data());
    const std::int64_t last = std::min(end, (k + 1) * cells);
    for (; q < last; ++q) {
      const auto cell = static_cast<int>(q - k * cells);
      const int at = cell / n * stride + cell % n;
      // Counter-clockwise as quads() walks the cell.
      const std::array<int, 4> loop{at, at + stride, at + stride + 1, at + 1};
      for (const auto& t : quad_triangles(loop, positions))
        for (const int s : t) {
          *indices++ = static_cast<int>(numbers[static_cast<size_t>(s)]);
          if (corners) *corners++ = positions[static_cast<size_t>(s)];
        }
    }
  }
}

}  // namespace stitch
