// stitch edit IN -o OUT --op "OP ARGS" [--op ...] [--ops FILE]: topology operations in order.
#include <fmt/format.h>

#include <memory>
#include <sstream>

#include "commands.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch::cli {

namespace {

struct EditArgs {
  std::string in, out;
  bool quiet = false;
};

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
  for (const OpLine& op : ops) {
    OperationReport r;
    try {
      r = apply_operation(mesh, op.text);
    } catch (const MeshError& e) {
      throw MeshError(fmt::format("{}: {} (nothing written)", op.where, e.what()));
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
  if (file_extension(a.out) != ".obj" && stats.crease_edges + stats.corner_vertices > 0)
    fmt::print(stderr,
               "stitch: warning: {}: crease and corner tags are only written to .obj files; "
               "this file will not have them\n",
               a.out);
  write_mesh(a.out, mesh);
  if (!a.quiet)
    for (const std::string& line : lines) fmt::print("{}\n", line);
}

}  // namespace

void add_edit_command(CLI::App& app) {
  auto args = std::make_shared<EditArgs>();
  auto* cmd = app.add_subcommand(
      "edit",
      "apply topology operations (insert-edge V@F V@F, delete-edge V W[@F], subdivide-edge V W, "
      "collapse-edge V W, extrude-face F DIST [SCALE], connect-faces F G [TWIST], delete-face F, "
      "open-face F, fill-hole F, crease V W SHARPNESS, corner V SHARPNESS, doo-sabin, "
      "vertex-insertion, catmull-clark, dual); vertices and faces are numbered from 1 "
      "in file order; see docs/editing.md");
  cmd->add_option("IN", args->in, "input mesh (.obj, .off, .ply)")->required();
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
  cmd->callback([args, cmd] { run_edit(*args, *cmd); });
}

}  // namespace stitch::cli
