// One frame of the window: ImGui's new frame, input, the panels and dialogs, the 3D view; and
// screenshots of it.
#pragma once

#include <string>

#include "app_state.hpp"

namespace stitch::modeler::app {

/// Draws one frame into the back buffer (input is handled only when `interactive`).
void render_frame(App& app, bool interactive);
/// Renders a frame and writes the window's pixels (what the user sees) as a PNG.
void screenshot(App& app, const std::string& path);

}  // namespace stitch::modeler::app
