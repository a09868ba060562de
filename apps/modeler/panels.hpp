// The panels: the menu bar, the Edit panel (picking, operators, vertex moves, K-gons, command
// line), the Display panel (method, split, resolution, modes, overlays, views, history), the
// status bar and the recover-autosave prompt. Every button runs a script line (commands.hpp).
#pragma once

#include "app_state.hpp"

namespace stitch::modeler::app {

/// Draws the menu bar, the panels and the status bar, and records where they are and every
/// label they drew in app.layout.
void draw_panels(App& app);
/// The prompt offering a newer autosave, begun after every other window.
void recover_dialog(App& app);

}  // namespace stitch::modeler::app
