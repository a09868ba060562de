// Mesh -> tessellated smooth surface: the paper's modified de Casteljau (mdc) against the
// Catmull-Clark limit surface through OpenSubdiv (cc), on generated meshes of about 1k, 10k and
// 100k faces.
//
// What is counted (the same for both methods): one sample = one evaluated point (position,
// derivatives, unit normal) of the (8+1)^2 grid of every corner patch, i.e. 81 samples per
// corner of the input mesh. The benchmark "compare" times, in each iteration:
//   mdc      stitch::Surface(mesh, mdc) + stitch::tessellate(resolution 8, welded)
//   cc       stitch::Surface(mesh, cc)  + stitch::tessellate(resolution 8, welded)
//            (Surface also builds the Bézier patches for cc, for overlays; that time is in here)
//   mdc_eval building the Bézier patches + evaluating every corner grid (the same parallel loop
//            as tessellate's sampling, keeping a checksum instead of storing the samples)
//   cc_eval  building the OpenSubdiv Bfr surfaces + evaluating every corner grid (same loop)
//   mdc_build, cc_build: the building part of mdc_eval and cc_eval
// and reports the wall-clock times, samples/s and the ratios cc/mdc and cc_eval/mdc_eval as
// counters, and the same ratios in process CPU time (cc/mdc_cpu, cc_eval/mdc_eval_cpu), which
// other processes on a shared machine disturb less.
// "osd_native" is OpenSubdiv's own route for reference: Far::TopologyDescriptor ->
// Bfr::RefinerSurfaceFactory -> Bfr::Tessellation with a uniform rate of 16 per face edge
// (17^2 = 289 points per quad face against the 4 * 81 = 324 of the corner grids); it reports its
// own sample count.
#include <benchmark/benchmark.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/surfaceFactoryCache.h>
#include <opensubdiv/bfr/tessellation.h>
#include <sys/resource.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <chrono>
#include <ctime>
#include <map>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <utility>
#include <vector>

#include "bench_meshes.hpp"
#include "eval/patch_sampler.hpp"
#include "mesh/opensubdiv_topology.hpp"
#include "stitch/eval/catmull_clark.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/primitives.hpp"
#include "support/fresh_storage.hpp"

namespace {

using stitch::Corner;
using stitch::HalfedgeMesh;
using namespace stitch::bench;

constexpr int kResolution = 8;
constexpr int kSamplesPerPatch = (kResolution + 1) * (kResolution + 1);

// Evaluates every corner grid the way tessellate() samples (in parallel over corners), keeping
// only a checksum: this measures evaluation without the memory traffic of storing 81 samples
// per corner (gigabytes at 100k faces).
template <class Evaluate>
double sample_corner_grids(const std::vector<Corner>& corners, const Evaluate& evaluate) {
  std::vector<double> checksum(corners.size(), 0.0);
  tbb::parallel_for(size_t{0}, corners.size(), [&](size_t k) {
    double sum = 0.0;
    for (int i = 0; i <= kResolution; ++i) {
      for (int j = 0; j <= kResolution; ++j) {
        const stitch::SurfacePoint s = evaluate(corners[k], static_cast<double>(i) / kResolution,
                                                static_cast<double>(j) / kResolution);
        sum += s.position.sum() + s.normal.sum();
      }
    }
    checksum[k] = sum;
  });
  double total = 0.0;
  for (double x : checksum) total += x;
  return total;
}

// Page faults of the process so far (all threads): first touches of fresh memory, which cost
// this project's VM about 20 microseconds of CPU each (support/fresh_storage.hpp).
long page_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Wall-clock time, process CPU time and page faults (all threads) of one stage. The machine is
// shared: CPU time is less sensitive than wall time to other processes taking the cores.
struct Stopwatch {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  std::clock_t cpu = std::clock();
  long faults = page_faults();
};

struct StageTime {
  double wall = 0.0, cpu = 0.0;
  long faults = 0;
  void add_since(const Stopwatch& start) {
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start.wall).count();
    cpu += static_cast<double>(std::clock() - start.cpu) / CLOCKS_PER_SEC;
    faults += page_faults() - start.faults;
  }
};

void BM_compare(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const HalfedgeMesh& mesh = bench_mesh(kind, static_cast<int>(state.range(1)));
  const std::vector<Corner> corners = mesh.halfedges().to_vector();
  const stitch::TessellationOptions options{kResolution, true};
  StageTime mdc, cc, mdc_eval, cc_eval, mdc_build, cc_build;
  for (auto _ : state) {
    const double before = mdc.wall + cc.wall + mdc_eval.wall + cc_eval.wall;
    Stopwatch start;
    {
      const stitch::Surface surface(mesh, stitch::Method::mdc);
      benchmark::DoNotOptimize(stitch::tessellate(mesh, surface, options));
    }
    mdc.add_since(start);

    start = Stopwatch();
    {
      const stitch::Surface surface(mesh, stitch::Method::cc);
      benchmark::DoNotOptimize(stitch::tessellate(mesh, surface, options));
    }
    cc.add_since(start);

    start = Stopwatch();
    {
      const stitch::BezierSurface bezier = stitch::build_bezier_surface(mesh);
      mdc_build.add_since(start);
      benchmark::DoNotOptimize(sample_corner_grids(corners, [&](Corner c, double u, double v) {
        return bezier.evaluate(c, u, v, stitch::BezierRule::mdc);
      }));
    }
    mdc_eval.add_since(start);

    start = Stopwatch();
    {
      const stitch::CatmullClarkSurface surface(mesh);
      cc_build.add_since(start);
      benchmark::DoNotOptimize(sample_corner_grids(
          corners, [&](Corner c, double u, double v) { return surface.evaluate(c, u, v); }));
    }
    cc_eval.add_since(start);
    state.SetIterationTime(mdc.wall + cc.wall + mdc_eval.wall + cc_eval.wall - before);
  }
  const double n = static_cast<double>(state.iterations());
  const double samples = static_cast<double>(corners.size()) * kSamplesPerPatch;
  state.SetLabel(mesh_label(kind, mesh));
  state.counters["samples"] = samples;
  // Wall-clock seconds per iteration of each stage; *_build is the part of *_eval building the
  // patches (mdc) or the Bfr surfaces (cc).
  state.counters["mdc_s"] = mdc.wall / n;
  state.counters["cc_s"] = cc.wall / n;
  state.counters["mdc_eval_s"] = mdc_eval.wall / n;
  state.counters["cc_eval_s"] = cc_eval.wall / n;
  state.counters["mdc_build_s"] = mdc_build.wall / n;
  state.counters["cc_build_s"] = cc_build.wall / n;
  state.counters["mdc_samples/s"] = samples * n / mdc.wall;
  state.counters["cc_samples/s"] = samples * n / cc.wall;
  state.counters["mdc_eval_samples/s"] = samples * n / mdc_eval.wall;
  state.counters["cc_eval_samples/s"] = samples * n / cc_eval.wall;
  state.counters["cc/mdc"] = cc.wall / mdc.wall;
  state.counters["cc_eval/mdc_eval"] = cc_eval.wall / mdc_eval.wall;
  // The same ratios in process CPU time (all threads).
  state.counters["cc/mdc_cpu"] = cc.cpu / mdc.cpu;
  state.counters["cc_eval/mdc_eval_cpu"] = cc_eval.cpu / mdc_eval.cpu;
}

namespace Osd = OpenSubdiv;
using ThreadSafeCache =
    Osd::Bfr::SurfaceFactoryCacheThreaded<std::shared_mutex, std::shared_lock<std::shared_mutex>,
                                          std::unique_lock<std::shared_mutex>>;

// What a user of Bfr keeps of the tessellation it computes: every face's points (Bfr tessellates
// face by face, so points on shared edges are repeated), position and unit normal, and the
// face's quads as indices into them (a triangle's facets are quads with -1 as fourth index).
struct BfrTessellation {
  std::vector<double> positions, normals;  // 3 per point
  std::vector<int> facets;                 // 4 per facet
};

// OpenSubdiv's own mesh -> tessellation route: positions and unit normals of every point, into
// `out` when it is given (sized like stitch's own arrays: reused when large enough, else fresh
// storage advised into huge pages), else summed into `checksum` like the *_eval variants.
// Returns the number of points.
size_t osd_native_tessellation(const HalfedgeMesh& mesh, double& checksum,
                               BfrTessellation* out = nullptr) {
  const stitch::PolygonSoup soup = stitch::to_polygon_soup(mesh);
  const auto refiner = stitch::catmark_refiner(mesh);
  const Osd::Bfr::RefinerSurfaceFactory<ThreadSafeCache> factory(*refiner);
  std::vector<double> points(3 * soup.positions.size());
  for (size_t i = 0; i < soup.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) points[3 * i + k] = soup.positions[i][k];
  }
  const int num_faces = refiner->GetLevel(0).GetNumFaces();
  constexpr int kRate = 2 * kResolution;
  Osd::Bfr::Tessellation::Options tess_options;
  tess_options.SetFacetSize(4).PreserveQuads(true);
  std::vector<size_t> offset(static_cast<size_t>(num_faces) + 1, 0);
  std::vector<size_t> facet_offset(static_cast<size_t>(num_faces) + 1, 0);
  for (int f = 0; f < num_faces; ++f) {
    const Osd::Bfr::Tessellation tess(
        Osd::Bfr::Parameterization(Osd::Sdc::SCHEME_CATMARK,
                                   refiner->GetLevel(0).GetFaceVertices(f).size()),
        kRate, tess_options);
    offset[f + 1] = offset[f] + static_cast<size_t>(tess.GetNumCoords());
    facet_offset[f + 1] = facet_offset[f] + static_cast<size_t>(tess.GetNumFacets());
  }
  if (out != nullptr) {
    stitch::detail::size_for_overwrite(out->positions, 3 * offset.back());
    stitch::detail::size_for_overwrite(out->normals, 3 * offset.back());
    stitch::detail::size_for_overwrite(out->facets, 4 * facet_offset.back());
  }
  std::vector<double> face_sum(static_cast<size_t>(num_faces), 0.0);
  tbb::parallel_for(0, num_faces, [&](int f) {
    Osd::Bfr::Surface<double> surface;
    factory.InitVertexSurface(f, &surface);
    std::vector<double> patch(3 * static_cast<size_t>(surface.GetNumPatchPoints()));
    const Osd::Bfr::Surface<double>::PointDescriptor xyz(3);
    surface.PreparePatchPoints(points.data(), xyz, patch.data(), xyz);
    const Osd::Bfr::Tessellation tess(surface.GetParameterization(), kRate, tess_options);
    std::vector<double> uv(2 * static_cast<size_t>(tess.GetNumCoords()));
    tess.GetCoords(uv.data());
    double sum = 0.0;
    for (int i = 0; i < tess.GetNumCoords(); ++i) {
      double p[3], du[3], dv[3];
      surface.Evaluate(&uv[2 * i], patch.data(), xyz, p, du, dv);
      const Eigen::Vector3d nrm = Eigen::Vector3d(du[0], du[1], du[2])
                                      .cross(Eigen::Vector3d(dv[0], dv[1], dv[2]))
                                      .normalized();
      if (out != nullptr) {
        const size_t at = 3 * (offset[f] + static_cast<size_t>(i));
        for (int k = 0; k < 3; ++k) {
          out->positions[at + k] = p[k];
          out->normals[at + k] = nrm[k];
        }
      } else {
        sum += p[0] + p[1] + p[2] + nrm.sum();
      }
    }
    if (out != nullptr) {
      int* facets = &out->facets[4 * facet_offset[f]];
      tess.GetFacets(facets);
      const int first = static_cast<int>(offset[f]);
      for (size_t k = 0; k < 4 * static_cast<size_t>(tess.GetNumFacets()); ++k)
        if (facets[k] >= 0) facets[k] += first;
    }
    face_sum[f] = sum;
  });
  checksum = 0.0;
  for (double x : face_sum) checksum += x;
  return offset.back();
}

void BM_osd_native(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const HalfedgeMesh& mesh = bench_mesh(kind, static_cast<int>(state.range(1)));
  double checksum = 0.0;
  size_t samples = 0;
  StageTime total;
  for (auto _ : state) {
    const Stopwatch start;
    samples = osd_native_tessellation(mesh, checksum);
    benchmark::DoNotOptimize(checksum);
    total.add_since(start);
  }
  state.SetLabel(mesh_label(kind, mesh));
  state.counters["samples"] = static_cast<double>(samples);
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(samples),
                                                   benchmark::Counter::kIsIterationInvariantRate);
  state.counters["cpu_s"] = total.cpu / static_cast<double>(state.iterations());  // all threads
}

// How each side keeps its tessellation in memory (stitch: the welded mesh; Bfr: every face's
// points, position and normal, and quads):
//   output 0: new arrays per call; stitch's with the per-sample attributes (tessellate()'s
//             default), which Bfr's side does not compute;
//   output 1: new arrays per call, positions and normals only (the same work on both sides);
//   output 2: the surface rebuilt into the previous run's storage (Surface::rebuild) and its
//             positions and normals into the previous run's arrays (tessellating again, as an
//             animation does: no fresh memory to fault in).
// Until 2026-12-02's fourth session the Bfr side kept nothing (a checksum, as BM_osd_native
// still does), so that outputs 0 and 1 compared stitch's fresh memory with none. Until its fifth,
// output 2 built a new Surface each run, whose 160 MB of control nets at 100k faces were fresh.
const char* const kOutputs[] = {"new, attributes", "new, positions+normals",
                                "reused, positions+normals"};

/// What output 2 keeps from one run of the pipeline to the next.
struct Kept {
  std::optional<stitch::Surface> surface;
  stitch::TessellatedMesh tessellation;
};

/// One run of the full pipeline: the mdc surface and its welded tessellation at kResolution,
/// into `kept` for output 2, else into a new surface and result.
void run_pipeline(const HalfedgeMesh& mesh, int output, Kept& kept) {
  const bool attributes = output == 0;
  const stitch::TessellationOptions options{
      .resolution = kResolution, .uv = attributes, .patch = attributes, .level = attributes};
  if (output == 2) {
    if (kept.surface)
      kept.surface->rebuild(mesh);
    else
      kept.surface.emplace(mesh, stitch::Method::mdc);
    stitch::tessellate(mesh, *kept.surface, options, kept.tessellation);
    benchmark::DoNotOptimize(kept.tessellation.positions.data());
  } else {
    const stitch::Surface surface(mesh, stitch::Method::mdc);
    benchmark::DoNotOptimize(stitch::tessellate(mesh, surface, options));
  }
}

// Issue 14's comparison: the full pipeline mesh -> welded tessellation in memory (run_pipeline)
// against OpenSubdiv's own route at rate 16 per face edge into memory (osd_native_tessellation
// into a BfrTessellation, new or reused as stitch's output is), both on
// both cores, timed one after the other in each iteration so that the ratio comes from one run.
// Rates are samples (stitch: 81 per corner, shared ones counted per patch) and points (Bfr: per
// face, shared ones counted per face) per second.
void BM_vs_bfr(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const HalfedgeMesh& mesh = bench_mesh(kind, static_cast<int>(state.range(1)));
  const auto output = static_cast<int>(state.range(2));
  Kept kept;
  BfrTessellation bfr_kept;
  double checksum = 0.0;
  // Untimed first runs: for output 2 they fill the arrays the timed runs reuse; for all outputs
  // they grow the process's heap for its small allocations and fault in its first memory, so
  // that one-iteration runs do not time the process's start. Output 2 runs twice on both sides:
  // glibc's malloc raises its mmap and trim thresholds only when the first large blocks are
  // freed, so the first rerun still gives memory back and faults it in again.
  run_pipeline(mesh, output, kept);
  if (output == 2) {
    run_pipeline(mesh, output, kept);
    for (int i = 0; i < 2; ++i) osd_native_tessellation(mesh, checksum, &bfr_kept);
  } else {
    BfrTessellation first;
    osd_native_tessellation(mesh, checksum, &first);
  }
  StageTime stitch_time, bfr_time;
  size_t bfr_points = 0;
  for (auto _ : state) {
    const double before = stitch_time.wall + bfr_time.wall;
    Stopwatch start;
    run_pipeline(mesh, output, kept);
    stitch_time.add_since(start);
    start = Stopwatch();
    if (output == 2) {
      bfr_points = osd_native_tessellation(mesh, checksum, &bfr_kept);
      benchmark::DoNotOptimize(bfr_kept.positions.data());
    } else {
      BfrTessellation fresh;
      bfr_points = osd_native_tessellation(mesh, checksum, &fresh);
      benchmark::DoNotOptimize(fresh.positions.data());
    }
    bfr_time.add_since(start);
    state.SetIterationTime(stitch_time.wall + bfr_time.wall - before);
  }
  const double n = static_cast<double>(state.iterations());
  const double samples = static_cast<double>(mesh.num_halfedges()) * kSamplesPerPatch;
  const double stitch_rate = samples * n / stitch_time.wall;
  const double bfr_rate = static_cast<double>(bfr_points) * n / bfr_time.wall;
  state.SetLabel(mesh_label(kind, mesh) + ", " + kOutputs[output]);
  state.counters["stitch_samples/s"] = stitch_rate;
  state.counters["bfr_points/s"] = bfr_rate;
  state.counters["stitch/bfr"] = stitch_rate / bfr_rate;
  state.counters["stitch/bfr_cpu"] =
      (samples / stitch_time.cpu) / (static_cast<double>(bfr_points) / bfr_time.cpu);
  state.counters["stitch_faults"] = static_cast<double>(stitch_time.faults) / n;
  state.counters["bfr_faults"] = static_cast<double>(bfr_time.faults) / n;
}

// Issue 40's cold path: one side of BM_vs_bfr's output 1 (new arrays, positions and normals),
// run once with nothing before it, so that a process running this one case alone times what a
// user's program pays on its first call, fresh memory and heap growth included.
// bench/cold_path.py runs each side in its own process, interleaved, and takes the best of three.
void BM_cold_path(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const HalfedgeMesh& mesh = bench_mesh(kind, static_cast<int>(state.range(1)));
  const bool bfr = state.range(2) == 1;
  Kept unused;
  double checksum = 0.0;
  StageTime time;
  size_t points = 0;
  for (auto _ : state) {
    const Stopwatch start;
    if (bfr) {
      BfrTessellation fresh;
      points = osd_native_tessellation(mesh, checksum, &fresh);
      benchmark::DoNotOptimize(fresh.positions.data());
    } else {
      run_pipeline(mesh, 1, unused);
      points = static_cast<size_t>(mesh.num_halfedges()) * kSamplesPerPatch;
    }
    time.add_since(start);
  }
  state.SetLabel(mesh_label(kind, mesh) + (bfr ? ", Bfr" : ", stitch"));
  state.counters["wall_s"] = time.wall;
  state.counters["cpu_s"] = time.cpu;
  state.counters["faults"] = static_cast<double>(time.faults);
  state.counters["points"] = static_cast<double>(points);
}

// The full pipeline alone (run_pipeline, output 0 or 2), on both cores: the stitch half of
// BM_vs_bfr, small enough at 10k faces to count instructions with valgrind --tool=callgrind.
void BM_tessellate(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const HalfedgeMesh& mesh = bench_mesh(kind, static_cast<int>(state.range(1)));
  const auto output = static_cast<int>(state.range(2));
  Kept kept;
  if (output == 2) run_pipeline(mesh, output, kept);
  for (auto _ : state) run_pipeline(mesh, output, kept);
  state.SetLabel(mesh_label(kind, mesh) + ", " + kOutputs[output]);
  state.counters["samples/s"] =
      benchmark::Counter(static_cast<double>(mesh.num_halfedges()) * kSamplesPerPatch,
                         benchmark::Counter::kIsIterationInvariantRate);
}

// Issue 14 item 2: the cost of one sample of a patch at an extraordinary point against one of a
// regular patch, on one thread, every corner grid of the mesh at resolution 8 sampled a grid at a
// time as a tessellation samples it (PatchSampler::evaluate_block; before it existed, this
// benchmark called evaluate_grid sample by sample). "ev/regular" is the ratio of the costs per
// sample.
void BM_patch_cost(benchmark::State& state) {
  const auto kind = static_cast<MeshKind>(state.range(0));
  const HalfedgeMesh& mesh = bench_mesh(kind, static_cast<int>(state.range(1)));
  const stitch::Surface surface(mesh, stitch::Method::mdc);
  std::vector<Corner> regular, extraordinary;
  for (const Corner c : surface.corners())
    (surface.bezier().nets[c.idx].regular() ? regular : extraordinary).push_back(c);
  auto sample = [&](const std::vector<Corner>& corners) {
    stitch::PatchSampler sampler(surface, kResolution);
    std::vector<stitch::Vec3> positions(kSamplesPerPatch), normals(kSamplesPerPatch);
    double sum = 0.0;
    for (const Corner c : corners) {
      sampler.evaluate_block(c, 0, kResolution, 0, kResolution,
                             {positions.data(), normals.data(), nullptr, kResolution + 1});
      sum += positions[kSamplesPerPatch / 2].x() + normals[kSamplesPerPatch / 2].x();
    }
    return sum;
  };
  StageTime regular_time, extraordinary_time;
  for (auto _ : state) {
    Stopwatch start;
    benchmark::DoNotOptimize(sample(regular));
    regular_time.add_since(start);
    start = Stopwatch();
    benchmark::DoNotOptimize(sample(extraordinary));
    extraordinary_time.add_since(start);
  }
  const double n = static_cast<double>(state.iterations());
  const auto per_sample = [&](const StageTime& t, size_t corners) {
    return corners == 0 ? 0.0 : t.cpu / n / static_cast<double>(corners * kSamplesPerPatch) * 1e9;
  };
  const double regular_ns = per_sample(regular_time, regular.size());
  const double extraordinary_ns = per_sample(extraordinary_time, extraordinary.size());
  state.SetLabel(mesh_label(kind, mesh));
  state.counters["regular_patches"] = static_cast<double>(regular.size());
  state.counters["ev_patches"] = static_cast<double>(extraordinary.size());
  state.counters["regular_ns/sample"] = regular_ns;
  state.counters["ev_ns/sample"] = extraordinary_ns;
  if (regular_ns > 0) state.counters["ev/regular"] = extraordinary_ns / regular_ns;
}

void mesh_sizes(benchmark::internal::Benchmark* b) {
  for (int kind : {quad_torus, mixed_torus}) {
    for (int faces : {1000, 10000, 100000}) b->Args({kind, faces});
  }
  b->ArgNames({"mesh", "faces"});
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

// The 100k meshes take seconds per iteration: a few iterations are enough for stable figures.
BENCHMARK(BM_compare)->Apply(mesh_sizes)->UseManualTime()->MinTime(2.0);
BENCHMARK(BM_osd_native)->Apply(mesh_sizes)->MinTime(1.0)->UseRealTime();
BENCHMARK(BM_vs_bfr)
    ->ArgsProduct({{quad_torus, mixed_torus, triangle_torus}, {10000, 100000}, {0, 1, 2}})
    ->ArgNames({"mesh", "faces", "output"})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(2.0);
BENCHMARK(BM_cold_path)
    ->ArgsProduct({{quad_torus, mixed_torus, triangle_torus}, {10000, 100000}, {0, 1}})
    ->ArgNames({"mesh", "faces", "bfr"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_tessellate)
    ->ArgsProduct({{quad_torus, mixed_torus, triangle_torus}, {10000, 100000}, {0, 2}})
    ->ArgNames({"mesh", "faces", "output"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_patch_cost)
    ->ArgsProduct({{mixed_torus, triangle_torus}, {10000}})
    ->ArgNames({"mesh", "faces"})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

BENCHMARK_MAIN();
