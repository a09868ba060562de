// Where things are on the screen: the panels, the 3D view in the area they leave free, the font
// scale, and every label the panels drew in the last frame with the room its window had for it
// (the `layout PATH` script line writes them as JSON, so tests can check that nothing is cut).
// Window coordinates: pixels, origin top left.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace stitch::modeler::app {

struct ScreenRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] float width() const { return x1 - x0; }
  [[nodiscard]] float height() const { return y1 - y0; }
};

/// One label as drawn: its text's box, and its window's box and content region (what the
/// window's padding leaves for items).
struct DrawnLabel {
  std::string window, text;
  ScreenRect box, window_box, content;
};

/// A panel window as drawn.
struct DrawnPanel {
  std::string name;
  ScreenRect box;
};

struct ScreenLayout {
  bool show_ui = true;  ///< the panels (`ui off` in a script hides them, e.g. for pictures)
  float font_scale = 1.0f;
  /// The area the model is drawn in: the window less the panels, menu bar and status bar.
  ScreenRect viewport;
  /// What the last frame drew (cleared when a frame starts).
  std::vector<DrawnPanel> panels;
  std::vector<DrawnLabel> labels;
};

/// Records the label of the item just drawn in the current ImGui window. `text` is what is
/// shown (the part before any "##"); `text_offset` is where the text starts inside the item,
/// for items wider than their text whose text is not at their left edge (a header's arrow).
void record_label(ScreenLayout& layout, std::string_view text, float text_offset = -1.0f);
/// Records the current ImGui window as a panel (call before End()).
void record_panel(ScreenLayout& layout);

}  // namespace stitch::modeler::app
