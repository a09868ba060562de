// The modeler's layout at several window sizes and font scales, checked on ImGui's own layout
// information (the `layout PATH` script line): no label runs past its window's work area, the
// panels stay inside the window, and after `frame all` the model's projected box lies in the
// 3D view's area, clear of the panels. Runs the real application under Xvfb.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "temp_folder.hpp"
#include "test_support.hpp"
#include "xvfb_support.hpp"

namespace stitch::modeler {
namespace {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
Box box_of(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>(), j[3].get<double>()};
}
bool overlap(const Box& a, const Box& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

struct Setting {
  int width = 0, height = 0;
  double font_scale = 1.0;
  std::string name;
  bool split = false;  ///< frame all in the split view: each half is framed
};

/// Runs the modeler on two cubes side by side (a wide model) with corners selected (long
/// labels), frames them in the front view and writes the layout and a screenshot.
nlohmann::json layout_of(const Setting& s, const stitch::testing::TempFolder& dir) {
  const std::string script = dir.write(
      s.name + ".txt",
      "open " + test::example_path("two_cubes.obj") + "\nselect corner 3@1\nselect corner 9@6\n" +
          (s.split ? "split asc\n" : "") +
          "view front\n"
          "frame all\nscreenshot " +
          dir.file(s.name + ".png") + "\nlayout " + dir.file(s.name + ".json") + "\ndialog open " +
          test::example_path("") + "\nlayout " + dir.file(s.name + "_dialog.json") + "\nquit\n");
  const std::string log = dir.file(s.name + ".log");
  // A screen larger than the window, so that the window is not cut by it.
  const std::string screen =
      std::to_string(s.width + 64) + "x" + std::to_string(s.height + 64) + "x24";
  const std::string args = "--size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                           " --font-scale " + std::to_string(s.font_scale) + " --script " + script;
  // The recent files come from the test's folder, not the user's.
  EXPECT_EQ(run_modeler(args, log, screen, "XDG_CONFIG_HOME='" + dir.file("config") + "'"), 0)
      << read_text(log);
  return nlohmann::json::parse(read_text(dir.file(s.name + ".json")));
}

/// Layout tolerance: half a pixel, ImGui's rounding of positions to whole pixels.
constexpr double kPixel = 0.5;

void check_labels(const Setting& s, const nlohmann::json& j) {
  ASSERT_EQ(j["window"][0].get<int>(), s.width);
  ASSERT_EQ(j["window"][1].get<int>(), s.height);
  // Every label ends inside its window's work area (what is beyond it is cut off; a header
  // begins in the padding by design, so only the right edges are compared).
  ASSERT_GT(j["labels"].size(), 40u);  // the panels' labels are there to check
  for (const auto& l : j["labels"]) {
    const Box b = box_of(l["box"]), c = box_of(l["content"]);
    const std::string what =
        l["window"].get<std::string>() + ": \"" + l["text"].get<std::string>() + "\"";
    EXPECT_LE(b.x1, c.x1 + kPixel)
        << what << " ends at " << b.x1 << ", its window's work area at " << c.x1;
  }
  // The panels inside the window.
  std::vector<Box> panels;
  for (const auto& p : j["panels"]) {
    const Box b = box_of(p["box"]);
    const std::string name = p["name"].get<std::string>();
    EXPECT_GE(b.x0, -kPixel) << name;
    EXPECT_GE(b.y0, -kPixel) << name;
    EXPECT_LE(b.x1, s.width + kPixel) << name;
    EXPECT_LE(b.y1, s.height + kPixel) << name;
    panels.push_back(b);
  }
  ASSERT_GE(panels.size(), 3u);  // Edit, Display, the status bar
}

bool has_label(const nlohmann::json& j, const std::string& window, const std::string& text) {
  for (const auto& l : j["labels"])
    if (l["window"].get<std::string>().starts_with(window) && l["text"] == text) return true;
  return false;
}

Box panel_box(const nlohmann::json& j, const std::string& name) {
  for (const auto& p : j["panels"])
    if (p["name"].get<std::string>().starts_with(name)) return box_of(p["box"]);
  ADD_FAILURE() << "no panel " << name;
  return {};
}

void check_layout(const Setting& s, const nlohmann::json& j) {
  SCOPED_TRACE(s.name);
  check_labels(s, j);
  EXPECT_TRUE(has_label(j, "Edit", "Insert edge"));
  std::vector<Box> panels;
  for (const auto& p : j["panels"]) panels.push_back(box_of(p["box"]));
  // The model, framed, inside the (left) view and clear of every panel.
  ASSERT_EQ(j["views"].size(), s.split ? 2u : 1u);
  const Box view = box_of(j["views"][0]);
  ASSERT_FALSE(j["model_box"].is_null());
  const Box model = box_of(j["model_box"]);
  EXPECT_GE(model.x0, view.x0 - kPixel);
  EXPECT_LE(model.x1, view.x1 + kPixel);
  EXPECT_GE(model.y0, view.y0 - kPixel);
  EXPECT_LE(model.y1, view.y1 + kPixel);
  for (size_t i = 0; i < panels.size(); ++i)
    EXPECT_FALSE(overlap(model, panels[i])) << "the model lies under " << j["panels"][i]["name"];
  // Framed, not lost: it fills a good part of the view's narrower side.
  EXPECT_GT(std::max(model.x1 - model.x0, model.y1 - model.y0),
            0.3 * std::min(view.x1 - view.x0, view.y1 - view.y0));
}

/// The frame rate in the status bar, measured (never 0 once a frame has been drawn).
double status_fps(const nlohmann::json& j) {
  const std::regex fps(R"(\| ([0-9]+) fps \|)");
  for (const auto& l : j["labels"]) {
    std::smatch m;
    const std::string text = l["text"].get<std::string>();
    if (std::regex_search(text, m, fps)) return std::stod(m[1]);
  }
  return -1;
}

TEST(ModelerXvfbLayout, PanelsFitAndFrameAllFramesBesideThem) {
  if (!have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb); skipping the GUI test";
  stitch::testing::TempFolder dir;
  const Setting settings[] = {{1280, 720, 1.0, "hd"},
                              {1920, 1080, 1.0, "full_hd"},
                              {1280, 720, 1.5, "hd_font_1.5"},
                              {1280, 720, 1.0, "hd_split", true}};
  std::vector<nlohmann::json> layouts;
  for (const Setting& s : settings) {
    // A recent file for the Open dialog to list.
    std::filesystem::create_directories(dir.file("config/stitch"));
    dir.write("config/stitch/recent-files", test::example_path("torus.obj") + "\n");
    layouts.push_back(layout_of(s, dir));
    check_layout(s, layouts.back());
    // The Open dialog over the examples: its labels fit too, it lists the meshes, folders
    // first, and the recent file.
    const auto dialog = nlohmann::json::parse(read_text(dir.file(s.name + "_dialog.json")));
    SCOPED_TRACE(s.name + " dialog");
    check_labels(s, dialog);
    EXPECT_TRUE(has_label(dialog, "Open", "cube.obj"));
    EXPECT_TRUE(has_label(dialog, "Open", "two_cubes.obj"));
    EXPECT_TRUE(has_label(dialog, "Open", "Recent files"));
    EXPECT_GT(panel_box(dialog, "Open").x1, 0);
    EXPECT_GT(status_fps(layouts.back()), 0) << s.name;
    const Png shot = load_png(dir.file(s.name + ".png"));
    EXPECT_EQ(shot.width, s.width);
    EXPECT_GT(colours(shot), 50u);
  }
  // The font scale scales the text: the same label is 1.5 times as high (to a pixel).
  auto height_of = [](const nlohmann::json& j, const std::string& text) {
    for (const auto& l : j["labels"])
      if (l["text"] == text) return box_of(l["box"]).y1 - box_of(l["box"]).y0;
    return -1.0;
  };
  const double plain = height_of(layouts[0], "Frame all"),
               large = height_of(layouts[2], "Frame all");
  ASSERT_GT(plain, 0);
  EXPECT_NEAR(large / plain, 1.5, 1.0 / plain);
}

}  // namespace
}  // namespace stitch::modeler
