#include "stitch/tess/bspline_faces.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "stitch/error.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch {

namespace {

using Cubic = std::array<Vec3, 4>;
using Net = std::array<Vec3, 16>;  ///< Q[a][b] = q[4 * a + b], a along the first parameter

/// The Bézier points of the cubic `c` over [a, b] of its [0, 1]: its blossom at (a, a, a),
/// (a, a, b), (a, b, b) and (b, b, b).
Cubic restrict_cubic(const Cubic& c, double a, double b) {
  const auto blossom = [&c](double t1, double t2, double t3) {
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = (1 - t1) * c[i] + t1 * c[i + 1];
    for (int i = 0; i < 2; ++i) q[i] = (1 - t2) * q[i] + t2 * q[i + 1];
    return Vec3((1 - t3) * q[0] + t3 * q[1]);
  };
  return {blossom(a, a, a), blossom(a, a, b), blossom(a, b, b), blossom(b, b, b)};
}

/// The Bézier net of the polynomial of `net` over [u0, u1] x [v0, v1] of its square.
Net restrict_net(const ControlNet& net, double u0, double u1, double v0, double v1) {
  Net rows;
  for (int a = 0; a < 4; ++a) {
    const Cubic r =
        restrict_cubic({net.at(a, 0), net.at(a, 1), net.at(a, 2), net.at(a, 3)}, v0, v1);
    for (int b = 0; b < 4; ++b) rows[4 * a + b] = r[b];
  }
  Net out;
  for (int b = 0; b < 4; ++b) {
    const Cubic c = restrict_cubic({rows[b], rows[4 + b], rows[8 + b], rows[12 + b]}, u0, u1);
    for (int a = 0; a < 4; ++a) out[4 * a + b] = c[a];
  }
  return out;
}

/// (x, y) of the quadrant for (s, t) of the face, inverting the quarter turn.
std::array<double, 2> unrotate(int rotation, double s, double t) {
  switch (rotation) {
    case 1:
      return {t, 1 - s};
    case 2:
      return {1 - s, 1 - t};
    case 3:
      return {1 - t, s};
    default:
      return {s, t};
  }
}

/// (s, t) of the face for (x, y) of the quadrant.
std::array<double, 2> rotate(int rotation, double x, double y) {
  switch (rotation) {
    case 1:
      return {1 - y, x};
    case 2:
      return {1 - x, 1 - y};
    case 3:
      return {y, 1 - x};
    default:
      return {x, y};
  }
}

/// (s, t) of the face for (u, v) of the quadrant's root.
std::array<double, 2> to_face(const FaceQuadrant& q, double u, double v) {
  const auto [x, y] = rotate(q.rotation, u, v);
  return {q.origin[0] + q.size * x, q.origin[1] + q.size * y};
}

/// (u, v) of the quadrant's root for (s, t) of the face.
std::array<double, 2> to_root(const FaceQuadrant& q, double s, double t) {
  return unrotate(q.rotation, (s - q.origin[0]) / q.size, (t - q.origin[1]) / q.size);
}

/// `inner` (a root in a square) placed in a face by `outer` (where that square lies): quarter
/// turns about the unit square's centre add up, and the origin is where the whole map takes the
/// point that the turn sends to (0, 0).
FaceQuadrant compose(const FaceQuadrant& outer, const FaceQuadrant& inner) {
  FaceQuadrant q{inner.corner, (outer.rotation + inner.rotation) % 4, outer.size * inner.size};
  const auto [u, v] = unrotate(q.rotation, 0, 0);
  const auto [x, y] = to_face(inner, u, v);
  q.origin = to_face(outer, x, y);
  return q;
}

/// Pole (p, q) of the face's net (p along s, q along t) from the root's net Q over the same
/// rectangle (indices along u and v).
const Vec3& reoriented(const Net& q_net, int rotation, int p, int q) {
  switch (rotation) {
    case 1:
      return q_net[4 * q + (3 - p)];
    case 2:
      return q_net[4 * (3 - p) + (3 - q)];
    case 3:
      return q_net[4 * (3 - q) + p];
    default:
      return q_net[4 * p + q];
  }
}

/// The cells of one root patch, by level, for finding the one that holds a point.
class RootCells {
 public:
  void add(const BezierPatch& cell) {
    if (static_cast<int>(by_level_.size()) <= cell.level) by_level_.resize(cell.level + 1);
    by_level_[cell.level].push_back(&cell);
  }
  /// The cell whose square holds (u, v) (inside it, not on its side).
  [[nodiscard]] const BezierPatch& at(double u, double v) const {
    for (size_t level = 0; level < by_level_.size(); ++level) {
      const double scale = std::ldexp(1.0, static_cast<int>(level));
      const int cu = static_cast<int>(std::floor(u * scale)),
                cv = static_cast<int>(std::floor(v * scale));
      for (const BezierPatch* cell : by_level_[level])
        if (cell->cell_u == cu && cell->cell_v == cv) return *cell;
    }
    throw Error(fmt::format("no cell of the patch holds ({}, {})", u, v));  // a broken patch set
  }
  /// The sides of the cells along u (or v): the root's knots.
  [[nodiscard]] std::vector<double> knots(bool along_u) const {
    std::vector<double> k{0.0, 1.0};
    for (size_t level = 0; level < by_level_.size(); ++level)
      for (const BezierPatch* cell : by_level_[level]) {
        const int first = along_u ? cell->cell_u : cell->cell_v;
        k.push_back(std::ldexp(first, -static_cast<int>(level)));
        k.push_back(std::ldexp(first + 1, -static_cast<int>(level)));
      }
    return k;
  }

 private:
  std::vector<std::vector<const BezierPatch*>> by_level_;
};

void sort_unique(std::vector<double>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

/// The face's knots: the sides of its quadrants' cells, in the face's (s, t).
void fill_knots(BsplineFace& face, const std::vector<RootCells>& cells) {
  for (const FaceQuadrant& quadrant : face.quadrants)
    // The root's u knots become s or t knots of the face, depending on the quarter turn.
    for (const bool along_u : {true, false})
      for (const double k : cells[quadrant.corner.idx].knots(along_u)) {
        const auto [s, t] = to_face(quadrant, along_u ? k : 0, along_u ? 0 : k);
        const bool gives_s = (quadrant.rotation % 2 == 0) == along_u;
        (gives_s ? face.u_knots : face.v_knots).push_back(gives_s ? s : t);
      }
  sort_unique(face.u_knots);
  sort_unique(face.v_knots);
}

/// The face's poles: the Bézier net of each rectangle of its knot grid, cut from the cell of the
/// hierarchy that holds it.
void fill_poles(BsplineFace& face, const std::vector<RootCells>& cells) {
  const int nv = face.num_v_poles();
  face.poles.assign(static_cast<size_t>(face.num_u_poles()) * nv, Vec3::Zero());
  for (size_t i = 0; i + 1 < face.u_knots.size(); ++i)
    for (size_t j = 0; j + 1 < face.v_knots.size(); ++j) {
      const double s0 = face.u_knots[i], s1 = face.u_knots[i + 1];
      const double t0 = face.v_knots[j], t1 = face.v_knots[j + 1];
      const RootPoint centre = root_point(face, (s0 + s1) / 2, (t0 + t1) / 2);
      size_t q = 0;
      while (face.quadrants[q].corner != centre.corner) ++q;
      const FaceQuadrant& quadrant = face.quadrants[q];
      // The rectangle in the root's (u, v), then in its cell's own square.
      const auto [ua, va] = to_root(quadrant, s0, t0);
      const auto [ub, vb] = to_root(quadrant, s1, t1);
      const double u0 = std::min(ua, ub), u1 = std::max(ua, ub);
      const double v0 = std::min(va, vb), v1 = std::max(va, vb);
      const BezierPatch& cell = cells[centre.corner.idx].at(centre.u, centre.v);
      const double scale = std::ldexp(1.0, cell.level);
      const Net net = restrict_net(cell.net, u0 * scale - cell.cell_u, u1 * scale - cell.cell_u,
                                   v0 * scale - cell.cell_v, v1 * scale - cell.cell_v);
      for (int p = 0; p < 4; ++p)
        for (int r = 0; r < 4; ++r)
          face.poles[(3 * i + p) * nv + 3 * j + r] = reoriented(net, quadrant.rotation, p, r);
    }
}

/// The cells of every root, by corner index.
std::vector<RootCells> cells_by_root(const HalfedgeMesh& mesh, const PatchSet& patches) {
  std::vector<RootCells> cells(mesh.halfedge_capacity());
  for (const BezierPatch& patch : patches.patches) cells[patch.corner.idx].add(patch);
  return cells;
}

/// The faces with their quadrants, sides and knots.
std::vector<BsplineFace> layout(const HalfedgeMesh& mesh, const Surface& surface,
                                const PatchSet& patches, FacePacking packing,
                                const std::vector<RootCells>& cells, const ControlMesh* control) {
  const HalfedgeMesh& named = control ? *control->mesh : mesh;
  // Each control corner's roots, where they lie in its patch's square, in the patch set's order
  // (without a control mesh, each corner is its own root).
  std::vector<Corner> corners;  // control corners, in the order of their first root
  std::vector<std::vector<FaceQuadrant>> tiles(named.halfedge_capacity());
  for (const BezierPatch& patch : patches.patches) {
    const Corner r = patch.corner;
    FaceQuadrant at = control ? control->roots[r.idx] : FaceQuadrant{r};
    const Corner c = at.corner;
    std::vector<FaceQuadrant>& tile = tiles[c.idx];
    if (!tile.empty() && tile.back().corner == r) continue;  // the root's other cells
    if (tile.empty()) corners.push_back(c);
    at.corner = r;
    tile.push_back(at);
  }
  const KgonSet& kgons = surface.bezier().kgons;
  // Whether side 0 (along the corner's edge) or side 3 (along the edge before it) of a control
  // corner's square lies on a sharp edge: the side of the root at the square's corner (0, 0)
  // there. A root's side j lies on the square's side (j + rotation) % 4; its sides 0 and 3 are
  // halves of the edges of its corner and the one before, sides 1 and 2 run inside its face.
  const auto sharp_side = [&](Corner c, int side) {
    for (const FaceQuadrant& q : tiles[c.idx]) {
      if (q.origin[0] != 0 || q.origin[1] != 0) continue;
      const int j = (side - q.rotation + 4) % 4;
      if (j == 0) return kgons.sharp(HalfedgeMesh::edge(q.corner));
      if (j == 3) return kgons.sharp(HalfedgeMesh::edge(mesh.prev(q.corner)));
    }
    return false;
  };
  const auto single = [&](Corner c) {
    BsplineFace face;
    face.face = named.face(c).idx;
    face.vertex = named.origin(c).idx;
    face.corner = c;
    face.quadrants = tiles[c.idx];
    face.sharp_side = {sharp_side(c, 0), false, false, sharp_side(c, 3)};
    return face;
  };
  std::vector<BsplineFace> faces;
  if (packing == FacePacking::corners) {
    for (Corner c : corners) faces.push_back(single(c));
  } else {
    // Corner k of a quad is the quadrant at the face's corner k, turned k quarter turns.
    constexpr std::array<std::array<double, 2>, 4> kOrigin{
        {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}};
    for (Face f : named.surface_faces()) {
      const std::vector<Halfedge> loop = named.face_loop(f);
      if (loop.size() != 4) {
        for (Halfedge h : loop) faces.push_back(single(h));
        continue;
      }
      BsplineFace face;
      face.face = f.idx;
      for (int k = 0; k < 4; ++k) {
        const FaceQuadrant square{loop[k], k, 0.5, kOrigin[k]};
        for (const FaceQuadrant& q : tiles[loop[k].idx])
          face.quadrants.push_back(compose(square, q));
        face.sharp_side[k] = sharp_side(loop[k], 0);  // side k runs along the edge of corner k
      }
      faces.push_back(std::move(face));
    }
  }
  for (BsplineFace& face : faces) fill_knots(face, cells);
  return faces;
}
}  // namespace

ChoiceTable<FacePacking> face_packing_table() {
  static constexpr Choice<FacePacking> kPackings[] = {
      {"quads", FacePacking::quads,
       "one face per quad of the mesh (its four corner patches), one per corner of any other "
       "face"},
      {"corners", FacePacking::corners, "one face per corner patch"},
  };
  return kPackings;
}

ControlMesh control_mesh(const HalfedgeMesh& input, const SemiSharpMesh& refined) {
  ControlMesh control;
  control.mesh = &input;
  control.roots.resize(static_cast<size_t>(refined.mesh.halfedge_capacity()));
  const int n = 1 << refined.quad_corners.size();  // refined patches along a side
  const double size = 1.0 / n;
  for (Corner c : input.patch_corners())
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        // The refined patch at the square's middle, and which way the input's u runs in it.
        const SemiSharpMesh::Point p = refined.point(c, (i + 0.5) * size, (j + 0.5) * size);
        const SemiSharpMesh::Point q = refined.point(c, (i + 0.75) * size, (j + 0.5) * size);
        const double du = q.u - p.u, dv = q.v - p.v;
        // The input's +u (+x) is the refined patch's +u (no turn), -v (1), -u (2) or +v (3).
        const int rotation = std::abs(du) > std::abs(dv) ? (du > 0 ? 0 : 2) : (dv > 0 ? 3 : 1);
        control.roots[p.corner.idx] = {c, rotation, size, {i * size, j * size}};
      }
  return control;
}

RootPoint root_point(const BsplineFace& face, double s, double t) {
  // The quadrant whose square holds (s, t) deepest inside (any of them on a shared side).
  const FaceQuadrant* best = &face.quadrants.front();
  double best_outside = std::numeric_limits<double>::infinity();
  for (const FaceQuadrant& q : face.quadrants) {
    const double outside = std::max(
        {q.origin[0] - s, s - q.origin[0] - q.size, q.origin[1] - t, t - q.origin[1] - q.size});
    if (outside < best_outside) {
      best_outside = outside;
      best = &q;
    }
  }
  const auto [u, v] = to_root(*best, s, t);
  return {best->corner, u, v};
}

std::string face_name(const HalfedgeMesh& mesh, const BsplineFace& face) {
  if (face.vertex < 0) return fmt::format("face {}", face.face + 1);
  return "corner " + corner_name(mesh, face.corner);
}

std::vector<BsplineFace> bspline_face_layout(const HalfedgeMesh& mesh, const Surface& surface,
                                             const PatchSet& patches, FacePacking packing,
                                             const ControlMesh* control) {
  return layout(mesh, surface, patches, packing, cells_by_root(mesh, patches), control);
}

std::vector<BsplineFace> bspline_faces(const HalfedgeMesh& mesh, const Surface& surface,
                                       const PatchSet& patches, FacePacking packing,
                                       const std::function<void(double)>& progress,
                                       const ControlMesh* control) {
  const std::vector<RootCells> cells = cells_by_root(mesh, patches);
  std::vector<BsplineFace> faces = layout(mesh, surface, patches, packing, cells, control);
  // In blocks, so that progress can be told from this thread between them.
  const size_t block = std::max<size_t>(64, faces.size() / 100);
  for (size_t begin = 0; begin < faces.size(); begin += block) {
    const size_t end = std::min(faces.size(), begin + block);
    tbb::parallel_for(begin, end, [&](size_t i) { fill_poles(faces[i], cells); });
    if (progress) progress(double(end) / faces.size());
  }
  return faces;
}

}  // namespace stitch
