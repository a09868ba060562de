// stitch edit IN -o OUT --op "OP ARGS" [--op ...] [--ops FILE]: topology operations in order.
// With --check, the patches the operations changed are checked for folds and self-intersections
// (local_check.hpp) and any are reported as a warning.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/analysis/local_check.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch::cli {

namespace {

struct EditArgs {
  std::string in, out;
  bool quiet = false;
  bool check = false, strict = false;
  bool unfold_tubes = true;
  int check_resolution = LocalCheckOptions{}.resolution;
};

/// The elements the operations touched (their journals), or `whole` after a remeshing, which
/// renumbers everything.
struct Touched {
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
  std::vector<Face> faces;
  bool whole = false;
};

bool is_remeshing(std::string_view text) {
  const auto words = split_words(text.substr(0, text.find(" #")));
  const OperationInfo* info = words.empty() ? nullptr : find_operation(words[0]);
  return info && info->renumbers;
}

/// Warns when the surface folds or meets itself near what the operations changed; returns
/// whether it does. Patches are named by their corners as the written file numbers them, and by
/// their `patch` numbers (the corner's half-edge when the file is read back, as `stitch smooth
/// --unwelded` and `.bez.json` number them).
bool check_edited_surface(const EditArgs& a, const HalfedgeMesh& mesh, const Touched& touched) {
  const std::vector<Corner> changed =
      touched.whole ? mesh.patch_corners()
                    : patches_touched(mesh, touched.vertices, touched.edges, touched.faces);
  // The surface `stitch smooth` makes of the output by default.
  const BuiltSurface built = build_surface(mesh, {Method::mdc, {}, a.unfold_tubes});
  const HalfedgeMesh& surface_mesh = built.mesh(mesh);
  report_unfolded_tubes(built.tubes, surface_mesh, a.out, a.quiet);
  const Surface& surface = built.surface;
  LocalCheckOptions options;
  options.resolution = a.check_resolution;
  // Refined for semi-sharp tags, a changed corner's patch is tiled by refined patches: those are
  // checked, and problems are named by the corners of the output that hold them.
  std::vector<Corner> checked = changed;
  if (built.refined) {
    checked.clear();
    for (Corner c : changed) {
      const std::vector<Corner> tiles = built.refined->patches_of(c);
      checked.insert(checked.end(), tiles.begin(), tiles.end());
    }
  }
  LocalCheckReport r = check_patches(surface_mesh, surface, checked, options);
  if (built.refined) {
    const std::vector<Corner> input = built.refined->input_corners();
    for (Corner& c : r.problem_corners) c = input[c.idx];
    std::sort(r.problem_corners.begin(), r.problem_corners.end());
    r.problem_corners.erase(std::unique(r.problem_corners.begin(), r.problem_corners.end()),
                            r.problem_corners.end());
  }
  if (r.clean()) {
    if (!a.quiet)
      fmt::print(
          "check: no folds or self-intersections near the edits ({} patches changed, {} "
          "around them, {} triangles at resolution {})\n",
          r.changed_patches, r.patches - r.changed_patches, r.triangles, options.resolution);
    return false;
  }
  std::vector<std::string> names = corner_names(mesh, r.problem_corners, true);
  // The corners as the written file reads back (build_mesh of the same polygons), in order.
  std::string patches;
  try {
    BuildOptions build;
    build.allow_two_gons = true;
    const HalfedgeMesh back = build_mesh(to_polygon_soup(mesh), build);
    std::vector<std::pair<int, std::string>> numbered;
    for (std::string& name : names) numbered.emplace_back(parse_corner(back, name).idx, name);
    std::sort(numbered.begin(), numbered.end());
    std::vector<int> numbers;
    for (size_t i = 0; i < numbered.size(); ++i) {
      numbers.push_back(numbered[i].first);
      names[i] = std::move(numbered[i].second);
    }
    patches = fmt::format("patches {} ", fmt::join(numbers, ", "));
  } catch (const Error&) {  // not expected: the mesh passed validate()
  }
  const char* what = r.folds > 0 && r.self_intersections > 0 ? "folds and intersects itself"
                     : r.folds > 0                           ? "folds"
                                                             : "intersects itself";
  fmt::print(stderr,
             "stitch: warning: the surface {} at {}(corners {} of {}): {} folded and {} "
             "crossing pairs of triangles at resolution {}; see stitch check-surface\n",
             what, patches, fmt::join(names, ", "), a.out, r.folds, r.self_intersections,
             options.resolution);
  return true;
}

/// One operation and where it came from, for messages.
struct OpLine {
  std::string text, where;
};

std::vector<OpLine> read_ops_file(const std::string& path) {
  std::istringstream file(read_regular_file(path));
  std::vector<OpLine> ops;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    ops.push_back({line, fmt::format("{}:{}", path, number)});
  }
  return ops;
}

void run_edit(const EditArgs& a, const CLI::App& cmd) {
  // --op and --ops are applied in the order they appear on the command line.
  std::vector<OpLine> ops;
  size_t op_index = 0, file_index = 0;
  const auto op_values = cmd.get_option("--op")->results();
  const auto file_values = cmd.get_option("--ops")->results();
  for (const CLI::Option* opt : cmd.parse_order()) {
    if (opt->get_name() == "--op") {
      const std::string& text = op_values.at(op_index++);
      ops.push_back({text, fmt::format("--op {} ('{}')", op_index, limits::quoted(text))});
    } else if (opt->get_name() == "--ops") {
      const auto lines = read_ops_file(file_values.at(file_index++));
      ops.insert(ops.end(), lines.begin(), lines.end());
    }
  }

  BuildOptions build;
  build.allow_two_gons = true;  // edited meshes have them, and must read back
  std::vector<std::string> warnings;
  BuildReport report;
  HalfedgeMesh mesh = read_mesh(a.in, build, &report, &warnings);
  warnings.insert(warnings.end(), report.warnings.begin(), report.warnings.end());
  // Texture coordinates live beside the mesh, not in it, and the operators do not carry them.
  if (!report.corner_uvs.empty())
    warnings.push_back("its texture coordinates are not kept by edits and not written");
  for (const std::string& w : warnings) fmt::print(stderr, "stitch: warning: {}: {}\n", a.in, w);

  std::vector<std::string> lines;
  Touched touched;
  for (const OpLine& op : ops) {
    OperationReport r;
    // A remeshing renumbers everything: no journal could say what it touched.
    std::optional<MeshJournal> journal;
    try {
      if (a.check && !is_remeshing(op.text)) journal.emplace(mesh);
      r = apply_operation(mesh, op.text);
    } catch (const Error& e) {
      throw_with_message(e, fmt::format("{}: {} (nothing written)", op.where, e.what()));
    }
    if (journal) {
      // Numbers stay valid for the whole run (until a remeshing), so the lists add up.
      const MeshDelta delta = journal->finish();
      touched.vertices.insert(touched.vertices.end(), delta.vertices.begin(), delta.vertices.end());
      touched.edges.insert(touched.edges.end(), delta.edges.begin(), delta.edges.end());
      touched.faces.insert(touched.faces.end(), delta.faces.begin(), delta.faces.end());
    } else if (a.check && !r.what.empty()) {
      touched.whole = true;
    }
    if (r.what.empty()) continue;  // blank or comment line
    std::string text = op.text.substr(0, op.text.find(" #"));
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
      text.erase(0, 1);
    lines.push_back(r.summary(text));
  }
  validate(mesh);
  const TopologyStats stats = topology_stats(mesh);
  if (mesh_file_format(a.out, kMeshWriteExtensions) != MeshFileFormat::obj &&
      stats.crease_edges + stats.corner_vertices > 0)
    fmt::print(stderr,
               "stitch: warning: {}: crease and corner tags are only written to OBJ files; this "
               "file will not have them\n",
               a.out);
  write_mesh(a.out, mesh);
  if (!a.quiet)
    for (const std::string& line : lines) fmt::print("{}\n", line);
  if (a.check && check_edited_surface(a, mesh, touched) && a.strict) throw ExitStatus(1, "");
}

}  // namespace

void add_edit_command(CLI::App& app) {
  auto args = std::make_shared<EditArgs>();
  std::string synopses;
  for (const OperationInfo& info : operation_table())
    synopses += (synopses.empty() ? "" : ", ") + std::string(info.synopsis);
  auto* cmd = app.add_subcommand(
      "edit", fmt::format("apply topology operations ({}); vertices and faces are numbered from "
                          "1 in file order; see docs/editing.md",
                          synopses));
  cmd->add_option("IN", args->in, "input mesh (" + extension_list(kMeshReadExtensions) + ")")
      ->required();
  cmd->add_option("-o,--output", args->out, "output mesh, compacted (renumbered without gaps)")
      ->required();
  cmd->add_option("--op", "one operation, e.g. \"insert-edge 1@1 7@2\" (repeatable)")
      ->type_size(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--ops", "file of operations: one per line, # comments, blank lines")
      ->type_size(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->check(CLI::ExistingFile);
  cmd->add_flag("-q,--quiet", args->quiet, "do not print the per-operation summary lines");
  cmd->add_flag("--check", args->check,
                "check the patches the operations changed, and their neighbours, for folds and "
                "self-intersections; a warning on stderr names them (exit status 0)");
  cmd->add_flag("--strict", args->strict,
                "check as --check does, and end with exit status 1 when it finds any (the output "
                "is written all the same)");
  cmd->add_option("--check-resolution", args->check_resolution,
                  "segments per patch side for --check")
      ->check(CLI::Range(1, limits::max_resolution))
      ->capture_default_str();
  cmd->add_flag_callback(
      "--no-unfold-tubes", [args] { args->unfold_tubes = false; },
      "--check the fitted K-gons of every tube, as stitch smooth "
      "--no-unfold-tubes builds them, instead of the controls stitch smooth "
      "chooses where they fold");
  cmd->callback([args, cmd] {
    args->check = args->check || args->strict;
    run_edit(*args, *cmd);
  });
}

}  // namespace stitch::cli
