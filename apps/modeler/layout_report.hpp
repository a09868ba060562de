// The `layout PATH` script line: the last frame's screen layout as JSON, for tests and for
// checking a layout by eye. Fields (window coordinates, boxes as [x0, y0, x1, y1]):
//   window [width, height], font_scale, viewport (the 3D view's area), views (the box of each
//   view: the viewport, or its two halves when split),
//   panels [{name, box}], labels [{window, text, box, window_box, content}] (content: the
//   window's work area, which items must stay inside), model_box (the input mesh's bounding box
//   projected into the view; for a split view, into its left half).
#pragma once

#include <string>

#include "app_state.hpp"

namespace stitch::modeler::app {

/// Writes the layout of the last frame drawn (render one first) to `path`, atomically.
void write_layout_report(const App& app, const std::string& path);

}  // namespace stitch::modeler::app
