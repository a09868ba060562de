#include "layout.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // the current window's name and work rectangle

#include <algorithm>

namespace stitch::modeler::app {

namespace {

ScreenRect rect(const ImVec2& min, const ImVec2& max) {
  return {min.x, min.y, max.x, max.y};
}

}  // namespace

void record_label(ScreenLayout& layout, std::string_view text, float text_offset) {
  const std::string_view shown = text.substr(0, text.find("##"));
  if (shown.empty()) return;
  const ImVec2 item_min = ImGui::GetItemRectMin(), item_max = ImGui::GetItemRectMax();
  const ImVec2 size = ImGui::CalcTextSize(shown.data(), shown.data() + shown.size());
  DrawnLabel l;
  l.window = ImGui::GetCurrentWindow()->Name;
  l.text = std::string(shown);
  // The item's box holds the label for buttons, check boxes, sliders and text; an item as wide
  // as its window (a header) holds it at text_offset.
  const float right = text_offset >= 0 ? item_min.x + text_offset + size.x : item_max.x;
  l.box = {item_min.x, item_min.y, std::max(right, item_min.x + size.x), item_max.y};
  const ImVec2 pos = ImGui::GetWindowPos();
  l.window_box =
      rect(pos, ImVec2(pos.x + ImGui::GetWindowWidth(), pos.y + ImGui::GetWindowHeight()));
  // The work rectangle: the window less its padding and scroll bars, where items are laid out.
  const ImRect work = ImGui::GetCurrentWindow()->WorkRect;
  l.content = rect(work.Min, work.Max);
  layout.labels.push_back(std::move(l));
}

void record_panel(ScreenLayout& layout) {
  const ImVec2 pos = ImGui::GetWindowPos();
  layout.panels.push_back(
      {ImGui::GetCurrentWindow()->Name,
       rect(pos, ImVec2(pos.x + ImGui::GetWindowWidth(), pos.y + ImGui::GetWindowHeight()))});
}

}  // namespace stitch::modeler::app
