// stitch's headers before OCCT's (see cad.hpp)
// clang-format off
#include "stitch/cad/cad.hpp"

#include "stitch/mesh/io.hpp"
// clang-format on

#include <fmt/format.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <algorithm>
#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace stitch::cad {

namespace {

struct Unit {
  const char* name;  ///< as the user writes it
  const char* occt;  ///< as OCCT's STEP and IGES writers name it
  double mm;         ///< its length in millimetres
};
constexpr std::array<Unit, 5> kUnits{{{"mm", "MM", 1.0},
                                      {"cm", "CM", 10.0},
                                      {"m", "M", 1000.0},
                                      {"in", "INCH", 25.4},
                                      {"ft", "FT", 304.8}}};

const Unit& find_unit(const std::string& name) {
  for (const Unit& u : kUnits)
    if (name == u.name) return u;
  throw UsageError(fmt::format("unknown unit '{}' (known: {})", name, kCadUnits));
}

/// The patch as a B-spline surface of degree 3 x 3 with the knots 0,0,0,0,1,1,1,1: a Bézier
/// patch, with u along the first pole index like P[a][b].
TopoDS_Face make_face(const BezierPatch& patch, double tolerance) {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const Vec3& p = patch.net.at(a, b);
      poles.SetValue(a + 1, b + 1, gp_Pnt(p.x(), p.y(), p.z()));
    }
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(4);
  // OCCT geometry lives in reference-counted handles, which take ownership of a new object.
  const Handle(Geom_BSplineSurface) surface =
      new Geom_BSplineSurface(poles, knots, knots, multiplicities, multiplicities, 3, 3);
  BRepBuilderAPI_MakeFace face(surface, tolerance);
  if (!face.IsDone())
    throw Error(fmt::format("OpenCASCADE refused the patch of corner {}@{} (level {})",
                            patch.vertex + 1, patch.face + 1, patch.level));
  return face.Face();
}

/// Runs an OCCT writer that writes to a path, atomically (OCCT writes to a temporary file).
void write_through(const std::string& path, const std::function<bool(const std::string&)>& write) {
  write_file_atomically_at(path, [&](const std::string& temporary) {
    if (!write(temporary))
      throw OutputError(fmt::format("cannot write {}: OpenCASCADE's writer failed", path));
  });
}

}  // namespace

void check_units(const std::string& units) {
  find_unit(units);
}

std::optional<CadFormat> cad_format(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext == ".step" || ext == ".stp") return CadFormat::step;
  if (ext == ".igs" || ext == ".iges") return CadFormat::iges;
  return std::nullopt;
}

TopoDS_Shape make_shape(const PatchSet& patches, const CadOptions& options, CadReport* report) {
  CadReport r;
  r.sewing_tolerance = options.sewing_tolerance > 0
                           ? options.sewing_tolerance
                           : std::max({2 * patches.max_position_deviation,
                                       1e-7 * patches.model_size, Precision::Confusion()});
  // Cutting (the third option) splits an edge where a smaller neighbour's edges end: the
  // hierarchy meets unsplit neighbours along halves, quarters, ... of their sides.
  BRepBuilderAPI_Sewing sewing(r.sewing_tolerance, true, true, true, false);
  for (const BezierPatch& patch : patches.patches)
    sewing.Add(make_face(patch, Precision::Confusion()));
  r.faces = static_cast<int>(patches.patches.size());
  sewing.Perform();
  r.free_edges = sewing.NbFreeEdges();
  const TopoDS_Shape sewn = sewing.SewedShape();

  // Every closed shell becomes a solid, oriented so that its faces point out of it.
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  std::vector<TopoDS_Shape> parts;
  for (TopExp_Explorer it(sewn, TopAbs_SHELL); it.More(); it.Next()) {
    const TopoDS_Shell& shell = TopoDS::Shell(it.Current());
    ++r.shells;
    if (BRep_Tool::IsClosed(shell)) {
      TopoDS_Solid solid = BRepBuilderAPI_MakeSolid(shell).Solid();
      BRepLib::OrientClosedSolid(solid);
      parts.push_back(solid);
      ++r.solids;
    } else {
      parts.push_back(shell);
    }
  }
  for (TopExp_Explorer it(sewn, TopAbs_FACE, TopAbs_SHELL); it.More(); it.Next())
    parts.push_back(it.Current());  // faces sewing left on their own
  if (report) *report = r;
  if (parts.size() == 1) return parts.front();
  for (const TopoDS_Shape& part : parts) builder.Add(compound, part);
  return compound;
}

CadReport write_cad(const std::string& path, const PatchSet& patches, const CadOptions& options) {
  const std::optional<CadFormat> format = cad_format(path);
  if (!format)
    throw UsageError(fmt::format("cannot write {}: unknown extension '{}' (supported: {})", path,
                                 file_extension(path), kCadExtensions));
  const Unit& unit = find_unit(options.units);
  CadReport report;
  const TopoDS_Shape shape = make_shape(patches, options, &report);
  if (*format == CadFormat::step) {
    STEPControl_Writer writer;
    // The shape's length unit (the model's local unit) is the written one, so the coordinates
    // go out unscaled under that unit's name. OCCT 7.6 takes the written unit from its
    // process-wide parameter only; it is set for this transfer and put back afterwards.
    writer.Model()->SetLocalLengthUnit(unit.mm);
    writer.Model()->SetWriteLengthUnit(unit.mm);
    const std::string previous_unit = Interface_Static::CVal("write.step.unit");
    Interface_Static::SetCVal("write.step.unit", unit.occt);
    const IFSelect_ReturnStatus transferred = writer.Transfer(shape, STEPControl_AsIs);
    Interface_Static::SetCVal("write.step.unit", previous_unit.c_str());
    if (transferred != IFSelect_RetDone)
      throw OutputError(
          fmt::format("cannot write {}: OpenCASCADE could not convert the shape", path));
    write_through(path, [&](const std::string& temporary) {
      return writer.Write(temporary.c_str()) == IFSelect_RetDone;
    });
  } else {
    IGESControl_Controller::Init();
    IGESControl_Writer writer(unit.occt, 1);  // 1: B-rep entities, which keep shells and solids
    writer.Model()->ChangeGlobalSection().SetCascadeUnit(unit.mm);
    if (!writer.AddShape(shape))
      throw OutputError(
          fmt::format("cannot write {}: OpenCASCADE could not convert the shape", path));
    writer.ComputeModel();
    write_through(path, [&](const std::string& temporary) {
      return writer.Write(temporary.c_str()) == Standard_True;
    });
  }
  return report;
}

PolygonSoup triangulate(const TopoDS_Shape& shape, double deflection) {
  BRepMesh_IncrementalMesh mesher(shape, deflection);
  if (!mesher.IsDone()) throw Error("OpenCASCADE could not triangulate the shape");
  PolygonSoup soup;
  // Faces along a shared edge take their nodes from the edge's one discretization, so equal
  // positions are equal bits.
  std::map<std::array<double, 3>, int> index;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangles = BRep_Tool::Triangulation(face, location);
    if (triangles.IsNull()) continue;
    std::vector<int> node(triangles->NbNodes() + 1);
    for (int i = 1; i <= triangles->NbNodes(); ++i) {
      const gp_Pnt p = triangles->Node(i).Transformed(location.Transformation());
      const auto [at, added] =
          index.emplace(std::array<double, 3>{p.X(), p.Y(), p.Z()}, int(soup.positions.size()));
      if (added) soup.positions.emplace_back(p.X(), p.Y(), p.Z());
      node[i] = at->second;
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= triangles->NbTriangles(); ++t) {
      int a = 0, b = 0, c = 0;
      triangles->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      if (node[a] == node[b] || node[b] == node[c] || node[c] == node[a]) continue;
      soup.faces.push_back({node[a], node[b], node[c]});
    }
  }
  if (soup.faces.empty()) throw InputError("the shape has no faces to triangulate");
  return soup;
}

void quiet_opencascade() {
  const Message_SequenceOfPrinters& printers = Message::DefaultMessenger()->Printers();
  for (Message_SequenceOfPrinters::Iterator it(printers); it.More(); it.Next())
    it.Value()->SetTraceLevel(Message_Fail);
}

TopoDS_Shape read_cad(const std::string& path) {
  const std::optional<CadFormat> format = cad_format(path);
  if (!format)
    throw InputError(fmt::format("{}: cannot read files with extension '{}' (supported: {})", path,
                                 file_extension(path), kCadExtensions));
  std::error_code ec;  // folders and devices are refused as by the mesh readers
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(fmt::format("{}: not a readable regular file", path));
  std::unique_ptr<XSControl_Reader> reader;
  if (*format == CadFormat::step)
    reader = std::make_unique<STEPControl_Reader>();
  else
    reader = std::make_unique<IGESControl_Reader>();
  if (reader->ReadFile(path.c_str()) != IFSelect_RetDone)
    throw InputError(fmt::format("{}: OpenCASCADE cannot read it", path));
  reader->TransferRoots();
  const TopoDS_Shape shape = reader->OneShape();
  if (shape.IsNull()) throw InputError(fmt::format("{}: no shape in the file", path));
  return shape;
}

}  // namespace stitch::cad
