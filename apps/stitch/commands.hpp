// The sub-commands of `stitch`. Each add_*_command registers one sub-command whose callback runs
// it; a callback reports failure by throwing (see main.cpp for the exit statuses).
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

namespace stitch::cli {

/// Ends the command with this exit status after printing `what()` (when not empty) to stderr.
/// Exit statuses: 0 success, 1 the command ran but its check failed (e.g. check-surface found
/// folds), 2 bad input or usage (nothing written), 3 internal error.
class ExitStatus : public std::runtime_error {
 public:
  ExitStatus(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  [[nodiscard]] int code() const { return code_; }

 private:
  int code_;
};

void add_smooth_command(CLI::App& app);
void add_analyze_command(CLI::App& app);
void add_info_command(CLI::App& app);
// more commands: registered below this line by their own files
void add_render_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_edit_command(CLI::App& app);
void add_primitive_command(CLI::App& app);
void add_check_surface_command(CLI::App& app);
void add_eval_command(CLI::App& app);
void add_cad_mesh_command(CLI::App& app);  // with OpenCASCADE only (STITCH_WITH_CAD)
}  // namespace stitch::cli
