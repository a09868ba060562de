#include "stitch/analysis/unfold_tubes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "eval/patch_sampler.hpp"
#include "mesh/sort_unique.hpp"
#include "stitch/kgon/kgon_topology.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch {

namespace {

/// How far a setting is from the fitted placement: scales count by their ratio, so that 0.8 and
/// 1.25 are as far, and 30 degrees of rotation as far as a factor of 1.5.
double distance(const TubeSetting& s) {
  const double step = std::log(1.5);
  return std::abs(std::log(s.face_scale)) / step + std::abs(s.face_rotate_deg) / 30.0 +
         std::abs(std::log(s.face_stretch)) / step + std::abs(std::log(s.bridge_scale)) / step;
}

std::vector<TubeSetting> make_settings() {
  std::vector<TubeSetting> out;
  for (double face_scale : {1.0, 0.8, 1.2, 0.6, 1.5, 0.4})
    for (double rotate : {0.0, -10.0, 10.0, -20.0, 20.0, -30.0, 30.0, -45.0, 45.0, -60.0, 60.0})
      for (double stretch : {1.0, 1.5})
        for (double bridge_scale : {1.0, 0.5, 1.5})
          out.push_back({face_scale, rotate, stretch, bridge_scale});
  // Nearest first; ties keep the order above (smaller changes listed first).
  std::stable_sort(out.begin(), out.end(), [](const TubeSetting& a, const TubeSetting& b) {
    return distance(a) < distance(b);
  });
  return out;
}

/// The two K-gons a setting changes, with the controls the options give them.
struct TubeControls {
  Face face;
  Edge bridge;
  Vec3 along;  ///< the tube's direction, from one rim's centre to the other's
  void set(KgonOptions& options, const TubeSetting& s) const {
    // On top of the global control, which the face K-gon (K > 4) has otherwise and which a
    // per-element control would replace.
    KgonControl c = options.global;
    c.scale *= s.face_scale;
    c.rotate_deg += s.face_rotate_deg;
    if (s.face_stretch != 1) {
      c.stretch = s.face_stretch;
      c.stretch_along = along;
    }
    options.face[face.idx] = c;
    options.edge[bridge.idx] = KgonControl{.scale = s.bridge_scale};
  }
  void clear(KgonOptions& options) const {
    options.face.erase(face.idx);
    options.edge.erase(bridge.idx);
  }
};

/// The centroid of a rim's vertices, each once (the bridge vertex begins and ends the rim's
/// corners).
Vec3 rim_centre(const HalfedgeMesh& mesh, const std::vector<Corner>& rim) {
  std::vector<Vertex> vertices;
  for (Corner c : rim) vertices.push_back(mesh.origin(c));
  detail::sort_unique(vertices);
  Vec3 sum = Vec3::Zero();
  for (Vertex v : vertices) sum += mesh.position(v);
  return sum / static_cast<double>(vertices.size());
}

/// Whether the line between the rims' centres runs along both rims' normals (within 10 degrees):
/// then it is the tube's axis, which a clean tube leaves open. Between faces that face different
/// ways (a bent tunnel) it is not, and the wall of a clean tube may cross it.
bool axis_through_rims(const HalfedgeMesh& mesh, const TwoOpenings& openings, const Vec3& along) {
  const double cos_limit = std::cos(10 * std::numbers::pi / 180);
  for (const auto* rim : {&openings.first, &openings.second}) {
    std::vector<Vec3> loop;
    for (Corner c : *rim) loop.push_back(mesh.position(mesh.origin(c)));
    const Vec3 n = newell_normal(loop);
    if (!(std::abs(n.dot(along)) >= cos_limit * n.norm() * along.norm())) return false;
  }
  return true;
}

/// Whether the segment from a to b misses the patches of `corners`, each sampled on the grid of
/// resolution n. Each cell is cut along both diagonals: a wall that comes this close to the line
/// blocks it in some tessellation of the same samples.
bool axis_open(const std::vector<Corner>& corners, int n, const Vec3& a, const Vec3& b,
               const PatchGridSampler& sample) {
  TriangleSoup soup;
  for (Corner c : corners) {
    const int first = static_cast<int>(soup.positions.size());
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) soup.positions.push_back(sample(c, i, j));
    auto at = [&](int i, int j) { return first + i * (n + 1) + j; };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        soup.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        soup.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        soup.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        soup.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return segment_hits(soup, a, b).empty();
}

}  // namespace

const std::vector<TubeSetting>& tube_settings() {
  static const std::vector<TubeSetting> settings = make_settings();
  return settings;
}

std::string describe(const HalfedgeMesh& mesh, const TubeUnfolding& tube) {
  const Halfedge h = HalfedgeMesh::halfedge(tube.bridge, 0);
  const std::string name =
      fmt::format("the tube of face {} (bridge {} {})", tube.face.idx + 1, mesh.origin(h).idx + 1,
                  mesh.origin(HalfedgeMesh::twin(h)).idx + 1);
  const std::string folds =
      tube.fitted.clean()
          ? fmt::format(
                "the line through the openings' centres meets {} with its fitted "
                "K-gons, which are clean at resolution {}",
                name, tube.resolution)
          : fmt::format(
                "{} folds with its fitted K-gons ({} folded and {} crossing pairs of "
                "triangles at resolution {})",
                name, tube.fitted.folds, tube.fitted.self_intersections, tube.resolution);
  if (!tube.unfolded())
    return fmt::format("{}, and none of the {} other K-gon settings tried is clean", folds,
                       tube.settings_tried - 1);
  const std::string stretch =
      tube.face_control.stretch == 1
          ? ""
          : fmt::format(" stretch {:g} along the tube", tube.face_control.stretch);
  return fmt::format(
      "{}; chosen instead: face K-gon scale {:g} rotate {:g}{}, bridge K-gon scale {:g} (clean{})",
      folds, tube.face_control.scale, tube.face_control.rotate_deg, stretch,
      tube.bridge_control.scale,
      tube.axis_open ? ""
                     : "; the line through the openings' centres meets the tube, as it does "
                       "with the fitted K-gons");
}

std::vector<Face> faces_with_two_openings(const HalfedgeMesh& mesh, const KgonOptions& options) {
  std::vector<Face> all;
  for (Face f : mesh.faces()) all.push_back(f);
  return faces_with_two_openings(mesh, options, all);
}

std::vector<Face> faces_with_two_openings(const HalfedgeMesh& mesh, const KgonOptions& options,
                                          const std::vector<Face>& faces) {
  std::vector<Face> out;
  if (options.construction != KgonConstruction::openings) return out;
  for (Face f : faces)
    if (f.idx < mesh.face_capacity() && !mesh.is_deleted(f) && two_openings(mesh, f, options))
      out.push_back(f);
  detail::sort_unique(out);
  return out;
}

std::vector<TubeUnfolding> unfold_tubes(const HalfedgeMesh& mesh, KgonOptions& options,
                                        BezierSurface& surface, const std::vector<Face>& faces,
                                        const UnfoldTubesOptions& unfold) {
  std::vector<TubeUnfolding> out;
  if (unfold.method == Method::cc) return out;
  for (Face f : faces) {
    if (f.idx >= mesh.face_capacity() || mesh.is_deleted(f)) continue;
    const auto openings = two_openings(mesh, f, options);
    if (!openings) continue;
    const Edge bridge = HalfedgeMesh::edge(openings->first.back());
    // The user's own controls on either K-gon are theirs to keep.
    if (options.face.contains(f.idx) || options.edge.contains(bridge.idx)) continue;
    // The line through the rims' centres, 3 times their distance beyond each (as the tube tests
    // look along it): the wall can bulge across it outside the rims' planes too.
    const Vec3 centre_a = rim_centre(mesh, openings->first),
               centre_b = rim_centre(mesh, openings->second);
    const Vec3 axis_a = centre_a + 3 * (centre_a - centre_b),
               axis_b = centre_b + 3 * (centre_b - centre_a);
    const TubeControls tube{f, bridge, centre_b - centre_a};

    KgonElements reach;
    reach.faces = {f};
    reach.edges = {tube.bridge};
    const std::vector<Corner> changed = nets_reading(mesh, reach);
    auto rebuild = [&] {
      update_kgons(mesh, options, surface.kgons, {f}, {}, {tube.bridge});
      for (Corner c : changed) surface.nets[c.idx] = build_control_net(mesh, surface.kgons, c);
    };
    auto check = [&](const LocalCheckOptions& options) {
      PatchSampler sampler(unfold.method, surface.nets, options.resolution);
      return check_patches(
          mesh, changed,
          [&](Corner c, int i, int j) { return sampler.evaluate_grid(c, i, j).position; }, options);
    };
    auto open = [&] {
      PatchSampler sampler(unfold.method, surface.nets, unfold.check.resolution);
      return axis_open(
          changed, unfold.check.resolution, axis_a, axis_b,
          [&](Corner c, int i, int j) { return sampler.evaluate_grid(c, i, j).position; });
    };
    // The settings tried only need to be told clean or not.
    LocalCheckOptions quick = unfold.check;
    quick.surface.crossings_only_when_unfolded = true;

    TubeUnfolding result;
    result.face = f;
    result.bridge = tube.bridge;
    result.fitted = check(unfold.check);
    result.chosen = result.fitted;
    result.settings_tried = 1;
    result.resolution = unfold.check.resolution;
    // A clean tube is searched too when the line between the rims' centres is its axis and
    // meets its wall: the hole is pushed off its axis (prism 16's half twists, docs/method.md).
    const bool fitted_clean = result.fitted.clean();
    if (fitted_clean && !axis_through_rims(mesh, *openings, centre_b - centre_a)) continue;
    const bool fitted_open = open();
    if (fitted_clean && fitted_open) continue;
    // A clean setting that closes the tube (the line between the rims' centres meets its wall)
    // is kept only when no clean setting leaves it open, and only when the fitted K-gons fold
    // and close it too: a hole pinched shut is not what the user made, a fold at least shows.
    std::optional<TubeSetting> closed;
    LocalCheckReport closed_report;
    std::optional<TubeSetting> chosen;
    // The first setting, nearest of all, is the fitted placement itself: checked above.
    for (const TubeSetting& s : std::span(tube_settings()).subspan(1)) {
      tube.set(options, s);
      rebuild();
      ++result.settings_tried;
      LocalCheckReport report = check(quick);
      if (!report.clean()) continue;
      if (open()) {
        chosen = s;
        result.chosen = std::move(report);
        break;
      }
      if (!closed && !fitted_open && !fitted_clean) {
        closed = s;
        closed_report = std::move(report);
      }
    }
    if (!chosen && closed) {
      chosen = closed;
      result.chosen = std::move(closed_report);
      result.axis_open = false;
    }
    if (chosen) {
      tube.set(options, *chosen);
      result.face_control = options.face[f.idx];
      result.bridge_control = options.edge[tube.bridge.idx];
    } else {
      tube.clear(options);
      result.axis_open = fitted_open;
    }
    rebuild();
    // A clean tube that no setting opens keeps its fitted K-gons, as any clean tube does.
    if (fitted_clean && !chosen) continue;
    out.push_back(std::move(result));
  }
  return out;
}

std::vector<TubeUnfolding> unfold_tubes(const HalfedgeMesh& mesh, KgonOptions& options,
                                        const UnfoldTubesOptions& unfold) {
  const std::vector<Face> faces = faces_with_two_openings(mesh, options);
  if (faces.empty() || unfold.method == Method::cc) return {};
  BezierSurface surface = build_bezier_surface(mesh, options);
  return unfold_tubes(mesh, options, surface, faces, unfold);
}

}  // namespace stitch
