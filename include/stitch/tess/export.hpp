// Writing tessellated surfaces.
#pragma once

#include <string>

#include "stitch/tess/surface_mesh.hpp"

namespace stitch {

/// Writes a welded surface by extension: .obj (with vn), .ply (with normals), .off, .stl.
/// Atomic (see write_file_atomically).
void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh);

/// Writes every sample with its patch attributes as binary little-endian PLY: double x y z
/// nx ny nz u v and int patch, so continuity can be checked from the file alone. Atomic.
void write_surface_samples_ply(const std::string& path, const SurfaceMesh& mesh);

}  // namespace stitch
