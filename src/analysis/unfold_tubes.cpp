#include "stitch/analysis/unfold_tubes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "analysis/tube_descent.hpp"
#include "eval/patch_sampler.hpp"
#include "kgon/openings.hpp"
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
struct TubeKgons {
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
  void set(KgonOptions& options, const detail::TubeControls& controls) const {
    options.face[face.idx] = controls.face;
    options.edge[bridge.idx] = controls.bridge;
  }
  void clear(KgonOptions& options) const {
    options.face.erase(face.idx);
    options.edge.erase(bridge.idx);
  }
};

/// The centroid of a rim's vertices, each once.
Vec3 rim_centre(const HalfedgeMesh& mesh, const std::vector<Corner>& rim) {
  const std::vector<Vec3> points = detail::rim_points(mesh, rim);
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

/// Whether the line between the rims' centres runs along both rims' normals (within 10 degrees):
/// then it is the tube's axis, which a clean tube leaves open. Between faces that face different
/// ways (a bent tunnel) it is not, and the wall of a clean tube may cross it.
bool axis_through_rims(const HalfedgeMesh& mesh, const TwoOpenings& openings, const Vec3& along) {
  const double cos_limit = std::cos(10 * std::numbers::pi / 180);
  for (const auto* rim : {&openings.first, &openings.second}) {
    const Vec3 n = newell_normal(detail::rim_points(mesh, *rim));
    if (!(std::abs(n.dot(along)) >= cos_limit * n.norm() * along.norm())) return false;
  }
  return true;
}

/// The patches of `corners` sampled on the grid of resolution n.
detail::PatchGrids sample_grids(const std::vector<Corner>& corners, int n, PatchSampler& sampler) {
  detail::PatchGrids grids;
  grids.n = n;
  grids.corners = corners;
  grids.positions.reserve(corners.size() * (n + 1) * (n + 1));
  for (Corner c : corners)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        grids.positions.push_back(sampler.evaluate_grid(c, i, j).position);
  return grids;
}

/// Where the segment from a to b meets the sampled patches. Each cell is cut along both
/// diagonals: a wall that comes this close to the line blocks it in some tessellation of the
/// same samples.
int axis_hits(const detail::PatchGrids& grids, const Vec3& a, const Vec3& b) {
  TriangleSoup soup;
  soup.positions = grids.positions;
  const int n = grids.n;
  for (size_t k = 0; k < grids.corners.size(); ++k) {
    auto at = [&](int i, int j) { return static_cast<int>((k * (n + 1) + i) * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        soup.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        soup.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        soup.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        soup.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return static_cast<int>(segment_hits(soup, a, b).size());
}

/// The mean distance of a rim's corners from its centre.
double rim_radius(const HalfedgeMesh& mesh, const std::vector<Corner>& rim, const Vec3& centre) {
  double sum = 0;
  for (Corner c : rim) sum += (mesh.position(mesh.origin(c)) - centre).norm();
  return sum / static_cast<double>(rim.size());
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
    return fmt::format("{}, and none of the {} other K-gon settings tried is clean{}", folds,
                       tube.settings_tried - 1, tube.fitted.clean() ? " and open" : "");
  // Three digits: the descent's values are continuous, and a note is read, not parsed.
  const KgonControl& face = tube.face_control;
  auto vector = [](const Vec3& v) {
    // Rounding leaves 1e-17 where a coordinate is 0 (the tube along z): shown as 0.
    const Vec3 shown =
        v.unaryExpr([&](double x) { return std::abs(x) < 1e-9 * v.norm() ? 0.0 : x; });
    return fmt::format("({:.3g}, {:.3g}, {:.3g})", shown.x(), shown.y(), shown.z());
  };
  std::string shape;
  if (face.stretch != 1)
    shape += tube.descended
                 ? fmt::format(" stretch {:.3g} along {}", face.stretch, vector(face.stretch_along))
                 : fmt::format(" stretch {:.3g} along the tube", face.stretch);
  if (!face.offset.isZero()) shape += " offset " + vector(face.offset);
  return fmt::format(
      "{}; chosen instead{}: face K-gon scale {:.3g} rotate {:.3g}{}, bridge K-gon scale {:.3g} "
      "(clean{})",
      folds,
      tube.descended ? fmt::format(" by the descent ({} settings tried)", tube.settings_tried) : "",
      face.scale, face.rotate_deg, shape, tube.bridge_control.scale,
      tube.axis_open ? ""
      : tube.descended
          // The descent looks at the line only where it is the tube's axis.
          ? "; the line through the openings' centres, more than 10 degrees off their normals "
            "and so not taken for the tube's axis, meets the tube"
          : "; the line through the openings' centres meets the tube, as it does with the "
            "fitted K-gons");
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
    const TubeKgons tube{f, bridge, centre_b - centre_a};

    KgonElements reach;
    reach.faces = {f};
    reach.edges = {tube.bridge};
    const std::vector<Corner> changed = nets_reading(mesh, reach);
    auto rebuild = [&] {
      update_kgons(mesh, options, surface.kgons, {f}, {}, {tube.bridge});
      for (Corner c : changed) surface.nets[c.idx] = build_control_net(mesh, surface.kgons, c);
    };
    const int n = unfold.check.resolution;
    // The changed patches are sampled once per setting, for the check, the axis and the
    // descent's sharp turns; their neighbours only by the check.
    std::vector<std::size_t> slot(mesh.halfedge_capacity(), changed.size());
    for (std::size_t k = 0; k < changed.size(); ++k) slot[changed[k].idx] = k;
    auto check = [&](const LocalCheckOptions& options, const detail::PatchGrids& grids,
                     PatchSampler& sampler) {
      return check_patches(
          mesh, changed,
          [&](Corner c, int i, int j) {
            const std::size_t k = slot[c.idx];
            return k < changed.size() ? grids.at(k, i, j) : sampler.evaluate_grid(c, i, j).position;
          },
          options);
    };
    // The settings tried only need to be told clean or not.
    LocalCheckOptions quick = unfold.check;
    quick.surface.crossings_only_when_unfolded = true;
    struct Checked {
      LocalCheckReport report;
      detail::PatchGrids grids;
    };
    auto check_setting = [&](const LocalCheckOptions& options) {
      PatchSampler sampler(unfold.method, surface.nets, n);
      Checked out{{}, sample_grids(changed, n, sampler)};
      out.report = check(options, out.grids, sampler);
      return out;
    };
    auto open = [&](const detail::PatchGrids& grids) {
      return axis_hits(grids, axis_a, axis_b) == 0;
    };

    TubeUnfolding result;
    result.face = f;
    result.bridge = tube.bridge;
    Checked fitted = check_setting(unfold.check);
    result.fitted = fitted.report;
    result.chosen = result.fitted;
    result.settings_tried = 1;
    result.resolution = n;
    // A clean tube is searched too when the line between the rims' centres is its axis and
    // meets its wall: the hole is pushed off its axis (prism 16's half twists, docs/method.md).
    const bool fitted_clean = result.fitted.clean();
    const bool axis_counts = axis_through_rims(mesh, *openings, centre_b - centre_a);
    if (fitted_clean && !axis_counts) continue;
    const bool fitted_open = open(fitted.grids);
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
      Checked setting = check_setting(quick);
      if (!setting.report.clean()) continue;
      if (open(setting.grids)) {
        chosen = s;
        result.chosen = std::move(setting.report);
        break;
      }
      if (!closed && !fitted_open && !fitted_clean) {
        closed = s;
        closed_report = std::move(setting.report);
      }
    }
    // Then downhill from the fitted placement over the same controls taken as continuous, with
    // the stretch's direction and the face K-gon's offset besides (tube_descent.hpp); the axis
    // counts where it is the tube's.
    std::optional<detail::TubeControls> descended;
    if (!chosen && unfold.descent_evaluations > 0) {
      tube.clear(options);
      rebuild();
      detail::TubeFrame frame;
      frame.length = (centre_b - centre_a).norm();
      frame.along = (centre_b - centre_a) / frame.length;
      frame.face_normal = surface.kgons.face[f.idx].normal;
      frame.across = frame.face_normal.cross(frame.along);
      // A K-gon facing along the tube (not met on the tubes measured) has no direction across
      // it that the cross product gives.
      frame.across = frame.across.norm() > 1e-6 ? Vec3(frame.across.normalized())
                                                : Vec3(frame.along.unitOrthogonal());
      frame.radius = rim_radius(mesh, openings->first, centre_a);
      int evaluations = 0;
      // The descent stops right after scoring the setting it returns: this is that one's check.
      Checked last;
      descended = detail::tube_descent(
          frame, options.global,
          [&](const detail::TubeControls& controls) {
            tube.set(options, controls);
            rebuild();
            last = check_setting(unfold.check);
            return detail::TubeScore{last.report, detail::sharp_turns(last.grids),
                                     axis_counts ? axis_hits(last.grids, axis_a, axis_b) : 0};
          },
          unfold.descent_evaluations, evaluations);
      result.settings_tried += evaluations;
      if (descended) {
        result.chosen = std::move(last.report);
        result.axis_open = open(last.grids);
        result.descended = true;
      }
    }
    if (descended) {
      tube.set(options, *descended);
      rebuild();
    } else if (chosen) {
      tube.set(options, *chosen);
      rebuild();
    } else if (closed) {
      tube.set(options, *closed);
      rebuild();
      result.chosen = std::move(closed_report);
      result.axis_open = false;
    } else {
      tube.clear(options);
      rebuild();
      result.axis_open = fitted_open;
    }
    if (descended || chosen || closed) {
      result.face_control = options.face[f.idx];
      result.bridge_control = options.edge[tube.bridge.idx];
    }
    // A clean tube that no setting opens keeps its fitted K-gons, as any clean tube does.
    if (fitted_clean && !chosen && !descended) continue;
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
