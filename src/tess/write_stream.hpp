// Writing a streamed surface mesh in the format its file extension names, shared by the uniform
// (export.cpp) and adaptive (adaptive.cpp) tessellations. Internal.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh_writer.hpp"
#include "stitch/tess/export.hpp"

namespace stitch::detail {

/// Writes `stream` to `path` (.obj, .ply, .off or .stl) with `comment` in the header.
/// `positions` are needed for .stl only.
void write_stream(const std::string& path, const detail::MeshStream& stream,
                  const std::vector<Vec3>& positions, const SurfaceFileOptions& options,
                  std::string_view comment);

}  // namespace stitch::detail
