#include "layout_report.hpp"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "stitch/mesh/io.hpp"
#include "viewport.hpp"

namespace stitch::modeler::app {

namespace {

nlohmann::json box(const ScreenRect& r) {
  return nlohmann::json::array({r.x0, r.y0, r.x1, r.y1});
}

/// The input mesh's box, projected into the (left) view: the smallest screen rectangle holding
/// its eight corners. Null when a corner is behind the eye.
nlohmann::json projected_model_box(const App& app) {
  const BoundingBox b = app.session.mesh_bounds();
  if (b.empty()) return nullptr;
  const ScreenRect r = view_rect(app, 0);
  const Camera camera = current_camera(app);
  const Eigen::Matrix4f m =
      projection_matrix(camera, r.width() / std::max(r.height(), 1.0f)) * view_matrix(camera);
  ScreenRect out{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                 std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest()};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? b.max.x() : b.min.x(), corner & 2 ? b.max.y() : b.min.y(),
                 corner & 4 ? b.max.z() : b.min.z());
    const Eigen::Vector4f clip = m * Eigen::Vector4f(float(p.x()), float(p.y()), float(p.z()), 1);
    if (clip.w() <= 0) return nullptr;
    const float x = r.x0 + (clip.x() / clip.w() + 1) / 2 * r.width();
    const float y = r.y0 + (1 - clip.y() / clip.w()) / 2 * r.height();
    out = {std::min(out.x0, x), std::min(out.y0, y), std::max(out.x1, x), std::max(out.y1, y)};
  }
  return box(out);
}

}  // namespace

void write_layout_report(const App& app, const std::string& path) {
  const ScreenLayout& l = app.layout;
  int w = 0, h = 0;
  glfwGetWindowSize(app.window, &w, &h);
  nlohmann::json j;
  j["window"] = {w, h};
  j["font_scale"] = l.font_scale;
  j["viewport"] = box(l.viewport);
  j["views"] = nlohmann::json::array({box(view_rect(app, 0))});
  if (app.session.display.split) j["views"].push_back(box(view_rect(app, 1)));
  j["panels"] = nlohmann::json::array();
  for (const DrawnPanel& p : l.panels)
    j["panels"].push_back({{"name", p.name}, {"box", box(p.box)}});
  j["labels"] = nlohmann::json::array();
  for (const DrawnLabel& d : l.labels)
    j["labels"].push_back({{"window", d.window},
                           {"text", d.text},
                           {"box", box(d.box)},
                           {"window_box", box(d.window_box)},
                           {"content", box(d.content)}});
  j["model_box"] = projected_model_box(app);
  const std::string text = j.dump(1);
  write_file_atomically(path, [&](std::ostream& out) { out << text << "\n"; });
}

}  // namespace stitch::modeler::app
