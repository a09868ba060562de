// The 3D views: uploading what the session changed to the GPU, drawing the main view (and the
// split view beside it) into the area the panels leave free, and the camera and mouse rays of
// that area.
#pragma once

#include "app_state.hpp"

namespace stitch::modeler::app {

/// The camera for the current view; the clipping planes contain the input mesh's box, enlarged
/// since the surface and the K-gons may reach a little beyond it.
Camera current_camera(const App& app);
/// After any session change: upload what the main surface recomputed (everything when `full`),
/// and bring the split view's surface along.
void after_change(App& app, bool full);
/// Draws the 3D view(s) into the window's framebuffer, in app.layout.viewport.
void draw_scene(App& app);
/// The ray through the window point (x, y) (window coordinates), in the view under it.
Ray mouse_ray(const App& app, double x, double y);
/// The rectangle one view is drawn in: the viewport, or its left or right half when split.
ScreenRect view_rect(const App& app, int side);

}  // namespace stitch::modeler::app
