// Internal to the library: the glTF 2.0 writer behind write_surface_mesh.
#pragma once

#include <string>
#include <vector>

#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

/// `binary`: one .glb file. Otherwise a .gltf file and its buffer beside it, named like the
/// .gltf with the extension .bin (written first, so the .gltf never refers to a missing file).
/// `texcoords`, if given, holds one UV per vertex in glTF's convention (v down from the top) and
/// becomes TEXCOORD_0.
void write_gltf(const std::string& path, const TessellatedMesh& mesh, bool binary,
                const std::vector<Eigen::Vector2f>* texcoords = nullptr);

}  // namespace stitch
