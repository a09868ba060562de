#include "stitch/tess/export.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "mesh/mesh_writer.hpp"
#include "mesh/tinygltf.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/tess/tessellate.hpp"
#include "support/finite.hpp"
#include "tess/gltf.hpp"
#include "tess/layout.hpp"
#include "tess/write_stream.hpp"

namespace stitch {

namespace {

constexpr std::string_view kComment =
    "stitch surface (bicubic Bezier patches, modified de Casteljau)";

void check_writable(const std::string& path, const TessellatedMesh& mesh) {
  const int nv = mesh.num_vertices();
  if (mesh.normals.size() != mesh.positions.size())
    throw OutputError(
        fmt::format("cannot write {}: {} positions but {} normals", path, nv, mesh.normals.size()));
  for (const auto& quad : mesh.quads)
    for (int v : quad)
      if (v < 0 || v >= nv)
        throw OutputError(
            fmt::format("cannot write {}: a quad refers to sample {} of {}", path, v, nv));
  if (const int bad = first_non_finite_sample(mesh); bad >= 0)
    throw OutputError(fmt::format("cannot write {}: sample {} has a non-finite position or normal",
                                  path, bad + 1));
}

bool is_gltf(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == ".glb" || ext == ".gltf";
}

void check_extension(const std::string& path) {
  const std::string ext = file_extension(path);
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl")
    throw UsageError(fmt::format("cannot write {}: unknown extension '{}' (supported: {})", path,
                                 ext, extension_list(kSurfaceMeshExtensions)));
}

/// Samples per patch grid: the number of `vt` lines and unwelded samples of one corner.
std::int64_t grid_size(int resolution) {
  return static_cast<std::int64_t>(resolution + 1) * (resolution + 1);
}

/// The UVs of every corner's (n + 1)^2 grid, corner after corner (TessellatedMesh order unwelded).
std::vector<Eigen::Vector2d> grid_uvs(const UvSurface& uvs, const std::vector<Corner>& corners,
                                      int resolution) {
  const std::int64_t per = grid_size(resolution);
  std::vector<Eigen::Vector2d> out(static_cast<size_t>(per) * corners.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, corners.size(), 64),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t k = r.begin(); k < r.end(); ++k)
                        uvs.evaluate_grid(corners[k], resolution, out.data() + k * per);
                    });
  for (size_t i = 0; i < out.size(); ++i)
    if (!out[i].allFinite())
      throw OutputError(fmt::format("texture coordinate {} is not finite", i + 1));
  return out;
}

/// The welded tessellation as glTF needs it: one UV per vertex, so a vertex whose patches give
/// it different UVs (a seam) is split, one copy per distinct UV as glTF stores it (float). A
/// vertex is split only where the floats differ: elsewhere the patches agree to round-off.
struct TexturedMesh {
  TessellatedMesh mesh;                    ///< positions, normals and quads only
  std::vector<Eigen::Vector2f> texcoords;  ///< glTF's: v down from the top
};

TexturedMesh textured_mesh(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                           const UvSurface& uvs) {
  const TessellatedMesh whole = tessellate(mesh, surface, {resolution, true, false});
  const std::vector<Eigen::Vector2d> grid = grid_uvs(uvs, surface.corners(), resolution);
  const int n = resolution;
  TexturedMesh out;
  out.mesh.quads.resize(whole.quads.size());
  // Copies of welded vertex v: head[v], then along `chain`; in order of first use by the quads,
  // so the file does not depend on threads.
  std::vector<int> head(whole.positions.size(), -1), chain;
  for (size_t q = 0; q < whole.quads.size(); ++q) {
    const auto k = static_cast<std::int64_t>(q / (static_cast<size_t>(n) * n));
    const int cell = static_cast<int>(q % (static_cast<size_t>(n) * n));
    const int i = cell / n, j = cell % n;
    const std::array<std::array<int, 2>, 4> at{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
    for (int m = 0; m < 4; ++m) {
      const Eigen::Vector2d& uv = grid[k * grid_size(n) + at[m][0] * (n + 1) + at[m][1]];
      const Eigen::Vector2f st(static_cast<float>(uv.x()), static_cast<float>(1.0 - uv.y()));
      const int v = whole.quads[q][m];
      int* link = &head[v];
      while (*link >= 0 && out.texcoords[*link] != st) link = &chain[*link];
      if (*link < 0) {
        *link = static_cast<int>(out.mesh.positions.size());
        out.mesh.positions.push_back(whole.positions[v]);
        out.mesh.normals.push_back(whole.normals[v]);
        out.texcoords.push_back(st);
        chain.push_back(-1);
      }
      out.mesh.quads[q][m] = *link;
    }
  }
  return out;
}

}  // namespace

void detail::write_stream(const std::string& path, const detail::MeshStream& stream,
                          const std::vector<Vec3>& positions, const SurfaceFileOptions& options,
                          std::string_view comment) {
  using namespace detail;
  const std::string ext = file_extension(path);
  write_mesh_file(path, [&](OutputFile& out) {
    if (ext == ".obj")
      write_obj(out, stream, comment, options.progress);
    else if (ext == ".ply")
      write_ply(out, stream,
                options.ascii_ply ? PlyEncoding::ascii : PlyEncoding::binary_little_endian,
                options.single_precision ? PlyPrecision::single : PlyPrecision::double_precision,
                comment, options.progress);
    else if (ext == ".off")
      write_off(out, stream, comment, options.progress);
    else
      write_stl(out, stream, positions, comment, options.progress);
  });
}

bool surface_file_takes_uvs(const std::string& path) {
  return file_extension(path) == ".obj" || is_gltf(path);
}

void write_surface_mesh(const std::string& path, const TessellatedMesh& mesh,
                        const SurfaceFileOptions& options) {
  if (is_gltf(path)) {
    check_writable(path, mesh);
    write_gltf(path, mesh, file_extension(path) == ".glb");
    return;
  }
  check_extension(path);
  check_writable(path, mesh);
  const bool normals = file_extension(path) != ".off" && file_extension(path) != ".stl";
  detail::write_stream(
      path, detail::stream_arrays(mesh.positions, normals ? &mesh.normals : nullptr, mesh.quads),
      mesh.positions, options, kComment);
}

SurfaceFileCounts write_smooth_surface(const std::string& path, const HalfedgeMesh& mesh,
                                       const Surface& surface, int resolution,
                                       const SurfaceFileOptions& options) {
  if (is_gltf(path) && options.uvs) {
    const TexturedMesh whole = textured_mesh(mesh, surface, resolution, *options.uvs);
    check_writable(path, whole.mesh);
    write_gltf(path, whole.mesh, file_extension(path) == ".glb", &whole.texcoords);
    return {static_cast<std::int64_t>(whole.mesh.positions.size()),
            static_cast<std::int64_t>(whole.mesh.quads.size()),
            static_cast<std::int64_t>(whole.texcoords.size())};
  }
  if (is_gltf(path)) {  // glTF holds its buffer whole: tessellate, then write
    const TessellatedMesh whole = tessellate(mesh, surface, {resolution, true});
    write_surface_mesh(path, whole, options);
    return {whole.num_vertices(), static_cast<std::int64_t>(whole.quads.size())};
  }
  check_extension(path);
  const std::string ext = file_extension(path);
  const TessellationLayout layout(mesh, surface.corners(), resolution, true);
  detail::MeshStream stream;
  stream.num_vertices = layout.num_vertices();
  stream.num_faces = layout.num_quads();
  stream.has_normals = ext == ".obj" || ext == ".ply";
  stream.max_face_degree = 4;
  stream.triangles = 2 * layout.num_quads();
  // Evaluates output vertices [begin, end), refusing what no file should hold.
  const auto evaluate = [&](std::int64_t begin, std::int64_t end, Vec3* positions, Vec3* normals) {
    layout.evaluate(surface, begin, end, positions, normals);
    if (const std::int64_t bad = detail::first_non_finite(positions, normals, end - begin);
        bad >= 0)
      throw OutputError(
          fmt::format("sample {} has a non-finite position or normal", begin + bad + 1));
  };
  stream.vertices = [&](std::int64_t begin, std::int64_t end, detail::VertexBlock& block) {
    block.positions.resize(static_cast<size_t>(end - begin));
    block.normals.resize(block.positions.size());
    evaluate(begin, end, block.positions.data(), block.normals.data());
    if (!stream.has_normals) block.normals.clear();
  };
  // OBJ's `vt` are numbered apart from `v`: one per grid sample of every patch (corner after
  // corner, row-major like the unwelded samples), so each side of a seam has its own, while the
  // positions stay welded.
  const bool texcoords = options.uvs && ext == ".obj";
  const int n = resolution;
  const std::int64_t per_patch = grid_size(n);
  if (texcoords) {
    stream.num_texcoords = per_patch * static_cast<std::int64_t>(surface.corners().size());
    if (stream.num_texcoords > std::numeric_limits<int>::max())
      throw OutputError(fmt::format(
          "cannot write {}: {} texture coordinates are more than 2^31 - 1; use a lower resolution",
          path, stream.num_texcoords));
    stream.texcoords = [&](std::int64_t begin, std::int64_t end,
                           std::vector<Eigen::Vector2d>& block) {
      block.resize(static_cast<size_t>(end - begin));
      std::vector<Eigen::Vector2d> grid(static_cast<size_t>(per_patch));
      for (std::int64_t k = begin / per_patch; k * per_patch < end; ++k) {
        options.uvs->evaluate_grid(surface.corners()[static_cast<size_t>(k)], n, grid.data());
        for (std::int64_t s = std::max(begin, k * per_patch);
             s < std::min(end, (k + 1) * per_patch); ++s) {
          const Eigen::Vector2d& uv = grid[static_cast<size_t>(s - k * per_patch)];
          if (!uv.allFinite())
            throw OutputError(fmt::format("texture coordinate {} is not finite", s + 1));
          block[static_cast<size_t>(s - begin)] = uv;
        }
      }
    };
  }
  stream.faces = [&](std::int64_t begin, std::int64_t end, detail::FaceBlock& block) {
    block.sizes.assign(static_cast<size_t>(end - begin), 4);
    block.indices.resize(4 * block.sizes.size());
    layout.quads(begin, end, block.indices.data());
    if (!texcoords) return;
    block.texcoords.resize(block.indices.size());
    const std::int64_t cells = static_cast<std::int64_t>(n) * n;
    for (std::int64_t q = begin; q < end; ++q) {
      const std::int64_t k = q / cells;
      const auto i = static_cast<int>(q % cells / n), j = static_cast<int>(q % cells % n);
      const auto at = [&](int a, int b) {
        return static_cast<int>(k * per_patch + static_cast<std::int64_t>(a) * (n + 1) + b);
      };
      int* out = block.texcoords.data() + 4 * static_cast<size_t>(q - begin);
      out[0] = at(i, j);  // the order of TessellationLayout::quad
      out[1] = at(i + 1, j);
      out[2] = at(i + 1, j + 1);
      out[3] = at(i, j + 1);
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
  detail::write_stream(path, stream, positions, options, kComment);
  return {layout.num_vertices(), layout.num_quads(), stream.num_texcoords};
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

void write_surface_samples_ply(const std::string& path, const TessellatedMesh& mesh,
                               const UvSurface* uvs) {
  check_writable(path, mesh);
  const size_t nv = mesh.positions.size();
  if (mesh.uv.size() != nv || mesh.patch.size() != nv)
    throw UsageError(
        fmt::format("cannot write {}: the samples lack (u, v) or patch numbers", path));
  if (file_extension(path) != ".ply")
    throw UsageError(fmt::format("cannot write {}: samples are written as .ply only", path));
  std::vector<Eigen::Vector2d> st;
  if (uvs) {
    st.resize(nv);
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, nv, 4096), [&](const tbb::blocked_range<size_t>& r) {
          for (size_t i = r.begin(); i < r.end(); ++i)
            st[i] = uvs->evaluate(Corner(mesh.patch[i]), mesh.uv[i].x(), mesh.uv[i].y());
        });
    for (size_t i = 0; i < nv; ++i)
      if (!st[i].allFinite())
        throw OutputError(fmt::format(
            "cannot write {}: sample {} has non-finite texture coordinates", path, i + 1));
  }
  // s t come after `patch`, so readers that know the records without them read on unchanged.
  const size_t record_size = uvs ? 84 : 68;
  detail::write_mesh_file(path, [&](detail::OutputFile& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment " << kComment
        << "\ncomment patch = corner (half-edge index) of the input mesh; u v = position in "
           "that patch\nelement vertex "
        << nv << '\n';
    for (const char* name : {"x", "y", "z", "nx", "ny", "nz", "u", "v"})
      out << "property double " << name << '\n';
    out << "property int patch\n";
    if (uvs) out << "property double s\nproperty double t\n";
    out << "element face " << mesh.quads.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    detail::write_blocks(out, static_cast<std::int64_t>(nv), 16384,
                         [&](std::int64_t begin, std::int64_t end, detail::OutputBuffer& bytes) {
                           detail::LittleEndianWriter record(
                               bytes, static_cast<size_t>(end - begin) * record_size);
                           for (std::int64_t i = begin; i < end; ++i) {
                             record.put(mesh.positions[i]);
                             record.put(mesh.normals[i]);
                             record.put(mesh.uv[i].x());
                             record.put(mesh.uv[i].y());
                             record.put(static_cast<std::int32_t>(mesh.patch[i]));
                             if (!st.empty()) {
                               record.put(st[i].x());
                               record.put(st[i].y());
                             }
                           }
                         });
    detail::write_blocks(out, static_cast<std::int64_t>(mesh.quads.size()), 32768,
                         [&](std::int64_t begin, std::int64_t end, detail::OutputBuffer& bytes) {
                           detail::LittleEndianWriter record(bytes,
                                                             static_cast<size_t>(end - begin) * 17);
                           for (std::int64_t q = begin; q < end; ++q) {
                             record.put(std::uint8_t{4});
                             for (int v : mesh.quads[q]) record.put(static_cast<std::int32_t>(v));
                           }
                         });
  });
}

}  // namespace stitch
