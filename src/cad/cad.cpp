// stitch's headers before OCCT's (see cad.hpp)
// clang-format off
#include "stitch/cad/cad.hpp"

#include "stitch/mesh/io.hpp"
#include "stitch/error.hpp"
#include "step_print.hpp"
// clang-format on

#include <fmt/format.h>
#include <sys/resource.h>
#include <tbb/parallel_for.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESBasic_Name.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESSolid_Face.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_StepModel.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <StepShape_AdvancedFace.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Wire.hxx>
#include <TransferBRep.hxx>
#include <TransferBRep_ShapeMapper.hxx>
#include <Transfer_FinderProcess.hxx>
#include <XSControl_TransferWriter.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
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

/// Forwards OCCT's progress to a callback, mapped into [from, to] of the whole export.
class ForwardProgress : public Message_ProgressIndicator {
 public:
  ForwardProgress(const std::function<void(double)>& callback, double from, double to)
      : callback_(callback), from_(from), to_(to) {}
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {
    // OCCT calls Show under its own lock, so the callback sees one thread at a time.
    if (callback_) callback_(from_ + (to_ - from_) * GetPosition());
  }

 private:
  const std::function<void(double)>& callback_;
  double from_, to_;
};

/// Whether the face is C1 across each knot line along u (or v): whether the pole at the knot
/// is, in every row of poles, the point its neighbours give at the knot, to `tolerance`. Then
/// removing it takes the triple knot to a double one exactly as OCCT's knot removal would, by
/// dropping that pole, at a fraction of the cost of OCCT's removal on the whole surface.
std::vector<bool> c1_across(const BsplineFace& face, bool along_u, double tolerance) {
  const std::vector<double>& k = along_u ? face.u_knots : face.v_knots;
  const int rows = along_u ? face.num_v_poles() : face.num_u_poles();
  const auto pole = [&](int across, int row) -> const Vec3& {
    return along_u ? face.pole(across, row) : face.pole(row, across);
  };
  std::vector<bool> c1(k.size(), false);
  for (size_t i = 1; i + 1 < k.size(); ++i) {
    const double left = k[i] - k[i - 1], right = k[i + 1] - k[i];
    const int at = 3 * static_cast<int>(i);
    bool smooth = true;
    for (int row = 0; row < rows && smooth; ++row)
      smooth =
          (pole(at, row) - (right * pole(at - 1, row) + left * pole(at + 1, row)) / (left + right))
              .norm() <= tolerance;
    c1[i] = smooth;
  }
  return c1;
}

/// The face as an OCCT B-spline surface, its interior knots lowered to the smallest
/// multiplicity that keeps the surface within `tolerance` (counted in `knots`).
Handle(Geom_BSplineSurface)
    make_surface(const BsplineFace& face, double tolerance, std::array<std::int64_t, 4>& knots) {
  const std::vector<bool> u_c1 = c1_across(face, true, tolerance);
  const std::vector<bool> v_c1 = c1_across(face, false, tolerance);
  // The poles kept: all but those at the knots where the face is C1.
  const auto kept = [](const std::vector<bool>& c1, int num_poles) {
    std::vector<int> indices;
    for (int i = 0; i < num_poles; ++i)
      if (i % 3 != 0 || !c1[i / 3]) indices.push_back(i);
    return indices;
  };
  const std::vector<int> us = kept(u_c1, face.num_u_poles()), vs = kept(v_c1, face.num_v_poles());
  const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const Vec3& p = face.pole(us[i], vs[j]);
      poles.SetValue(i + 1, j + 1, gp_Pnt(p.x(), p.y(), p.z()));
    }
  const auto knot_arrays = [](const std::vector<double>& values, const std::vector<bool>& c1,
                              TColStd_Array1OfReal& k, TColStd_Array1OfInteger& m) {
    const int n = static_cast<int>(values.size());
    k.Resize(1, n, false);
    m.Resize(1, n, false);
    for (int i = 0; i < n; ++i) {
      k.SetValue(i + 1, values[i]);
      m.SetValue(i + 1, i == 0 || i == n - 1 ? 4 : c1[i] ? 2 : 3);
    }
  };
  TColStd_Array1OfReal u_knots(1, 2), v_knots(1, 2);
  TColStd_Array1OfInteger u_mults(1, 2), v_mults(1, 2);
  knot_arrays(face.u_knots, u_c1, u_knots, u_mults);
  knot_arrays(face.v_knots, v_c1, v_knots, v_mults);
  // OCCT geometry lives in reference-counted handles, which take ownership of a new object.
  Handle(Geom_BSplineSurface) surface =
      new Geom_BSplineSurface(poles, u_knots, v_knots, u_mults, v_mults, 3, 3);
  // From the last interior knot to the first, so that removing one keeps the others' indices.
  for (int i = surface->NbUKnots() - 1; i >= 2; --i) {
    int m = surface->UMultiplicity(i);
    while (m > 0 && surface->RemoveUKnot(i, m - 1, tolerance)) --m;
    ++knots[m];
  }
  for (int i = surface->NbVKnots() - 1; i >= 2; --i) {
    int m = surface->VMultiplicity(i);
    while (m > 0 && surface->RemoveVKnot(i, m - 1, tolerance)) --m;
    ++knots[m];
  }
  return surface;
}

/// The side (t = 0, s = 1, t = 1, s = 0) an edge of a face made from a whole surface runs
/// along, from its parameter curve's middle.
int side_of(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  double first = 0, last = 0;
  const Handle(Geom2d_Curve) curve = BRep_Tool::CurveOnSurface(edge, face, first, last);
  if (curve.IsNull()) return -1;
  const gp_Pnt2d p = curve->Value((first + last) / 2);
  constexpr double kEps = 1e-9;
  if (p.Y() < kEps) return 0;
  if (p.X() > 1 - kEps) return 1;
  if (p.Y() > 1 - kEps) return 2;
  if (p.X() < kEps) return 3;
  return -1;
}

/// A face along one of its edges: the outward normal at a point of the edge's parameter curve
/// on it (the curve and the surface's adaptor made once for all the points).
class NormalsAlong {
 public:
  NormalsAlong(const TopoDS_Edge& edge, const TopoDS_Face& face)
      : curve_(BRep_Tool::CurveOnSurface(edge, face, first_, last_)),
        adaptor_(face, false),
        reversed_(face.Orientation() == TopAbs_REVERSED) {}

  [[nodiscard]] std::optional<gp_Dir> at(double x) const {
    if (curve_.IsNull()) return std::nullopt;
    const gp_Pnt2d uv = curve_->Value(first_ + x * (last_ - first_));
    BRepLProp_SLProps props(adaptor_, uv.X(), uv.Y(), 1, Precision::Confusion());
    if (!props.IsNormalDefined()) return std::nullopt;
    gp_Dir n = props.Normal();
    if (reversed_) n.Reverse();
    return n;
  }

 private:
  double first_ = 0, last_ = 0;
  Handle(Geom2d_Curve) curve_;
  BRepAdaptor_Surface adaptor_;
  bool reversed_;
};

/// The largest angle between the normals of the two faces along a shared edge, in degrees,
/// sampled inside the edge (its ends may be points without a normal): evenly, and towards each
/// end at 2^-k of its length, where the innermost cells of a hierarchy meet.
double largest_angle_deg(const TopoDS_Edge& edge, const TopoDS_Face& a, const TopoDS_Face& b) {
  static const std::vector<double> kAt = [] {
    constexpr int kEven = 9, kTowardsEnds = 24;
    std::vector<double> at;
    for (int k = 0; k < kEven; ++k) at.push_back((k + 0.5) / kEven);
    for (int k = 4; k < kTowardsEnds; ++k) {
      at.push_back(std::ldexp(1.0, -k));
      at.push_back(1 - std::ldexp(1.0, -k));
    }
    return at;
  }();
  const NormalsAlong along_a(edge, a), along_b(edge, b);
  double worst = 0;
  for (const double x : kAt) {
    const auto na = along_a.at(x), nb = along_b.at(x);
    if (na && nb) worst = std::max(worst, na->Angle(*nb) * 180.0 / std::numbers::pi);
  }
  return worst;
}

/// The shape and the name of each of its faces.
struct NamedShape {
  TopoDS_Shape shape;
  std::vector<std::pair<TopoDS_Face, std::string>> names;
};

/// The one part, or a compound of the parts.
TopoDS_Shape one_shape(const std::vector<TopoDS_Shape>& parts) {
  if (parts.size() == 1) return parts.front();
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const TopoDS_Shape& part : parts) builder.Add(compound, part);
  return compound;
}

/// The faces joined along their shared edges: a shell, or a compound of shells and faces on
/// their own; what became of each B-spline face; the shared edges on sharp mesh edges.
struct Joined {
  TopoDS_Shape shape;
  std::vector<TopoDS_Shape> faces;
  TopTools_MapOfShape sharp;
  int free_edges = 0;
  double max_gap = 0;
};

/// A point where faces meet, named by the element of the mesh it lies on.
struct Joint {
  enum Kind { vertex, edge_middle, face_centre } kind;
  int idx;
  auto operator<=>(const Joint&) const = default;
};

/// A stretch of the mesh along which face sides meet: a whole edge, the half of edge(h) at
/// origin(h), or the spoke inside face(h) from the middle of edge(h) to the face's centre.
struct Stretch {
  enum Kind { edge, half, spoke } kind;
  int idx;
  auto operator<=>(const Stretch&) const = default;
};

/// A piece of a face's boundary, counterclockwise in (s, t): the fractions [a, b] of side `side`
/// (which runs from corner `side` of kSquare to the next), from joint `from` to `to`.
struct BoundaryPiece {
  Stretch along;
  int side;
  double a, b;
  Joint from, to;
};

/// The corners of a face's parameter square, counterclockwise from (0, 0).
constexpr std::array<std::array<double, 2>, 4> kSquare{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

gp_Pnt2d on_side(int side, double fraction) {
  const auto& [s0, t0] = kSquare[side];
  const auto& [s1, t1] = kSquare[(side + 1) % 4];
  return {s0 + fraction * (s1 - s0), t0 + fraction * (t1 - t0)};
}

/// The face's boundary as stretches of the mesh it is laid out after. A packed quad's side k
/// runs along the edge of its corner k, cut at the middle where the face across is not packed
/// (its corner faces each meet half of it); a corner face's sides are the halves of its
/// corner's two edges at its vertex and the spokes from their middles to the face centre (the
/// root patch's (u, v) = (0, 0), (1, 0), (1, 1), (0, 1): vertex, edge middle, centre, middle).
std::vector<BoundaryPiece> boundary(const HalfedgeMesh& mesh, const BsplineFace& face,
                                    const std::vector<bool>& packed) {
  const auto middle = [](Halfedge h) {
    return Joint{Joint::edge_middle, HalfedgeMesh::edge(h).idx};
  };
  const auto vertex = [&](Vertex v) { return Joint{Joint::vertex, v.idx}; };
  if (face.vertex >= 0) {
    const Halfedge c = face.corner, before = mesh.prev(c);
    const Joint corner = vertex(mesh.origin(c)), centre{Joint::face_centre, face.face};
    return {{{Stretch::half, c.idx}, 0, 0, 1, corner, middle(c)},
            {{Stretch::spoke, c.idx}, 1, 0, 1, middle(c), centre},
            {{Stretch::spoke, before.idx}, 2, 0, 1, centre, middle(before)},
            {{Stretch::half, HalfedgeMesh::twin(before).idx}, 3, 0, 1, middle(before), corner}};
  }
  std::vector<BoundaryPiece> pieces;
  const std::vector<Halfedge> loop = mesh.face_loop(Face(face.face));
  for (int k = 0; k < 4; ++k) {
    const Halfedge h = loop[k], across = HalfedgeMesh::twin(h);
    const Joint from = vertex(mesh.origin(h)), to = vertex(mesh.target(h));
    if (packed[across.idx] || mesh.is_hole(across)) {
      pieces.push_back({{Stretch::edge, HalfedgeMesh::edge(h).idx}, k, 0, 1, from, to});
    } else {
      pieces.push_back({{Stretch::half, h.idx}, k, 0, 0.5, from, middle(h)});
      pieces.push_back({{Stretch::half, across.idx}, k, 0.5, 1, middle(h), to});
    }
  }
  return pieces;
}

/// The straight segment from `a` at parameter `first` to `b` at `last`: a line where that is its
/// arc length (as for an isoline of the face it bounds), else a B-spline of degree 1.
Handle(Geom2d_Curve) segment(const gp_Pnt2d& a, const gp_Pnt2d& b, double first, double last) {
  const gp_Vec2d d(a, b);
  const gp_Dir2d direction(d);
  if (std::abs(d.Magnitude() - (last - first)) < 1e-12)
    return new Geom2d_Line(a.Translated(-first * gp_Vec2d(direction)), direction);
  TColgp_Array1OfPnt2d poles(1, 2);
  poles.SetValue(1, a);
  poles.SetValue(2, b);
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, first);
  knots.SetValue(2, last);
  TColStd_Array1OfInteger mults(1, 2);
  mults.Init(2);
  return new Geom2d_BSplineCurve(poles, knots, mults, 1);
}

/// One edge of the shell: its 3D curve (an isoline of its first face) over [first, last], from
/// joint `start`, its segment on each face, and the largest distance from the curve to the
/// other face measured along it.
struct SharedEdge {
  Handle(Geom_Curve) curve;
  double first = 0, last = 1;
  Joint start{}, end{};
  std::vector<Handle(Geom2d_Curve)> segments;
  double gap = 0;
};

/// Where two faces share a piece of boundary, a sample every quarter of a knot span of the first
/// face along it suffices: both are the same polynomials there, so what is measured is the
/// knot removal and round-off.
constexpr int kGapSamplesPerSpan = 4;

struct Use {
  int face, piece;
};

/// The face's isoline along side `side` (t = 0, s = 1, t = 1, s = 0), parametrized by s or t.
Handle(Geom_Curve) isoline(const Handle(Geom_BSplineSurface) & surface, int side) {
  const double at = side == 1 || side == 2 ? 1 : 0;
  return side % 2 == 0 ? surface->VIso(at) : surface->UIso(at);
}

SharedEdge shared_edge(const std::vector<Use>& uses, const std::vector<BsplineFace>& faces,
                       const std::vector<Handle(Geom_BSplineSurface)>& surfaces,
                       const std::vector<std::vector<BoundaryPiece>>& pieces) {
  const BoundaryPiece& p = pieces[uses[0].face][uses[0].piece];
  // On sides 2 and 3 the boundary runs against the isoline's parameter.
  const bool backwards = p.side >= 2;
  SharedEdge e;
  e.curve = isoline(surfaces[uses[0].face], p.side);
  e.first = backwards ? 1 - p.b : p.a;
  e.last = backwards ? 1 - p.a : p.b;
  e.start = backwards ? p.to : p.from;
  e.end = backwards ? p.from : p.to;
  for (const Use& use : uses) {
    const BoundaryPiece& q = pieces[use.face][use.piece];
    const bool forward = q.from == e.start;
    e.segments.push_back(segment(on_side(q.side, forward ? q.a : q.b),
                                 on_side(q.side, forward ? q.b : q.a), e.first, e.last));
  }
  // The other face's points on its segment, from its own isoline (a curve evaluates several
  // times faster than the surface).
  const std::vector<double>& knots =
      p.side % 2 == 0 ? faces[uses[0].face].u_knots : faces[uses[0].face].v_knots;
  for (size_t i = 1; i < uses.size(); ++i) {
    const int side = pieces[uses[i].face][uses[i].piece].side;
    const Handle(Geom_Curve) other = isoline(surfaces[uses[i].face], side);
    for (size_t k = 0; k + 1 < knots.size(); ++k) {
      const double from = std::max(knots[k], e.first), to = std::min(knots[k + 1], e.last);
      for (int j = 0; j <= kGapSamplesPerSpan && from < to; ++j) {
        const double t = from + (to - from) * j / kGapSamplesPerSpan;
        const gp_Pnt2d uv = e.segments[i]->Value(t);
        e.gap = std::max(e.gap,
                         e.curve->Value(t).Distance(other->Value(side % 2 == 0 ? uv.X() : uv.Y())));
      }
    }
  }
  return e;
}

/// The faces joined along the sides the mesh says they share (`mesh`: the one they are laid out
/// after), each edge's tolerance the gap measured along it, each vertex's the spread of the
/// faces' corners there. nullopt where the mesh cannot tell: vertices at one position (repair
/// leaves them where the input was not manifold, and only a geometric search joins the pieces
/// there), or sides paired as a shell cannot hold them (a face meeting itself, a closed edge).
std::optional<Joined> join_by_adjacency(const HalfedgeMesh& mesh,
                                        const std::vector<BsplineFace>& faces,
                                        const std::vector<Handle(Geom_BSplineSurface)>& surfaces) {
  {
    std::vector<std::array<double, 3>> positions;
    for (Vertex v : mesh.vertices()) {
      const Vec3& p = mesh.position(v);
      positions.push_back({p.x(), p.y(), p.z()});
    }
    std::sort(positions.begin(), positions.end());
    if (std::adjacent_find(positions.begin(), positions.end()) != positions.end())
      return std::nullopt;
  }
  std::vector<bool> packed(mesh.halfedge_capacity(), false);
  for (const BsplineFace& f : faces)
    if (f.vertex < 0)
      for (Halfedge h : mesh.face_loop(Face(f.face))) packed[h.idx] = true;
  std::vector<std::vector<BoundaryPiece>> pieces(faces.size());
  std::map<Stretch, std::vector<Use>> uses_of;
  for (size_t i = 0; i < faces.size(); ++i) {
    pieces[i] = boundary(mesh, faces[i], packed);
    for (size_t j = 0; j < pieces[i].size(); ++j)
      uses_of[pieces[i][j].along].push_back({int(i), int(j)});
  }
  std::vector<std::vector<Use>> edge_uses;
  for (auto& [stretch, uses] : uses_of) {
    const BoundaryPiece& p = pieces[uses[0].face][uses[0].piece];
    if (uses.size() > 2 || p.from == p.to) return std::nullopt;
    if (uses.size() == 2) {
      const BoundaryPiece& q = pieces[uses[1].face][uses[1].piece];
      if (uses[0].face == uses[1].face || q.from != p.to || q.to != p.from) return std::nullopt;
    }
    edge_uses.push_back(std::move(uses));
  }
  std::vector<SharedEdge> edges(edge_uses.size());
  tbb::parallel_for(size_t{0}, edges.size(), [&](size_t i) {
    edges[i] = shared_edge(edge_uses[i], faces, surfaces, pieces);
  });

  // The vertices: at the first face's corner, their tolerance the distance to every other
  // face's corner there and at least their edges'.
  std::map<Joint, std::pair<gp_Pnt, double>> joints;
  for (size_t i = 0; i < faces.size(); ++i)
    for (const BoundaryPiece& p : pieces[i]) {
      const gp_Pnt2d uv = on_side(p.side, p.a);
      const gp_Pnt point = surfaces[i]->Value(uv.X(), uv.Y());
      const auto at = joints.try_emplace(p.from, point, Precision::Confusion()).first;
      at->second.second = std::max(at->second.second, at->second.first.Distance(point));
    }
  Joined joined;
  for (const SharedEdge& e : edges) {
    joined.max_gap = std::max(joined.max_gap, e.gap);
    for (const Joint& j : {e.start, e.end})
      joints[j].second = std::max(joints[j].second, std::max(e.gap, Precision::Confusion()));
  }
  BRep_Builder builder;
  std::map<Joint, TopoDS_Vertex> vertices;
  for (const auto& [joint, point] : joints)
    builder.MakeVertex(vertices[joint], point.first, point.second);
  std::vector<TopoDS_Face> occt_faces(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    builder.MakeFace(occt_faces[i], surfaces[i], Precision::Confusion());
    builder.NaturalRestriction(occt_faces[i], true);
  }

  // The edges, with their segments on the faces; each face's wire takes its pieces in order.
  std::vector<std::vector<TopoDS_Edge>> wire_edges(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) wire_edges[i].resize(pieces[i].size());
  std::vector<int> component(faces.size());
  std::iota(component.begin(), component.end(), 0);
  const std::function<int(int)> root = [&](int f) {
    return component[f] == f ? f : component[f] = root(component[f]);
  };
  for (size_t i = 0; i < edges.size(); ++i) {
    const SharedEdge& e = edges[i];
    const double tolerance = std::max(e.gap, Precision::Confusion());
    TopoDS_Edge edge;
    builder.MakeEdge(edge, e.curve, tolerance);
    builder.Add(edge, vertices[e.start].Oriented(TopAbs_FORWARD));
    builder.Add(edge, vertices[e.end].Oriented(TopAbs_REVERSED));
    for (size_t u = 0; u < edge_uses[i].size(); ++u) {
      const Use& use = edge_uses[i][u];
      builder.UpdateEdge(edge, e.segments[u], occt_faces[use.face], tolerance);
      const bool forward = pieces[use.face][use.piece].from == e.start;
      wire_edges[use.face][use.piece] =
          TopoDS::Edge(edge.Oriented(forward ? TopAbs_FORWARD : TopAbs_REVERSED));
      if (faces[use.face].sharp_side[pieces[use.face][use.piece].side]) joined.sharp.Add(edge);
    }
    builder.Range(edge, e.first, e.last);
    if (edge_uses[i].size() == 1)
      ++joined.free_edges;
    else
      component[root(edge_uses[i][0].face)] = root(edge_uses[i][1].face);
  }
  for (size_t i = 0; i < faces.size(); ++i) {
    TopoDS_Wire wire;
    builder.MakeWire(wire);
    for (const TopoDS_Edge& edge : wire_edges[i]) builder.Add(wire, edge);
    wire.Closed(true);
    builder.Add(occt_faces[i], wire);
  }

  // A shell per connected set of faces; a face that shares no edge stays on its own, as sewing
  // leaves it.
  std::map<int, std::vector<int>> sets;
  for (size_t i = 0; i < faces.size(); ++i) sets[root(int(i))].push_back(int(i));
  std::vector<TopoDS_Shape> parts;
  for (const auto& [first, members] : sets) {
    if (members.size() == 1) {
      parts.push_back(occt_faces[members.front()]);
      continue;
    }
    TopoDS_Shell shell;
    builder.MakeShell(shell);
    for (int f : members) builder.Add(shell, occt_faces[f]);
    shell.Closed(BRep_Tool::IsClosed(shell));
    parts.push_back(shell);
  }
  joined.shape = one_shape(parts);
  joined.faces.assign(occt_faces.begin(), occt_faces.end());
  return joined;
}

/// The faces joined by OpenCASCADE's sewing, which searches for the sides that meet within
/// `tolerance`.
Joined sew(const std::vector<BsplineFace>& faces,
           const std::vector<Handle(Geom_BSplineSurface)>& surfaces, double tolerance,
           const HalfedgeMesh& named_after, const CadOptions& options) {
  std::vector<TopoDS_Face> occt_faces(faces.size());
  TopTools_MapOfShape sharp_edges;  // edges of occt_faces
  for (size_t i = 0; i < faces.size(); ++i) {
    BRepBuilderAPI_MakeFace make(surfaces[i], Precision::Confusion());
    if (!make.IsDone())
      throw Error(fmt::format("OpenCASCADE refused the B-spline face of {}",
                              face_name(named_after, faces[i])));
    occt_faces[i] = make.Face();
    for (TopExp_Explorer e(occt_faces[i], TopAbs_EDGE); e.More(); e.Next()) {
      const int side = side_of(TopoDS::Edge(e.Current()), occt_faces[i]);
      if (side >= 0 && faces[i].sharp_side[side]) sharp_edges.Add(e.Current());
    }
  }
  BRepBuilderAPI_Sewing sewing(tolerance, true, true, true, false);
  for (const TopoDS_Face& face : occt_faces) sewing.Add(face);
  {
    Handle(ForwardProgress) indicator = new ForwardProgress(options.progress, 0.5, 0.8);
    sewing.Perform(indicator->Start());
  }
  Joined joined;
  joined.free_edges = sewing.NbFreeEdges();
  joined.shape = sewing.SewedShape();
  for (TopTools_MapOfShape::Iterator it(sharp_edges); it.More(); it.Next()) {
    const TopoDS_Shape& original = it.Value();
    const TopoDS_Shape now =
        sewing.IsModifiedSubShape(original) ? sewing.ModifiedSubShape(original) : original;
    for (TopExp_Explorer e(now, TopAbs_EDGE); e.More(); e.Next()) joined.sharp.Add(e.Current());
  }
  for (const TopoDS_Face& face : occt_faces)
    joined.faces.push_back(sewing.IsModified(face) ? sewing.Modified(face) : TopoDS_Shape(face));
  return joined;
}

NamedShape build_shape(const HalfedgeMesh& mesh, const Surface& surface, const PatchSet& patches,
                       const CadOptions& options, CadReport& r) {
  const auto progress = [&](double from, double to, double done) {
    if (options.progress) options.progress(from + (to - from) * done);
  };
  r.sewing_tolerance = options.sewing_tolerance > 0
                           ? options.sewing_tolerance
                           : std::max({2 * patches.max_position_deviation,
                                       1e-7 * patches.model_size, Precision::Confusion()});
  const std::vector<BsplineFace> faces = bspline_faces(
      mesh, surface, patches, options.packing, [&](double done) { progress(0.0, 0.3, done); },
      options.control);
  const HalfedgeMesh& named_after = options.control ? *options.control->mesh : mesh;
  r.faces = static_cast<int>(faces.size());

  // The OCCT surfaces, their knots lowered (each face on its own, so in parallel).
  const double knot_tolerance = kKnotRemovalTolerance * patches.model_size;
  std::vector<Handle(Geom_BSplineSurface)> surfaces(faces.size());
  std::vector<std::array<std::int64_t, 4>> knots(faces.size());
  tbb::parallel_for(size_t{0}, faces.size(), [&](size_t i) {
    knots[i] = {};
    surfaces[i] = make_surface(faces[i], knot_tolerance, knots[i]);
  });
  for (size_t i = 0; i < faces.size(); ++i) {
    for (int m = 0; m < 4; ++m) r.knots[m] += knots[i][m];
    r.poles += static_cast<std::int64_t>(surfaces[i]->NbUPoles()) * surfaces[i]->NbVPoles();
  }
  progress(0.3, 0.5, 1.0);
  // The mesh tells which sides meet; sewing searches for them where it cannot.
  std::optional<Joined> joined;
  if (!options.force_sewing) joined = join_by_adjacency(named_after, faces, surfaces);
  r.sewn = !joined;
  if (!joined) joined = sew(faces, surfaces, r.sewing_tolerance, named_after, options);
  r.free_edges = joined->free_edges;
  r.max_edge_gap = joined->max_gap;
  const TopoDS_Shape& sewn = joined->shape;
  const TopTools_MapOfShape& sewn_sharp = joined->sharp;

  // Regularity: an edge where the faces' normals meet within the angle tolerance, measured
  // along it and towards its ends, is G1. (OCCT's EncodeRegularity asks for parallel
  // cross-boundary derivatives, which faces meeting tangentially near an extraordinary point
  // need not have.)
  const double g1_angle_deg = options.angle_tolerance_deg;
  BRep_Builder builder;
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(sewn, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  struct SmoothEdge {
    TopoDS_Edge edge;
    TopoDS_Face a, b;
    double angle_deg = 0;
  };
  std::vector<SmoothEdge> smooth;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopTools_ListOfShape& around = edge_faces.FindFromIndex(i);
    if (around.Extent() != 2) continue;
    if (sewn_sharp.Contains(edge_faces.FindKey(i)))
      ++r.sharp_edges;
    else
      smooth.push_back({TopoDS::Edge(edge_faces.FindKey(i)), TopoDS::Face(around.First()),
                        TopoDS::Face(around.Last())});
  }
  // The angles on all cores; the continuity is written into the shape on one.
  tbb::parallel_for(size_t{0}, smooth.size(), [&](size_t k) {
    smooth[k].angle_deg = largest_angle_deg(smooth[k].edge, smooth[k].a, smooth[k].b);
  });
  r.smooth_edges = static_cast<int>(smooth.size());
  for (const SmoothEdge& e : smooth) {
    r.max_smooth_angle_deg = std::max(r.max_smooth_angle_deg, e.angle_deg);
    if (e.angle_deg <= g1_angle_deg) {
      builder.Continuity(e.edge, e.a, e.b, GeomAbs_G1);
      ++r.g1_edges;
    }
  }

  // Every closed shell becomes a solid, oriented so that its faces point out of it.
  std::vector<TopoDS_Shell> shells;
  for (TopExp_Explorer it(sewn, TopAbs_SHELL); it.More(); it.Next())
    shells.push_back(TopoDS::Shell(it.Current()));
  const bool loose_faces = TopExp_Explorer(sewn, TopAbs_FACE, TopAbs_SHELL).More();
  // The faces are the patches' polynomials, so the solids' volume is theirs, integrated exactly
  // (OCCT's numerical integration over many knot spans takes seconds).
  const bool closed = !shells.empty() && !loose_faces &&
                      std::all_of(shells.begin(), shells.end(), [](const TopoDS_Shell& shell) {
                        return BRep_Tool::IsClosed(shell);
                      });
  if (closed) r.volume = enclosed_volume(patches);
  std::vector<TopoDS_Shape> parts;
  for (const TopoDS_Shell& shell : shells) {
    ++r.shells;
    if (BRep_Tool::IsClosed(shell)) {
      TopoDS_Solid solid = BRepBuilderAPI_MakeSolid(shell).Solid();
      // One shell whose faces keep their surfaces' orientation encloses the patches' volume with
      // its sign (du x dv out of it when positive): then it is oriented already, and OCCT's
      // classification against a point at infinity (about a second for 3k faces) is not needed.
      bool forward = closed && shells.size() == 1 && r.volume > 0;
      for (TopExp_Explorer f(solid, TopAbs_FACE); forward && f.More(); f.Next())
        forward = f.Current().Orientation() == TopAbs_FORWARD;
      if (!forward) BRepLib::OrientClosedSolid(solid);
      parts.push_back(solid);
      ++r.solids;
    } else {
      parts.push_back(shell);
    }
  }
  for (TopExp_Explorer it(sewn, TopAbs_FACE, TopAbs_SHELL); it.More(); it.Next())
    parts.push_back(it.Current());  // faces left on their own
  NamedShape named;
  for (size_t i = 0; i < faces.size(); ++i)
    for (TopExp_Explorer f(joined->faces[i], TopAbs_FACE); f.More(); f.Next())
      named.names.emplace_back(TopoDS::Face(f.Current()), face_name(named_after, faces[i]));
  named.shape = one_shape(parts);
  progress(0.8, 0.8, 1.0);
  return named;
}

/// Sets each face's name on the entity the writer made of it.
template <class Entity, class SetName>
void name_entities(const Handle(Transfer_FinderProcess) & process, const NamedShape& named,
                   const Handle(Standard_Type) & type, SetName set_name) {
  for (const auto& [face, name] : named.names) {
    const Handle(TransferBRep_ShapeMapper) mapper = TransferBRep::ShapeMapper(process, face);
    Handle(Entity) entity;
    if (process->FindTypedTransient(mapper, type, entity)) set_name(entity, name);
  }
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

TopoDS_Shape make_shape(const HalfedgeMesh& mesh, const Surface& surface, const PatchSet& patches,
                        const CadOptions& options, CadReport* report) {
  CadReport r;
  NamedShape named = build_shape(mesh, surface, patches, options, r);
  if (report) *report = r;
  return named.shape;
}

CadEstimate estimate_cad(const HalfedgeMesh& mesh, const Surface& surface, const PatchSet& patches,
                         FacePacking packing, CadFormat format, const ControlMesh* control) {
  // Bytes per pole and per face of OCCT's writers, measured on the examples (docs/formats.md).
  const double pole_bytes = format == CadFormat::step ? 100 : 64;
  const double face_bytes = format == CadFormat::step ? 3000 : 1500;
  CadEstimate e;
  for (const BsplineFace& face : bspline_face_layout(mesh, surface, patches, packing, control)) {
    ++e.faces;
    // Simple knots inside a root patch's hierarchy (C2), double ones where root patches meet
    // (C1): the quadrants' sides inside the face.
    const auto poles_along = [&](const std::vector<double>& knots, int axis) {
      std::int64_t n = static_cast<std::int64_t>(knots.size()) + 2;
      for (const double k : knots)
        if (k > 0 && k < 1 &&
            std::any_of(face.quadrants.begin(), face.quadrants.end(), [&](const FaceQuadrant& q) {
              return q.origin[axis] == k || q.origin[axis] + q.size == k;
            }))
          ++n;
      return n;
    };
    e.poles += poles_along(face.u_knots, 0) * poles_along(face.v_knots, 1);
  }
  e.bytes = static_cast<std::int64_t>(e.poles * pole_bytes + e.faces * face_bytes);
  // Measured with `stitch smooth` (catmark_smoothtris0, a 1k-triangle torus): the faces, shell
  // and file take about 3.5 microseconds a pole on the 2-core VM.
  e.seconds = 3.5e-6 * static_cast<double>(e.poles);
  return e;
}

CadReport write_cad(const std::string& path, CadFormat format, const HalfedgeMesh& mesh,
                    const Surface& surface, const PatchSet& patches, const CadOptions& options) {
  const Unit& unit = find_unit(options.units);
  CadReport report;
  const NamedShape named = build_shape(mesh, surface, patches, options, report);
  const TopoDS_Shape& shape = named.shape;
  if (format == CadFormat::step) {
    STEPControl_Writer writer;
    // The shape's length unit (the model's local unit) is the written one, so the coordinates
    // go out unscaled under that unit's name. OCCT 7.6 takes the written unit from its
    // process-wide parameter only; it is set for this transfer and put back afterwards.
    writer.Model()->SetLocalLengthUnit(unit.mm);
    writer.Model()->SetWriteLengthUnit(unit.mm);
    const std::string previous_unit = Interface_Static::CVal("write.step.unit");
    Interface_Static::SetCVal("write.step.unit", unit.occt);
    // The shape's share of the time is about 0.8 (build_shape), the transfer's and the file's
    // about a third and two thirds of the rest.
    Handle(ForwardProgress) indicator = new ForwardProgress(options.progress, 0.8, 0.87);
    // Without the work session's entity graph (a third of the transfer): only OCCT's own
    // Write reads it, and print_step writes the model instead.
    const IFSelect_ReturnStatus transferred =
        writer.Transfer(shape, STEPControl_AsIs, false, indicator->Start());
    Interface_Static::SetCVal("write.step.unit", previous_unit.c_str());
    if (transferred != IFSelect_RetDone)
      throw OutputError(
          fmt::format("cannot write {}: OpenCASCADE could not convert the shape", path));
    name_entities<StepRepr_RepresentationItem>(
        writer.WS()->TransferWriter()->FinderProcess(), named,
        STANDARD_TYPE(StepRepr_RepresentationItem),
        [](const Handle(StepRepr_RepresentationItem) & item, const std::string& name) {
          item->SetName(new TCollection_HAsciiString(name.c_str()));
        });
    write_through(path, [&](const std::string& temporary) {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      return print_step(writer.Model(),
                        Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol()), out,
                        [&](double done) {
                          if (options.progress) options.progress(0.87 + 0.13 * done);
                        });
    });
  } else {
    IGESControl_Controller::Init();
    IGESControl_Writer writer(unit.occt, 1);  // 1: B-rep entities, which keep shells and solids
    writer.Model()->ChangeGlobalSection().SetCascadeUnit(unit.mm);
    Handle(ForwardProgress) indicator = new ForwardProgress(options.progress, 0.8, 0.9);
    if (!writer.AddShape(shape, indicator->Start()))
      throw OutputError(
          fmt::format("cannot write {}: OpenCASCADE could not convert the shape", path));
    // The name as IGES keeps it: an 8-character label and the whole name in a Name property
    // (entity 406, form 15), as OCCT's own IGESCAFControl_Writer writes names.
    name_entities<IGESData_IGESEntity>(
        writer.TransferProcess(), named, STANDARD_TYPE(IGESData_IGESEntity),
        [&writer](const Handle(IGESData_IGESEntity) & entity, const std::string& name) {
          entity->SetLabel(new TCollection_HAsciiString(name.substr(0, 8).c_str()));
          Handle(IGESBasic_Name) long_name = new IGESBasic_Name;
          long_name->Init(1, new TCollection_HAsciiString(name.c_str()));
          entity->AddProperty(long_name);
          writer.AddEntity(long_name);
        });
    writer.ComputeModel();
    write_through(path, [&](const std::string& temporary) {
      return writer.Write(temporary.c_str()) == Standard_True;
    });
  }
  if (options.progress) options.progress(1.0);
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

std::vector<std::string> read_face_names(const std::string& path) {
  const std::optional<CadFormat> format = cad_format(path);
  if (!format)
    throw InputError(fmt::format("{}: cannot read files with extension '{}' (supported: {})", path,
                                 file_extension(path), kCadExtensions));
  std::vector<std::string> names;
  const auto text = [](const Handle(TCollection_HAsciiString) & s) {
    return s.IsNull() ? std::string() : std::string(s->ToCString());
  };
  if (*format == CadFormat::step) {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw InputError(fmt::format("{}: OpenCASCADE cannot read it", path));
    const Handle(StepData_StepModel) model = reader.StepModel();
    for (int i = 1; i <= model->NbEntities(); ++i)
      if (const auto face = Handle(StepShape_AdvancedFace)::DownCast(model->Value(i));
          !face.IsNull())
        names.push_back(text(face->Name()));
  } else {
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw InputError(fmt::format("{}: OpenCASCADE cannot read it", path));
    const Handle(IGESData_IGESModel) model = reader.IGESModel();
    for (int i = 1; i <= model->NbEntities(); ++i)
      if (const auto face = Handle(IGESSolid_Face)::DownCast(model->Value(i)); !face.IsNull())
        names.push_back(text(face->NameValue()));
  }
  return names;
}

}  // namespace stitch::cad
