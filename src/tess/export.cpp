#include "stitch/tess/export.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "../mesh/mesh_writer.hpp"
#include "layout.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/tess/tessellate.hpp"
#include "tess/gltf.hpp"

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
  if (const int bad = first_non_finite_sample(mesh); bad >= 0)
    throw MeshError(fmt::format("cannot write {}: sample {} has a non-finite position or normal",
                                path, bad + 1));
}

bool is_gltf(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == ".glb" || ext == ".gltf";
}

void check_extension(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl")
    throw MeshError(fmt::format("cannot write {}: unknown extension '{}' (supported: {})", path,
                                ext, kSurfaceMeshExtensions));
}

/// Writes `stream` to `path` in the format its extension names. `positions` are needed for .stl
/// only.
void write_stream(const std::string& path, const io_detail::MeshStream& stream,
                  const std::vector<Vec3>& positions, const SurfaceFileOptions& options) {
  using namespace io_detail;
  const std::string ext = file_extension(path);
  const bool binary = ext == ".stl" || (ext == ".ply" && !options.ascii_ply);
  write_mesh_file(path, binary, [&](std::ostream& out) {
    if (ext == ".obj")
      write_obj(out, stream, kComment, options.progress);
    else if (ext == ".ply")
      write_ply(out, stream,
                options.ascii_ply ? PlyEncoding::ascii : PlyEncoding::binary_little_endian,
                options.single_precision ? PlyPrecision::single : PlyPrecision::double_precision,
                kComment, options.progress);
    else if (ext == ".off")
      write_off(out, stream, kComment, options.progress);
    else
      write_stl(out, stream, positions, kComment, options.progress);
  });
}

}  // namespace

void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh,
                        const SurfaceFileOptions& options) {
  if (is_gltf(path)) {
    check_surface(path, mesh);
    write_gltf(path, mesh, file_extension(path) == ".glb");
    return;
  }
  check_extension(path);
  check_surface(path, mesh);
  const bool normals = file_extension(path) != ".off" && file_extension(path) != ".stl";
  write_stream(
      path, io_detail::stream_arrays(mesh.positions, normals ? &mesh.normals : nullptr, mesh.quads),
      mesh.positions, options);
}

SurfaceFileCounts write_smooth_surface(const std::string& path, const HalfedgeMesh& mesh,
                                       const Surface& surface, int resolution,
                                       const SurfaceFileOptions& options) {
  if (is_gltf(path)) {  // glTF holds its buffer whole: tessellate, then write
    const SurfaceMesh whole = tessellate(mesh, surface, {resolution, true});
    write_surface_mesh(path, whole, options);
    return {whole.num_vertices(), static_cast<std::int64_t>(whole.quads.size())};
  }
  check_extension(path);
  const std::string ext = file_extension(path);
  const TessellationLayout layout(mesh, surface.corners(), resolution, true);
  io_detail::MeshStream stream;
  stream.num_vertices = layout.num_vertices();
  stream.num_faces = layout.num_quads();
  stream.has_normals = ext == ".obj" || ext == ".ply";
  stream.max_face_degree = 4;
  stream.triangles = 2 * layout.num_quads();
  // Evaluates output vertices [begin, end), refusing what no file should hold.
  const auto evaluate = [&](std::int64_t begin, std::int64_t end, Vec3* positions, Vec3* normals) {
    layout.evaluate(surface, begin, end, positions, normals);
    for (std::int64_t i = 0; i < end - begin; ++i)
      if (!positions[i].allFinite() || !normals[i].allFinite())
        throw MeshError(
            fmt::format("sample {} has a non-finite position or normal", begin + i + 1));
  };
  stream.vertices = [&](std::int64_t begin, std::int64_t end, io_detail::VertexBlock& block) {
    block.positions.resize(static_cast<size_t>(end - begin));
    block.normals.resize(block.positions.size());
    evaluate(begin, end, block.positions.data(), block.normals.data());
    if (!stream.has_normals) block.normals.clear();
  };
  stream.faces = [&](std::int64_t begin, std::int64_t end, io_detail::FaceBlock& block) {
    block.sizes.assign(static_cast<size_t>(end - begin), 4);
    block.indices.resize(4 * block.sizes.size());
    for (std::int64_t q = begin; q < end; ++q) {
      const auto quad = layout.quad(q);
      for (int k = 0; k < 4; ++k)
        block.indices[4 * static_cast<size_t>(q - begin) + k] = static_cast<int>(quad[k]);
    }
  };
  std::vector<Vec3> positions;
  if (ext == ".stl") {
    // STL repeats the corners of every triangle: evaluate them all first, then stream the
    // triangles.
    positions.resize(static_cast<size_t>(layout.num_vertices()));
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, layout.num_vertices(), 4096),
                      [&](const tbb::blocked_range<std::int64_t>& r) {
                        std::vector<Vec3> normals(r.size());
                        evaluate(r.begin(), r.end(), positions.data() + r.begin(), normals.data());
                      });
  }
  write_stream(path, stream, positions, options);
  return {layout.num_vertices(), layout.num_quads()};
}

std::int64_t smooth_memory_estimate(const HalfedgeMesh& mesh, int resolution, bool welded,
                                    const std::string& path) {
  // Measured peak resident size of `stitch smooth` to binary PLY divided by the corners: 806
  // bytes at 100k and 1M faces (mesh, K-gons, 16-point nets, the input file's text); rounded up.
  constexpr std::int64_t kBytesPerCorner = 1024;
  const auto corners = static_cast<std::int64_t>(mesh.num_halfedges());
  const std::int64_t n = resolution;
  std::int64_t bytes = kBytesPerCorner * corners;
  if (!welded)  // positions, normals, uv, patch and level per sample, 4 ints per quad
    bytes += corners * ((n + 1) * (n + 1) * 72 + n * n * 16);
  else if (is_gltf(path))  // the whole tessellation, then its buffer: positions, normals, quads
    bytes += corners * n * n * (48 + 16) * 2;
  else if (file_extension(path) == ".stl")  // every position (about n^2 per corner)
    bytes += corners * n * n * 24;
  return bytes;
}

void write_surface_samples_ply(const std::string& path, const SurfaceMesh& mesh) {
  check_surface(path, mesh);
  const size_t nv = mesh.positions.size();
  if (mesh.uv.size() != nv || mesh.patch.size() != nv)
    throw MeshError(fmt::format("cannot write {}: the samples lack (u, v) or patch numbers", path));
  if (file_extension(path) != ".ply")
    throw MeshError(fmt::format("cannot write {}: samples are written as .ply only", path));
  io_detail::write_mesh_file(path, true, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment " << kComment
        << "\ncomment patch = corner (half-edge index) of the input mesh; u v = position in "
           "that patch\nelement vertex "
        << nv << '\n';
    for (const char* name : {"x", "y", "z", "nx", "ny", "nz", "u", "v"})
      out << "property double " << name << '\n';
    out << "property int patch\nelement face " << mesh.quads.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    io_detail::write_blocks(
        out, static_cast<std::int64_t>(nv), 16384,
        [&](std::int64_t begin, std::int64_t end, io_detail::OutputBuffer& bytes) {
          io_detail::LittleEndianWriter record(bytes, static_cast<size_t>(end - begin) * 68);
          for (std::int64_t i = begin; i < end; ++i) {
            record.put(mesh.positions[i]);
            record.put(mesh.normals[i]);
            record.put(mesh.uv[i].x());
            record.put(mesh.uv[i].y());
            record.put(static_cast<std::int32_t>(mesh.patch[i]));
          }
        });
    io_detail::write_blocks(
        out, static_cast<std::int64_t>(mesh.quads.size()), 32768,
        [&](std::int64_t begin, std::int64_t end, io_detail::OutputBuffer& bytes) {
          io_detail::LittleEndianWriter record(bytes, static_cast<size_t>(end - begin) * 17);
          for (std::int64_t q = begin; q < end; ++q) {
            record.put(std::uint8_t{4});
            for (int v : mesh.quads[q]) record.put(static_cast<std::int32_t>(v));
          }
        });
  });
}

}  // namespace stitch
