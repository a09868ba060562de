// The exact surface out: the patch set against exact evaluation, Bézier JSON and STL read back,
// glTF through the Khronos validator, `stitch eval`, and the refusals of bad output requests.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cli_run.hpp"
#include "gltf_validator.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/patches.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using testing::stitch_cli;
using testing::TempFolder;

double angle_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

/// Every patch against Surface::evaluate at random interior points of its cell (not the grid
/// the depth was chosen on). Exact cells are the surface at the same (u, v) up to the round-off
/// of evaluating the same polynomial with and without moving it to the origin first (1e-12 of
/// the model size is a thousand times that round-off); inexact ones are within the tolerances
/// asked for of the surface's nearest point: the distance, and half the angle tolerance.
void expect_patches_match_surface(const Surface& surface, const PatchSet& set) {
  std::mt19937 random(12);
  std::uniform_real_distribution<double> unit(0.01, 0.99);
  double worst_exact = 0, worst_inexact = 0, worst_angle = 0;
  for (const BezierPatch& patch : set.patches)
    for (int k = 0; k < 4; ++k) {
      const double s = unit(random), t = unit(random);
      const auto [u, v] = cell_to_root(patch, s, t);
      const SurfacePoint cell = evaluate_cell(patch, s, t);
      if (patch.exact) {
        const SurfacePoint exact = surface.evaluate(patch.corner, u, v);
        worst_exact = std::max(worst_exact, (cell.position - exact.position).norm());
      } else {
        const SurfacePoint nearest = nearest_on_surface(surface, patch.corner, cell.position, u, v);
        worst_inexact = std::max(worst_inexact, (cell.position - nearest.position).norm());
        worst_angle = std::max(worst_angle, angle_deg(cell.normal, nearest.normal));
      }
    }
  EXPECT_LE(worst_exact, 1e-12 * set.model_size);
  EXPECT_LE(worst_inexact, set.tolerance * set.model_size);
  EXPECT_LE(worst_angle, set.angle_tolerance_deg / 2);
}

TEST(BezierPatches, RegularPatchesAreTheNetsAndTheHierarchyIsWithinTolerance) {
  for (const char* name : {"cube.obj", "cube_hole.obj", "torus.obj"}) {
    SCOPED_TRACE(name);
    const HalfedgeMesh mesh = read_mesh(test::example_path(name));
    const Surface surface(mesh, Method::mdc);
    const PatchSet set = bezier_patches(mesh, surface);
    // Each root's cells tile its square (their areas 4^-level add up to 1, computed exactly in
    // binary); a root with k extraordinary corners that was split has one innermost cell per
    // extraordinary corner, the rest exact.
    std::map<int, double> area;
    std::map<int, int> inexact, cells;
    for (const BezierPatch& p : set.patches) {
      area[p.corner.idx] += std::ldexp(1.0, -2 * p.level);
      inexact[p.corner.idx] += p.exact ? 0 : 1;
      ++cells[p.corner.idx];
    }
    int extraordinary_corners = 0;
    for (Corner c : surface.corners()) {
      const int k = std::popcount(unsigned(surface.bezier().nets[c.idx].extraordinary));
      extraordinary_corners += k;
      EXPECT_EQ(area[c.idx], 1.0);
      if (k == 0) {
        EXPECT_EQ(cells[c.idx], 1);
        EXPECT_EQ(inexact[c.idx], 0);
      } else if (cells[c.idx] > 1) {
        EXPECT_EQ(inexact[c.idx], k);
      }
    }
    EXPECT_EQ(set.depth > 0, extraordinary_corners > 0);
    for (const BezierPatch& p : set.patches) {
      if (p.level != 0) continue;
      EXPECT_EQ(p.net.p, surface.bezier().nets[p.corner.idx].p);  // a regular root, as it is
    }
    EXPECT_LE(set.max_position_deviation, set.tolerance * set.model_size);
    EXPECT_LE(set.max_normal_deviation_deg, set.angle_tolerance_deg / 2);
    expect_patches_match_surface(surface, set);
  }
}

TEST(BezierPatches, TighterToleranceGoesDeeperAndAscNeedsNoSplits) {
  const HalfedgeMesh mesh = read_mesh(test::example_path("cube.obj"));
  const Surface mdc(mesh, Method::mdc);
  const PatchSet coarse = bezier_patches(mesh, mdc, {1e-3, 1.0});
  const PatchSet fine = bezier_patches(mesh, mdc, {1e-8, 0.01});
  EXPECT_LT(coarse.depth, fine.depth);
  expect_patches_match_surface(mdc, fine);
  const Surface asc(mesh, Method::asc);
  const PatchSet plain = bezier_patches(mesh, asc);
  EXPECT_EQ(plain.depth, 0);
  EXPECT_EQ(plain.patches.size(), mdc.corners().size());
  EXPECT_EQ(plain.num_exact(), static_cast<int>(plain.patches.size()));
}

TEST(BezierPatches, PointsWithoutANormalAreNamedAndLeftOutOfTheAngleTolerance) {
  // catmark_inf_crease0: an infinitely sharp crease ends in a cone at vertex 19, where the
  // surface has no tangent plane; no depth brings the innermost cell's normal there to the
  // surface's. The patch set still meets both tolerances everywhere else and names the point.
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_inf_crease0.obj"));
  const Surface surface(mesh, Method::mdc);
  const PatchSet set = bezier_patches(mesh, surface);
  ASSERT_EQ(set.points_without_normal.size(), 1u);
  const PointWithoutNormal& point = set.points_without_normal.front();
  EXPECT_EQ(describe(mesh, point), "vertex 19");
  EXPECT_NE(vertex_kind(mesh, Vertex(point.index), KgonOptions{}), VertexKind::smooth);
  EXPECT_GT(point.angle_deg, set.angle_tolerance_deg);
  EXPECT_LE(set.max_position_deviation, set.tolerance * set.model_size);
  EXPECT_LE(set.max_normal_deviation_deg, set.angle_tolerance_deg / 2);
  // Positions hold everywhere: every patch against the surface at random points.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const BezierPatch& patch : set.patches)
    for (int k = 0; k < 4; ++k) {
      const double s = unit(random), t = unit(random);
      const auto [u, v] = cell_to_root(patch, s, t);
      const Vec3 point = evaluate_cell(patch, s, t).position;
      EXPECT_LE((point - nearest_on_surface(surface, patch.corner, point, u, v).position).norm(),
                set.tolerance * set.model_size);
    }
}

TEST(BezierPatches, RefusesCatmullClarkAndToleranceNotAboveZero) {
  const HalfedgeMesh mesh = test::tetrahedron_mesh();
  const Surface mdc(mesh, Method::mdc);
  EXPECT_THROW(bezier_patches(mesh, Surface(mesh, Method::cc)), UsageError);
  for (double bad : {0.0, -1e-6, std::nan("")}) {
    EXPECT_THROW(bezier_patches(mesh, mdc, {bad, 0.1}), UsageError);
    EXPECT_THROW(bezier_patches(mesh, mdc, {1e-6, bad}), UsageError);
  }
  // Beyond what double precision reaches, the depth cap refuses instead of looping.
  EXPECT_THROW(bezier_patches(mesh, mdc, {1e-30, 0.1, 20}), Error);
}

TEST(BezierJson, ReadsBackBitForBit) {
  TempFolder folder;
  const HalfedgeMesh mesh = read_mesh(test::example_path("cube_hole.obj"));
  const Surface surface(mesh, Method::mdc);
  const PatchSet set = bezier_patches(mesh, surface);
  const std::string path = folder.file("hole.bez.json");
  write_bezier_json(path, set, &surface.bezier().kgons);
  const PatchSet back = read_bezier_json(path);
  ASSERT_EQ(back.patches.size(), set.patches.size());
  EXPECT_EQ(back.depth, set.depth);
  EXPECT_EQ(back.method, set.method);
  EXPECT_EQ(back.max_position_deviation, set.max_position_deviation);
  // Numbers are written as the shortest text that reads back as the same double, so the
  // polynomials are the same and evaluate the same: well within 1e-15 relative.
  double worst = 0;
  for (size_t i = 0; i < set.patches.size(); ++i) {
    const BezierPatch &a = set.patches[i], &b = back.patches[i];
    EXPECT_EQ(a.net.p, b.net.p);
    EXPECT_EQ(a.corner, b.corner);
    EXPECT_EQ(a.face, b.face);
    EXPECT_EQ(a.vertex, b.vertex);
    EXPECT_EQ(a.occurrence, b.occurrence);
    EXPECT_EQ(a.level, b.level);
    EXPECT_EQ(a.cell_u, b.cell_u);
    EXPECT_EQ(a.cell_v, b.cell_v);
    EXPECT_EQ(a.exact, b.exact);
    for (double s : {0.1, 0.5, 0.9}) {
      const SurfacePoint pa = evaluate_cell(a, s, 1 - s), pb = evaluate_cell(b, s, 1 - s);
      worst = std::max(worst, (pa.position - pb.position).norm() / set.model_size);
    }
  }
  EXPECT_LE(worst, 1e-15);
  const nlohmann::json doc = nlohmann::json::parse(testing::read_file(path));
  EXPECT_EQ(doc["version"], kBezierJsonVersion);
  EXPECT_EQ(doc["kgons"]["face"].size(), size_t(mesh.num_faces()));
  // Each patch names its corner as operations and STEP do; the 10-sided face has V@F#k names.
  int repeated = 0;
  for (size_t i = 0; i < set.patches.size(); ++i) {
    const std::string name = doc["patches"][i]["corner_name"];
    EXPECT_EQ(name, corner_name(mesh, set.patches[i].corner));
    EXPECT_EQ(parse_corner(mesh, name), set.patches[i].corner);
    repeated += name.find('#') != std::string::npos;
  }
  EXPECT_GT(repeated, 0);
  // Files without the names (written before they were added) read the same.
  nlohmann::json unnamed = doc;
  for (auto& p : unnamed["patches"]) p.erase("corner_name");
  const PatchSet old = read_bezier_json(folder.write("old.bez.json", unnamed.dump()));
  ASSERT_EQ(old.patches.size(), set.patches.size());
  EXPECT_EQ(old.patches.back().net.p, set.patches.back().net.p);
  nlohmann::json wrong = doc;
  wrong["patches"][0]["corner_name"] = "9@9";
  EXPECT_NE(test::error_of([&] {
              read_bezier_json(folder.write("wrong.bez.json", wrong.dump()));
            }).find("corner_name"),
            std::string::npos);
}

TEST(BezierJson, RefusesOtherJsonNamingWhatIsWrong) {
  TempFolder folder;
  const std::string other = folder.write("other.json", R"({"format": "something else"})");
  EXPECT_NE(test::error_of([&] { read_bezier_json(other); }).find("stitch-bezier-patches"),
            std::string::npos);
  const std::string broken =
      folder.write("broken.json",
                   R"({"format": "stitch-bezier-patches", "version": 1, "method": "mdc", "depth": 0,
          "model_size": 1, "tolerance": {"position": 1e-6, "normal_deg": 0.1},
          "deviation": {"position": 0, "normal_deg": 0}, "patch_count": 1,
          "patches": [{"corner": 0, "face": 1, "vertex": 1, "level": 0, "cell": [0, 0],
                       "exact": true, "points": [[0, 0, 0]]}]})");
  EXPECT_NE(test::error_of([&] { read_bezier_json(broken); }).find("patch 1"), std::string::npos);
}

TEST(ReadStl, BinaryAndAsciiWeldBackIntoTheClosedMesh) {
  TempFolder folder;
  // The smooth surface of the hole through a cube, as `stitch smooth -o x.stl` writes it.
  const HalfedgeMesh hole = read_mesh(test::example_path("cube_hole.obj"));
  const TessellatedMesh surface = tessellate(hole, Surface(hole, Method::mdc), {3, true});
  const std::string binary = folder.file("hole.stl");
  write_surface_mesh(binary, MeshFileFormat::stl, surface);
  const TopologyStats stats = topology_stats(read_mesh(binary));
  EXPECT_EQ(stats.genus, 1);
  EXPECT_EQ(stats.vertices, surface.num_vertices());
  EXPECT_EQ(stats.faces, 2 * static_cast<int>(surface.quads.size()));
  // The same tetrahedron as ASCII, one corner written with a float round-off difference of
  // 1e-9 (below the welding tolerance of 1e-6 of the size).
  const std::string ascii = folder.write("tet.stl", R"(solid tet
facet normal 0 0 0
 outer loop
  vertex 1 1 1
  vertex 1 -1 -1
  vertex -1 1 -1
 endloop
endfacet
facet normal 0 0 0
 outer loop
  vertex 1 1 1.000000001
  vertex -1 1 -1
  vertex -1 -1 1
 endloop
endfacet
facet normal 0 0 0
 outer loop
  vertex 1 1 1
  vertex -1 -1 1
  vertex 1 -1 -1
 endloop
endfacet
facet normal 0 0 0
 outer loop
  vertex 1 -1 -1
  vertex -1 -1 1
  vertex -1 1 -1
 endloop
endfacet
endsolid tet
)");
  const HalfedgeMesh tet = read_mesh(ascii);
  EXPECT_EQ(tet.num_vertices(), 4);
  EXPECT_EQ(tet.num_faces(), 4);
  EXPECT_NE(test::error_of([&] { read_mesh(folder.write("bad.stl", "hello")); }).find("STL"),
            std::string::npos);
}

TEST(CliExact, SmoothWritesStlThatInfoReadsBack) {
  TempFolder folder;
  const std::string in = test::example_path("torus.obj");
  ASSERT_EQ(stitch_cli(folder, "smooth '" + in + "' -o t.stl --resolution 2").status, 0);
  const auto r = stitch_cli(folder, "info t.stl");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("genus"), std::string::npos) << r.out;
  EXPECT_EQ(topology_stats(read_mesh(folder.file("t.stl"))).genus, 1);
}

using test::validate_gltf;

TEST(CliExact, GltfPassesTheKhronosValidator) {
  TempFolder folder;
  const std::string in = test::example_path("cube_hole.obj");
  for (const char* out : {"hole.glb", "hole.gltf"}) {
    const auto r = stitch_cli(folder, "smooth '" + in + "' -o " + out + " --resolution 3");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  EXPECT_TRUE(std::filesystem::exists(folder.file("hole.bin")));
  int status = -1;
  const std::string report =
      validate_gltf({folder.file("hole.glb"), folder.file("hole.gltf")}, &status);
  if (report.empty()) GTEST_SKIP() << "node is not installed";
  EXPECT_EQ(status, 0) << report;
  EXPECT_NE(report.find("hole.glb: 0 errors"), std::string::npos) << report;
  EXPECT_NE(report.find("hole.gltf: 0 errors"), std::string::npos) << report;
}

TEST(CliExact, PatchesJsonBesideAMeshAndReportOnStderr) {
  TempFolder folder;
  const std::string in = test::example_path("cube.obj");
  const auto r = stitch_cli(folder, "smooth '" + in + "' -o c.obj --patches c.json --kgons");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("depth"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("largest deviation"), std::string::npos) << r.err;
  const PatchSet set = read_bezier_json(folder.file("c.json"));
  EXPECT_NE(r.err.find(std::to_string(set.patches.size()) + " Bezier patches"), std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::exists(folder.file("c.obj")));
}

TEST(CliExact, FailedGltfLeavesAnEarlierBufferAlone) {
  TempFolder folder;
  const std::string in = test::example_path("cube.obj");
  std::filesystem::create_directory(folder.file("s.gltf"));  // the .gltf cannot be written
  { std::ofstream(folder.file("s.bin")) << "an earlier buffer"; }
  const auto r = stitch_cli(folder, "smooth '" + in + "' -o s.gltf --resolution 2");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(testing::read_file(folder.file("s.bin")), "an earlier buffer");
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"s.bin", "s.gltf"}));
  // Where it can be written, the pair replaces the old buffer.
  std::filesystem::remove(folder.file("s.gltf"));
  ASSERT_EQ(stitch_cli(folder, "smooth '" + in + "' -o s.gltf --resolution 2").status, 0);
  EXPECT_NE(testing::read_file(folder.file("s.bin")), "an earlier buffer");
}

TEST(CliExact, InfoReportsThePatchSetThatWouldBeWritten) {
  TempFolder folder;
  const std::string in = test::example_path("cube_hole.obj");
  const HalfedgeMesh mesh = read_mesh(in);
  const PatchSet set = bezier_patches(mesh, Surface(mesh, Method::mdc));
  const auto text = stitch_cli(folder, "info '" + in + "' --patches");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find(fmt::format("{} patches ({} exact", set.patches.size(), set.num_exact())),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find(fmt::format("depth {}", set.depth)), std::string::npos) << text.out;
  const auto json = stitch_cli(folder, "info '" + in + "' --patches --json --tolerance 1e-4");
  ASSERT_EQ(json.status, 0) << json.err;
  const auto report = nlohmann::json::parse(json.out).at("bezier_patch_set");
  EXPECT_EQ(report.at("tolerance").get<double>(), 1e-4);
  // A looser tolerance needs no deeper hierarchy, and what is reported is within it.
  EXPECT_LE(report.at("depth").get<int>(), set.depth);
  EXPECT_LE(report.at("max_position_deviation").get<double>(),
            1e-4 * report.at("model_size").get<double>());
  EXPECT_EQ(stitch_cli(folder, "info '" + in + "' --patches --method cc").status, 2);
}

TEST(CliExact, BadOutputRequestsExitTwoAndLeaveNothing) {
  TempFolder folder;
  const std::string in = test::example_path("cube.obj");
  // An unknown extension names every known one.
  auto r = stitch_cli(folder, "smooth '" + in + "' -o part.xyz");
  EXPECT_EQ(r.status, 2);
  for (const char* ext : {".obj", ".glb", ".gltf", ".json", ".step", ".stp", ".igs", ".iges"})
    EXPECT_NE(r.err.find(ext), std::string::npos) << ext << ": " << r.err;
  // A tolerance that is not above zero.
  for (const char* tol : {"0", "-1e-6"}) {
    r = stitch_cli(folder, "smooth '" + in + "' -o p.json --tolerance " + tol);
    EXPECT_EQ(r.status, 2) << tol;
    EXPECT_NE(r.err.find("tolerance"), std::string::npos) << r.err;
  }
  r = stitch_cli(folder, "smooth '" + in + "' -o p.json --angle-tolerance 0");
  EXPECT_EQ(r.status, 2);
  // A folder that does not exist, or a folder as the output: refused before any work (no
  // patch set was measured).
  std::filesystem::create_directory(folder.file("sub.step"));
  for (const auto& [out, said] :
       {std::pair{"missing/p.json", "does not exist"},
        std::pair{"missing/p.step", "does not exist"}, std::pair{"sub.step", "it is a folder"}}) {
    r = stitch_cli(folder, "smooth '" + in + "' -o " + out);
    EXPECT_EQ(r.status, 2) << out;
    EXPECT_NE(r.err.find(said), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("largest deviation"), std::string::npos) << r.err;
  }
  std::filesystem::remove(folder.file("sub.step"));
  // A full disk: the output name leads to /dev/full, which takes no byte (ENOSPC).
  std::filesystem::create_symlink("/dev/full", folder.file("full.json"));
  std::filesystem::create_symlink("/dev/full", folder.file("full.glb"));
  for (const char* out : {"full.json", "full.glb"}) {
    r = stitch_cli(folder, "smooth '" + in + "' -o " + out);
    EXPECT_EQ(r.status, 2) << out << ": " << r.err;
    EXPECT_NE(r.err.find("disk full"), std::string::npos) << r.err;
  }
  // Nothing was left behind, and /dev/full is still the device.
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"full.glb", "full.json"}));
  struct stat device {};
  ASSERT_EQ(::stat("/dev/full", &device), 0);
  EXPECT_TRUE(S_ISCHR(device.st_mode));
}

/// The numbers of one CSV row of `stitch eval`.
std::vector<double> csv_numbers(const std::string& row) {
  std::vector<double> values;
  std::stringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) {
    double x = 0;
    std::from_chars(cell.data(), cell.data() + cell.size(), x);
    values.push_back(x);
  }
  return values;
}

TEST(CliEval, PrintsExactEvaluationAtFullPrecision) {
  TempFolder folder;
  const std::string in = test::example_path("cube_hole.obj");
  const HalfedgeMesh mesh = read_mesh(in);
  const Surface surface(mesh, Method::mdc);
  // Patch 0 by number, and the corner of vertex 1 on face 2 as face and vertex, near and at the
  // vertex, and by its name V@F.
  folder.write(
      "at.txt",
      "# patch u v, or face vertex u v\n0 0.25 0.75\n2 1 1e-9 0.3\n2 1 0 0\n1@2 0 0 # by name\n");
  const auto csv = stitch_cli(folder, "eval '" + in + "' --at at.txt");
  ASSERT_EQ(csv.status, 0) << csv.err;
  std::vector<std::string> rows;
  std::stringstream lines(csv.out);
  for (std::string row; std::getline(lines, row);) rows.push_back(row);
  ASSERT_EQ(rows.size(), 5u) << csv.out;
  const std::array<std::pair<Corner, std::array<double, 2>>, 4> expected{
      {{Corner(0), {0.25, 0.75}},
       {parse_corner(mesh, "1@2"), {1e-9, 0.3}},
       {parse_corner(mesh, "1@2"), {0, 0}},
       {parse_corner(mesh, "1@2"), {0, 0}}}};
  for (int i = 0; i < 4; ++i) {
    const auto [corner, uv] = expected[i];
    const SurfacePoint p = surface.evaluate(corner, uv[0], uv[1]);
    const std::vector<double> got = csv_numbers(rows[i + 1]);
    ASSERT_EQ(got.size(), 20u);
    EXPECT_EQ(got[1], corner.idx);
    // The last column names the corner as Bezier JSON, STEP and Python do.
    EXPECT_EQ(rows[i + 1].substr(rows[i + 1].rfind(',') + 1), corner_name(mesh, corner));
    // Shortest round-trip text: the very doubles of the library, bit for bit.
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(got[6 + k], p.position[k]);
      EXPECT_EQ(got[9 + k], p.du[k]);
      EXPECT_EQ(got[12 + k], p.dv[k]);
      EXPECT_EQ(got[15 + k], p.normal[k]);
    }
  }
  const auto json = stitch_cli(folder, "eval '" + in + "' --at at.txt --format json");
  ASSERT_EQ(json.status, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  const SurfacePoint p = surface.evaluate(Corner(0), 0.25, 0.75);
  EXPECT_EQ(doc["points"][0]["position"][2].get<double>(), p.position.z());
  EXPECT_EQ(doc["points"][0]["normal"][0].get<double>(), p.normal.x());

  folder.write("bad.txt", "0 0.5 1.5\n");
  const auto bad = stitch_cli(folder, "eval '" + in + "' --at bad.txt");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("line 1"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace stitch
