// Writing tessellated surfaces.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "stitch/eval/surface.hpp"
#include "stitch/eval/uv_surface.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

/// How a welded surface is written.
struct SurfaceFileOptions {
  /// .ply as text instead of binary little-endian (both hold double x y z nx ny nz: exact).
  bool ascii_ply = false;
  /// .ply positions and normals as 32-bit floats: half the bytes, about 7 significant digits
  /// (enough to render or print; the default doubles read back exactly).
  bool single_precision = false;
  /// Called with the fraction (0..1) done; from one thread at a time.
  std::function<void(double)> progress;
  /// Texture coordinates for write_smooth_surface to write where the format has a place for them;
  /// null: none. Not owned. OBJ gets `vt`, one per grid sample of each patch, so the two sides
  /// of a seam keep their own; glTF TEXCOORD_0, vertices split where a seam needs two UVs.
  /// Welded PLY, OFF and STL have no place for UVs that differ on the two sides of a seam, and
  /// are written without them.
  const UvSurface* uvs = nullptr;
};

/// Writes a welded surface in `format` (whatever the path's extension): OBJ (with vn), PLY
/// (binary with normals unless options.ascii_ply), OFF, STL (binary), and glTF 2.0 with normals:
/// .glb, or .gltf with its buffer in a .bin beside it. Atomic (see write_file_atomically).
/// stitch::output's table of formats is what turns a path into a format.
void write_surface_mesh(const std::string& path, MeshFileFormat format, const TessellatedMesh& mesh,
                        const SurfaceFileOptions& options = {});

/// What write_smooth_surface wrote.
struct SurfaceFileCounts {
  std::int64_t vertices = 0, quads = 0;
  std::int64_t texcoords = 0;  ///< texture coordinates written (0: none)
};

/// The same file as write_surface_mesh(path, format, tessellate(mesh, surface, {resolution,
/// true})), byte for byte, made block by block while it is written: memory grows with the input
/// mesh, not with the resolution, and evaluation runs on every core. The formats made of
/// triangles (STL, glTF) split each block's quads by positions evaluated for the block; glTF
/// reads the vertices once more for the bounds its header states. Refuses non-finite samples.
/// Atomic. With options.uvs the file also has texture coordinates (then it is no longer
/// write_surface_mesh's; glTF's vertices are split at seams, over the whole tessellation held in
/// memory).
SurfaceFileCounts write_smooth_surface(const std::string& path, MeshFileFormat format,
                                       const HalfedgeMesh& mesh, const Surface& surface,
                                       int resolution, const SurfaceFileOptions& options = {});

/// Writes every sample with its patch attributes as binary little-endian PLY: double x y z
/// nx ny nz u v and int patch, so continuity can be checked from the file alone; with `uvs`, also
/// double s t, the sample's texture coordinates. Written as PLY whatever the path's extension.
/// Atomic.
void write_surface_samples_ply(const std::string& path, const TessellatedMesh& mesh,
                               const UvSurface* uvs = nullptr);

}  // namespace stitch
