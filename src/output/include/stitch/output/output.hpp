// One way out: every file a smooth surface is written to, tessellated or exact, goes through
// write_surface and the table of output formats (one row per format: its extensions, traits,
// memory model and writer). The command line, Python and the modeler write through it; their
// checks, help texts and file dialogs read the table. CONTRIBUTING.md shows how a format is added:
// its writer and one row.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "stitch/analysis/build_surface.hpp"
#include "stitch/eval/surface.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/tess/bspline_faces.hpp"
#include "stitch/tess/patches.hpp"
#include "stitch/tess/tessellate.hpp"

namespace stitch {

enum class OutputKind {
  tessellated,  ///< a polygon mesh of surface samples
  exact,        ///< the patches themselves: Bézier data or B-spline faces
};

/// What a writer holds in memory besides the mesh and its surface.
enum class MemoryModel {
  streamed,   ///< a few blocks at a time: memory does not grow with the resolution
  whole,      ///< the whole tessellation, then the file's buffer
  patch_set,  ///< the exact patches (a few hundred bytes per cell of the hierarchy)
  cad_model,  ///< the patches and OpenCASCADE's model of the file (about 1 kB per pole)
};

/// What is asked of a file besides its path. Fields that do not apply to a format are refused
/// by check_output when they differ from their defaults.
struct OutputSpec {
  // Tessellated formats.
  int resolution = kDefaultResolution;  ///< segments per patch side
  /// > 0: adaptive triangles instead of `resolution`, each patch side's segments from the
  /// control nets' flatness at this tolerance relative to the model size.
  double adaptive_tolerance = 0;
  bool unwelded = false;          ///< every patch's own grid with its (u, v) and patch (.ply)
  bool ascii = false;             ///< .ply as text
  bool single_precision = false;  ///< .ply positions and normals as floats
  /// Texture coordinates to write where the format has a place for them (OutputFormat::uvs);
  /// null: none. Not owned.
  const UvSurface* uvs = nullptr;
  // Exact formats.
  PatchSetOptions patches;  ///< the position and angle tolerances of the hierarchy's cells
  FacePacking packing = FacePacking::quads;
  std::string units = "mm";  ///< declared by STEP and IGES; coordinates are not scaled
  bool kgons = false;        ///< Bézier JSON: every K-gon as well
  /// STEP and IGES: the mesh to pack and name the faces after when the surface's mesh refines it
  /// (write_surface of a BuiltSurface sets it; other formats ignore it); not owned.
  const ControlMesh* control = nullptr;
  // Both.
  /// The fraction (0..1) done, from one thread at a time.
  std::function<void(double)> progress;
  /// Lines worth telling while the work goes on (the patch set's depth and deviation, the size
  /// of a large file before it is written); none when empty.
  std::function<void(const std::string&)> note;
};

/// What write_surface wrote.
struct OutputReport {
  std::string summary;  ///< one line: counts and what they mean
  std::int64_t vertices = 0, faces = 0;
  std::int64_t texcoords = 0;  ///< texture coordinates written (0: none)
};

struct OutputFormat {
  std::string_view name{};  ///< for people: "binary PLY", "STEP AP214"
  /// Lower case with the dot; the first is the one a dialog proposes. Unused slots are empty.
  std::array<std::string_view, 2> extensions{};
  OutputKind kind = OutputKind::tessellated;
  /// What a tessellated row's writer hands the core's mesh writers: the one place a path's
  /// extension becomes a mesh file format. None for the exact rows.
  std::optional<MeshFileFormat> mesh_format{};
  bool uvs = false;        ///< texture coordinates (welded; unwelded .ply has its own)
  bool unwelded = false;   ///< takes OutputSpec::unwelded
  bool adaptive = false;   ///< takes OutputSpec::adaptive_tolerance
  bool needs_cad = false;  ///< written through OpenCASCADE (a build without it refuses)
  MemoryModel memory = MemoryModel::streamed;
  std::string_view help{};
  OutputReport (*write)(const std::string& path, const HalfedgeMesh& mesh, const Surface& surface,
                        const OutputSpec& spec, const OutputFormat& format) = nullptr;
};

/// Every format stitch writes, tessellated first.
std::span<const OutputFormat> output_formats();

/// The row whose extension `path` ends with (".bez.json" before ".json"); null for none.
const OutputFormat* find_output_format(std::string_view path,
                                       std::span<const OutputFormat> formats = output_formats());
/// The same; throws UsageError naming the path and the known extensions for none.
const OutputFormat& output_format(const std::string& path,
                                  std::span<const OutputFormat> formats = output_formats());

/// ".obj, .ply, ..." of the rows of `kind` (all rows without one), for messages and help.
std::string output_extensions(std::optional<OutputKind> kind = std::nullopt,
                              std::span<const OutputFormat> formats = output_formats());
/// The length units STEP and IGES declare, for help texts ("" in a build without them).
std::string output_units();
/// One line for --help: what each memory model means.
std::string_view describe(MemoryModel memory);

/// One tolerance for both kinds of output, as `stitch smooth --tolerance` and Python's
/// `export(tolerance=...)` take it: for an exact format the cells' position tolerance; for a mesh
/// format adaptive triangles instead of a fixed resolution, which it refuses together with an
/// explicit resolution or for a format that takes no adaptive triangles. Throws UsageError.
void set_tolerance(OutputSpec& spec, const OutputFormat& format, double tolerance,
                   bool resolution_given);

/// Whether a file of `format` written with `spec` has a place for texture coordinates (the row's
/// `uvs`, or the unwelded samples of a format that takes them), so that no UV surface is built
/// for a file that would not carry it.
bool writes_uvs(const OutputFormat& format, const OutputSpec& spec);

/// Refuses, before any work, a request that would fail later: an unknown extension, a folder
/// that does not exist or a path that is a folder, an option the format does not take
/// (unwelded, adaptive), a unit STEP and IGES do not know, an exact format in a build without
/// OpenCASCADE. Throws UsageError or OutputError.
void check_output(const std::string& path, const OutputSpec& spec,
                  std::span<const OutputFormat> formats = output_formats());

/// Writes the surface to `path` in the format its extension names: check_output, then the row's
/// writer. Atomic: nothing is left at `path` unless the whole file was written.
OutputReport write_surface(const std::string& path, const HalfedgeMesh& mesh,
                           const Surface& surface, const OutputSpec& spec = {},
                           std::span<const OutputFormat> formats = output_formats());

/// The surface a request built on `input` (build_surface), written as above on the mesh it was
/// built on; when the request refined `input` for semi-sharp tags, STEP and IGES pack and name
/// their faces after `input`'s faces and corners (ControlMesh).
OutputReport write_surface(const std::string& path, const HalfedgeMesh& input,
                           const BuiltSurface& built, OutputSpec spec = {},
                           std::span<const OutputFormat> formats = output_formats());

/// Whether write_surface writes this request block by block, holding no more than the mesh, its
/// surface and a few blocks at any resolution: a welded tessellation in a streamed format (glTF
/// without texture coordinates).
bool output_streams(const OutputFormat& format, const OutputSpec& spec);

/// Bytes of memory write_surface needs at its peak for this mesh and request (the mesh and its
/// surface, and what the format's memory model holds; glTF with `spec.uvs` holds the whole
/// tessellation to split it at seams), for refusing up front what would not fit.
std::int64_t output_memory_estimate(const HalfedgeMesh& mesh, const OutputFormat& format,
                                    const OutputSpec& spec);

}  // namespace stitch
