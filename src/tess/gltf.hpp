// Internal to the library: the glTF 2.0 writer behind write_surface_mesh.
#pragma once

#include <string>

#include "stitch/tess/surface_mesh.hpp"

namespace stitch {

/// `binary`: one .glb file. Otherwise a .gltf file and its buffer beside it, named like the
/// .gltf with the extension .bin (written first, so the .gltf never refers to a missing file).
void write_gltf(const std::string& path, const SurfaceMesh& mesh, bool binary);

}  // namespace stitch
