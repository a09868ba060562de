// The patch set as CAD geometry through OpenCASCADE: one B-spline face per Bézier patch, sewn
// into shells, a solid where a shell is closed; written and read as STEP (AP214) or IGES.
#pragma once

#include <optional>
#include <string>

// stitch's headers come first: OCCT defines a macro Handle(C), which would break stitch's
// Handle template if its header came after OCCT's.
// clang-format off
#include "stitch/mesh/build.hpp"
#include "stitch/tess/patches.hpp"
#include <TopoDS_Shape.hxx>
// clang-format on

namespace stitch::cad {

enum class CadFormat { step, iges };

/// The extensions write_cad takes, for messages.
inline constexpr const char* kCadExtensions = ".step, .stp, .igs, .iges";

/// The format an output path asks for by its extension; nullopt for any other extension.
std::optional<CadFormat> cad_format(const std::string& path);

/// Length units a file can declare: "mm", "cm", "m", "in", "ft". The coordinates are written
/// as they are and labelled with the unit, never scaled.
inline constexpr const char* kCadUnits = "mm, cm, m, in, ft";
/// Throws stitch::Error naming the known units when `units` is not one of them.
void check_units(const std::string& units);

struct CadOptions {
  std::string units = "mm";
  /// Largest gap closed by sewing, in model units; 0 chooses it from the patch set: twice the
  /// measured deviation of its inexact cells, at least 1e-7 of the model size.
  double sewing_tolerance = 0;
};

struct CadReport {
  int faces = 0;       ///< B-spline faces, one per patch
  int shells = 0;      ///< shells after sewing
  int solids = 0;      ///< closed shells made into solids
  int free_edges = 0;  ///< edges on one face only (0 for a closed input)
  double sewing_tolerance = 0;
};

/// The faces of every patch sewn into shells, each closed shell a solid oriented outward; one
/// shape (a compound when there is more than one). Throws stitch::Error for a patch OCCT refuses.
TopoDS_Shape make_shape(const PatchSet& patches, const CadOptions& options = {},
                        CadReport* report = nullptr);

/// Writes the shape as STEP AP214 or IGES 5.3 by the extension of `path`. Atomic: nothing is
/// left at `path` unless the whole file was written. Throws stitch::Error (unknown extension or
/// unit, write failures).
CadReport write_cad(const std::string& path, const PatchSet& patches,
                    const CadOptions& options = {});

/// The faces of a shape triangulated by OCCT's BRepMesh (chordal deflection `deflection`, in the
/// shape's units), with the nodes that faces share along their edges welded into one vertex:
/// a closed sewn shell gives a closed mesh. For viewing re-read files.
PolygonSoup triangulate(const TopoDS_Shape& shape, double deflection);

/// OCCT's readers and writers print statistics to stdout through its process-wide default
/// messenger. An application whose stdout carries results calls this once: it lets through
/// only failures. (A library function cannot decide that for its caller.)
void quiet_opencascade();

/// Reads a STEP or IGES file (by extension) into one shape, for checks and viewers, with
/// lengths in millimetres (OCCT's unit). Throws stitch::Error when it cannot be read.
TopoDS_Shape read_cad(const std::string& path);

}  // namespace stitch::cad
