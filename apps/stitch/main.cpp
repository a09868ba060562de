#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "stitch/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "stitch: smooth surfaces of hierarchically organized bicubic Bezier patches from any "
      "orientable polygon mesh, closed or with boundaries (modified de Casteljau subdivision)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "stitch 0.1.0");
  stitch::cli::add_smooth_command(app);
  stitch::cli::add_analyze_command(app);
  stitch::cli::add_info_command(app);
  // more commands: add_*_command calls below this line
#if STITCH_WITH_RENDER
  stitch::cli::add_render_command(app);
  stitch::cli::add_compare_command(app);
#endif
  stitch::cli::add_edit_command(app);
  stitch::cli::add_primitive_command(app);
  stitch::cli::add_check_surface_command(app);
  stitch::cli::add_eval_command(app);
#if STITCH_WITH_CAD
  stitch::cli::add_cad_mesh_command(app);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const stitch::cli::ExitStatus& e) {
    if (e.what()[0] != '\0') fmt::print(stderr, "stitch: {}\n", e.what());
    return e.code();
  } catch (const stitch::Error& e) {
    // Every kind (InputError, TopologyError, UsageError, OutputError) is the user's to fix:
    // status 2, as the README promises for bad input. 1 is kept for checks that found problems
    // (edit --strict) and 3 for stitch's own failures.
    fmt::print(stderr, "stitch: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "stitch: internal error: {}\n", e.what());
    return 3;
  }
  return 0;
}
