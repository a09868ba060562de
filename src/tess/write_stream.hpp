// Writing a streamed surface mesh, shared by the uniform (export.cpp) and adaptive (adaptive.cpp)
// tessellations: SurfaceFileOptions as the mesh stage's writers take them. Internal.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh_writer.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/tess/export.hpp"

namespace stitch::detail {

/// Writes `stream` to `path` in `format` with `comment` in the header (write_mesh_stream).
/// `positions` are needed for .stl and glTF only.
void write_stream(const std::string& path, MeshFileFormat format, const MeshStream& stream,
                  const std::vector<Vec3>& positions, const SurfaceFileOptions& options,
                  std::string_view comment);

}  // namespace stitch::detail
