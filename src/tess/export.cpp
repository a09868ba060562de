#include "stitch/tess/export.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <optional>

#include "mesh/mesh_writer.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/tess/tessellate.hpp"
#include "support/finite.hpp"
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
/// it different UVs (a seam) is split, one copy per distinct UV as glTF stores it (float, v down
/// from the top). A vertex is split only where the floats differ: elsewhere the patches agree to
/// round-off.
struct TexturedMesh {
  TessellatedMesh mesh;                    ///< positions, normals and quads only
  std::vector<Eigen::Vector2d> texcoords;  ///< one per vertex, the first of its float's UVs
};

TexturedMesh textured_mesh(const HalfedgeMesh& mesh, const Surface& surface, int resolution,
                           const UvSurface& uvs) {
  const TessellatedMesh whole = tessellate(mesh, surface, {.resolution = resolution});
  const std::vector<Eigen::Vector2d> grid = grid_uvs(uvs, surface.corners(), resolution);
  const int n = resolution;
  const auto stored = [](const Eigen::Vector2d& uv) {  // as the glTF writer stores it
    return Eigen::Vector2f(static_cast<float>(uv.x()), static_cast<float>(1.0 - uv.y()));
  };
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
      const Eigen::Vector2f st = stored(uv);
      const int v = whole.quads[q][m];
      int* link = &head[v];
      while (*link >= 0 && stored(out.texcoords[*link]) != st) link = &chain[*link];
      int copy = *link;
      if (copy < 0) {
        copy = static_cast<int>(out.mesh.positions.size());
        *link = copy;  // before chain grows: `link` may point into it
        out.mesh.positions.push_back(whole.positions[v]);
        out.mesh.normals.push_back(whole.normals[v]);
        out.texcoords.push_back(uv);
        chain.push_back(-1);
      }
      out.mesh.quads[q][m] = copy;
    }
  }
  return out;
}

}  // namespace

void detail::write_stream(const std::string& path, MeshFileFormat format, const MeshStream& stream,
                          const std::vector<Vec3>& positions, const SurfaceFileOptions& options,
                          std::string_view comment) {
  MeshFileOptions file;
  file.ply_encoding = options.ascii_ply ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
  file.ply_precision =
      options.single_precision ? PlyPrecision::single : PlyPrecision::double_precision;
  file.comment = comment;
  file.progress = options.progress;
  write_mesh_stream(path, format, stream, positions, file);
}

void write_surface_mesh(const std::string& path, MeshFileFormat format, const TessellatedMesh& mesh,
                        const SurfaceFileOptions& options) {
  check_writable(path, mesh);
  const bool normals = has_vertex_normals(format);
  detail::write_stream(
      path, format,
      detail::stream_arrays(mesh.positions, normals ? &mesh.normals : nullptr, mesh.quads),
      mesh.positions, options, kComment);
}

SurfaceFileCounts write_smooth_surface(const std::string& path, MeshFileFormat format,
                                       const HalfedgeMesh& mesh, const Surface& surface,
                                       int resolution, const SurfaceFileOptions& options) {
  if (is_gltf(format) && options.uvs) {
    const TexturedMesh whole = textured_mesh(mesh, surface, resolution, *options.uvs);
    check_writable(path, whole.mesh);
    detail::write_stream(path, format,
                         detail::stream_arrays(whole.mesh.positions, &whole.mesh.normals,
                                               whole.mesh.quads, &whole.texcoords),
                         whole.mesh.positions, options, kComment);
    return {static_cast<std::int64_t>(whole.mesh.positions.size()),
            static_cast<std::int64_t>(whole.mesh.quads.size()),
            static_cast<std::int64_t>(whole.texcoords.size())};
  }
  const TessellationLayout layout(mesh, surface.corners(), resolution, true);
  detail::MeshStream stream;
  stream.num_vertices = layout.num_vertices();
  stream.num_faces = layout.num_quads();
  stream.has_normals = has_vertex_normals(format);
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
  const bool texcoords = options.uvs && format == MeshFileFormat::obj;
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
  // STL and glTF split the quads by their vertices' positions: each block of quads evaluates
  // the grids it needs rather than every position being held.
  stream.triangulated = [&](std::int64_t begin, std::int64_t end, detail::TriangleBlock& block) {
    block.indices.resize(static_cast<size_t>(6 * (end - begin)));
    block.corners.resize(block.indices.size());
    layout.triangles(surface, begin, end, block.indices.data(), block.corners.data());
    if (!detail::all_finite(block.corners.data(), static_cast<std::int64_t>(block.corners.size())))
      for (size_t c = 0; c < block.corners.size(); ++c)
        if (!block.corners[c].allFinite())
          throw OutputError(
              fmt::format("sample {} has a non-finite position or normal", block.indices[c] + 1));
  };
  detail::write_stream(path, format, stream, {}, options, kComment);
  return {layout.num_vertices(), layout.num_quads(), stream.num_texcoords};
}

void write_surface_samples_ply(const std::string& path, const TessellatedMesh& mesh,
                               const UvSurface* uvs) {
  check_writable(path, mesh);
  const size_t nv = mesh.positions.size();
  if (mesh.uv.size() != nv || mesh.patch.size() != nv)
    throw UsageError(
        fmt::format("cannot write {}: the samples lack (u, v) or patch numbers", path));
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
