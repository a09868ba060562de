// ImGui's widgets as the panels and dialogs use them: each records its label in the screen
// layout as it is drawn (layout.hpp), so that the `layout` script line can report every label.
#pragma once

#include <imgui.h>

#include <string>

#include "layout.hpp"

namespace stitch::modeler::app {

/// ImGui's widgets, each recording its label in the layout as it is drawn.
class Widgets {
 public:
  explicit Widgets(ScreenLayout& layout) : layout_(layout) {}
  bool button(const char* label, bool enabled = true) {
    if (!enabled) ImGui::BeginDisabled();
    const bool pressed = ImGui::Button(label);
    if (!enabled) ImGui::EndDisabled();
    record_label(layout_, label);
    return pressed;
  }
  bool radio(const char* label, bool active) {
    const bool pressed = ImGui::RadioButton(label, active);
    record_label(layout_, label);
    return pressed;
  }
  bool checkbox(const char* label, bool* value) {
    const bool changed = ImGui::Checkbox(label, value);
    record_label(layout_, label);
    return changed;
  }
  void text(const std::string& text) {
    ImGui::TextUnformatted(text.c_str());
    record_label(layout_, text);
  }
  void text_disabled(const std::string& text) {
    ImGui::TextDisabled("%s", text.c_str());
    record_label(layout_, text);
  }
  bool header(const char* label, ImGuiTreeNodeFlags flags = 0) {
    const bool open = ImGui::CollapsingHeader(label, flags);
    // The text follows the arrow: a frame padding, the arrow (a font size), a padding.
    const ImGuiStyle& style = ImGui::GetStyle();
    record_label(layout_, label, ImGui::GetFontSize() + 2 * style.FramePadding.x);
    return open;
  }
  bool combo(const char* label, int* current, const char* const items[], int count) {
    const bool changed = ImGui::Combo(label, current, items, count);
    record_label(layout_, label);
    return changed;
  }
  bool slider(const char* label, float* value, float low, float high) {
    const bool changed = ImGui::SliderFloat(label, value, low, high);
    record_label(layout_, label);
    return changed;
  }
  bool slider(const char* label, int* value, int low, int high) {
    const bool changed = ImGui::SliderInt(label, value, low, high);
    record_label(layout_, label);
    return changed;
  }
  bool drag3(const char* label, float* values, float speed) {
    const bool changed = ImGui::DragFloat3(label, values, speed);
    record_label(layout_, label);
    return changed;
  }
  bool input_int(const char* label, int* value) {
    const bool changed = ImGui::InputInt(label, value);
    record_label(layout_, label);
    return changed;
  }

 private:
  ScreenLayout& layout_;
};

/// `text`, shortened with "..." in the middle to at most `width` pixels of the current font:
/// for texts of any length (paths, messages) in panels sized to their fixed content.
std::string elided(const std::string& text, float width);
/// Widths in units of the font size, so that they grow with the font scale.
float ems(float n);

}  // namespace stitch::modeler::app
