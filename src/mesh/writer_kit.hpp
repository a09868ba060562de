// What the per-format writers (io_obj.cpp, io_off.cpp, io_ply.cpp, io_stl.cpp, io_gltf.cpp)
// share: pulling a MeshStream block by block, numbers as text, and progress. Inline where it
// formats: these run once per number of files with hundreds of millions of them. Internal to the
// mesh stage's writers; everyone else writes through mesh_writer.hpp.
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string_view>
#include <vector>

#include "mesh/mesh_writer.hpp"
#include "mesh/number_text.hpp"
#include "stitch/mesh/polygon.hpp"

namespace stitch::detail {

// Large enough that formatting a block dwarfs the hand-over between threads, small enough that a
// few blocks per thread in flight stay within a few megabytes.
inline constexpr std::int64_t kVerticesPerBlock = 16384;
inline constexpr std::int64_t kFacesPerBlock = 32768;

/// Bytes of one text line of `count` numbers after a prefix of at most `prefix` bytes.
constexpr size_t line_room(size_t prefix, size_t count) {
  return prefix + count * (kMaxDoubleChars + 1) + 1;
}

/// Writes `text` at `at`; returns the end.
inline char* put(char* at, std::string_view text) {
  std::memcpy(at, text.data(), text.size());
  return at + text.size();
}

/// The shortest text of x that reads back as x (a float's when `single`: rounded to the nearest
/// float, std::to_chars's text).
inline char* put(char* at, double x, bool single) {
  if (single) return std::to_chars(at, at + kMaxDoubleChars, static_cast<float>(x)).ptr;
  return write_shortest(at, x);
}

/// `prefix` and the three coordinates, space-separated.
inline char* put_xyz(char* at, std::string_view prefix, const Vec3& p, bool single = false) {
  at = put(at, prefix);
  at = put(at, p.x(), single);
  *at++ = ' ';
  at = put(at, p.y(), single);
  *at++ = ' ';
  return put(at, p.z(), single);
}

/// A 0-based index as `base`-based text.
inline char* put_index(char* at, int index, int base) {
  return write_decimal(at, static_cast<std::uint64_t>(std::int64_t{index} + base));
}

/// Where the writing stands, for the progress callback: items (vertices, then faces) written.
class Progress {
 public:
  Progress(const WriteProgress& report, std::int64_t total) : report_(report), total_(total) {}
  void operator()(std::int64_t items) {
    done_ += items;
    if (report_ && total_ > 0) report_(static_cast<double>(done_) / static_cast<double>(total_));
  }

 private:
  const WriteProgress& report_;
  std::int64_t total_;
  std::int64_t done_ = 0;
};

/// The text or bytes of vertex blocks, one record per vertex.
using VertexFormat = std::function<void(const VertexBlock&, OutputBuffer&)>;
/// The text or bytes of face blocks; `sizes` and `indices` as in FaceBlock.
using FaceFormat = std::function<void(const FaceBlock&, OutputBuffer&)>;

/// Blocks of `count` records, filled by fill(begin, end, block) and formatted by `format`.
template <class Block>
void write_records(OutputFile& out, std::int64_t count, std::int64_t per_block,
                   const std::function<void(std::int64_t, std::int64_t, Block&)>& fill,
                   const std::function<void(const Block&, OutputBuffer&)>& format,
                   Progress& progress) {
  // One block per thread, refilled: allocating (and page-faulting) a few hundred kilobytes per
  // block cost more than filling them.
  tbb::enumerable_thread_specific<Block> blocks;
  write_blocks(
      out, count, per_block,
      [&](std::int64_t begin, std::int64_t end, OutputBuffer& text) {
        Block& block = blocks.local();
        fill(begin, end, block);
        format(block, text);
      },
      std::ref(progress));
}

inline void write_vertices(OutputFile& out, const MeshStream& mesh, const VertexFormat& format,
                           Progress& progress) {
  write_records(out, mesh.num_vertices, kVerticesPerBlock, mesh.vertices, format, progress);
}

inline void write_faces(OutputFile& out, const MeshStream& mesh, const FaceFormat& format,
                        Progress& progress) {
  write_records(out, mesh.num_faces, kFacesPerBlock, mesh.faces, format, progress);
}

/// Calls visit(size, indices of the face) for every face of a block.
template <class Visit>
void for_each_face(const FaceBlock& block, Visit&& visit) {
  const int* at = block.indices.data();
  for (int size : block.sizes) {
    visit(size, at);
    at += size;
  }
}

/// Calls visit(a, b, c) for the triangles of every face of a block, for the formats that hold
/// triangles only (STL, glTF): a quad split along its shorter diagonal (quad_triangles of
/// `positions`, every vertex of the mesh) as everything else splits the tessellation's quads,
/// another polygon fanned from its first vertex.
template <class Visit>
void for_each_triangle(const FaceBlock& block, const std::vector<Vec3>& positions, Visit&& visit) {
  for_each_face(block, [&](int size, const int* loop) {
    if (size == 4) {
      for (const auto& t :
           quad_triangles(std::array{loop[0], loop[1], loop[2], loop[3]}, positions))
        visit(t[0], t[1], t[2]);
      return;
    }
    for (int k = 1; k + 1 < size; ++k) visit(loop[0], loop[k], loop[k + 1]);
  });
}

/// The bytes of triangle blocks.
using TriangleFormat = std::function<void(const TriangleBlock&, OutputBuffer&)>;

/// The faces as triangles, block by block: the stream's own (MeshStream::triangulated), or split
/// by for_each_triangle over `positions`; formatted by `format`.
void write_triangles(OutputFile& out, const MeshStream& mesh, const std::vector<Vec3>& positions,
                     const TriangleFormat& format, Progress& progress);

/// Faces as text lines `prefix[count] i0 i1 ...` with indices shifted by `base` (1 for OBJ),
/// each index twice (`a//a`) with OBJ normals.
FaceFormat text_faces(std::string_view prefix, bool with_count, int base, bool obj_normals);

}  // namespace stitch::detail
