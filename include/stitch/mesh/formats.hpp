// The polygon mesh file formats: the enum the writers take, and the extensions the mesh reader and
// writer take, which the readers, the writers, their messages and the modeler's file dialogs all
// use. The smooth surface's output formats are a table of their own (stitch::output), whose
// tessellated rows name one of these.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace stitch {

/// A polygon mesh file format: one file per format in src/mesh/ (io_obj.cpp, ...) holds its
/// reader and its writer. Writers take it as an argument and never look at the path's extension.
enum class MeshFileFormat { obj, ply, off, stl, glb, gltf };

/// glTF, binary or not: one buffer written whole, not a stream of blocks; triangles only.
constexpr bool is_gltf(MeshFileFormat format) {
  return format == MeshFileFormat::glb || format == MeshFileFormat::gltf;
}

/// The formats with per-vertex normals (OBJ `vn`, PLY nx ny nz, glTF NORMAL); OFF has none and
/// STL only facet normals, computed from the triangles.
constexpr bool has_vertex_normals(MeshFileFormat format) {
  return format != MeshFileFormat::off && format != MeshFileFormat::stl;
}

/// The extensions read_polygon_soup (mesh/io.hpp) reads, lower case with the dot.
inline constexpr std::array<std::string_view, 6> kMeshReadExtensions{".obj", ".off", ".ply",
                                                                     ".stl", ".glb", ".gltf"};
/// The extensions write_polygon_soup writes.
inline constexpr std::array<std::string_view, 4> kMeshWriteExtensions{".obj", ".off", ".ply",
                                                                      ".stl"};
/// ".obj, .off, .ply" for messages.
std::string extension_list(std::span<const std::string_view> extensions);

/// The format `path`'s extension (file_extension: any case) names when it is one of
/// `extensions`, or none: the one place a mesh file's extension becomes its format.
std::optional<MeshFileFormat> mesh_file_format(const std::string& path,
                                               std::span<const std::string_view> extensions);

}  // namespace stitch
