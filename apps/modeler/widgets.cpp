#include "widgets.hpp"

namespace stitch::modeler::app {

std::string elided(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  const std::string dots = "...";
  size_t keep = text.size();
  std::string out;
  do {
    --keep;
    out = text.substr(0, keep / 2) + dots + text.substr(text.size() - (keep - keep / 2));
  } while (keep > 0 && ImGui::CalcTextSize(out.c_str()).x > width);
  return out;
}

float ems(float n) {
  return n * ImGui::GetFontSize();
}

}  // namespace stitch::modeler::app
