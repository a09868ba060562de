#include "viewport.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stitch/render/overlays.hpp"
#include "stitch/render/scene.hpp"

namespace stitch::modeler::app {

namespace {

/// Highlight of the selection (and the first element of a two-element operation).
void add_highlight(const HalfedgeMesh& m, const Pick& p, const Colour& colour, LineSet& lines,
                   MarkerSet& markers) {
  auto mark = [&](const Vec3& x) {
    markers.positions.push_back(x);
    markers.colours.push_back(colour);
  };
  switch (p.kind) {
    case PickKind::vertex:
      if (p.index < m.vertex_capacity() && !m.is_deleted(Vertex(p.index)))
        mark(m.position(Vertex(p.index)));
      break;
    case PickKind::edge: {
      const Halfedge h(p.index);
      if (h.idx < m.halfedge_capacity() && !m.is_deleted(h))
        lines.add(m.position(m.origin(h)), m.position(m.target(h)), colour);
      break;
    }
    case PickKind::face:
      if (p.index < m.face_capacity() && !m.is_deleted(Face(p.index))) {
        std::vector<Vec3> loop;
        for (Halfedge h : m.face_loop(Face(p.index))) loop.push_back(m.position(m.origin(h)));
        lines.add_loop(loop, colour);
      }
      break;
    case PickKind::corner: {
      const Halfedge h(p.index);
      if (h.idx < m.halfedge_capacity() && !m.is_deleted(h)) {
        // A point inside the face next to the vertex, and the two sides meeting there.
        const Vec3 v = m.position(m.origin(h));
        const Vec3 a = m.position(m.target(h)), b = m.position(m.origin(m.prev(h)));
        lines.add(v, v + 0.3 * (a - v), colour);
        lines.add(v, v + 0.3 * (b - v), colour);
        mark(v + 0.15 * (a - v) + 0.15 * (b - v));
      }
      break;
    }
  }
}

RenderStyle style_for(const App& app) {
  const DisplaySettings& d = app.session.display;
  RenderStyle style;
  style.mode = d.mode;
  style.overlays = d.overlays;
  style.markers = d.markers;
  // The selection is drawn in the mesh overlay and the markers, so those are on when needed.
  if (app.session.selection || app.picking.previous) {
    style.show(Overlay::mesh);
    style.markers = true;
  }
  if (!app.session.surface_problems().empty()) style.markers = true;  // their outlines
  style.background = Colour(0.96f, 0.96f, 0.97f);
  return style;
}

void upload_overlays(const App& app, const View3D& view, const IncrementalSurface& surface) {
  const Session& s = app.session;
  const HalfedgeMesh& m = s.document.mesh();
  const DisplaySettings& d = s.display;
  // Overlays are rebuilt only when shown: they cost time proportional to the mesh.
  LineSet mesh_set = d.overlays[int(Overlay::mesh)] ? mesh_lines(m) : LineSet{};
  MarkerSet markers;
  if (d.markers)
    markers = extraordinary_markers(extraordinary_points(surface.mesh(m), surface.kgons()));
  if (app.picking.previous)
    add_highlight(m, *app.picking.previous, Colour(0.1f, 0.7f, 0.2f), mesh_set, markers);
  if (s.selection) add_highlight(m, *s.selection, Colour(1.0f, 0.45f, 0.0f), mesh_set, markers);
  // Patches that fold or cross, outlined on the main view's own tessellation.
  if (&surface == &s.surface)
    add_problem_outlines(surface, s.surface_problems().corners, markers.curves);
  view.renderer->set_overlay(Overlay::mesh, mesh_set);
  view.renderer->set_overlay(
      Overlay::kgons, d.overlays[int(Overlay::kgons)] ? kgon_lines(surface.kgons()) : LineSet{});
  view.renderer->set_overlay(Overlay::nets,
                             d.overlays[int(Overlay::nets)]
                                 ? control_net_lines(surface.nets(), surface.corners())
                                 : LineSet{});
  view.renderer->set_overlay(Overlay::tessellation, d.overlays[int(Overlay::tessellation)]
                                                        ? surface_mesh_lines(surface.tessellation())
                                                        : LineSet{});
  view.renderer->set_markers(markers);
}

/// Uploads what changed: the vertex blocks `blocks` (recomputed patches, slots laid out again), or
/// everything.
void sync_view(const Session& s, View3D& view, const IncrementalSurface& surface,
               std::vector<int> blocks, bool full) {
  if (s.display.input_polygons) {
    if (full || view.geometry_dirty || !view.input_uploaded)
      view.renderer->set_surface(input_faces(s.document.mesh()));
    view.input_uploaded = true;
  } else if (full || view.geometry_dirty || view.input_uploaded) {
    view.renderer->set_block_surface(surface.tessellation(), surface.vertices_per_patch(),
                                     surface.quads_per_patch());
    view.input_uploaded = false;
  } else {
    // The blocks (indexed by corner) of recomputed patches and of slots laid out again.
    view.renderer->update_surface_blocks(surface.tessellation(), std::move(blocks));
  }
  view.geometry_dirty = false;
}

bool same_controls(const KgonOptions& a, const KgonOptions& b) {
  return a.construction == b.construction && a.global == b.global && a.face == b.face &&
         a.vertex == b.vertex && a.edge == b.edge;
}

/// Window coordinates to framebuffer pixels (they differ on high-DPI screens).
float framebuffer_scale(const App& app) {
  int ww = 0, wh = 0, fw = 0, fh = 0;
  glfwGetWindowSize(app.window, &ww, &wh);
  glfwGetFramebufferSize(app.window, &fw, &fh);
  return ww > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
}

}  // namespace

Camera current_camera(const App& app) {
  BoundingBox box = app.session.mesh_bounds();
  if (!box.empty()) {
    const Vec3 c = box.center(), half = 0.75 * (box.max - box.min) + Vec3::Constant(1e-6);
    box.extend(c + half);
    box.extend(c - half);
  }
  return app.session.view.camera(box);
}

/// The split view's surface follows the document through Session::take_changes (every document
/// change since the last call, moves and topology edits alike); a K-gon control change, a new
/// method or resolution rebuilds it.
void after_change(App& app, bool full) {
  Session& s = app.session;
  SceneViews& v = app.views;
  const Change missed = s.take_changes();
  // The session's list: an edit that unfolded a tube updated its surface twice.
  sync_view(s, v.main, s.surface, s.changed_blocks(), full);
  if (s.display.split) {
    SurfaceUpdateStats stats;
    if (!v.split_current || v.split_surface.method() != *s.display.split ||
        v.split_surface.resolution() != s.display.resolution || full ||
        !same_controls(v.split_kgons, s.document.kgon_options())) {
      stats = v.split_surface.rebuild(s.document.mesh(), s.document.kgon_options(),
                                      *s.display.split, s.display.resolution);
      v.split_current = true;
      v.split_kgons = s.document.kgon_options();
    } else {
      stats = v.split_surface.update(s.document.mesh(), s.document.kgon_options(), missed);
    }
    if (!v.split.renderer) v.split.renderer = std::make_unique<Renderer>();
    sync_view(s, v.split, v.split_surface, changed_blocks(v.split_surface), stats.full);
  } else {
    v.split_current = false;
  }
  v.overlays_dirty = true;
}

ScreenRect view_rect(const App& app, int side) {
  ScreenRect r = app.layout.viewport;
  if (!app.session.display.split) return r;
  const float middle = std::floor((r.x0 + r.x1) / 2);
  if (side == 0)
    r.x1 = middle;
  else
    r.x0 = middle;
  return r;
}

void draw_scene(App& app) {
  SceneViews& v = app.views;
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(app.window, &fw, &fh);
  if (fw <= 0 || fh <= 0) return;
  if (v.overlays_dirty) {
    upload_overlays(app, v.main, app.session.surface);
    if (app.session.display.split && v.split.renderer)
      upload_overlays(app, v.split, v.split_surface);
    v.overlays_dirty = false;
  }
  const RenderStyle style = style_for(app);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fw, fh);
  glClearColor(style.background.x(), style.background.y(), style.background.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Camera camera = current_camera(app);
  const float scale = framebuffer_scale(app);
  const bool split = app.session.display.split && v.split.renderer;
  const View3D* views[2] = {&v.main, &v.split};
  for (int side = 0; side < (split ? 2 : 1); ++side) {
    const ScreenRect r = view_rect(app, split ? side : 0);
    // Framebuffer pixels, rounded to whole pixels; GL counts rows from the bottom.
    const int x0 = int(std::lround(r.x0 * scale)), x1 = int(std::lround(r.x1 * scale));
    const int y0 = int(std::lround(r.y0 * scale)), y1 = int(std::lround(r.y1 * scale));
    const int w = std::clamp(x1 - x0, 1, fw), h = std::clamp(y1 - y0, 1, fh);
    v.target.resize(w, h);
    v.target.bind();
    views[side]->renderer->draw(camera, style, w, h);
    v.target.present(x0, fh - y0 - h);
  }
  glViewport(0, 0, fw, fh);
}

Ray mouse_ray(const App& app, double x, double y) {
  const bool split = app.session.display.split.has_value();
  const ScreenRect whole = app.layout.viewport;
  const int side = split && x >= (whole.x0 + whole.x1) / 2 ? 1 : 0;
  const ScreenRect r = view_rect(app, side);
  return pixel_ray(current_camera(app), x - r.x0, y - r.y0, int(std::lround(r.width())),
                   int(std::lround(r.height())));
}

}  // namespace stitch::modeler::app
