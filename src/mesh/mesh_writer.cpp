#include "mesh/mesh_writer.hpp"

#include <fmt/format.h>
#include <tbb/concurrent_queue.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>

#include "mesh/number_text.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/polygon.hpp"

namespace stitch::detail {

namespace {

// Large enough that formatting a block dwarfs the hand-over between threads, small enough that a
// few blocks per thread in flight stay within a few megabytes.
constexpr std::int64_t kVerticesPerBlock = 16384;
constexpr std::int64_t kFacesPerBlock = 32768;

/// Bytes of one text line of `count` numbers after a prefix of at most `prefix` bytes.
constexpr size_t line_room(size_t prefix, size_t count) {
  return prefix + count * (kMaxDoubleChars + 1) + 1;
}

/// Writes `text` at `at`; returns the end.
char* put(char* at, std::string_view text) {
  std::memcpy(at, text.data(), text.size());
  return at + text.size();
}

/// The shortest text of x that reads back as x (a float's when `single`: rounded to the nearest
/// float, std::to_chars's text).
char* put(char* at, double x, bool single) {
  if (single) return std::to_chars(at, at + kMaxDoubleChars, static_cast<float>(x)).ptr;
  return write_shortest(at, x);
}

/// `prefix` and the three coordinates, space-separated.
char* put_xyz(char* at, std::string_view prefix, const Vec3& p, bool single = false) {
  at = put(at, prefix);
  at = put(at, p.x(), single);
  *at++ = ' ';
  at = put(at, p.y(), single);
  *at++ = ' ';
  return put(at, p.z(), single);
}

/// A 0-based index as `base`-based text.
char* put_index(char* at, int index, int base) {
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

void write_vertices(OutputFile& out, const MeshStream& mesh, const VertexFormat& format,
                    Progress& progress) {
  write_records(out, mesh.num_vertices, kVerticesPerBlock, mesh.vertices, format, progress);
}

void write_faces(OutputFile& out, const MeshStream& mesh, const FaceFormat& format,
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

/// OBJ faces with texture coordinates: `f a/t/a ...` (or `a/t` without normals), 1-based. Apart
/// from text_faces so that files without them take no branch per corner.
FaceFormat obj_textured_faces(bool normals) {
  return [=](const FaceBlock& block, OutputBuffer& text) {
    char* at = text.claim(block.indices.size() * (3 * (kMaxDecimalChars + 1) + 1) +
                          block.sizes.size() * 3);
    const int* uv = block.texcoords.data();
    for_each_face(block, [&](int size, const int* loop) {
      *at++ = 'f';
      for (int k = 0; k < size; ++k) {
        *at++ = ' ';
        char* const index = at;
        at = put_index(at, loop[k], 1);
        const size_t length = static_cast<size_t>(at - index);
        *at++ = '/';
        at = put_index(at, *uv++, 1);
        if (normals) {
          *at++ = '/';
          std::memmove(at, index, length);  // the same number again
          at += length;
        }
      }
      *at++ = '\n';
    });
    text.commit(at);
  };
}

/// Faces as text lines `prefix[count] i0 i1 ...` with indices shifted by `base` (1 for OBJ),
/// each index twice (`a//a`) with OBJ normals.
FaceFormat text_faces(std::string_view prefix, bool with_count, int base, bool obj_normals) {
  return [=](const FaceBlock& block, OutputBuffer& text) {
    char* at = text.claim(block.indices.size() * (2 * kMaxDecimalChars + 3) +
                          block.sizes.size() * (prefix.size() + kMaxDecimalChars + 1));
    for_each_face(block, [&](int size, const int* loop) {
      at = put(at, prefix);
      if (with_count) at = write_decimal(at, static_cast<std::uint64_t>(size));
      for (int k = 0; k < size; ++k) {
        *at++ = ' ';
        char* const index = at;
        at = put_index(at, loop[k], base);
        if (obj_normals) {
          const size_t length = static_cast<size_t>(at - index);
          *at++ = '/';
          *at++ = '/';
          std::memmove(at, index, length);  // the same number again, not formatted twice
          at += length;
        }
      }
      *at++ = '\n';
    });
    text.commit(at);
  };
}

/// Binary PLY vertex records: x y z (nx ny nz), little-endian doubles or floats.
void ply_binary_vertices(const VertexBlock& block, bool normals, bool single, OutputBuffer& bytes) {
  const size_t count = block.positions.size();
  const size_t scalars = normals ? 6 : 3;
  if constexpr (std::endian::native == std::endian::little) {
    // A record is the values' own bytes: copied whole, not value by value (the PLY writer's
    // share of the CPU was as large as the evaluation's).
    if (!single) {
      char* at = bytes.extend(count * scalars * sizeof(double));
      static_assert(sizeof(Vec3) == 3 * sizeof(double));
      if (!normals) {
        std::memcpy(at, block.positions.data(), count * sizeof(Vec3));
        return;
      }
      for (size_t i = 0; i < count; ++i) {
        std::memcpy(at, block.positions[i].data(), sizeof(Vec3));
        std::memcpy(at + sizeof(Vec3), block.normals[i].data(), sizeof(Vec3));
        at += 2 * sizeof(Vec3);
      }
      return;
    }
    char* at = bytes.extend(count * scalars * sizeof(float));
    for (size_t i = 0; i < count; ++i) {
      std::array<float, 6> record{};
      for (int axis = 0; axis < 3; ++axis) {
        record[axis] = static_cast<float>(block.positions[i][axis]);
        if (normals) record[3 + axis] = static_cast<float>(block.normals[i][axis]);
      }
      std::memcpy(at, record.data(), scalars * sizeof(float));
      at += scalars * sizeof(float);
    }
    return;
  }
  LittleEndianWriter record(bytes, count * scalars * (single ? sizeof(float) : sizeof(double)));
  const auto put = [&](const Vec3& p) {
    if (single)
      record.put(p.cast<float>().eval());
    else
      record.put(p);
  };
  for (size_t i = 0; i < count; ++i) {
    put(block.positions[i]);
    if (normals) put(block.normals[i]);
  }
}

/// Binary PLY faces: the vertex count (uchar when `byte_counts`, else int), then int indices.
void ply_binary_faces(const FaceBlock& block, bool byte_counts, OutputBuffer& bytes) {
  const size_t size = block.sizes.size() * (byte_counts ? 1 : 4) + block.indices.size() * 4;
  if constexpr (std::endian::native == std::endian::little) {
    static_assert(sizeof(int) == sizeof(std::int32_t));
    if (byte_counts) {
      char* at = bytes.extend(size);
      for_each_face(block, [&](int count, const int* loop) {
        *at++ = static_cast<char>(static_cast<std::uint8_t>(count));
        // A fixed size for the usual quads and triangles: a move, not a call to memcpy.
        if (count == 4)
          std::memcpy(at, loop, 4 * sizeof(int));
        else if (count == 3)
          std::memcpy(at, loop, 3 * sizeof(int));
        else
          std::memcpy(at, loop, static_cast<size_t>(count) * sizeof(int));
        at += static_cast<size_t>(count) * sizeof(int);
      });
      return;
    }
  }
  LittleEndianWriter record(bytes, size);
  for_each_face(block, [&](int count, const int* loop) {
    if (byte_counts)
      record.put(static_cast<std::uint8_t>(count));
    else
      record.put(static_cast<std::int32_t>(count));
    for (int k = 0; k < count; ++k) record.put(static_cast<std::int32_t>(loop[k]));
  });
}

}  // namespace

void write_blocks(OutputFile& out, std::int64_t count, std::int64_t block,
                  const std::function<void(std::int64_t, std::int64_t, OutputBuffer&)>& format,
                  const std::function<void(std::int64_t)>& written) {
  struct Chunk {
    std::int64_t begin = 0, end = 0;
    OutputBuffer* text = nullptr;
  };
  // One buffer per block in flight, handed from block to block.
  const auto tokens = static_cast<size_t>(4 * tbb::this_task_arena::max_concurrency());
  std::vector<OutputBuffer> buffers(tokens);
  tbb::concurrent_queue<OutputBuffer*> free;
  for (OutputBuffer& buffer : buffers) free.push(&buffer);
  std::int64_t next = 0;
  tbb::parallel_pipeline(
      tokens,
      tbb::make_filter<void, Chunk>(tbb::filter_mode::serial_in_order,
                                    [&](tbb::flow_control& control) {
                                      Chunk chunk{next, std::min(count, next + block), nullptr};
                                      if (next >= count || !free.try_pop(chunk.text)) {
                                        control.stop();
                                        return Chunk{};
                                      }
                                      next = chunk.end;
                                      return chunk;
                                    }) &
          tbb::make_filter<Chunk, Chunk>(tbb::filter_mode::parallel,
                                         [&](Chunk chunk) {
                                           format(chunk.begin, chunk.end, *chunk.text);
                                           return chunk;
                                         }) &
          tbb::make_filter<Chunk, void>(tbb::filter_mode::serial_in_order, [&](const Chunk& chunk) {
            // Throws at once (e.g. on a full disk): the rest would be computed for nothing.
            out.write(chunk.text->data(), chunk.text->size());
            chunk.text->clear();
            free.push(chunk.text);
            if (written) written(chunk.end - chunk.begin);
          }));
  if (next < count) throw Error("internal error: a block buffer went missing");
}

void OutputBuffer::reserve(size_t capacity) {
  if (capacity <= capacity_) return;
  auto bigger = std::make_unique_for_overwrite<char[]>(capacity);
  if (size_ > 0) std::memcpy(bigger.get(), data_.get(), size_);
  data_ = std::move(bigger);
  capacity_ = capacity;
}

void write_obj(OutputFile& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_texcoords + mesh.num_faces);
  out << "# " << comment << '\n';
  write_vertices(
      out, mesh,
      [&](const VertexBlock& block, OutputBuffer& text) {
        char* at = text.claim((block.positions.size() + block.normals.size()) * line_room(3, 3));
        for (const Vec3& p : block.positions) {
          at = put_xyz(at, "v ", p);
          *at++ = '\n';
        }
        // OBJ numbers `vn` lines separately from `v` lines, so they may follow block by block.
        for (const Vec3& n : block.normals) {
          at = put_xyz(at, "vn ", n);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  if (mesh.num_texcoords == 0) {
    write_faces(out, mesh, text_faces("f", false, 1, mesh.has_normals), progress);
    return;
  }
  write_records<std::vector<Eigen::Vector2d>>(
      out, mesh.num_texcoords, kVerticesPerBlock, mesh.texcoords,
      [](const std::vector<Eigen::Vector2d>& block, OutputBuffer& text) {
        char* at = text.claim(block.size() * line_room(3, 2));
        for (const Eigen::Vector2d& t : block) {
          at = put(at, "vt ");
          at = put(at, t.x(), false);
          *at++ = ' ';
          at = put(at, t.y(), false);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  write_faces(out, mesh, obj_textured_faces(mesh.has_normals), progress);
}

void write_off(OutputFile& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_faces);
  out << "OFF\n# " << comment << '\n' << mesh.num_vertices << ' ' << mesh.num_faces << " 0\n";
  write_vertices(
      out, mesh,
      [](const VertexBlock& block, OutputBuffer& text) {
        char* at = text.claim(block.positions.size() * line_room(0, 3));
        for (const Vec3& p : block.positions) {
          at = put_xyz(at, "", p);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  write_faces(out, mesh, text_faces("", true, 0, false), progress);
}

void write_ply(OutputFile& out, const MeshStream& mesh, PlyEncoding encoding,
               PlyPrecision precision, std::string_view comment, const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_faces);
  const bool binary = encoding == PlyEncoding::binary_little_endian;
  const bool single = precision == PlyPrecision::single;
  const bool byte_counts = mesh.max_face_degree <= 255;
  const char* type = single ? "float" : "double";
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\ncomment "
      << comment << "\nelement vertex " << mesh.num_vertices;
  for (const char* name : {"x", "y", "z"}) out << "\nproperty " << type << ' ' << name;
  if (mesh.has_normals)
    for (const char* name : {"nx", "ny", "nz"}) out << "\nproperty " << type << ' ' << name;
  out << '\n';
  out << "element face " << mesh.num_faces << "\nproperty list " << (byte_counts ? "uchar" : "int")
      << " int vertex_indices\nend_header\n";
  if (binary) {
    write_vertices(
        out, mesh,
        [&](const VertexBlock& block, OutputBuffer& bytes) {
          ply_binary_vertices(block, mesh.has_normals, single, bytes);
        },
        progress);
    write_faces(
        out, mesh,
        [&](const FaceBlock& block, OutputBuffer& bytes) {
          ply_binary_faces(block, byte_counts, bytes);
        },
        progress);
    return;
  }
  write_vertices(
      out, mesh,
      [&](const VertexBlock& block, OutputBuffer& text) {
        char* at = text.claim(block.positions.size() * line_room(1, 6));
        for (size_t i = 0; i < block.positions.size(); ++i) {
          at = put_xyz(at, "", block.positions[i], single);
          if (mesh.has_normals) at = put_xyz(at, " ", block.normals[i], single);
          *at++ = '\n';
        }
        text.commit(at);
      },
      progress);
  write_faces(out, mesh, text_faces("", true, 0, false), progress);
}

void write_stl(OutputFile& out, const MeshStream& mesh, const std::vector<Vec3>& positions,
               std::string_view comment, const WriteProgress& report) {
  if (mesh.triangles > std::numeric_limits<std::uint32_t>::max())
    throw OutputError(
        fmt::format("{} triangles are more than binary STL can hold (2^32 - 1)", mesh.triangles));
  Progress progress(report, mesh.num_faces);
  std::array<char, 80> header{};
  std::memcpy(header.data(), comment.data(), std::min(comment.size(), header.size()));
  out.write(header.data(), header.size());
  OutputBuffer count;
  LittleEndianWriter(count, 4).put(static_cast<std::uint32_t>(mesh.triangles));
  out.write(count.data(), count.size());
  write_faces(
      out, mesh,
      [&](const FaceBlock& block, OutputBuffer& bytes) {
        size_t triangles = 0;
        for (int size : block.sizes) triangles += static_cast<size_t>(std::max(0, size - 2));
        LittleEndianWriter record(bytes, triangles * 50);
        auto put = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
          const Vec3 n = (b - a).cross(c - a).stableNormalized();
          for (const Vec3* p : {&n, &a, &b, &c})
            for (int axis = 0; axis < 3; ++axis) record.put(static_cast<float>((*p)[axis]));
          record.put(std::uint16_t{0});
        };
        for_each_face(block, [&](int size, const int* loop) {
          if (size == 4) {  // as the tessellation's quads are split everywhere
            for (const auto& t :
                 quad_triangles(std::array{loop[0], loop[1], loop[2], loop[3]}, positions))
              put(positions[t[0]], positions[t[1]], positions[t[2]]);
            return;
          }
          for (int k = 1; k + 1 < size; ++k)
            put(positions[loop[0]], positions[loop[k]], positions[loop[k + 1]]);
        });
      },
      progress);
}

void write_mesh_file(const std::string& path, const std::function<void(OutputFile&)>& write) {
  write_file_atomically_at(path, [&](const std::string& temporary) {
    OutputFile out(temporary);
    try {
      write(out);
      out.close();
    } catch (const Error& e) {
      // The writers do not know the file's name; every message about a file names it.
      if (std::string_view(e.what()).find(path) != std::string_view::npos) throw;
      throw_with_message(e, fmt::format("cannot write {}: {}", path, e.what()));
    }
  });
}

}  // namespace stitch::detail
