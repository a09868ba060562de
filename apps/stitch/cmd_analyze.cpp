// stitch analyze IN: the continuity of each method's surface, as numbers.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/analysis/continuity.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::cli {

namespace {

struct AnalyzeArgs {
  InputOptions in;
  std::string method = "all";
  bool json = false;
  ProgressFlags progress;
  int samples = 8;
  KgonCliOptions kgon;
};

nlohmann::json to_json(const ContinuityReport& r) {
  auto stats = [](const JumpStats& s) {
    return nlohmann::json{{"max_deg", s.max_deg}, {"mean_deg", s.mean_deg}, {"samples", s.samples}};
  };
  nlohmann::json j{{"method", to_string(r.method)},
                   {"touching_extraordinary", stats(r.touching_ev)},
                   {"away_from_extraordinary", stats(r.away_from_ev)},
                   {"max_position_gap_relative", r.max_gap},
                   {"extraordinary_points", r.extraordinary_points},
                   {"g1_normal_spread_at_extraordinary_points_deg", r.ev_normal_spread_deg}};
  for (const auto& [d, jump] : r.jump_by_distance)
    j["max_jump_by_distance"].push_back({{"distance", d}, {"max_deg", jump}});
  if (r.has_sharp_features) {
    const FeatureReport& f = r.features;
    j["sharp_features"] = {{"boundary_sides", f.boundary_sides},
                           {"crease_sides", f.crease_sides},
                           {"crease_max_position_gap_relative", f.crease_gap},
                           {"sector_vertices", f.sector_vertices},
                           {"sectors_compared", f.sectors_compared},
                           {"cone_points", f.cone_points},
                           {"g1_normal_spread_in_sectors_deg", f.sector_normal_spread_deg}};
  }
  return j;
}

void run_analyze(const AnalyzeArgs& a) {
  StageReporter stage(a.progress);
  const HalfedgeMesh mesh = load_input(a.in);
  std::vector<Method> methods;
  if (a.method == "all")
    methods = {Method::asc, Method::mdc, Method::cc};
  else
    methods = {parse_method(a.method)};

  ContinuityOptions opt;
  opt.samples_per_side = a.samples;
  nlohmann::json out;
  out["file"] = a.in.path;
  if (!a.json)
    fmt::print(
        "{}: normal jump across patch boundaries, degrees (samples away from patch corners)\n"
        "{:<6} {:>24} {:>24} {:>13} {:>18}\n",
        a.in.path, "method", "touching EV: max / mean", "elsewhere: max / mean", "gap (rel.)",
        "G1 at EVs: spread");
  for (Method m : methods) {
    stage.begin("analyzing " + to_string(m));
    std::optional<BuiltSurface> built;
    try {
      built.emplace(build_cli_surface(a.kgon, mesh, m, a.in.path, a.progress.quiet));
    } catch (const Error& e) {
      // With --method all, a method that cannot take this mesh is reported, not fatal.
      if (methods.size() == 1) throw;
      stage.end();
      if (a.json)
        out["methods"].push_back({{"method", to_string(m)}, {"refused", e.what()}});
      else
        fmt::print("{:<6} refused: {}\n", to_string(m), e.what());
      continue;
    }
    // Refined for semi-sharp tags, the surface is measured on the mesh its patches come from.
    const ContinuityReport r = analyze_continuity(built->mesh(mesh), built->surface, opt);
    stage.end();
    if (a.json) {
      out["methods"].push_back(to_json(r));
      continue;
    }
    fmt::print("{:<6} {:>11.3e} / {:<10.3e} {:>11.3e} / {:<10.3e} {:>13.3e} {:>18.3e}\n",
               to_string(m), r.touching_ev.max_deg, r.touching_ev.mean_deg, r.away_from_ev.max_deg,
               r.away_from_ev.mean_deg, r.max_gap, r.ev_normal_spread_deg);
    if (r.has_sharp_features) {
      // The sides above are the smooth ones; across these the surface is C0 by design.
      const FeatureReport& f = r.features;
      fmt::print(
          "{:<6} sharp: {} boundary, {} crease sides; crease gap (rel.) {:.3e}; G1 in {} "
          "sectors of 2+ patches at {} vertices: spread {:.3e}; {} cone points\n",
          "", f.boundary_sides, f.crease_sides, f.crease_gap, f.sectors_compared, f.sector_vertices,
          f.sector_normal_spread_deg, f.cone_points);
    }
  }
  if (a.json) fmt::print("{}\n", out.dump(2));
}

}  // namespace

void add_analyze_command(CLI::App& app) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Measure continuity: the largest and mean normal jump across patch boundaries, near "
      "extraordinary points and elsewhere, and the tangent plane at extraordinary points; on "
      "meshes with boundaries or creases also the crease gap and G1 within each sector. Memory: "
      "the mesh and one method's surface at a time, its patches measured a chunk at a time");
  add_input_options(cmd, args->in);
  add_method_option(cmd, args->method, true, &args->in);
  cmd->add_flag("--json", args->json,
                "print JSON (includes the jump against distance from "
                "extraordinary points)");
  cmd->add_option("--samples", args->samples, "evenly spaced samples per patch side")
      ->check(CLI::Range(1, limits::max_resolution))
      ->capture_default_str();
  add_kgon_options(cmd, args->kgon, &args->in);
  add_progress_option(cmd, args->progress);
  cmd->callback([args] { run_analyze(*args); });
}

}  // namespace stitch::cli
