// The state of the modeler application, in pieces by concern: the session (the window-free
// document, view and surface), the 3D views and their GPU buffers, picking, the mouse gesture in
// progress, the panels' fields, the dialogs, autosave, frame timing and the screen layout.
#pragma once

#include <epoxy/gl.h>  // before GLFW, which must not include GL headers itself
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "file_dialog.hpp"
#include "gl_objects.hpp"
#include "layout.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/render/renderer.hpp"

namespace stitch::modeler::app {

using Clock = std::chrono::steady_clock;

/// What a Renderer shows and whether its buffers are current.
struct View3D {
  std::unique_ptr<Renderer> renderer;
  bool input_uploaded = false;  ///< the input polygons are uploaded instead of the surface
  bool geometry_dirty = true;   ///< everything must be uploaded again
};

/// The main view, the split view's second method, and the buffers they are drawn into.
struct SceneViews {
  View3D main, split;
  IncrementalSurface split_surface;  ///< the second method of the split view
  KgonOptions split_kgons;           ///< the controls split_surface was built with
  bool split_current = false;
  bool overlays_dirty = true;
  OffscreenTarget target;
};

/// What the mouse picks, and the pick before the selection (two-element operations use both).
struct Picking {
  PickKind kind = PickKind::vertex;
  std::optional<Pick> previous;
};

enum class DragTool { view_plane, axis_x, axis_y, axis_z };

/// The mouse gesture in progress (a press, then drags, then the release).
struct MouseGesture {
  int button = -1;  ///< the button held, -1 for none
  bool moved = false;
  bool dragging_vertex = false;
  bool vertex_moved = false;  ///< the vertex drag has recorded its move (its undo step)
  double press_x = 0, press_y = 0, last_x = 0, last_y = 0;
  Vec3 drag_origin = Vec3::Zero();
  DragTool tool = DragTool::view_plane;
};

/// What the panels' fields hold between frames.
struct PanelFields {
  std::array<char, 512> command_line{};
  double extrude_distance = 0.5;
  int connect_twist = 0;
  bool connect_least_twist = true;  ///< connect-faces picks the twist (least_twist)
  int primitive_index = 1;
  bool kgon_global = false;  ///< edit the global K-gon control whatever is selected
};

struct Autosave {
  bool enabled = true;
  Clock::time_point last = Clock::now();
  /// An autosave newer than the document, offered in a dialog at start; empty when none.
  std::string offered_path;
  bool offer_pending = false;
};

/// Frame times measured as they happen: the time to draw a frame (until the GL has finished
/// it), and the rate frames are shown at while the window runs its loop.
struct FrameTimer {
  static constexpr int kKept = 15;
  std::array<double, kKept> draw_ms{};  ///< the last frames' drawing times, a ring
  int drawn_count = 0;
  double shown_fps = 0.0;  ///< frames shown per second in the loop (0 until it has run)
  std::optional<Clock::time_point> last_shown;
  void drawn(double milliseconds);
  void shown(Clock::time_point when);
  /// The median drawing time of the last frames (0 before the first).
  [[nodiscard]] double median_draw_ms() const;
  /// The rate for the status bar: frames shown per second while looping; in a script, where
  /// frames are drawn only for screenshots, the rate the median drawing time allows.
  [[nodiscard]] double fps() const;
};

struct App {
  explicit App(GLFWwindow* window);
  Session session;
  GLFWwindow* window;
  ScriptHooks hooks;
  SceneViews views;
  Picking picking;
  MouseGesture mouse;
  PanelFields fields;
  FileDialogs files;
  Autosave autosave;
  FrameTimer frames;
  ScreenLayout layout;
  std::string status = "ready";
};

}  // namespace stitch::modeler::app
