// Options and steps shared by several sub-commands: reading the input mesh, the K-gon
// controls, the method, and stage messages on long runs.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <string>

#include "stitch/eval/surface.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::cli {

struct InputOptions {
  std::string path;
  bool fill_holes = false;
};
/// Adds the positional IN and --fill-holes.
void add_input_options(CLI::App* cmd, InputOptions& in);
/// Reads and checks the mesh, printing warnings (dropped vertices, filled holes, 2-gons,
/// valence-2 vertices) to stderr. Throws MeshError on bad input.
HalfedgeMesh load_input(const InputOptions& in);

struct KgonCliOptions {
  double scale = 1.0;
  double rotate_deg = 0.0;
  bool regularize = false;
  std::string construction = "openings";
};
/// Adds --kgon-scale, --kgon-rotate, --regularize and --kgon-construction.
void add_kgon_options(CLI::App* cmd, KgonCliOptions& k);
KgonOptions to_kgon_options(const KgonCliOptions& k);

/// Adds --method with the given default; `allow_all` accepts "all" as well.
void add_method_option(CLI::App* cmd, std::string& method, bool allow_all = false);

/// Prints "stitch: <stage>..." and the time it took, on stderr, when stderr is a terminal or
/// progress was asked for; silent otherwise so scripts and tests see only results.
class StageReporter {
 public:
  explicit StageReporter(bool enabled);
  void begin(const std::string& stage);
  void end();

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};
/// Adds --progress (force stage messages).
void add_progress_option(CLI::App* cmd, bool& progress);
bool stderr_is_terminal();

}  // namespace stitch::cli
