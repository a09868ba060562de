// STEP and IGES read back with OpenCASCADE's readers: every face against exact evaluation, the
// shell closed with the input's Euler characteristic, faces pointing outward, units declared.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

// stitch's headers before OCCT's (OCCT defines a macro Handle, see cad.hpp)
// clang-format off
#include "stitch/cad/cad.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"
// clang-format on

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

namespace stitch {
namespace {

using testing::TempFolder;

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum kind) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, kind, map);
  return map.Extent();
}

struct RoundTrip {
  HalfedgeMesh mesh;
  Surface surface;
  PatchSet set;
};

RoundTrip patches_of(const std::string& name, Method method = Method::mdc) {
  HalfedgeMesh mesh = read_mesh(test::example_path(name));
  Surface surface(mesh, method);
  PatchSet set = bezier_patches(mesh, surface);
  return {std::move(mesh), std::move(surface), std::move(set)};
}

/// Every face of the re-read shape is matched with its patch by the point at its centre, then
/// compared with exact evaluation at interior points. The files hold the patches' poles to 12
/// or more significant digits, so the faces are within the patch set's tolerance (in model
/// units: tolerance times model size) plus 1e-10 of the model size for that rounding.
void expect_faces_match_surface(const TopoDS_Shape& shape, const RoundTrip& rt) {
  const PatchSet& set = rt.set;
  std::vector<Vec3> centres;
  for (const BezierPatch& p : set.patches) centres.push_back(evaluate_cell(p, 0.5, 0.5).position);
  const double allowed = (set.tolerance + 1e-10) * set.model_size;
  double worst = 0;
  int outward = 0, faces = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next(), ++faces) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    BRepAdaptor_Surface adaptor(face);
    // The faces are untrimmed Bézier patches: their whole parameter square is [0, 1]^2.
    ASSERT_NEAR(adaptor.FirstUParameter(), 0, 1e-12);
    ASSERT_NEAR(adaptor.LastUParameter(), 1, 1e-12);
    const gp_Pnt c = adaptor.Value(0.5, 0.5);
    size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < centres.size(); ++i) {
      const double d = (centres[i] - Vec3(c.X(), c.Y(), c.Z())).norm();
      if (d < best_distance) best_distance = d, best = i;
    }
    const BezierPatch& patch = set.patches[best];
    for (double s : {0.1, 0.37, 0.5, 0.81})
      for (double t : {0.13, 0.5, 0.9}) {
        const gp_Pnt q = adaptor.Value(s, t);
        const auto [u, v] = cell_to_root(patch, s, t);
        const SurfacePoint exact = rt.surface.evaluate(patch.corner, u, v);
        worst = std::max(worst, (exact.position - Vec3(q.X(), q.Y(), q.Z())).norm());
      }
    // The face's normal (with its orientation in the solid) agrees with the surface's, which
    // points out of a closed input oriented outward.
    BRepLProp_SLProps props(adaptor, 0.5, 0.5, 1, 1e-9);
    ASSERT_TRUE(props.IsNormalDefined());
    gp_Dir n = props.Normal();
    if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
    const Vec3 exact_normal = rt.surface
                                  .evaluate(patch.corner, cell_to_root(patch, 0.5, 0.5)[0],
                                            cell_to_root(patch, 0.5, 0.5)[1])
                                  .normal;
    if (exact_normal.dot(Vec3(n.X(), n.Y(), n.Z())) > 0.99) ++outward;
  }
  EXPECT_EQ(faces, static_cast<int>(set.patches.size()));
  EXPECT_LE(worst, allowed);
  EXPECT_EQ(outward, faces);
}

class CadRoundTrip : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(CadRoundTrip, ClosedSolidWithTheInputsEulerCharacteristicAndExactFaces) {
  const auto& [name, extension] = GetParam();
  TempFolder folder;
  const RoundTrip rt = patches_of(name);
  const std::string path = folder.file("surface" + extension);
  const cad::CadReport report = cad::write_cad(path, rt.set);
  EXPECT_EQ(report.faces, static_cast<int>(rt.set.patches.size()));
  EXPECT_EQ(report.free_edges, 0);
  EXPECT_EQ(report.solids, 1);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"surface" + extension});

  const TopoDS_Shape shape = cad::read_cad(path);
  EXPECT_EQ(count(shape, TopAbs_SOLID), 1);
  ASSERT_EQ(count(shape, TopAbs_SHELL), 1);
  TopExp_Explorer shell(shape, TopAbs_SHELL);
  EXPECT_TRUE(BRep_Tool::IsClosed(shell.Current()));
  const int chi =
      count(shape, TopAbs_VERTEX) - count(shape, TopAbs_EDGE) + count(shape, TopAbs_FACE);
  EXPECT_EQ(chi, topology_stats(rt.mesh).euler);
  EXPECT_EQ(count(shape, TopAbs_FACE), static_cast<int>(rt.set.patches.size()));
  // Outward faces enclose a positive volume.
  GProp_GProps volume;
  BRepGProp::VolumeProperties(shape, volume);
  EXPECT_GT(volume.Mass(), 0);
  expect_faces_match_surface(shape, rt);
}

INSTANTIATE_TEST_SUITE_P(CubeAndHole, CadRoundTrip,
                         ::testing::Combine(::testing::Values("cube.obj", "cube_hole.obj"),
                                            ::testing::Values(".step", ".igs")),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == "cube.obj" ? "cube"
                                                                                    : "hole") +
                                  "_" + std::get<1>(info.param).substr(1);
                         });

TEST(CadUnits, DeclaredNotScaled) {
  TempFolder folder;
  // The AS&C patches (one per corner, no hierarchy): units do not depend on the depth.
  const RoundTrip rt = patches_of("tetrahedron.obj", Method::asc);
  const Vec3 corner = rt.set.patches.front().net.p[0];
  // OCCT's readers convert lengths to millimetres: a file declared in metres reads back 1000
  // times larger, which shows the unit is declared and the coordinates were written unscaled.
  for (const auto& [unit, mm] : {std::pair{"mm", 1.0}, {"m", 1000.0}, {"in", 25.4}}) {
    SCOPED_TRACE(unit);
    for (const char* ext : {".step", ".igs"}) {
      const std::string path = folder.file(std::string("t_") + unit + ext);
      cad::write_cad(path, rt.set, {unit, 0});
      const TopoDS_Shape shape = cad::read_cad(path);
      double nearest = std::numeric_limits<double>::infinity();
      for (TopExp_Explorer it(shape, TopAbs_VERTEX); it.More(); it.Next()) {
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(it.Current()));
        nearest = std::min(nearest, (Vec3(p.X(), p.Y(), p.Z()) / mm - corner).norm());
      }
      EXPECT_LE(nearest, 1e-6 * rt.set.model_size) << ext;
    }
  }
  EXPECT_THROW(cad::write_cad(folder.file("t.step"), rt.set, {"furlong", 0}), Error);
  EXPECT_THROW(cad::write_cad(folder.file("t.brep"), rt.set), Error);
}

TEST(CadWrite, FullDiskLeavesNothing) {
  TempFolder folder;
  const RoundTrip rt = patches_of("tetrahedron.obj", Method::asc);
  std::filesystem::create_symlink("/dev/full", folder.file("full.step"));
  const std::string message =
      test::error_of([&] { cad::write_cad(folder.file("full.step"), rt.set); });
  EXPECT_NE(message.find("disk full"), std::string::npos) << message;
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"full.step"});
}

}  // namespace
}  // namespace stitch
