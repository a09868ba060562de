// Evaluating many points of a few patches after another, as tessellation does: the modified de
// Casteljau splits of an extraordinary net are made once and kept while the points stay on that
// patch, so each further point costs one polynomial evaluation instead of a descent of its own.
// The results are bit for bit Surface::evaluate's. Internal.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "eval/polynomial.hpp"
#include "stitch/eval/surface.hpp"

namespace stitch {

namespace detail {
/// A point as one vector of 4 doubles (x, y, z, 0): the extraordinary nets' splits and leaves
/// work on whole points with the operations of the Vec3 code, coordinate by coordinate.
using Lanes = double __attribute__((vector_size(32)));
/// A control net in Lanes (the flags that evaluation reads, not corner_k).
struct LaneNet {
  Lanes p[16];  ///< P[a][b] = p[4 * a + b]
  std::uint8_t extraordinary = 0;
};
}  // namespace detail

/// Where PatchSampler::evaluate_block writes sample (i, j) of its block [i0, i1] x [j0, j1]:
/// element (i - i0) * stride + (j - j0) of each array (levels may be null).
struct GridOut {
  Vec3* positions = nullptr;
  Vec3* normals = nullptr;
  int* levels = nullptr;
  std::ptrdiff_t stride = 0;
};

class PatchSampler {
 public:
  /// `resolution`: the grid evaluate_grid samples (0 when it is not used).
  explicit PatchSampler(const Surface& surface, int resolution = 0);
  /// The Bézier patches of `nets` (indexed by corner) for method mdc or asc, without a Surface
  /// (IncrementalSurface keeps its own nets): the same points as a Surface with these nets.
  PatchSampler(Method method, const std::vector<ControlNet>& nets, int resolution);
  /// Surface::evaluate(c, u, v). Cheapest when the calls stay on the last few corners (a side
  /// shared by two patches is sampled from both in turn).
  SurfacePoint evaluate(Corner c, double u, double v);
  /// Surface::evaluate(c, i / n, j / n) for the resolution n. A polynomial patch keeps its net
  /// summed against the basis at every j (the inner sums of evaluate_polynomial), so a point of
  /// a patch sampled many times costs 12 multiply-adds and a normal.
  SurfacePoint evaluate_grid(Corner c, int i, int j);
  /// evaluate_grid(c, i, j)'s position, normal and level for every i in [i0, i1] and j in
  /// [j0, j1], to the bit, at a fraction of the cost: a polynomial net is summed against basis
  /// tables a grid row at a time (loops over j the compiler vectorises); an extraordinary net is
  /// split once per level for all the samples below each child (a point per vector of 4 doubles,
  /// the children kept only while their samples are evaluated, not between calls), and each
  /// regular child is summed the same way, a point per vector, with the bases of its own
  /// parameters (the resolution's table entries where they are grid values). Which nets are
  /// split and which samples go where is planned once per block and corner mask (Plan).
  void evaluate_block(Corner c, int i0, int i1, int j0, int j1, const GridOut& out);

 private:
  struct Split {
    std::uint64_t path;
    std::array<ControlNet, 4> children;
  };
  /// What is kept of one corner's net: the splits made so far (extraordinary nets), or its rows
  /// summed against the basis at each grid j (polynomial ones).
  struct Patch {
    int corner = -1;
    ControlNet relative;  ///< the corner's net minus its first point
    std::vector<Split> splits;
    std::vector<std::array<Vec3, 4>> rows, rows_dv;  ///< [j][a]: sum over b, of b(v) and b'(v)
    std::vector<char> row_ready;                     ///< [j]: rows[j] and rows_dv[j] are summed
    double tiny = 0;                                 ///< detail::degenerate_threshold
  };
  Patch& patch(Corner c);
  /// Surface::evaluate(c, u, v), with no caching.
  [[nodiscard]] SurfacePoint direct(Corner c, double u, double v) const;
  const std::array<ControlNet, 4>& split_at(Patch& patch, const ControlNet& net,
                                            std::uint64_t path);
  /// Bases in structure-of-arrays form: b[a][k], d[a][k] for the k-th parameter value.
  struct BasisColumns {
    std::vector<double> t;  ///< the parameter values
    std::array<std::vector<double>, 4> b, d;
    void resize(size_t n);
    void set(size_t k, double value);  ///< entry k from detail::cubic_basis(value)
  };
  /// One step of an extraordinary net's descent for a block (see Plan).
  struct PlanOp {
    enum Kind : std::uint8_t { split, corner, block };
    Kind kind = block;
    std::uint8_t level = 0;  ///< the level of the net the step works on
    std::uint8_t child = 0;  ///< that net: children_[level - 1][child], or the root at level 0
    std::uint8_t u_end = 0, v_end = 0;   ///< corner: the sample's parameters are 1 (else 0)
    int iu = 0, nu = 0, jv = 0, nv = 0;  ///< the sub-block (block-relative; corner: its sample)
    int bases = 0;  ///< block: its nu u, then nv v bases from here in Plan::bases (and params)
    int skip = 0;   ///< block: its nu x nv flags (1: written higher up) from here in Plan::skip
  };
  /// The descent of an extraordinary net with a given mask of extraordinary corners for the
  /// samples of one block: which nets are split, which samples are at a net's corner, which
  /// sub-blocks are regular children with which bases. It depends only on the block, the mask
  /// and the resolution, so it is made once per sampler and replayed for every net (the
  /// recursion's bookkeeping, the parameters and their bases are not redone per patch).
  struct Plan {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    int levels = 0;  ///< the splits' deepest level + 1
    std::vector<PlanOp> ops;
    std::vector<const detail::CubicBasis*> bases;  ///< into basis_ or computed
    std::vector<double> params;                    ///< the parameter of each entry of bases
    std::vector<char> skip;
    std::vector<detail::CubicBasis> computed;  ///< bases of parameters that are not grid values
  };
  /// The plan of the block [i0, i1] x [j0, j1] for nets of extraordinary corners `mask`.
  const Plan& plan(std::uint8_t mask, int i0, int i1, int j0, int j1);
  /// detail::descend for every sample of the sub-block at once, recorded into `plan`: the
  /// samples whose descent reaches the net `child` of `level` (of corner mask `mask`), with
  /// their parameters in it u_[level][iu..] and v_[level][jv..].
  void plan_descent(Plan& plan, std::uint8_t mask, int level, int child, int iu, int nu, int jv,
                    int nv);
  /// polynomial_block for a LaneNet: the same sums, a point (3 coordinates) per vector; `bu`,
  /// `tu` and `bv`, `tv`: the bases and parameters of the rows and columns; `skip`: nu x nv flags
  /// of samples not to write.
  void lane_block(const detail::LaneNet& net, int level, int iu, int nu, int jv, int nv,
                  const detail::CubicBasis* const* bu, const detail::CubicBasis* const* bv,
                  const double* tu, const double* tv, const char* skip, const GridOut& out);
  /// Replays `steps` on the extraordinary net `net`.
  void run_plan(const Plan& steps, const ControlNet& net, const GridOut& out);
  /// The sample of a net at its corner (u_end, v_end), as evaluate_at_patch_corner sums it.
  void corner_sample(const detail::LaneNet& net, const PlanOp& op, const GridOut& out) const;
  /// Whether a sample of the sub-block is not yet in done_.
  [[nodiscard]] bool pending(int iu, int nu, int jv, int nv) const;
  /// The polynomial of `net` (a regular net, or any net under asc) at the grid samples
  /// [i0, i0 + nu) x [j0, j0 + nv), with the resolution's bases.
  void polynomial_block(const ControlNet& net, int i0, int j0, int nu, int nv, const GridOut& out);

  const Surface* surface_;  ///< null: the Bézier patches of nets_ alone (not cc)
  Method method_;
  const std::vector<ControlNet>& nets_;
  int resolution_;
  std::vector<detail::CubicBasis> basis_;    ///< at t = k / resolution, k = 0..resolution
  BasisColumns table_;                       ///< basis_ as columns
  std::array<std::vector<Plan>, 16> plans_;  ///< by mask of extraordinary corners
  // Scratch of plan_descent.
  std::vector<std::vector<double>> u_, v_;  ///< [level][k]: parameters in the level's net
  /// [level]: the four children of the last split at that level (allocated per level, so that
  /// adding levels moves none).
  std::vector<std::unique_ptr<detail::LaneNet[]>> children_;
  std::vector<char> done_;  ///< [i][j] of the block: already written (plan_descent)
  int done_stride_ = 0;
  Vec3 origin_ = Vec3::Zero();  ///< the extraordinary root net's first point
  std::array<Patch, 4> patches_;
  int next_ = 0;                                   ///< the slot a new corner takes (round robin)
  std::array<std::array<ControlNet, 4>, 2> deep_;  ///< uncached splits, alternately
  int latest_deep_ = 0;
};

}  // namespace stitch
