// The modeler's project file (JSON): the mesh and the per-element K-gon controls (the core's
// part, which `stitch` commands read too: stitch/project/project_file.hpp describes the whole
// format), plus the view and the display settings; and where autosaves go.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "stitch/choices.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/modeler/document.hpp"
#include "stitch/modeler/navigation.hpp"
#include "stitch/render/renderer.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch::modeler {

struct DisplaySettings {
  Method method = method_table().front().value;
  int resolution = kDefaultResolution;
  ShadingMode mode = shading_mode_table().front().value;
  bool input_polygons = false;  ///< show the input polygons instead of the smooth surface
  std::array<bool, num_overlays> overlays{};
  bool markers = false;
  std::optional<Method> split;  ///< the method shown on the right half, if split
  bool operator==(const DisplaySettings&) const = default;
};

/// What the view shows: the smooth surface in a shading mode, or (nullopt) the input polygons.
using DisplayMode = std::optional<ShadingMode>;
/// The display modes by name, for the `mode` line and the Display panel: the renderer's shading
/// modes (shading_mode_table()), then the modeler's own row, "input", the input polygons instead
/// of the smooth surface.
ChoiceTable<DisplayMode> display_mode_table();
[[nodiscard]] DisplayMode display_mode(const DisplaySettings& display);
void set_display_mode(DisplaySettings& display, DisplayMode mode);

/// The split view's choices by name, for the `split` line and the Display panel: the modeler's
/// own "off" (one view), then the methods (method_table()) shown on the right half.
ChoiceTable<std::optional<Method>> split_table();

struct Project {
  DocumentState state;
  OrbitView view;
  DisplaySettings display;
};

/// Files with a project extension (kProjectExtensions, stitch/project/project_file.hpp) are
/// projects; anything else is a mesh file.
bool is_project_path(const std::string& path);

std::string project_to_json(const Project& project);
/// Throws stitch::Error naming `source` and what is wrong.
Project project_from_json(const std::string& text, const std::string& source);
/// Atomic (write_file_atomically).
void save_project(const std::string& path, const Project& project);
Project load_project(const std::string& path);

/// Where the autosave of `document_path` goes: `.NAME.autosave.stitch` beside the document, or
/// for an untitled document `$XDG_DATA_HOME/stitch/autosave/untitled.stitch` (default
/// ~/.local/share/stitch/autosave/untitled.stitch).
std::string autosave_path(const std::string& document_path);
/// True when the autosave exists and is newer than the document (or the document is missing).
bool autosave_is_newer(const std::string& autosave, const std::string& document_path);

}  // namespace stitch::modeler
