#include "stitch/tess/export.hpp"

#include "../mesh/io_detail.hpp"
#include "stitch/mesh/io.hpp"

namespace stitch {

namespace {

constexpr std::string_view kComment =
    "stitch surface (bicubic Bezier patches, modified de Casteljau)";

void check_surface(const std::string& path, const SurfaceMesh& mesh) {
  const int nv = mesh.num_vertices();
  if (mesh.normals.size() != mesh.positions.size())
    throw MeshError(
        fmt::format("cannot write {}: {} positions but {} normals", path, nv, mesh.normals.size()));
  for (const auto& quad : mesh.quads)
    for (int v : quad)
      if (v < 0 || v >= nv)
        throw MeshError(
            fmt::format("cannot write {}: a quad refers to sample {} of {}", path, v, nv));
}

}  // namespace

void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh) {
  using namespace io_detail;
  check_surface(path, mesh);
  const std::string ext = file_extension(path);
  if (ext == ".obj")
    write_file_atomically(path, [&](std::ostream& out) {
      write_obj(out, mesh.positions, &mesh.normals, mesh.quads, kComment);
    });
  else if (ext == ".ply")
    write_file_atomically(path, [&](std::ostream& out) {
      write_ply_ascii(out, mesh.positions, &mesh.normals, mesh.quads, kComment);
    });
  else if (ext == ".off")
    write_file_atomically(
        path, [&](std::ostream& out) { write_off(out, mesh.positions, mesh.quads, kComment); });
  else if (ext == ".stl")
    write_file_atomically(
        path, [&](std::ostream& out) { write_stl(out, mesh.positions, mesh.quads, kComment); },
        true);
  else
    throw MeshError(fmt::format(
        "cannot write {}: unknown extension '{}' (supported: .obj, .ply, .off, .stl)", path, ext));
}

void write_surface_samples_ply(const std::string& path, const SurfaceMesh& mesh) {
  using io_detail::put_le;
  check_surface(path, mesh);
  const size_t nv = mesh.positions.size();
  if (mesh.uv.size() != nv || mesh.patch.size() != nv)
    throw MeshError(fmt::format("cannot write {}: the samples lack (u, v) or patch numbers", path));
  if (file_extension(path) != ".ply")
    throw MeshError(fmt::format("cannot write {}: samples are written as .ply only", path));
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out << "ply\nformat binary_little_endian 1.0\ncomment " << kComment
            << "\ncomment patch = corner (half-edge index) of the input mesh; u v = position in "
               "that patch\nelement vertex "
            << nv << '\n';
        for (const char* name : {"x", "y", "z", "nx", "ny", "nz", "u", "v"})
          out << "property double " << name << '\n';
        out << "property int patch\nelement face " << mesh.quads.size()
            << "\nproperty list uchar int vertex_indices\nend_header\n";
        for (size_t i = 0; i < nv; ++i) {
          for (int k = 0; k < 3; ++k) put_le(out, mesh.positions[i][k]);
          for (int k = 0; k < 3; ++k) put_le(out, mesh.normals[i][k]);
          put_le(out, mesh.uv[i].x());
          put_le(out, mesh.uv[i].y());
          put_le(out, static_cast<std::int32_t>(mesh.patch[i]));
        }
        for (const auto& quad : mesh.quads) {
          put_le(out, std::uint8_t{4});
          for (int v : quad) put_le(out, static_cast<std::int32_t>(v));
        }
      },
      true);
}

}  // namespace stitch
