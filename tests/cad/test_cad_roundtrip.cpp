// STEP and IGES read back with OpenCASCADE's readers: a valid closed solid with the input's Euler
// characteristic, the face counts of the packings, every face against exact evaluation, face
// names, volumes against the tessellation, measured knot multiplicities and edge regularity,
// units declared; the faces joined by the mesh's adjacency as sewing joins them; and every
// OpenSubdiv shape that smooths exports STEP, IGES and Bézier JSON.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

// stitch's headers before OCCT's (OCCT defines a macro Handle, see cad.hpp)
// clang-format off
#include "stitch/analysis/build_surface.hpp"
#include "stitch/cad/cad.hpp"
#include "stitch/output/output.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/tessellate.hpp"
#include "step_print.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"
// clang-format on

#include <BRepAdaptor_Surface.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <XSControl_WorkSession.hxx>

namespace stitch {
namespace {

using testing::TempFolder;

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum kind) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, kind, map);
  return map.Extent();
}

struct Exact {
  HalfedgeMesh mesh;
  Surface surface;
  PatchSet set;
};

Exact exact_of(const std::string& path, Method method = Method::mdc) {
  HalfedgeMesh mesh = read_mesh(path);
  Surface surface(mesh, method);
  PatchSet set = bezier_patches(mesh, surface);
  return {std::move(mesh), std::move(surface), std::move(set)};
}

/// The volume a closed triangle mesh encloses (sum of signed tetrahedra from the origin).
double mesh_volume(const TessellatedMesh& t) {
  double volume = 0;
  for (const auto& quad : t.quads)
    for (const auto& tri :
         {std::array{quad[0], quad[1], quad[2]}, std::array{quad[0], quad[2], quad[3]}})
      volume += t.positions[tri[0]].dot(t.positions[tri[1]].cross(t.positions[tri[2]])) / 6;
  return volume;
}

/// Every face of the re-read shape is matched with the face written for it by the point at its
/// centre, then compared with exact evaluation at interior points of its parameter square. The
/// faces are within the patch set's tolerance, plus the knot removal's (kKnotRemovalTolerance)
/// and 1e-10 of the model size for the files' 12 significant digits.
void expect_faces_match_surface(const TopoDS_Shape& shape, const Exact& e, FacePacking packing,
                                const ControlMesh* control = nullptr) {
  const std::vector<BsplineFace> written =
      bspline_face_layout(e.mesh, e.surface, e.set, packing, control);
  std::vector<Vec3> centres;
  for (const BsplineFace& f : written) {
    const RootPoint p = root_point(f, 0.5, 0.5);
    centres.push_back(e.surface.evaluate(p.corner, p.u, p.v).position);
  }
  const double allowed = (e.set.tolerance + cad::kKnotRemovalTolerance + 1e-10) * e.set.model_size;
  double worst = 0;
  int outward = 0, faces = 0;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next(), ++faces) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    BRepAdaptor_Surface adaptor(face);
    // The faces are untrimmed: their whole parameter square is [0, 1]^2.
    ASSERT_NEAR(adaptor.FirstUParameter(), 0, 1e-12);
    ASSERT_NEAR(adaptor.LastUParameter(), 1, 1e-12);
    ASSERT_NEAR(adaptor.FirstVParameter(), 0, 1e-12);
    ASSERT_NEAR(adaptor.LastVParameter(), 1, 1e-12);
    const gp_Pnt c = adaptor.Value(0.5, 0.5);
    size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < centres.size(); ++i) {
      const double d = (centres[i] - Vec3(c.X(), c.Y(), c.Z())).norm();
      if (d < best_distance) best_distance = d, best = i;
    }
    for (double s : {0.01, 0.1, 0.37, 0.5, 0.81, 0.999})
      for (double t : {0.002, 0.13, 0.5, 0.62, 0.9}) {
        const gp_Pnt q = adaptor.Value(s, t);
        const RootPoint p = root_point(written[best], s, t);
        const Vec3 point(q.X(), q.Y(), q.Z());
        const SurfacePoint nearest = nearest_on_surface(e.surface, p.corner, point, p.u, p.v);
        worst = std::max(worst, (nearest.position - point).norm());
      }
    // The face's normal (with its orientation in the solid) agrees with the surface's, which
    // points out of a closed input oriented outward.
    BRepLProp_SLProps props(adaptor, 0.3, 0.3, 1, 1e-9);
    ASSERT_TRUE(props.IsNormalDefined());
    gp_Dir n = props.Normal();
    if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
    const RootPoint p = root_point(written[best], 0.3, 0.3);
    if (e.surface.evaluate(p.corner, p.u, p.v).normal.dot(Vec3(n.X(), n.Y(), n.Z())) > 0.99)
      ++outward;
  }
  EXPECT_EQ(faces, static_cast<int>(written.size()));
  EXPECT_LE(worst, allowed);
  EXPECT_EQ(outward, faces);
}

/// The faces joined by the mesh's adjacency, against OpenCASCADE's sewing of the same faces:
/// the same shells, solids, free, smooth and sharp edges, vertices and volume, and a valid shape.
void expect_joined_as_sewn(const HalfedgeMesh& mesh, const Surface& surface, const PatchSet& set,
                           cad::CadOptions options) {
  cad::CadReport joined, sewn;
  const TopoDS_Shape by_adjacency = cad::make_shape(mesh, surface, set, options, &joined);
  options.force_sewing = true;
  const TopoDS_Shape by_sewing = cad::make_shape(mesh, surface, set, options, &sewn);
  EXPECT_FALSE(joined.sewn);
  EXPECT_TRUE(sewn.sewn);
  EXPECT_TRUE(BRepCheck_Analyzer(by_adjacency).IsValid());
  EXPECT_LE(joined.max_edge_gap, joined.sewing_tolerance);
  EXPECT_EQ(joined.faces, sewn.faces);
  EXPECT_EQ(joined.shells, sewn.shells);
  EXPECT_EQ(joined.solids, sewn.solids);
  EXPECT_EQ(joined.free_edges, sewn.free_edges);
  EXPECT_EQ(joined.smooth_edges, sewn.smooth_edges);
  EXPECT_EQ(joined.sharp_edges, sewn.sharp_edges);
  EXPECT_EQ(joined.g1_edges, sewn.g1_edges);
  EXPECT_NEAR(joined.max_smooth_angle_deg, sewn.max_smooth_angle_deg, 1e-6);
  EXPECT_NEAR(joined.volume, sewn.volume, 1e-12 * std::abs(sewn.volume));
  for (const TopAbs_ShapeEnum kind : {TopAbs_FACE, TopAbs_EDGE, TopAbs_VERTEX})
    EXPECT_EQ(count(by_adjacency, kind), count(by_sewing, kind)) << kind;
}

struct RoundTripCase {
  std::string name;
  FacePacking packing;
  int faces;  ///< issue #35's counts: a quad is one face, a K-sided face K faces
};

class CadRoundTrip : public ::testing::TestWithParam<std::tuple<RoundTripCase, std::string>> {};

TEST_P(CadRoundTrip, ValidClosedSolidNamedFacesWithinToleranceAndTheTessellatedVolume) {
  const auto& [c, extension] = GetParam();
  TempFolder folder;
  const Exact e = exact_of(test::example_path(c.name));
  const std::string path = folder.file("surface" + extension);
  cad::CadOptions options;
  options.packing = c.packing;
  const cad::CadReport report =
      cad::write_cad(path, *cad::cad_format(path), e.mesh, e.surface, e.set, options);
  EXPECT_EQ(report.faces, c.faces);
  EXPECT_EQ(report.free_edges, 0);
  EXPECT_EQ(report.solids, 1);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"surface" + extension});

  const TopoDS_Shape shape = cad::read_cad(path);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
  EXPECT_EQ(count(shape, TopAbs_SOLID), 1);
  ASSERT_EQ(count(shape, TopAbs_SHELL), 1);
  TopExp_Explorer shell(shape, TopAbs_SHELL);
  EXPECT_TRUE(BRep_Tool::IsClosed(shell.Current()));
  const int chi =
      count(shape, TopAbs_VERTEX) - count(shape, TopAbs_EDGE) + count(shape, TopAbs_FACE);
  EXPECT_EQ(chi, topology_stats(e.mesh).euler);
  EXPECT_EQ(count(shape, TopAbs_FACE), c.faces);
  expect_faces_match_surface(shape, e, c.packing);

  // Every face carries its control element's name.
  std::vector<std::string> names = cad::read_face_names(path), expected;
  for (const BsplineFace& f : bspline_face_layout(e.mesh, e.surface, e.set, c.packing))
    expected.push_back(face_name(e.mesh, f));
  std::sort(names.begin(), names.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names, expected);

  // The solid's volume (OCCT's integration of the file's faces) against the tessellated
  // surface's: closer at resolution 32 than at 8, and within 1e-3 there. The report's volume
  // (the patches integrated exactly) is the file's to OCCT's integration accuracy. OCCT's fixed
  // Gauss rule misses by 4e-4 on the packed faces' many knot spans; its adaptive rule, asked for
  // 1e-8, meets the exact integral.
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props, 1e-8);
  const double volume = props.Mass();
  const double coarse = mesh_volume(tessellate(e.mesh, e.surface, {8, true}));
  const double fine = mesh_volume(tessellate(e.mesh, e.surface, {32, true}));
  EXPECT_LT(std::abs(fine - volume), std::abs(coarse - volume));
  EXPECT_LE(std::abs(fine - volume), 1e-3 * volume);
  EXPECT_NEAR(report.volume, volume, 1e-6 * volume);
}

INSTANTIATE_TEST_SUITE_P(
    CubeAndHole, CadRoundTrip,
    ::testing::Combine(::testing::Values(RoundTripCase{"cube.obj", FacePacking::quads, 6},
                                         RoundTripCase{"cube.obj", FacePacking::corners, 24},
                                         RoundTripCase{"cube_hole.obj", FacePacking::quads, 14},
                                         RoundTripCase{"cube_hole.obj", FacePacking::corners, 26}),
                       ::testing::Values(".step", ".igs")),
    [](const auto& info) {
      const RoundTripCase& c = std::get<0>(info.param);
      return std::string(c.name == "cube.obj" ? "cube" : "hole") +
             (c.packing == FacePacking::quads ? "_packed_" : "_corners_") +
             std::get<1>(info.param).substr(1);
    });

// Semi-sharp creases honoured by refinement (two levels): the refined patches of each input
// quad pack into one face again, named after the input's face, and the faces match the refined
// surface as the unrefined ones match theirs.
TEST(CadSemiSharp, RefinedSurfaceKeepsTheInputsFacesAndNames) {
  TempFolder folder;
  HalfedgeMesh input = read_mesh(test::example_path("cube.obj"));
  for (Halfedge h : input.face_loop(Face(0))) input.set_sharpness(HalfedgeMesh::edge(h), 1.5);
  const BuiltSurface built = build_surface(input, {});
  ASSERT_TRUE(built.refined);
  ASSERT_EQ(built.refinement.levels, 2);
  const std::string path = folder.file("creased.step");
  const OutputReport report = write_surface(path, input, built);
  EXPECT_EQ(report.faces, 6);

  const TopoDS_Shape shape = cad::read_cad(path);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
  EXPECT_EQ(count(shape, TopAbs_SOLID), 1);
  EXPECT_EQ(count(shape, TopAbs_FACE), 6);
  std::vector<std::string> names = cad::read_face_names(path);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"face 1", "face 2", "face 3", "face 4", "face 5", "face 6"}));
  const ControlMesh control = control_mesh(input, *built.refined);
  const HalfedgeMesh& refined = built.refined->mesh;
  const Exact e{refined, built.surface, bezier_patches(refined, built.surface)};
  expect_faces_match_surface(shape, e, FacePacking::quads, &control);
  cad::CadOptions options;
  options.control = &control;
  expect_joined_as_sewn(e.mesh, e.surface, e.set, options);

  // The estimate told before writing counts the refined patches' double knots where they meet
  // and C2 knots inside the input's patches. Knot removal finds fewer poles: where the tags do
  // not reach, the refined patches of an input patch are pieces of its one polynomial, so their
  // knots go entirely (measured: 5476 poles written, 5892 estimated). The estimate is an upper
  // bound there, and within a tenth.
  cad::CadReport r;
  cad::make_shape(e.mesh, e.surface, e.set, options, &r);
  const std::int64_t estimated = cad::estimate_cad(e.mesh, e.surface, e.set, FacePacking::quads,
                                                   cad::CadFormat::step, &control)
                                     .poles;
  EXPECT_GE(estimated, r.poles);
  EXPECT_LE(estimated, r.poles + r.poles / 10);
}

TEST(CadEstimate, PolesAsWrittenWhereKnotsAreAsSmoothAsTheirPlace) {
  // Simple knots inside a root's hierarchy, double ones between root patches: the estimate is
  // the count written wherever knot removal finds the surface that smooth, as on these shapes.
  for (const std::string& path :
       {test::example_path("cube.obj"), test::example_path("cube_hole.obj"),
        test::opensubdiv_shape("catmark_smoothtris0.obj")}) {
    SCOPED_TRACE(path);
    const Exact e = exact_of(path);
    for (const FacePacking packing : {FacePacking::quads, FacePacking::corners}) {
      cad::CadOptions options;
      options.packing = packing;
      cad::CadReport r;
      cad::make_shape(e.mesh, e.surface, e.set, options, &r);
      const cad::CadEstimate estimate =
          cad::estimate_cad(e.mesh, e.surface, e.set, packing, cad::CadFormat::step);
      EXPECT_EQ(estimate.faces, r.faces);
      EXPECT_EQ(estimate.poles, r.poles);
    }
  }
}

TEST(CadContinuity, KnotsAndEdgesAsTheSurfaceIsSmooth) {
  // The cube's packed faces: inside each corner patch the hierarchy is C2 (every interior knot
  // simple), between a quad's four patches C1 (the knots at 1/2, one per direction and face);
  // the faces meet tangentially along all 12 edges.
  const Exact e = exact_of(test::example_path("cube.obj"));
  cad::CadReport r;
  cad::make_shape(e.mesh, e.surface, e.set, {}, &r);
  EXPECT_EQ(r.knots[3], 0);
  EXPECT_EQ(r.knots[2], 12);
  EXPECT_GT(r.knots[1], 0);
  EXPECT_EQ(r.smooth_edges, 12);
  EXPECT_EQ(r.g1_edges, 12);
  EXPECT_EQ(r.sharp_edges, 0);
  EXPECT_LE(r.max_smooth_angle_deg, e.set.angle_tolerance_deg);
  // Along each direction of a face, each half refined towards its vertex to the depth: 4 end
  // poles, one per simple knot and two at 1/2.
  const std::int64_t side = 2 * e.set.depth + 6;
  EXPECT_EQ(r.poles, 6 * side * side);
}

TEST(CadContinuity, InfinitelySharpCreasesAreTheSharpEdges) {
  // Two cubes with every edge infinitely sharp, all quads: each crease edge of the mesh is one
  // edge of the shape, where the faces meet at an angle; no edge inside a face is sharp.
  const Exact e = exact_of(test::opensubdiv_shape("catmark_cubes_infsharp.obj"));
  int sharp = 0;
  for (Edge edge : e.mesh.edges()) sharp += e.surface.bezier().kgons.sharp(edge) ? 1 : 0;
  cad::CadReport r;
  cad::make_shape(e.mesh, e.surface, e.set, {}, &r);
  EXPECT_GT(sharp, 0);
  EXPECT_EQ(r.sharp_edges, sharp);
  EXPECT_EQ(r.g1_edges, r.smooth_edges);
}

TEST(CadUnits, DeclaredNotScaled) {
  TempFolder folder;
  // The AS&C patches (one per corner, no hierarchy): units do not depend on the depth.
  const Exact e = exact_of(test::example_path("tetrahedron.obj"), Method::asc);
  const Vec3 corner = e.set.patches.front().net.p[0];
  // OCCT's readers convert lengths to millimetres: a file declared in metres reads back 1000
  // times larger, which shows the unit is declared and the coordinates were written unscaled.
  for (const auto& [unit, mm] : {std::pair{"mm", 1.0}, {"m", 1000.0}, {"in", 25.4}}) {
    SCOPED_TRACE(unit);
    for (const char* ext : {".step", ".igs"}) {
      const std::string path = folder.file(std::string("t_") + unit + ext);
      cad::CadOptions options;
      options.units = unit;
      cad::write_cad(path, *cad::cad_format(path), e.mesh, e.surface, e.set, options);
      const TopoDS_Shape shape = cad::read_cad(path);
      double nearest = std::numeric_limits<double>::infinity();
      for (TopExp_Explorer it(shape, TopAbs_VERTEX); it.More(); it.Next()) {
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(it.Current()));
        nearest = std::min(nearest, (Vec3(p.X(), p.Y(), p.Z()) / mm - corner).norm());
      }
      EXPECT_LE(nearest, 1e-6 * e.set.model_size) << ext;
    }
  }
  cad::CadOptions furlong;
  furlong.units = "furlong";
  EXPECT_THROW(cad::write_cad(folder.file("t.step"), cad::CadFormat::step, e.mesh, e.surface, e.set,
                              furlong),
               Error);
  EXPECT_FALSE(cad::cad_format(folder.file("t.brep")));
}

TEST(CadWrite, FullDiskLeavesNothing) {
  TempFolder folder;
  const Exact e = exact_of(test::example_path("tetrahedron.obj"), Method::asc);
  std::filesystem::create_symlink("/dev/full", folder.file("full.step"));
  const std::string message = test::error_of([&] {
    cad::write_cad(folder.file("full.step"), cad::CadFormat::step, e.mesh, e.surface, e.set);
  });
  EXPECT_NE(message.find("disk full"), std::string::npos) << message;
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"full.step"});
}

// The STEP file printed in ranges on all cores is OpenCASCADE's own, byte for byte: one range
// (the cube) and about 20 (catmark_smoothtris0, 80k entities).
TEST(CadWrite, StepPrintedInRangesIsOpenCascadesFile) {
  TempFolder folder;
  for (const std::string& path :
       {test::example_path("cube.obj"), test::opensubdiv_shape("catmark_smoothtris0.obj")}) {
    SCOPED_TRACE(path);
    const Exact e = exact_of(path);
    STEPControl_Writer writer;
    ASSERT_EQ(writer.Transfer(cad::make_shape(e.mesh, e.surface, e.set), STEPControl_AsIs),
              IFSelect_RetDone);
    ASSERT_EQ(writer.Write(folder.file("occt.step").c_str()), IFSelect_RetDone);
    std::ostringstream printed;
    ASSERT_TRUE(cad::print_step(
        writer.Model(), Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol()), printed));
    std::ifstream in(folder.file("occt.step"), std::ios::binary);
    const std::string occt{std::istreambuf_iterator<char>(in), {}};
    EXPECT_GT(writer.Model()->NbEntities(),
              path.find("smoothtris") != std::string::npos ? 60000 : 0);
    EXPECT_EQ(printed.str(), occt);
  }
}

struct JoinCase {
  std::string path;
  FacePacking packing;
};

class JoinedAsSewn : public ::testing::TestWithParam<JoinCase> {};

TEST_P(JoinedAsSewn, Meshes) {
  const JoinCase& c = GetParam();
  const Exact e = exact_of(c.path);
  cad::CadOptions options;
  options.packing = c.packing;
  expect_joined_as_sewn(e.mesh, e.surface, e.set, options);
}

// Closed and open, quads, triangles and other K-gons (whose corner faces meet a packed quad on
// half its side), creases, two solids.
INSTANTIATE_TEST_SUITE_P(
    Meshes, JoinedAsSewn,
    ::testing::Values(
        JoinCase{test::example_path("cube.obj"), FacePacking::quads},
        JoinCase{test::example_path("cube.obj"), FacePacking::corners},
        JoinCase{test::example_path("cube_hole.obj"), FacePacking::quads},
        JoinCase{test::example_path("cube_hole.obj"), FacePacking::corners},
        JoinCase{test::example_path("open_box.obj"), FacePacking::quads},
        JoinCase{test::example_path("open_box.obj"), FacePacking::corners},
        JoinCase{test::opensubdiv_shape("catmark_nonquads.obj"), FacePacking::quads},
        JoinCase{test::opensubdiv_shape("catmark_smoothtris0.obj"), FacePacking::quads},
        JoinCase{test::opensubdiv_shape("catmark_edgecorner.obj"), FacePacking::quads},
        JoinCase{test::opensubdiv_shape("catmark_cubes_infsharp.obj"), FacePacking::quads}),
    [](const auto& info) {
      const std::string name = std::filesystem::path(info.param.path).stem().string();
      return name + (info.param.packing == FacePacking::quads ? "_packed" : "_corners");
    });

TEST(CadJoin, OneEdgePerSharedSideOneVertexPerJoint) {
  // A closed quad mesh packed: the mesh's own faces, edges and vertices. Per corner: each mesh
  // edge in two halves and a spoke per corner (4E edges), a vertex at every vertex, edge middle
  // and face centre.
  const Exact e = exact_of(test::example_path("cube.obj"));
  const int v = e.mesh.num_vertices(), edges = e.mesh.num_edges(), f = e.mesh.num_faces();
  for (const FacePacking packing : {FacePacking::quads, FacePacking::corners}) {
    cad::CadOptions options;
    options.packing = packing;
    cad::CadReport r;
    const TopoDS_Shape shape = cad::make_shape(e.mesh, e.surface, e.set, options, &r);
    EXPECT_FALSE(r.sewn);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
    EXPECT_EQ(r.solids, 1);
    const bool packed = packing == FacePacking::quads;
    EXPECT_EQ(count(shape, TopAbs_FACE), packed ? f : 2 * edges);
    EXPECT_EQ(count(shape, TopAbs_EDGE), packed ? edges : 4 * edges);
    EXPECT_EQ(count(shape, TopAbs_VERTEX), packed ? v : v + edges + f);
  }
}

TEST(CadJoin, RepairedNonManifoldMeshesAreSewn) {
  // Repair leaves vertices at one position where the input was not manifold; only a geometric
  // search joins the pieces there.
  const HalfedgeMesh mesh = read_mesh(test::opensubdiv_shape("catmark_nonman_verts.obj"));
  const Surface surface(mesh, Method::mdc);
  const PatchSet set = bezier_patches(mesh, surface);
  cad::CadReport r;
  const TopoDS_Shape shape = cad::make_shape(mesh, surface, set, {}, &r);
  EXPECT_TRUE(r.sewn);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
}

/// Every OpenSubdiv shape in tests/data (the non-manifold ones repaired on reading) exports STEP,
/// IGES and Bézier JSON at the default tolerances; the Bézier JSON and the smaller CAD files are
/// read back.
class EveryShapeExports : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryShapeExports, StepIgesAndBezierJson) {
  const std::string path = test::opensubdiv_shape(GetParam());
  BuildOptions build;
  build.allow_two_gons = true;
  const HalfedgeMesh mesh = read_mesh(path, build);
  const Surface surface(mesh, Method::mdc);
  const PatchSet set = bezier_patches(mesh, surface);
  EXPECT_LE(set.max_position_deviation, set.tolerance * set.model_size);
  EXPECT_LE(set.max_normal_deviation_deg, set.angle_tolerance_deg);
  TempFolder folder;
  write_bezier_json(folder.file("s.bez.json"), set);
  EXPECT_EQ(read_bezier_json(folder.file("s.bez.json")).patches.size(), set.patches.size());
  for (const char* ext : {".step", ".igs"}) {
    SCOPED_TRACE(ext);
    const std::string out = folder.file(std::string("s") + ext);
    const cad::CadReport report = cad::write_cad(out, *cad::cad_format(out), mesh, surface, set);
    EXPECT_EQ(report.faces,
              static_cast<int>(bspline_face_layout(mesh, surface, set, FacePacking::quads).size()));
    // Reading a file back costs about as much as writing it; the largest (the 360-valent
    // poles, 200 MB) are written but not read.
    if (std::filesystem::file_size(out) > 30'000'000) continue;
    const TopoDS_Shape shape = cad::read_cad(out);
    EXPECT_EQ(count(shape, TopAbs_FACE), report.faces);
    EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
  }
}

INSTANTIATE_TEST_SUITE_P(OpenSubdivShapes, EveryShapeExports,
                         ::testing::ValuesIn(test::opensubdiv_shape_files()), [](const auto& info) {
                           return info.param.substr(0, info.param.size() - 4);
                         });

}  // namespace
}  // namespace stitch
