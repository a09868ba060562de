// Project files: what is saved comes back, per-element K-gon controls stay on their elements
// even when saving compacts the numbering, and bad files are refused with their name.
#include "stitch/modeler/project.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"

namespace stitch::modeler {
namespace {

Project sample() {
  Project p;
  p.state.mesh = make_cube();
  KgonControl c;
  c.scale = 0.75;
  c.rotate_deg = 10;
  c.offset = Vec3(0.1, 0.2, 1.0 / 3.0);
  p.state.kgons.face[2] = c;
  c.regularize = true;
  c.stretch = 1.25;
  c.stretch_along = Vec3(0, 0.5, 1);
  p.state.kgons.vertex[6] = c;
  p.state.kgons.edge[5] = c;
  p.state.kgons.global.scale = 0.9;
  p.view.yaw_deg = 33;
  p.view.up = UpAxis::y;
  p.view.target = Vec3(0.1, 0.2, 0.3);
  p.display.method = Method::asc;
  p.display.mode = ShadingMode::zebra;
  p.display.resolution = 5;
  p.display.overlays[1] = true;
  p.display.split = Method::cc;
  return p;
}

TEST(ModelerProject, RoundTripsExactly) {
  stitch::testing::TempFolder dir;
  const Project p = sample();
  const std::string path = (dir.path() / "a.stitch").string();
  save_project(path, p);
  const Project q = load_project(path);
  EXPECT_TRUE(q.state.mesh == p.state.mesh);
  EXPECT_EQ(q.state.kgons.face, p.state.kgons.face);
  EXPECT_EQ(q.state.kgons.vertex, p.state.kgons.vertex);
  EXPECT_EQ(q.state.kgons.edge, p.state.kgons.edge);
  EXPECT_EQ(q.state.kgons.global, p.state.kgons.global);
  EXPECT_EQ(q.view, p.view);
  EXPECT_EQ(q.display, p.display);
  EXPECT_EQ(project_to_json(q), project_to_json(p));
}

TEST(ModelerProject, ControlsFollowTheirElementsThroughCompaction) {
  Project p = sample();
  apply_operation(p.state.mesh, "insert-edge 1@1 5@2");  // removes face 2: a gap in the numbers
  apply_operation(p.state.mesh, "subdivide-edge 2 3");
  p.state.kgons.face.clear();
  p.state.kgons.face[4] = KgonControl{0.5, 0, Vec3::Zero(), false};
  const Project q = project_from_json(project_to_json(p), "test");
  // The same K-gons, built from both meshes, compared in live-element order.
  const KgonSet a = build_kgons(p.state.mesh, p.state.kgons),
                b = build_kgons(q.state.mesh, q.state.kgons);
  const auto fa = p.state.mesh.faces().to_vector(), fb = q.state.mesh.faces().to_vector();
  ASSERT_EQ(fa.size(), fb.size());
  for (size_t i = 0; i < fa.size(); ++i)
    EXPECT_EQ(a.face[fa[i].idx].points, b.face[fb[i].idx].points);
  const auto va = p.state.mesh.vertices().to_vector(), vb = q.state.mesh.vertices().to_vector();
  for (size_t i = 0; i < va.size(); ++i)
    EXPECT_EQ(a.vertex[va[i].idx].points, b.vertex[vb[i].idx].points);
  double sum_a = 0, sum_b = 0;  // edges are renumbered: compare the sets through a checksum
  for (Edge e : p.state.mesh.edges()) sum_a += a.edge[e.idx].centroid.sum();
  for (Edge e : q.state.mesh.edges()) sum_b += b.edge[e.idx].centroid.sum();
  EXPECT_NEAR(sum_a, sum_b, 1e-12);  // the order of summation differs: round-off only
}

TEST(ModelerProject, BadFilesAreRefusedWithTheirName) {
  EXPECT_THROW(
      {
        try {
          project_from_json("{ not json", "broken.stitch");
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("broken.stitch"), std::string::npos);
          throw;
        }
      },
      Error);
  std::string text = project_to_json(sample());
  text.replace(text.find("\"asc\""), 5, "\"xyz\"");  // the method
  EXPECT_THROW(project_from_json(text, "m.stitch"), Error);
  EXPECT_THROW(project_from_json("{\"format\": \"other\"}", "x.stitch"), Error);
  EXPECT_THROW(load_project("/nonexistent/file.stitch"), Error);
}

TEST(ModelerProject, AutosavePaths) {
  EXPECT_EQ(autosave_path("/a/b/model.obj"), "/a/b/.model.obj.autosave.stitch");
  EXPECT_TRUE(is_project_path("x.stitch"));
  EXPECT_TRUE(is_project_path("x.JSON"));
  EXPECT_FALSE(is_project_path("x.obj"));
  stitch::testing::TempFolder dir;
  ::setenv("XDG_DATA_HOME", dir.path().c_str(), 1);
  EXPECT_EQ(autosave_path(""), (dir.path() / "stitch" / "autosave" / "untitled.stitch").string());
  ::unsetenv("XDG_DATA_HOME");
  const std::string doc = (dir.path() / "m.obj").string(), save = autosave_path(doc);
  EXPECT_FALSE(autosave_is_newer(save, doc));
  std::ofstream(doc) << "x";
  std::filesystem::last_write_time(
      doc, std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
  std::ofstream(save) << "y";
  EXPECT_TRUE(autosave_is_newer(save, doc));
}

}  // namespace
}  // namespace stitch::modeler
