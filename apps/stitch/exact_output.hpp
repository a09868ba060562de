// The exact surface out of `stitch smooth`: the patch set as Bézier JSON, STEP or IGES, chosen
// by the output's extension, with the depth and deviation report.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "options.hpp"
#include "stitch/eval/surface.hpp"

namespace stitch::cli {

struct ExactOutputOptions {
  double tolerance = 1e-6;
  double angle_tolerance_deg = 0.1;
  std::string units = "mm";
  bool kgons = false;
  std::string patches;  ///< --patches: Bézier JSON besides the main output
};

/// Adds --tolerance, --angle-tolerance, --units, --kgons and --patches.
void add_exact_output_options(CLI::App* cmd, ExactOutputOptions& options);

/// True for the extensions written from the patch set (.json, .step, .stp, .igs, .iges).
bool is_exact_output(const std::string& path);

/// Every output extension of `stitch smooth`, for messages.
std::string smooth_output_extensions();

/// Refuses, before any work, what would fail later: an unknown unit, a CAD output in a build
/// without OpenCASCADE, a --patches name that is not .json. Throws stitch::Error.
void check_exact_outputs(const std::string& out, const ExactOutputOptions& options);

/// Writes `out` when it is an exact output, and --patches when given, reporting the patch set
/// on stderr. Returns a one-line summary of what `out` holds ("" when `out` is not exact).
std::string write_exact_outputs(const std::string& out, const HalfedgeMesh& mesh,
                                const Surface& surface, const ExactOutputOptions& options,
                                StageReporter& stage);

}  // namespace stitch::cli
