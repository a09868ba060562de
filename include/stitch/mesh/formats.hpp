// The file formats the mesh reader and writer take, by extension: one table that the readers,
// the writers, their messages and the modeler's file dialogs all use.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>

namespace stitch {

/// The extensions read_polygon_soup (mesh/io.hpp) reads, lower case with the dot.
inline constexpr std::array<std::string_view, 6> kMeshReadExtensions{".obj", ".off", ".ply",
                                                                     ".stl", ".glb", ".gltf"};
/// The extensions write_polygon_soup writes.
inline constexpr std::array<std::string_view, 4> kMeshWriteExtensions{".obj", ".off", ".ply",
                                                                      ".stl"};
/// ".obj, .off, .ply" for messages.
std::string extension_list(std::span<const std::string_view> extensions);

}  // namespace stitch
