// Per-element K-gon controls reach `stitch`: a project saved by the modeler, and a K-gon
// controls file beside a mesh file, smooth to the very surface the modeler exports.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/modeler/session.hpp"
#include "stitch/project/kgon_controls.hpp"
#include "stitch/project/project_file.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"

namespace stitch::modeler {
namespace {

using stitch::testing::read_file;
using stitch::testing::stitch_cli;
using stitch::testing::TempFolder;

/// Shapes a cube's K-gons through every kind of control, as a modeler user would.
const std::vector<std::string> kShaping = {
    "select face 2",         "kgon scale 0.6", "select vertex 7", "kgon offset 0 0 0.2",
    "select edge 6 7",       "kgon rotate 15", "select vertex 1", "kgon regularize on",
    "kgon global rotate 10", "method asc",     "resolution 5"};

TEST(ProjectFromTheCommandLine, SmoothsToTheSurfaceTheModelerExports) {
  TempFolder dir;
  Session s(make_cube());
  std::vector<std::string> script = kShaping;
  script.push_back("export " + dir.file("modeler.ply"));
  script.push_back("save " + dir.file("shaped.stitch"));
  ASSERT_FALSE(run_script(s, script, {}));
  ASSERT_EQ(s.document.kgon_options().face.size(), 1u);
  ASSERT_EQ(s.document.kgon_options().edge.size(), 1u);

  // The project's method (asc) is used: --method is not given.
  const auto run = stitch_cli(dir, "smooth shaped.stitch -o cli.ply --resolution 5");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("method asc"), std::string::npos) << run.out;
  EXPECT_EQ(read_file(dir.file("cli.ply")), read_file(dir.file("modeler.ply")));

  // The controls matter: without them, or with another method, the surface differs.
  write_mesh(dir.file("plain.obj"), make_cube());
  ASSERT_EQ(stitch_cli(dir, "smooth plain.obj -o plain.ply --resolution 5 --method asc").status, 0);
  EXPECT_NE(read_file(dir.file("plain.ply")), read_file(dir.file("modeler.ply")));
  ASSERT_EQ(stitch_cli(dir, "smooth shaped.stitch -o mdc.ply --resolution 5 --method mdc").status,
            0);
  EXPECT_NE(read_file(dir.file("mdc.ply")), read_file(dir.file("modeler.ply")));

  // A flag given replaces the project's global control; the per-element ones stay.
  ASSERT_FALSE(run_script(s, {"kgon global rotate 0", "export " + dir.file("unrotated.ply")}, {}));
  ASSERT_EQ(
      stitch_cli(dir, "smooth shaped.stitch -o flag.ply --resolution 5 --kgon-rotate 0").status, 0);
  EXPECT_EQ(read_file(dir.file("flag.ply")), read_file(dir.file("unrotated.ply")));
}

TEST(ProjectFromTheCommandLine, RenderAndAnalyzeReadProjectsToo) {
  TempFolder dir;
  Session s(make_cube());
  std::vector<std::string> script = kShaping;
  script.push_back("save " + dir.file("shaped.stitch"));
  ASSERT_FALSE(run_script(s, script, {}));
  const auto analyze = stitch_cli(dir, "analyze shaped.stitch --json");
  ASSERT_EQ(analyze.status, 0) << analyze.err;
  // The project's method replaces analyze's default (all methods).
  EXPECT_NE(analyze.out.find("\"asc\""), std::string::npos) << analyze.out;
  EXPECT_EQ(analyze.out.find("\"mdc\""), std::string::npos) << analyze.out;
  const auto render = stitch_cli(dir, "render shaped.stitch -o p.png --size 64x48");
  ASSERT_EQ(render.status, 0) << render.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("p.png")));
}

TEST(KgonControlsFile, GivesAMeshFileTheModelersControls) {
  TempFolder dir;
  Session s(make_cube());
  std::vector<std::string> script = kShaping;
  script.push_back("export " + dir.file("modeler.ply"));
  ASSERT_FALSE(run_script(s, script, {}));
  write_mesh(dir.file("cube.obj"), make_cube());
  // 1-based numbers as in the file; the edge by its ends, as operation lines write it.
  dir.write("controls.json", R"({
  "format": "stitch-kgon-controls",
  "controls": [
    {"face": 2, "scale": 0.6},
    {"vertex": 7, "offset": [0, 0, 0.2]},
    {"edge": "6 7", "rotate": 15},
    {"vertex": 1, "regularize": true}
  ]
})");
  const auto run = stitch_cli(dir,
                              "smooth cube.obj -o cli.ply --resolution 5 --method asc "
                              "--kgon-rotate 10 --kgon-controls controls.json");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(read_file(dir.file("cli.ply")), read_file(dir.file("modeler.ply")));

  // The same edge by the library's number.
  KgonOptions by_ends, by_number;
  const HalfedgeMesh cube = make_cube();
  parse_kgon_controls(R"({"controls": [{"edge": "6 7", "scale": 2}]})", "a", cube, by_ends);
  ASSERT_EQ(by_ends.edge.size(), 1u);
  const int edge = by_ends.edge.begin()->first;
  parse_kgon_controls(
      R"({"controls": [{"edge": )" + std::to_string(edge + 1) + R"(, "scale": 2}]})", "b", cube,
      by_number);
  EXPECT_EQ(by_number.edge, by_ends.edge);

  KgonOptions stretched;
  parse_kgon_controls(R"({"controls": [{"face": 2, "stretch": 1.5, "stretch_along": [0, 0, 2]}]})",
                      "c", cube, stretched);
  EXPECT_EQ(stretched.face.at(1), (KgonControl{.stretch = 1.5, .stretch_along = Vec3(0, 0, 2)}));
}

TEST(KgonControlsFile, BadFilesSayWhereAndExitWithTwo) {
  TempFolder dir;
  write_mesh(dir.file("cube.obj"), make_cube());
  struct Bad {
    std::string text, expected;
  };
  for (const Bad& bad : std::vector<Bad>{
           {"{\"controls\": [\n  {\"face\": 1,}\n]}", "line 2"},
           {R"({"controls": [{"face": 7, "scale": 2}]})", "control 1: there is no face 7"},
           {R"({"controls": [{"face": 1}, {"vertex": 0}]})", "control 2: there is no vertex 0"},
           {R"({"controls": [{"face": 1.5}]})", "whole number"},
           {R"({"controls": [{"face": 1, "scael": 2}]})", "unknown member \"scael\""},
           {R"({"controls": [{"scale": 2}]})", "name the element"},
           {R"({"controls": [{"face": 1, "vertex": 2}]})", "name one element"},
           {R"({"controls": [{"face": 1, "scale": 0}]})", "control 1 (face 1): the scale"},
           {R"({"controls": [{"face": 3}, {"face": 3, "rotate": 5}]})", "control 1 already"},
           {R"({"controls": [{"edge": "1 7"}]})", "control 1"},
           {R"({"controls": [{"face": 2, "offset": [0, 1]}]})", "offset"},
           {R"({"controls": [{"face": 2, "stretch_along": [0, 1]}]})", "\"stretch_along\" must"},
           {R"({"controls": [{"face": 2, "stretch": -1}]})", "control 1 (face 2): the stretch"},
           {R"([{"face": 1}])", "\"controls\" array"},
       }) {
    SCOPED_TRACE(bad.text);
    dir.write("bad.json", bad.text);
    const auto run = stitch_cli(dir, "smooth cube.obj -o out.ply --kgon-controls bad.json");
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.err.find("bad.json: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(bad.expected), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.ply")));
  }
  // A file that is not there, and a project that is not one.
  EXPECT_EQ(stitch_cli(dir, "smooth cube.obj -o out.ply --kgon-controls none.json").status, 2);
  dir.write("not.stitch", R"({"format": "something else"})");
  const auto run = stitch_cli(dir, "smooth not.stitch -o out.ply");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("not.stitch: not a stitch modeler project"), std::string::npos) << run.err;
}

TEST(ProjectFile, RoundTripsControlsAcrossHolesAndDeletedElements) {
  // A deleted face leaves a gap and a hole sits between live faces: the saved numbers must
  // still name the same elements when read back.
  Session s(make_cube());
  ASSERT_FALSE(
      run_script(s,
                 {"insert-edge 1@1 5@2", "open-face 4", "select face 6", "kgon scale 0.5",
                  "select vertex 7", "kgon rotate 20", "select edge 2 3", "kgon scale 1.5"},
                 {}));
  const HalfedgeMesh& m = s.document.mesh();
  const std::string text = write_project_json(m, s.document.kgon_options());
  const ProjectFile back = parse_project_json(text, "p");
  // Compare through positions: the numbers differ (compacted), the places must not.
  auto face_centre = [](const HalfedgeMesh& mesh, int f) {
    Vec3 c = Vec3::Zero();
    for (Halfedge h : mesh.face_loop(Face(f))) c += mesh.position(mesh.origin(h));
    return Vec3(c / mesh.degree(Face(f)));
  };
  auto edge_mid = [](const HalfedgeMesh& mesh, int e) {
    const Halfedge h = HalfedgeMesh::halfedge(Edge(e), 0);
    return Vec3(0.5 * (mesh.position(mesh.origin(h)) + mesh.position(mesh.target(h))));
  };
  const KgonOptions& k = s.document.kgon_options();
  ASSERT_EQ(back.kgons.face.size(), k.face.size());
  ASSERT_EQ(back.kgons.vertex.size(), k.vertex.size());
  ASSERT_EQ(back.kgons.edge.size(), k.edge.size());
  EXPECT_LT((face_centre(back.mesh, back.kgons.face.begin()->first) -
             face_centre(m, k.face.begin()->first))
                .norm(),
            1e-12);
  EXPECT_EQ(back.kgons.face.begin()->second, k.face.begin()->second);
  EXPECT_EQ(back.mesh.position(Vertex(back.kgons.vertex.begin()->first)),
            m.position(Vertex(k.vertex.begin()->first)));
  EXPECT_LT(
      (edge_mid(back.mesh, back.kgons.edge.begin()->first) - edge_mid(m, k.edge.begin()->first))
          .norm(),
      1e-12);
}

TEST(ProjectFile, ControlsAreWrittenByTheFieldsSetAndReadStrictly) {
  KgonOptions k;
  k.face[1] = KgonControl{.stretch = 1.5, .stretch_along = Vec3(0, 0, 2)};
  const std::string text = write_project_json(make_cube(), k);
  // Only the fields that differ from no change are written; the rest read back as defaults.
  const auto saved = nlohmann::json::parse(text)["kgons"];
  EXPECT_EQ(saved["global"], nlohmann::json::object());
  EXPECT_EQ(saved["faces"][0],
            nlohmann::json::parse(R"({"face": 1, "stretch": 1.5, "stretch_along": [0, 0, 2]})"));
  EXPECT_EQ(parse_project_json(text, "p").kgons.face, k.face);

  // The saved face control, changed into what a hand-edited file might hold.
  using nlohmann::json;
  struct Bad {
    json control;
    std::string expected;
  };
  for (const Bad& bad : std::vector<Bad>{
           {{{"face", 1}, {"strech_along", {0, 0, 2}}},
            "p: K-gon control of face 1: unknown member \"strech_along\" (scale, rotate"},
           {{{"face", 1}, {"stretch", "long"}},
            "p: K-gon control of face 1: \"stretch\" must be a number"},
           {{{"face", 1}, {"stretch_along", {0, 2}}},
            "p: K-gon control of face 1: \"stretch_along\" must be an array of 3 numbers"},
           {{{"face", 1}, {"regularize", 1}},
            "p: K-gon control of face 1: \"regularize\" must be true or false"},
           {{{"face", 1}, {"stretch", 0}},
            "p: K-gon control of face 1: the stretch must be a number from"},
       }) {
    SCOPED_TRACE(bad.control.dump());
    json broken = json::parse(text);
    broken["kgons"]["faces"][0] = bad.control;
    try {
      parse_project_json(broken.dump(), "p");
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(bad.expected, 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace stitch::modeler
