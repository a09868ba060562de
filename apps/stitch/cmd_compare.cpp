// stitch compare IN -o DIR: AS&C, the modified de Casteljau and Catmull-Clark side by side in
// zebra stripes, the normal jump against distance from extraordinary points (gnuplot), and an
// index.html with the continuity numbers of `stitch analyze`.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/analysis/continuity.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"
#include "stitch/render/options.hpp"
#include "stitch/render/scene.hpp"

extern char** environ;

namespace stitch::cli {

namespace {

namespace fs = std::filesystem;

struct CompareArgs {
  InputOptions in;
  std::string out;
  std::string size = "480x480";
  std::string view = "iso";
  std::string up{up_axis_table().front().name};
  int resolution = 16;
  int stripes = 32;
  double zoom = 0.6;
  ProgressFlags progress;
  KgonCliOptions kgon;
};

constexpr std::array<Method, 3> kMethods{Method::asc, Method::mdc, Method::cc};

std::string method_title(Method m) {
  switch (m) {
    case Method::asc:
      return "AS&amp;C (patches as plain polynomials)";
    case Method::mdc:
      return "modified de Casteljau (ours)";
    case Method::cc:
      return "Catmull-Clark (OpenSubdiv)";
  }
  return "";
}

/// Runs a program with arguments (no shell); returns its exit status, 127 when it cannot start.
int run_program(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return 127;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

/// The plot of the largest jump against distance, by gnuplot. Returns "" on success, else
/// why there is no plot.
std::string plot_jumps(const fs::path& dir, const std::vector<ContinuityReport>& all_reports) {
  // Only methods with samples near an extraordinary point have a curve (gnuplot refuses
  // empty data blocks).
  std::vector<ContinuityReport> reports;
  for (const ContinuityReport& r : all_reports) {
    if (!r.jump_by_distance.empty()) reports.push_back(r);
  }
  if (reports.empty()) {
    return "the mesh has no extraordinary point, so there is no jump against distance from "
           "one to plot";
  }
  const fs::path data = dir / "jump_by_distance.dat";
  const fs::path script = dir / "jump_by_distance.gp";
  const fs::path png = dir / ("jump_by_distance" + std::string(kImageExtension));
  // A log axis cannot show 0: jumps below 1e-12 degrees (round-off of exact agreement) are
  // drawn at 1e-12.
  write_file_atomically(data.string(), [&](std::ostream& out) {
    out << "# largest normal jump (degrees) across patch boundaries touching an extraordinary\n"
           "# point, against the parametric distance t from that point along the boundary\n";
    for (const ContinuityReport& r : reports) {
      out << "# method " << to_string(r.method) << "\n";
      for (const auto& [t, jump] : r.jump_by_distance) {
        out << fmt::format("{:.9g} {:.9g}\n", t, std::max(jump, 1e-12));
      }
      out << "\n\n";
    }
  });
  const fs::path temporary = dir / (".jump_by_distance" + std::string(kImageExtension) + ".tmp");
  write_file_atomically(script.string(), [&](std::ostream& out) {
    out << "set terminal pngcairo size 720,480 font 'sans,10'\n"
        << "set output '" << temporary.filename().string() << "'\n"
        << "set logscale xy\nset format y '10^{%L}'\nset yrange [1e-13:*]\nset grid\nset key "
           "bottom right\n"
        << "set xlabel 'distance from the extraordinary point along the boundary (parameter t)'\n"
        << "set ylabel 'largest normal jump (degrees)'\n"
        << "set title 'Normal jump across patch boundaries near extraordinary points'\n"
        << "plot ";
    for (size_t i = 0; i < reports.size(); ++i) {
      out << (i ? ", " : "") << "'" << data.filename().string() << "' index " << i
          << " using 1:2 with linespoints title '" << to_string(reports[i].method) << "'";
    }
    out << "\n";
  });
  // gnuplot runs in DIR so that the script names files relative to it.
  const fs::path previous = fs::current_path();
  fs::current_path(dir);
  const int status = run_program({"gnuplot", script.filename().string()});
  fs::current_path(previous);
  if (status == 127) {
    fs::remove(dir / temporary.filename());
    return "gnuplot was not found (Debian: apt-get install gnuplot-nox); the data and script "
           "are in " +
           data.string() + " and " + script.string();
  }
  if (status != 0 || !fs::exists(dir / temporary.filename())) {
    fs::remove(dir / temporary.filename());
    return fmt::format("gnuplot failed (exit status {}) on {}", status, script.string());
  }
  fs::rename(dir / temporary.filename(), png);
  return "";
}

std::string number(double x) {
  return fmt::format("{:.3e}", x);
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void write_index(const fs::path& dir, const std::string& input_path, const CompareArgs& a,
                 const std::vector<ContinuityReport>& reports,
                 const std::vector<std::string>& refusals, bool has_closeup,
                 const std::string& closeup_note, const std::string& plot_problem) {
  const std::string input = html_escape(input_path);
  write_file_atomically((dir / "index.html").string(), [&](std::ostream& out) {
    out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>stitch compare: " << input
        << "</title>\n<style>body{font-family:sans-serif;max-width:1500px;margin:1em auto}"
           "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 8px;"
           "text-align:right}img{max-width:100%}figure{display:inline-block;margin:0 8px}"
           "</style></head><body>\n";
    out << "<h1>AS&amp;C, modified de Casteljau and Catmull-Clark on " << input << "</h1>\n";
    out << fmt::format(
        "<p>Zebra stripes ({} stripes, resolution {} per patch side), view {}. Reflection lines "
        "bend smoothly across a join with continuous normals and kink where the normal "
        "jumps.</p>\n",
        a.stripes, a.resolution, a.view);
    out << "<h2>Continuity (as <code>stitch analyze</code>)</h2>\n<table><tr><th>method</th>"
           "<th>max jump touching EV (deg)</th><th>mean jump touching EV</th>"
           "<th>max jump elsewhere</th><th>mean jump elsewhere</th><th>position gap "
           "(rel.)</th><th>G1 spread at EVs (deg)</th></tr>\n";
    for (const ContinuityReport& r : reports) {
      out << "<tr><th>" << to_string(r.method) << "</th><td>" << number(r.touching_ev.max_deg)
          << "</td><td>" << number(r.touching_ev.mean_deg) << "</td><td>"
          << number(r.away_from_ev.max_deg) << "</td><td>" << number(r.away_from_ev.mean_deg)
          << "</td><td>" << number(r.max_gap) << "</td><td>" << number(r.ev_normal_spread_deg)
          << "</td></tr>\n";
    }
    out << "</table>\n";
    for (const std::string& r : refusals) {
      out << "<p><strong>Not shown:</strong> " << html_escape(r) << "</p>\n";
    }
    std::string order;
    for (const ContinuityReport& r : reports)
      order += (order.empty() ? "" : " | ") + to_string(r.method);
    const auto row = [&](const std::string& name, const std::string& heading) {
      out << "<h2>" << heading << "</h2>\n<p><img src=\"" << name << kImageExtension << "\" alt=\""
          << order << "\"></p>\n<div>";
      for (const ContinuityReport& r : reports) {
        out << "<figure><img src=\"" << name << "_" << to_string(r.method) << kImageExtension
            << "\" width=\"240\"><figcaption>" << method_title(r.method)
            << "</figcaption></figure>";
      }
      out << "</div>\n";
    };
    row("zebra_whole", "Whole model: " + order);
    if (has_closeup) {
      row("zebra_closeup", "Close-up of " + closeup_note + ": " + order);
    } else {
      out << "<h2>Close-up</h2><p>" << closeup_note << "</p>\n";
    }
    out << "<h2>Normal jump against distance from extraordinary points</h2>\n";
    if (plot_problem.empty()) {
      out << "<p><img src=\"jump_by_distance" << kImageExtension << "\" alt=\"plot\"></p>\n";
    } else {
      out << "<p><strong>No plot:</strong> " << html_escape(plot_problem) << "</p>\n";
    }
    const bool has_data = std::any_of(reports.begin(), reports.end(),
                                      [](const auto& r) { return !r.jump_by_distance.empty(); });
    if (has_data) {
      out << "<p>Data: <a href=\"jump_by_distance.dat\">jump_by_distance.dat</a>.</p>\n";
    }
    out << "</body></html>\n";
  });
}

void run_compare(const CompareArgs& a) {
  const ImageSize size = parse_image_size(a.size);
  const View view = parse_view(a.view);
  const UpAxis up = parse_choice(up_axis_table(), a.up, "up axis");
  const fs::path dir(a.out);
  if (fs::exists(dir) && !fs::is_directory(dir)) {
    throw UsageError(fmt::format("the output '{}' exists and is not a directory", a.out));
  }

  StageReporter stage(a.progress);
  stage.begin("reading " + a.in.path);
  const HalfedgeMesh mesh = load_input(a.in);
  stage.end();
  fs::create_directories(dir);

  const double aspect = static_cast<double>(size.width) / size.height;
  RenderStyle style;
  style.mode = ShadingMode::zebra;
  style.stripes = a.stripes;
  const OffscreenContext context;
  Renderer renderer;
  std::vector<Image> whole, closeup;
  std::vector<ContinuityReport> reports;
  std::vector<Method> shown;
  std::vector<std::string> refusals;  // methods that cannot handle this mesh, and why
  bool has_camera = false, has_closeup = false;
  std::string closeup_note;
  Camera whole_camera, closeup_camera;
  for (const Method m : kMethods) {
    stage.begin("building, rendering and analyzing " + to_string(m));
    std::optional<BuiltSurface> built;
    try {
      built.emplace(build_cli_surface(a.kgon, mesh, m, a.in.path, a.progress.quiet));
    } catch (const Error& e) {
      // Should OpenSubdiv reject the mesh: show the other methods and say why this one is
      // missing.
      stage.end();
      refusals.push_back(to_string(m) + ": " + e.what());
      fmt::print(stderr, "stitch: warning: {} skipped: {}\n", to_string(m), e.what());
      continue;
    }
    // Refined for semi-sharp tags, the surface goes with the mesh its patches come from.
    const HalfedgeMesh& surface_mesh = built->mesh(mesh);
    const Surface& surface = built->surface;
    const SceneGeometry scene =
        build_scene(surface_mesh, surface, a.resolution, OverlaySelection{}, SceneSurface::blocks);
    const SurfaceBlocks blocks = surface_blocks(surface_mesh, surface, a.resolution);
    // One camera for all methods (from the first one's surface), so the images line up.
    if (!has_camera) {
      has_camera = true;
      whole_camera = frame_view(view, scene.bounds, aspect, up);
      if (scene.extraordinary.empty()) {
        closeup_note = "no close-up: the mesh has no extraordinary point";
      } else {
        const ExtraordinaryPoint& p = highest_valence_point(scene.extraordinary);
        closeup_camera = focus_camera(p, scene, aspect, a.zoom, up);
        has_closeup = true;
        closeup_note =
            fmt::format("the extraordinary point of highest valence ({} {}, K = {})",
                        p.kind == KgonKind::vertex ? "vertex" : "face", p.element + 1, p.k);
      }
    }
    upload_scene(renderer, scene);
    whole.push_back(
        render_image(renderer, whole_camera, style, size.width, size.height, {}, &blocks));
    write_png((dir / ("zebra_whole_" + to_string(m) + std::string(kImageExtension))).string(),
              whole.back());
    if (has_closeup) {
      closeup.push_back(
          render_image(renderer, closeup_camera, style, size.width, size.height, {}, &blocks));
      write_png((dir / ("zebra_closeup_" + to_string(m) + std::string(kImageExtension))).string(),
                closeup.back());
    }
    reports.push_back(analyze_continuity(surface_mesh, surface));
    shown.push_back(m);
    stage.end();
  }
  if (shown.empty()) {
    throw InputError("no method can handle " + a.in.path + ": " + refusals.front());
  }
  const int gap = std::max(4, size.width / 60);
  write_png((dir / ("zebra_whole" + std::string(kImageExtension))).string(),
            side_by_side(whole, gap));
  if (has_closeup)
    write_png((dir / ("zebra_closeup" + std::string(kImageExtension))).string(),
              side_by_side(closeup, gap));

  stage.begin("plotting");
  const std::string plot_problem = plot_jumps(dir, reports);
  stage.end();
  write_index(dir, a.in.path, a, reports, refusals, has_closeup, closeup_note, plot_problem);
  std::string names;
  for (const Method m : shown) names += (names.empty() ? "" : ", ") + to_string(m);
  fmt::print("wrote {}/index.html (zebra images of {}{}{})\n", a.out, names,
             has_closeup ? ", whole and close-up" : "", plot_problem.empty() ? ", jump plot" : "");
  if (!plot_problem.empty()) fmt::print(stderr, "stitch: warning: {}\n", plot_problem);
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare AS&C, modified de Casteljau and Catmull-Clark: zebra images side by side, the "
      "normal jump against distance from extraordinary points, and DIR/index.html. Memory: the "
      "mesh and one method's surface at a time, each picture drawn a block of patches at a "
      "time, so nothing grows with --resolution");
  add_input_options(cmd, args->in);
  cmd->add_option("-o,--output", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--size", args->size, "size WxH of each image")->capture_default_str();
  cmd->add_option("--view", args->view, "front, back, left, right, top, bottom or iso")
      ->capture_default_str();
  cmd->add_option("--up", args->up,
                  "the world axis up in the images: " + choice_help(up_axis_table()))
      ->check(choice_validator(up_axis_table()))
      ->capture_default_str();
  cmd->add_option("--resolution", args->resolution, "segments per patch side")
      ->check(CLI::Range(1, limits::max_resolution))
      ->capture_default_str();
  cmd->add_option("--stripes", args->stripes, "zebra stripes around the full circle")
      ->check(CLI::Range(2, 512))
      ->capture_default_str();
  cmd->add_option("--zoom", args->zoom,
                  "radius of the region shown in the close-up, in patch sizes")
      ->check(finite_range(kMinZoom, kMaxZoom))
      ->capture_default_str();
  add_kgon_options(cmd, args->kgon, &args->in);
  add_progress_option(cmd, args->progress);
  cmd->callback([args] { run_compare(*args); });
}

}  // namespace stitch::cli
