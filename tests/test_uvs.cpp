// Texture coordinates from the input to every output: reading (OBJ vt, PLY s t, glTF
// TEXCOORD_0), the UV surface (smooth and linear), and writing (OBJ vt, unwelded PLY s t, glTF
// TEXCOORD_0 through the Khronos validator).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "cli_run.hpp"
#include "gltf_validator.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using testing::stitch_cli;
using testing::TempFolder;

/// A planar grid of (nx + 1) x (ny + 1) vertices in z = 0 whose texture coordinates are
/// A * (x, y) + b, one vt per vertex (no seams). `irregular`: the vertices are moved off the
/// lattice and one quad is split into two triangles, so there are extraordinary points (valence
/// 5 and 3-sided faces) and patches that are not plain polynomials.
std::string planar_grid_obj(int nx, int ny, bool irregular, const Eigen::Matrix2d& a,
                            const Eigen::Vector2d& b) {
  std::string text;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      Eigen::Vector2d p(i, j);
      if (irregular) p += Eigen::Vector2d(0.2 * std::sin(1.7 * j + i), 0.15 * std::cos(i * j));
      const Eigen::Vector2d t = a * p + b;
      text += fmt::format("v {} {} 0\nvt {} {}\n", p.x(), p.y(), t.x(), t.y());
    }
  auto at = [&](int i, int j) { return j * (nx + 1) + i + 1; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c00 = at(i, j), c10 = at(i + 1, j), c11 = at(i + 1, j + 1), c01 = at(i, j + 1);
      if (irregular && i == 1 && j == 1) {
        text += fmt::format("f {0}/{0} {1}/{1} {2}/{2}\nf {0}/{0} {2}/{2} {3}/{3}\n", c00, c10, c11,
                            c01);
      } else {
        text += fmt::format("f {0}/{0} {1}/{1} {2}/{2} {3}/{3}\n", c00, c10, c11, c01);
      }
    }
  return text;
}

/// The cube of README.md (vertices 1..8, faces bottom, top, front, right, back, left) with the
/// usual cross-shaped unfolding: one UV island, 14 vt, and 7 seam edges (3-4, 4-8, 8-7, 2-3,
/// 6-7, 4-1, 5-8) where the two faces give their shared vertices different vt. Vertices 3 and 7
/// have two UVs, 4 and 8 three, the others one.
constexpr const char* kCubeCrossObj = R"(v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
vt 0.25 0.25
vt 0.5 0.25
vt 0.5 0.5
vt 0.25 0.5
vt 0.75 0.25
vt 0.75 0.5
vt 1 0.25
vt 1 0.5
vt 0 0.25
vt 0 0.5
vt 0.5 0.75
vt 0.25 0.75
vt 0.5 0
vt 0.25 0
f 1/1 4/14 3/13 2/2
f 5/4 6/3 7/11 8/12
f 1/1 2/2 6/3 5/4
f 2/2 3/5 7/6 6/3
f 3/5 4/7 8/8 7/6
f 4/9 1/1 5/4 8/10
)";
constexpr int kCubeSeamEdges = 7;
constexpr int kCubeSeamVertices = 4;  // 3, 4, 7 and 8

struct Loaded {
  HalfedgeMesh mesh;
  BuildReport report;
};

Loaded load(const std::string& path) {
  Loaded out;
  out.mesh = read_mesh(path, {}, &out.report);
  return out;
}

// --- reading ---------------------------------------------------------------------------------

TEST(UvRead, ObjVtGoToTheCornersInLoopOrder) {
  TempFolder folder;
  // Relative vt indices in the second face; vt with a third (w) value.
  const std::string path = folder.write("t.obj",
                                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                        "vt 0.1 0.2\nvt 0.3 0.4 0\nvt 0.5 0.6\nvt 0.7 0.8\n"
                                        "f 1/1 2/2 3/3\nf 2/-3/1 4/-1 3/-2\n");
  const PolygonSoup soup = read_polygon_soup(path);
  ASSERT_EQ(soup.uvs.size(), 4U);
  EXPECT_EQ(soup.face_uvs, (std::vector<std::vector<int>>{{0, 1, 2}, {1, 3, 2}}));
  const Loaded l = load(path);
  const CornerUvs& uvs = l.report.corner_uvs;
  ASSERT_EQ(uvs.uv.size(), 4U);
  ASSERT_EQ(uvs.index.size(), static_cast<size_t>(l.mesh.halfedge_capacity()));
  for (int f = 0; f < 2; ++f) {
    const auto loop = l.mesh.face_loop(Face(f));
    for (size_t i = 0; i < loop.size(); ++i) {
      EXPECT_EQ(uvs.index[loop[i].idx], soup.face_uvs[f][i]);
      EXPECT_EQ(l.mesh.origin(loop[i]).idx, soup.faces[f][i]);
    }
  }
  for (Halfedge h : l.mesh.halfedges())
    if (l.mesh.is_hole(h)) {
      EXPECT_EQ(uvs.index[h.idx], -1);
    }
  EXPECT_EQ(uvs.uv[3], Eigen::Vector2d(0.7, 0.8));
}

TEST(UvRead, MalformedVtRefusedWithFileAndLine) {
  TempFolder folder;
  const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
  struct Case {
    std::string body, expect1, expect2;
  };
  const std::vector<Case> cases{
      {"f 1/1 2/2 3/9\n", "bad.obj, line 8", "texture coordinate 9"},  // out of range
      {"f 1/1 2 3/3\n", "bad.obj, line 8", "every corner"},            // part of a face
      {"f 1/-4 2/2 3/3\n", "bad.obj, line 8", "relative texture coordinate index -4"},
      {"f 1/0 2/2 3/3\n", "bad.obj, line 8", "index 0"},
      {"vt 1 x\nf 1/1 2/2 3/3\n", "bad.obj, line 8", "'x' is not a number"},
      {"vt\nf 1/1 2/2 3/3\n", "bad.obj, line 8", "texture coordinate needs"},
      {"vt 0 0 0 0\nf 1/1 2/2 3/3\n", "bad.obj, line 8", "texture coordinate needs"},
      {"vt nan 0\nf 1/1 2/2 3/3\n", "bad.obj, line 8", "not finite"},
  };
  for (const Case& c : cases) {
    const std::string path = folder.write("bad.obj", head + c.body);
    const std::string message = test::error_of([&] { read_mesh(path); });
    EXPECT_NE(message.find(c.expect1), std::string::npos) << c.body << " -> " << message;
    EXPECT_NE(message.find(c.expect2), std::string::npos) << c.body << " -> " << message;
  }
  // The command line refuses it too, naming the place, and writes nothing.
  folder.write("bad.obj", head + cases[0].body);
  const auto r = stitch_cli(folder, "smooth bad.obj -o out.obj");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.obj, line 8"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("out.obj")));
}

TEST(UvRead, FacesWithAndWithoutVtDropTheUvsWithAWarning) {
  TempFolder folder;
  const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
  for (const std::string& body :
       {std::string("f 1/1 2/2 3/3\nf 2 4 3\n"), std::string("f 1 2 3\nf 2/2 4/3 3/1\n")}) {
    const std::string path = folder.write("mixed.obj", head + body);
    std::vector<std::string> warnings;
    const PolygonSoup soup = read_polygon_soup(path, &warnings);
    EXPECT_TRUE(soup.uvs.empty());
    EXPECT_TRUE(soup.face_uvs.empty());
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_NE(warnings[0].find("has no texture coordinate indices"), std::string::npos)
        << warnings[0];
  }
}

TEST(UvRead, VtThatNoFaceUsesAreDroppedWithAWarning) {
  TempFolder folder;
  const std::string path =
      folder.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1//1 2//1 3//1\n");
  std::vector<std::string> warnings;
  const PolygonSoup soup = read_polygon_soup(path, &warnings);
  EXPECT_TRUE(soup.uvs.empty());
  EXPECT_TRUE(soup.face_uvs.empty());
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_NE(warnings[0].find("t.obj, line 4"), std::string::npos) << warnings[0];
}

TEST(UvRead, PlyPerVertexCoordinatesUnderEachName) {
  TempFolder folder;
  for (const auto& [s, t] : std::vector<std::pair<std::string, std::string>>{
           {"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}}) {
    const std::string path = folder.write(
        "t.ply", fmt::format("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty "
                             "float y\nproperty float z\nproperty float {}\nproperty float {}\n"
                             "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0 0 0.5\n1 0 0 0.25 0.5\n0 1 0 0 1\n1 1 0 0.25 1\n"
                             "3 0 1 2\n3 1 3 2\n",
                             s, t));
    const PolygonSoup soup = read_polygon_soup(path);
    ASSERT_EQ(soup.uvs.size(), 4U) << s;
    EXPECT_EQ(soup.face_uvs, soup.faces);
    EXPECT_EQ(soup.uvs[3], Eigen::Vector2d(0.25, 1.0));
    const Loaded l = load(path);
    EXPECT_EQ(l.report.corner_uvs.uv.size(), 4U);
  }
  // Without texture coordinates there are none.
  const std::string plain = folder.write(
      "p.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
      "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
      "0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(read_polygon_soup(plain).uvs.empty());
}

TEST(UvRead, SoupMadeInCodeIsChecked) {
  PolygonSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  soup.faces = {{0, 1, 2}};
  soup.uvs = {{0, 0}, {1, 0}};
  soup.face_uvs = {{0, 1, 2}};
  EXPECT_NE(test::error_of([&] { build_mesh(soup); }).find("texture coordinate 3"),
            std::string::npos);
  // Faces changed after reading by code that knows nothing of UVs: they are dropped, not
  // misapplied, and the report says so.
  soup.face_uvs = {{0, 1}};
  BuildReport report;
  build_mesh(soup, {}, &report);
  EXPECT_TRUE(report.corner_uvs.empty());
  ASSERT_EQ(report.warnings.size(), 1U);
  EXPECT_NE(report.warnings[0].find("texture coordinates dropped"), std::string::npos);
}

// --- the UV surface ----------------------------------------------------------------------------

/// The construction is affine-invariant: on a planar mesh whose UVs are an affine map of the
/// positions, the smooth UV surface is that map of the smooth surface, point for point, at
/// boundaries and extraordinary points too (the UV mesh is the mesh itself, mapped).
TEST(UvSurface, SmoothReproducesAnAffineMapOfAPlanarMesh) {
  TempFolder folder;
  Eigen::Matrix2d a;
  a << 0.3, 0.1, -0.05, 0.25;
  const Eigen::Vector2d b(0.2, 0.4);
  for (bool irregular : {false, true}) {
    const Loaded l = load(folder.write("g.obj", planar_grid_obj(5, 4, irregular, a, b)));
    const Surface surface(l.mesh, Method::mdc);
    const UvSurface uvs(l.mesh, l.report.corner_uvs);
    ASSERT_EQ(uvs.mode(), UvMode::smooth);
    EXPECT_TRUE(uvs.warnings().empty());
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst = 0;
    for (Corner c : l.mesh.patch_corners())
      for (int k = 0; k < 30; ++k) {
        // Grid points (corners and sides included), then random ones.
        const double u = k < 25 ? (k % 5) / 4.0 : unit(random);
        const double v = k < 25 ? (k / 5) / 4.0 : unit(random);
        const Vec3 p = surface.evaluate(c, u, v).position;
        ASSERT_NEAR(p.z(), 0, 1e-12);
        worst = std::max(worst, (uvs.evaluate(c, u, v) - (a * p.head<2>() + b)).norm());
      }
    EXPECT_LT(worst, 1e-12) << "irregular " << irregular;
  }
}

/// linear: bilinear between the corner's UV, the edge midpoints' and the face centre's, which
/// for affine UVs is the affine image of the same four points of the mesh. On a uniform grid the
/// surface passes through those points, so there the linear UVs are the surface's x, y; between
/// them they are not, because the surface's parameterization is not linear (the Bézier points
/// along an edge are spaced 1/8, 2/8, 1/8 of its half): `smooth` is needed for an exact map.
TEST(UvSurface, LinearIsBilinearBetweenThePatchCorners) {
  TempFolder folder;
  const Loaded l = load(folder.write(
      "g.obj", planar_grid_obj(6, 6, false, Eigen::Matrix2d::Identity(), Eigen::Vector2d::Zero())));
  const Surface surface(l.mesh, Method::mdc);
  const UvSurface uvs(l.mesh, l.report.corner_uvs, UvMode::linear);
  EXPECT_EQ(uvs.mode(), UvMode::linear);
  const HalfedgeMesh& m = l.mesh;
  double at_corners = 0, between = 0;
  for (Corner c : m.patch_corners()) {
    const Vec3 p00 = m.position(m.origin(c));
    const Vec3 p30 = 0.5 * (p00 + m.position(m.target(c)));
    const Vec3 p03 = 0.5 * (p00 + m.position(m.origin(m.prev(c))));
    Vec3 p33 = Vec3::Zero();
    for (Halfedge h : m.face_loop(m.face(c))) p33 += m.position(m.origin(h)) / 4.0;
    for (int k = 0; k < 25; ++k) {
      const int i = k % 5, j = k / 5;
      const double u = i / 4.0, v = j / 4.0;
      const Vec3 bilinear =
          (1 - u) * (1 - v) * p00 + u * (1 - v) * p30 + u * v * p33 + (1 - u) * v * p03;
      EXPECT_LT((uvs.evaluate(c, u, v) - bilinear.head<2>()).norm(), 1e-14);
      const double off =
          (uvs.evaluate(c, u, v) - surface.evaluate(c, u, v).position.head<2>()).norm();
      double& worst = (i % 4 == 0 && j % 4 == 0) ? at_corners : between;
      worst = std::max(worst, off);
    }
  }
  EXPECT_LT(at_corners, 1e-12);
  EXPECT_GT(between, 1e-3);
}

/// Across an edge the two patches give the same UVs unless the edge is a seam, where each side
/// keeps its own; within a face the patches always agree.
TEST(UvSurface, SeamsPartTheUvsAndNothingElseDoes) {
  TempFolder folder;
  const Loaded l = load(folder.write("cube.obj", kCubeCrossObj));
  const HalfedgeMesh& m = l.mesh;
  const CornerUvs& corner_uvs = l.report.corner_uvs;
  for (UvMode mode : {UvMode::smooth, UvMode::linear}) {
    const UvSurface uvs(m, corner_uvs, mode);
    ASSERT_EQ(uvs.mode(), mode);
    int seams = 0;
    for (Edge e : m.edges()) {
      const Halfedge h = HalfedgeMesh::halfedge(e, 0), g = HalfedgeMesh::halfedge(e, 1);
      // The edge h runs from a to b; g from b to a: both ends must have the same vt.
      const bool seam = corner_uvs.index[h.idx] != corner_uvs.index[m.next(g).idx] ||
                        corner_uvs.index[m.next(h).idx] != corner_uvs.index[g.idx];
      seams += seam;
      double worst = 0;
      for (int k = 1; k < 8; ++k) {
        const double t = k / 8.0;
        // Point t of h's half at a is point t of rotate_cw(h)'s side 3 (control_net.hpp).
        worst =
            std::max(worst, (uvs.evaluate(h, t, 0) - uvs.evaluate(m.rotate_cw(h), 0, t)).norm());
        worst =
            std::max(worst, (uvs.evaluate(g, t, 0) - uvs.evaluate(m.rotate_cw(g), 0, t)).norm());
      }
      if (seam)
        EXPECT_GT(worst, 1e-3) << "edge " << e.idx;
      else
        EXPECT_LT(worst, 1e-12) << "edge " << e.idx;
    }
    EXPECT_EQ(seams, kCubeSeamEdges);
    for (Corner c : m.patch_corners())
      for (int k = 0; k <= 8; ++k) {  // side 1 of c is side 2 of next(c): inside the face
        const double t = k / 8.0;
        EXPECT_LT((uvs.evaluate(c, 1, t) - uvs.evaluate(m.next(c), t, 1)).norm(), 1e-12);
      }
  }
}

TEST(UvSurface, ALayoutThatIsNoManifoldFallsBackToLinear) {
  // Around the centre vertex of a 2 x 2 grid, opposite faces share a vt and neighbours do not:
  // as a mesh of its own the layout touches itself at that vertex.
  TempFolder folder;
  std::string text;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) text += fmt::format("v {} {} 0\nvt {} {}\n", i, j, i, j);
  text += "vt 5 5\n";  // vt 10: the centre, as faces 1 and 3 see it
  text += "f 1/1 2/2 5/5 4/4\nf 2/2 3/3 6/6 5/10\nf 5/5 6/6 9/9 8/8\nf 4/4 5/10 8/8 7/7\n";
  const Loaded l = load(folder.write("g.obj", text));
  const UvSurface uvs(l.mesh, l.report.corner_uvs);
  EXPECT_EQ(uvs.mode(), UvMode::linear);
  ASSERT_EQ(uvs.warnings().size(), 1U);
  EXPECT_NE(uvs.warnings()[0].find("linearly"), std::string::npos) << uvs.warnings()[0];
  EXPECT_EQ(uvs.evaluate(l.mesh.halfedge(Face(1)), 0, 0), Eigen::Vector2d(1, 0));
}

TEST(UvSurface, RefusesCornersWithoutCoordinates) {
  TempFolder folder;
  const std::string path = folder.write(
      "open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  BuildOptions fill;
  fill.fill_holes = true;
  BuildReport report;
  const HalfedgeMesh mesh = read_mesh(path, fill, &report);
  EXPECT_NE(
      test::error_of([&] { const UvSurface uvs(mesh, report.corner_uvs); }).find("no texture"),
      std::string::npos);
}

// --- writing -----------------------------------------------------------------------------------

/// An OBJ as written by stitch: positions, texture coordinates and the faces' v/vt pairs.
struct ObjFile {
  std::vector<Vec3> v;
  std::vector<Eigen::Vector2d> vt;
  std::vector<std::vector<std::array<int, 2>>> f;  ///< 0-based (v, vt) per corner
};

ObjFile parse_obj(const std::string& path) {
  ObjFile out;
  std::istringstream in(testing::read_file(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "v") {
      Vec3 p;
      words >> p.x() >> p.y() >> p.z();
      out.v.push_back(p);
    } else if (key == "vt") {
      Eigen::Vector2d t;
      words >> t.x() >> t.y();
      out.vt.push_back(t);
    } else if (key == "f") {
      std::vector<std::array<int, 2>> face;
      std::string entry;
      while (words >> entry) {
        int a = 0, b = 0;
        EXPECT_EQ(std::sscanf(entry.c_str(), "%d/%d", &a, &b), 2) << entry;
        face.push_back({a - 1, b - 1});
      }
      out.f.push_back(face);
    }
  }
  return out;
}

TEST(UvWrite, ObjKeepsBothSidesOfEverySeam) {
  TempFolder folder;
  folder.write("cube.obj", kCubeCrossObj);
  constexpr int n = 4;
  const auto r = stitch_cli(folder, fmt::format("smooth cube.obj -o s.obj --resolution {}", n));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("texture coordinates (smooth UVs)"), std::string::npos) << r.out;
  const ObjFile obj = parse_obj(folder.file("s.obj"));
  // One vt per grid sample of each of the 24 patches; faces refer to all of them in range.
  ASSERT_EQ(obj.vt.size(), static_cast<size_t>(24 * (n + 1) * (n + 1)));
  ASSERT_EQ(obj.f.size(), static_cast<size_t>(24 * n * n));
  std::vector<std::vector<Eigen::Vector2d>> at_vertex(obj.v.size());
  for (const auto& face : obj.f)
    for (const auto& [v, t] : face) {
      ASSERT_TRUE(v >= 0 && v < static_cast<int>(obj.v.size()));
      ASSERT_TRUE(t >= 0 && t < static_cast<int>(obj.vt.size()));
      at_vertex[v].push_back(obj.vt[t]);
    }
  // Every output vertex has UVs that are either the same (to round-off: the patches around it
  // agree) or clearly apart (a seam); those with more than one are the samples on the 7 seam
  // edges (2n - 1 each, their ends not counted) and the 4 cube vertices with several vt.
  int parted = 0;
  for (const auto& uvs : at_vertex) {
    std::vector<Eigen::Vector2d> groups;
    for (const Eigen::Vector2d& uv : uvs) {
      bool joined = false;
      for (const Eigen::Vector2d& g : groups) {
        const double d = (g - uv).norm();
        EXPECT_TRUE(d < 1e-12 || d > 1e-3) << d;
        joined = joined || d < 1e-12;
      }
      if (!joined) groups.push_back(uv);
    }
    parted += groups.size() > 1;
  }
  EXPECT_EQ(parted, kCubeSeamEdges * (2 * n - 1) + kCubeSeamVertices);
}

TEST(UvWrite, ObjReadsBackWithTheSameCoordinates) {
  TempFolder folder;
  const std::string in = folder.write("cube.obj", kCubeCrossObj);
  constexpr int n = 3;
  ASSERT_EQ(stitch_cli(folder, fmt::format("smooth cube.obj -o s.obj --resolution {}", n)).status,
            0);
  const Loaded input = load(in);
  const Surface surface(input.mesh, Method::mdc);
  const UvSurface uvs(input.mesh, input.report.corner_uvs);
  const Loaded back = load(folder.file("s.obj"));
  const CornerUvs& read = back.report.corner_uvs;
  const auto corners = input.mesh.patch_corners();
  ASSERT_EQ(read.uv.size(), corners.size() * (n + 1) * (n + 1));
  ASSERT_EQ(back.mesh.num_faces(), static_cast<int>(corners.size()) * n * n);
  // Output quad q is cell (i, j) of corner k, corners (i, j), (i+1, j), (i+1, j+1), (i, j+1);
  // the text holds the shortest digits that read back as the same doubles.
  for (int q = 0; q < back.mesh.num_faces(); ++q) {
    const int k = q / (n * n), i = q % (n * n) / n, j = q % n;
    const std::array<std::array<int, 2>, 4> at{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
    const auto loop = back.mesh.face_loop(Face(q));
    ASSERT_EQ(loop.size(), 4U);
    for (int m = 0; m < 4; ++m) {
      const int index = read.index[loop[m].idx];
      ASSERT_EQ(index, k * (n + 1) * (n + 1) + at[m][0] * (n + 1) + at[m][1]);
      EXPECT_EQ(read.uv[index],
                uvs.evaluate(corners[k], at[m][0] / double(n), at[m][1] / double(n)));
    }
  }
}

TEST(UvWrite, WithoutUvsTheObjIsAsBefore) {
  TempFolder folder;
  folder.write("cube.obj", kCubeCrossObj);
  const std::string plain = test::example_path("cube.obj");
  ASSERT_EQ(stitch_cli(folder, "smooth '" + plain + "' -o a.obj --resolution 2").status, 0);
  ASSERT_EQ(stitch_cli(folder, "smooth cube.obj -o b.obj --resolution 2 --uv none").status, 0);
  const std::string a = testing::read_file(folder.file("a.obj"));
  const std::string b = testing::read_file(folder.file("b.obj"));
  EXPECT_EQ(a.find("\nvt "), std::string::npos);
  EXPECT_EQ(b.find("\nvt "), std::string::npos);
  // The same cube and numbering: the files are the same byte for byte.
  EXPECT_EQ(a, b);
  const auto r = stitch_cli(folder, "smooth '" + plain + "' -o c.obj --uv linear");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("no texture coordinates"), std::string::npos) << r.err;
}

TEST(UvWrite, LinearUvsOnRequest) {
  TempFolder folder;
  const std::string in = folder.write("cube.obj", kCubeCrossObj);
  const auto r = stitch_cli(folder, "smooth cube.obj -o s.obj --resolution 2 --uv linear");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("(linear UVs)"), std::string::npos) << r.out;
  const Loaded input = load(in);
  const UvSurface uvs(input.mesh, input.report.corner_uvs, UvMode::linear);
  const Loaded back = load(folder.file("s.obj"));
  // Sample (1, 1) of the first patch is its centre: the mean of its four corner UVs.
  const Corner c = input.mesh.patch_corners()[0];
  EXPECT_EQ(back.report.corner_uvs.uv[1 * 3 + 1], uvs.evaluate(c, 0.5, 0.5));
}

TEST(UvWrite, FormatsWithoutAPlaceForUvsSayTheyDropThem) {
  TempFolder folder;
  folder.write("cube.obj", kCubeCrossObj);
  for (const char* out : {"s.off", "s.stl", "s.ply"}) {
    const auto r = stitch_cli(folder, std::string("smooth cube.obj --resolution 2 -o ") + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("texture coordinates are not written"), std::string::npos)
        << out << ": " << r.err;
  }
}

TEST(UvWrite, UnweldedPlyHasTheSamplesCoordinates) {
  TempFolder folder;
  const std::string in = folder.write("cube.obj", kCubeCrossObj);
  constexpr int n = 3;
  ASSERT_EQ(
      stitch_cli(folder, fmt::format("smooth cube.obj -o s.ply --unwelded --resolution {}", n))
          .status,
      0);
  EXPECT_NE(testing::read_file(folder.file("s.ply")).find("property double s\nproperty double t\n"),
            std::string::npos);
  const Loaded input = load(in);
  const UvSurface uvs(input.mesh, input.report.corner_uvs);
  // s t are read back in preference to the patch's u v.
  const PolygonSoup soup = read_polygon_soup(folder.file("s.ply"));
  const auto corners = input.mesh.patch_corners();
  ASSERT_EQ(soup.uvs.size(), corners.size() * (n + 1) * (n + 1));
  for (size_t s = 0; s < soup.uvs.size(); ++s) {
    const size_t k = s / ((n + 1) * (n + 1));
    const int i = static_cast<int>(s % ((n + 1) * (n + 1))) / (n + 1),
              j = static_cast<int>(s % (n + 1));
    EXPECT_EQ(soup.uvs[s], uvs.evaluate(corners[k], i / double(n), j / double(n))) << s;
  }
}

using test::validate_gltf;

TEST(UvWrite, GltfSplitsVerticesOnSeamsAndPassesTheValidator) {
  TempFolder folder;
  const std::string in = folder.write("cube.obj", kCubeCrossObj);
  constexpr int n = 4;
  for (const char* out : {"s.glb", "s.gltf"}) {
    const auto r = stitch_cli(folder, fmt::format("smooth cube.obj -o {} --resolution {}", out, n));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const Loaded input = load(in);
  const Surface surface(input.mesh, Method::mdc);
  const UvSurface uvs(input.mesh, input.report.corner_uvs);
  const TessellatedMesh welded = tessellate(input.mesh, surface, {n, true});
  for (const char* out : {"s.glb", "s.gltf"}) {
    // Read back, the positions weld into the welded tessellation again, and each seam vertex
    // keeps one UV per side: one vt more per extra UV than the welded vertices.
    const Loaded back = load(folder.file(out));
    EXPECT_EQ(back.mesh.num_vertices(), welded.num_vertices()) << out;
    const size_t extra = kCubeSeamEdges * (2 * n - 1) + 2 * 1 + 2 * 2;  // 3, 7: +1; 4, 8: +2
    EXPECT_EQ(back.report.corner_uvs.uv.size(), welded.positions.size() + extra) << out;
    // Each corner's UV is its patch's sample to float precision (glTF stores floats).
    const auto corners = input.mesh.patch_corners();
    for (int q = 0; q < back.mesh.num_faces(); q += 7) {
      const auto loop = back.mesh.face_loop(Face(q));
      // glTF holds triangles: quad q / 2 split along its shorter diagonal (quad_triangles),
      // corners 0 1 2 and 0 2 3, or 0 1 3 and 1 2 3.
      ASSERT_EQ(loop.size(), 3U);
      const int quad = q / 2, k = quad / (n * n), i = quad % (n * n) / n, j = quad % n;
      const std::array<std::array<int, 2>, 4> at{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
      const auto& wq = welded.quads[quad];
      const auto& P = welded.positions;
      const std::array<int, 3> which =
          quad_triangles(std::array{0, 1, 2, 3}, P[wq[0]], P[wq[1]], P[wq[2]], P[wq[3]])[q % 2];
      for (int m = 0; m < 3; ++m) {
        const auto& ij = at[which[m]];
        const Eigen::Vector2d expected =
            uvs.evaluate(corners[k], ij[0] / double(n), ij[1] / double(n));
        EXPECT_LT((back.report.corner_uvs.uv[back.report.corner_uvs.index[loop[m].idx]] - expected)
                      .norm(),
                  1e-6);
      }
    }
  }
  int status = -1;
  const std::string report = validate_gltf({folder.file("s.glb"), folder.file("s.gltf")}, &status);
  if (report.empty()) GTEST_SKIP() << "node is not installed";
  EXPECT_EQ(status, 0) << report;
  EXPECT_NE(report.find("s.glb: 0 errors"), std::string::npos) << report;
  EXPECT_NE(report.find("s.gltf: 0 errors"), std::string::npos) << report;
}

}  // namespace
}  // namespace stitch
