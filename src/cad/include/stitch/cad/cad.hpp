// The exact surface as CAD geometry through OpenCASCADE: B-spline faces (tess/bspline_faces.hpp)
// with the lowest knot multiplicities the surface's continuity allows, named after their control
// elements, joined into shells along the sides the mesh says they share, a solid where a shell
// is closed; written and read as STEP (AP214) or IGES.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

// stitch's headers come first: OCCT defines a macro Handle(C), which would break stitch's
// Handle template if its header came after OCCT's.
// clang-format off
#include "stitch/mesh/build.hpp"
#include "stitch/tess/bspline_faces.hpp"
#include "stitch/tess/patches.hpp"
#include <TopoDS_Shape.hxx>
// clang-format on

namespace stitch::cad {

enum class CadFormat { step, iges };

/// The extensions read_cad reads, for messages (writers are chosen by the output table,
/// stitch/output/output.hpp).
inline constexpr const char* kCadExtensions = ".step, .stp, .igs, .iges";

/// The format a CAD file is read as, by its extension; nullopt for any other extension.
std::optional<CadFormat> cad_format(const std::string& path);

/// Length units a file can declare: "mm", "cm", "m", "in", "ft". The coordinates are written
/// as they are and labelled with the unit, never scaled.
inline constexpr const char* kCadUnits = "mm, cm, m, in, ft";
/// Throws stitch::Error naming the known units when `units` is not one of them.
void check_units(const std::string& units);

/// A knot is removed (its multiplicity lowered) only where that moves the surface by at most
/// this, relative to the model size: far below any tolerance of the patch set, far above the
/// round-off of the poles (about 1e-15 of the model size after a few dozen splits). So a lower
/// multiplicity means the surface is that much smoother there, measured.
inline constexpr double kKnotRemovalTolerance = 1e-10;

struct CadOptions {
  std::string units = "mm";
  FacePacking packing = FacePacking::quads;
  /// Faces whose normals differ by at most this along a shared edge that is not a sharp edge of
  /// the mesh meet tangentially: the edge is marked G1 (OpenCASCADE's regularity).
  double angle_tolerance_deg = 0.1;
  /// Largest gap closed by sewing (where the faces are sewn, CadReport::sewn), in model units;
  /// 0 chooses it from the patch set: twice the measured deviation of its inexact cells, at
  /// least 1e-7 of the model size.
  double sewing_tolerance = 0;
  /// Sew the faces even where the mesh tells which sides meet (to compare the two).
  bool force_sewing = false;
  /// Called with the fraction (0..1) done, from one thread at a time.
  std::function<void(double)> progress;
  /// The mesh to pack and name the faces after when the surface's mesh refines it (not owned).
  const ControlMesh* control = nullptr;
};

struct CadReport {
  int faces = 0;       ///< B-spline faces
  int shells = 0;      ///< shells the faces were joined into
  int solids = 0;      ///< closed shells made into solids
  int free_edges = 0;  ///< edges on one face only (0 for a closed input)
  /// Whether OpenCASCADE's sewing joined the faces (where the mesh cannot tell which sides meet:
  /// vertices at one position, as repair leaves them) rather than the mesh's adjacency.
  bool sewn = false;
  double sewing_tolerance = 0;
  /// The largest distance between two faces measured along their shared edges when joined by
  /// adjacency (the edges' tolerance; knot removal and round-off); 0 when sewn.
  double max_edge_gap = 0;
  std::int64_t poles = 0;  ///< of all faces, after the knots were lowered
  /// Interior knots of all faces by the multiplicity they kept: [0] removed (the pieces on both
  /// sides are one polynomial), [1] C2, [2] C1, [3] C0 across the knot.
  std::array<std::int64_t, 4> knots{};
  int smooth_edges = 0;  ///< shared edges inside the smooth surface (not on a sharp mesh edge)
  int sharp_edges = 0;   ///< shared edges along infinitely sharp creases
  int g1_edges = 0;      ///< smooth edges OpenCASCADE marked G1 at the angle tolerance
  double max_smooth_angle_deg = 0;  ///< largest angle between the faces' normals along them
  double volume = 0;  ///< of the solids, in model units cubed (0 when no shell is closed)
};

/// The faces of the patch set as one shape, joined, each closed shell a solid oriented outward
/// (a compound when there is more than one part). Throws stitch::Error for a face OCCT refuses.
TopoDS_Shape make_shape(const HalfedgeMesh& mesh, const Surface& surface, const PatchSet& patches,
                        const CadOptions& options = {}, CadReport* report = nullptr);

/// What a file of the patch set will hold, told before the work: faces, poles (assuming C2
/// inside the faces, as the modified rule gives; knot removal can find fewer, where neighbouring
/// patches are pieces of one polynomial, as away from the tags of a surface refined for them),
/// bytes, and the seconds writing it takes on a 2-core machine (docs/performance.md, "Exporting
/// the exact surface").
struct CadEstimate {
  int faces = 0;
  std::int64_t poles = 0;
  std::int64_t bytes = 0;
  double seconds = 0;
};
CadEstimate estimate_cad(const HalfedgeMesh& mesh, const Surface& surface, const PatchSet& patches,
                         FacePacking packing, CadFormat format,
                         const ControlMesh* control = nullptr);

/// Writes the shape as STEP AP214 or IGES 5.3, every face named (face_name). Atomic: nothing is
/// left at `path` unless the whole file was written. Throws stitch::Error (unknown unit, write
/// failures).
CadReport write_cad(const std::string& path, CadFormat format, const HalfedgeMesh& mesh,
                    const Surface& surface, const PatchSet& patches,
                    const CadOptions& options = {});

/// The faces of a shape triangulated by OCCT's BRepMesh (chordal deflection `deflection`, in the
/// shape's units), with the nodes that faces share along their edges welded into one vertex:
/// a closed shell gives a closed mesh. For viewing re-read files.
PolygonSoup triangulate(const TopoDS_Shape& shape, double deflection);

/// OCCT's readers and writers print statistics to stdout through its process-wide default
/// messenger. An application whose stdout carries results calls this once: it lets through
/// only failures. (A library function cannot decide that for its caller.)
void quiet_opencascade();

/// Reads a STEP or IGES file (by extension) into one shape, for checks and viewers, with
/// lengths in millimetres (OCCT's unit). Throws stitch::Error when it cannot be read.
TopoDS_Shape read_cad(const std::string& path);

/// The names of the faces of a STEP or IGES file, in the file's order (empty strings for
/// faces without one).
std::vector<std::string> read_face_names(const std::string& path);

}  // namespace stitch::cad
