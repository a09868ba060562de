// Mouse and keyboard in the 3D view: orbit, pan, zoom, picking, dragging the selected vertex,
// and the keys for undo, redo and framing. Input ImGui takes (over a panel) is left to it.
#pragma once

#include "app_state.hpp"

namespace stitch::modeler::app {

void handle_mouse(App& app);
void handle_keys(App& app);

}  // namespace stitch::modeler::app
