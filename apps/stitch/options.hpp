// Options and steps shared by several sub-commands: reading the input mesh, the K-gon
// controls, the method, and stage messages on long runs.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <functional>
#include <string>

#include "stitch/analysis/build_surface.hpp"
#include "stitch/analysis/unfold_tubes.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::cli {

struct KgonCliOptions;

struct InputOptions {
  std::string path;
  bool fill_holes = false;
  bool strict = false;  ///< --strict: refuse what the repair would fix (BuildOptions::repair off)
  // Where load_input puts what the input brings besides the mesh: a project's K-gon controls and
  // method, a --kgon-controls file's controls. add_kgon_options and add_method_option on the same
  // sub-command set them (the sub-commands add their options with separate calls).
  KgonCliOptions* kgon = nullptr;
  std::string* method = nullptr;
  const CLI::Option* method_option = nullptr;
};
/// Adds the positional IN, --fill-holes and --strict.
void add_input_options(CLI::App* cmd, InputOptions& in);
/// Reads, repairs (unless --strict) and checks the mesh, printing warnings (repairs, dropped
/// vertices, filled holes, 2-gons, valence-2 vertices) to stderr. Throws stitch::Error on bad
/// input. `report` (optional) receives the build report, e.g. the texture coordinates of the
/// corners. A project (.stitch) brings its K-gon controls and, unless --method was given, its
/// method; a --kgon-controls file is read against the mesh here, so its numbers are checked before
/// any work. `progress` (optional) is told how much of the reading is done.
HalfedgeMesh load_input(const InputOptions& in, BuildReport* report = nullptr,
                        const std::function<void(double)>& progress = {});

struct KgonCliOptions {
  double scale = 1.0;
  double rotate_deg = 0.0;
  bool regularize = false;
  std::string construction{kgon_construction_table().front().name};
  std::string boundary{boundary_table().front().name};
  double sharp_from = KgonOptions{}.sharp_from;
  std::string controls_path;  ///< --kgon-controls
  bool unfold_tubes = true;   ///< --no-unfold-tubes turns it off
  /// Set by load_input: the per-element controls of a project or a --kgon-controls file, and a
  /// project's global control, which --kgon-scale, --kgon-rotate and --regularize override one
  /// by one when given.
  KgonOptions from_input;
  bool input_has_global = false;
  const CLI::Option *scale_option = nullptr, *rotate_option = nullptr, *regularize_option = nullptr;
};
/// Adds --kgon-scale, --kgon-rotate, --regularize, --kgon-controls, --kgon-construction,
/// --no-unfold-tubes, --boundary and --sharp-from.
/// With `in`, a .stitch input's K-gon controls reach `k` through load_input.
void add_kgon_options(CLI::App* cmd, KgonCliOptions& k, InputOptions* in = nullptr);
KgonOptions to_kgon_options(const KgonCliOptions& k);
/// The request the options make: the method, to_kgon_options, and unless --no-unfold-tubes the
/// tube policy.
SurfaceSpec surface_spec(const KgonCliOptions& k, Method method);
/// build_surface of that request, each tube unfold_tubes found reported on stderr against
/// `where` (the input): what was chosen as a note (not under `quiet`), a tube that still folds
/// as a warning.
BuiltSurface build_cli_surface(const KgonCliOptions& k, const HalfedgeMesh& mesh, Method method,
                               const std::string& where, bool quiet = false);
/// Reports unfold_tubes' results for `mesh` on stderr, as surface_kgon_options does.
void report_unfolded_tubes(const std::vector<TubeUnfolding>& tubes, const HalfedgeMesh& mesh,
                           const std::string& where, bool quiet);

/// A CLI11 check for a finite number from lo to hi (CLI::Range and CLI::PositiveNumber let NaN
/// through, and a number too large to use would turn the output into NaN).
CLI::Validator finite_range(double lo, double hi);
/// A CLI11 check that the value is a name of the table.
template <class T>
CLI::Validator choice_validator(ChoiceTable<T> table) {
  std::vector<std::string> names;
  for (const Choice<T>& c : table) names.emplace_back(c.name);
  return CLI::IsMember(names);
}
/// --zoom of render and compare, in patch sizes.
inline constexpr double kMinZoom = 1e-3, kMaxZoom = 1e3;

/// Adds --method with the given default; `allow_all` accepts "all" as well.
/// With `in`, a .stitch input's method applies unless --method is given.
void add_method_option(CLI::App* cmd, std::string& method, bool allow_all = false,
                       InputOptions* in = nullptr);

/// --progress and --quiet.
struct ProgressFlags {
  bool progress = false;  ///< stage lines even when stderr is not a terminal
  bool quiet = false;     ///< nothing on stderr but errors and warnings
};

/// Prints "stitch: <stage>..." and the time it took, on stderr, when stderr is a terminal or
/// --progress was given, never under --quiet; silent otherwise so scripts and tests see only
/// results. On a terminal, long stages also show the percentage done.
class StageReporter {
 public:
  explicit StageReporter(const ProgressFlags& flags);
  void begin(const std::string& stage);
  /// How much of the current stage is done (0..1). Call from one thread at a time.
  void fraction(double done);
  /// A line about the work in the current stage ("stitch: LINE" on stderr, not under --quiet),
  /// on a line of its own; the stage's line is shown again after it.
  void note(const std::string& line);
  void end();

 private:
  bool enabled_;
  bool terminal_;
  bool quiet_;
  bool open_ = false;  ///< a stage's line is on the screen, not yet ended
  int percent_ = -1;
  std::string stage_;
  std::chrono::steady_clock::time_point start_;
};
/// Adds --progress (force stage messages) and --quiet.
void add_progress_option(CLI::App* cmd, ProgressFlags& flags);
bool stderr_is_terminal();

}  // namespace stitch::cli
