#include "mesh_writer.hpp"

#include <fmt/format.h>
#include <tbb/concurrent_queue.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/io.hpp"

namespace stitch::io_detail {

namespace {

// Large enough that formatting a block dwarfs the hand-over between threads, small enough that a
// few blocks per thread in flight stay within a few megabytes.
constexpr std::int64_t kVerticesPerBlock = 16384;
constexpr std::int64_t kFacesPerBlock = 32768;

void put(OutputBuffer& s, double x) {
  std::array<char, 32> digits;
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), x);
  s.append(digits.data(), result.ptr);
}

void put(OutputBuffer& s, std::int64_t x) {
  std::array<char, 24> digits;
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), x);
  s.append(digits.data(), result.ptr);
}

void put(OutputBuffer& s, float x) {
  std::array<char, 24> digits;
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), x);
  s.append(digits.data(), result.ptr);
}

/// `prefix` and the three coordinates, as floats when `single` (rounded to the nearest float).
void put_xyz(OutputBuffer& s, const char* prefix, const Vec3& p, bool single = false) {
  s += std::string_view(prefix);
  for (int k = 0; k < 3; ++k) {
    if (k > 0) s += ' ';
    if (single)
      put(s, static_cast<float>(p[k]));
    else
      put(s, p[k]);
  }
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
void write_records(std::ostream& out, std::int64_t count, std::int64_t per_block,
                   const std::function<void(std::int64_t, std::int64_t, Block&)>& fill,
                   const std::function<void(const Block&, OutputBuffer&)>& format,
                   Progress& progress) {
  write_blocks(
      out, count, per_block,
      [&](std::int64_t begin, std::int64_t end, OutputBuffer& text) {
        Block block;
        fill(begin, end, block);
        format(block, text);
      },
      std::ref(progress));
}

void write_vertices(std::ostream& out, const MeshStream& mesh, const VertexFormat& format,
                    Progress& progress) {
  write_records(out, mesh.num_vertices, kVerticesPerBlock, mesh.vertices, format, progress);
}

void write_faces(std::ostream& out, const MeshStream& mesh, const FaceFormat& format,
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
    text.reserve(block.indices.size() * 24 + block.sizes.size() * 4);
    const int* uv = block.texcoords.data();
    for_each_face(block, [&](int size, const int* loop) {
      text += 'f';
      for (int k = 0; k < size; ++k) {
        text += ' ';
        const std::int64_t index = std::int64_t{loop[k]} + 1;
        put(text, index);
        text += '/';
        put(text, std::int64_t{*uv++} + 1);
        if (normals) {
          text += '/';
          put(text, index);
        }
      }
      text += '\n';
    });
  };
}

/// Faces as text lines `prefix[count] i0 i1 ...` with indices shifted by `base` (1 for OBJ).
FaceFormat text_faces(const char* prefix, bool with_count, int base, bool obj_normals) {
  return [=](const FaceBlock& block, OutputBuffer& text) {
    text.reserve(block.indices.size() * 10 + block.sizes.size() * 4);
    for_each_face(block, [&](int size, const int* loop) {
      text += std::string_view(prefix);
      if (with_count) put(text, std::int64_t{size});
      for (int k = 0; k < size; ++k) {
        text += ' ';
        const std::int64_t index = std::int64_t{loop[k]} + base;
        put(text, index);
        if (obj_normals) {
          text += std::string_view("//");
          put(text, index);
        }
      }
      text += '\n';
    });
  };
}

}  // namespace

void write_blocks(std::ostream& out, std::int64_t count, std::int64_t block,
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
            out.write(chunk.text->data(), static_cast<std::streamsize>(chunk.text->size()));
            // Stop at once: the rest would be computed for nothing (e.g. on a full disk).
            if (!out) throw MeshError("write error (disk full?)");
            chunk.text->clear();
            free.push(chunk.text);
            if (written) written(chunk.end - chunk.begin);
          }));
  if (next < count) throw MeshError("internal error: a block buffer went missing");
}

void OutputBuffer::reserve(size_t capacity) {
  if (capacity <= capacity_) return;
  auto bigger = std::make_unique_for_overwrite<char[]>(capacity);
  if (size_ > 0) std::memcpy(bigger.get(), data_.get(), size_);
  data_ = std::move(bigger);
  capacity_ = capacity;
}

void write_obj(std::ostream& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_texcoords + mesh.num_faces);
  out << "# " << comment << '\n';
  write_vertices(
      out, mesh,
      [&](const VertexBlock& block, OutputBuffer& text) {
        text.reserve(block.positions.size() * (mesh.has_normals ? 150 : 75));
        for (const Vec3& p : block.positions) {
          put_xyz(text, "v ", p);
          text += '\n';
        }
        // OBJ numbers `vn` lines separately from `v` lines, so they may follow block by block.
        for (const Vec3& n : block.normals) {
          put_xyz(text, "vn ", n);
          text += '\n';
        }
      },
      progress);
  if (mesh.num_texcoords == 0) {
    write_faces(out, mesh, text_faces("f", false, 1, mesh.has_normals), progress);
    return;
  }
  write_records<std::vector<Eigen::Vector2d>>(
      out, mesh.num_texcoords, kVerticesPerBlock, mesh.texcoords,
      [](const std::vector<Eigen::Vector2d>& block, OutputBuffer& text) {
        text.reserve(block.size() * 52);
        for (const Eigen::Vector2d& t : block) {
          text += std::string_view("vt ");
          put(text, t.x());
          text += ' ';
          put(text, t.y());
          text += '\n';
        }
      },
      progress);
  write_faces(out, mesh, obj_textured_faces(mesh.has_normals), progress);
}

void write_off(std::ostream& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& report) {
  Progress progress(report, mesh.num_vertices + mesh.num_faces);
  out << "OFF\n# " << comment << '\n' << mesh.num_vertices << ' ' << mesh.num_faces << " 0\n";
  write_vertices(
      out, mesh,
      [](const VertexBlock& block, OutputBuffer& text) {
        text.reserve(block.positions.size() * 75);
        for (const Vec3& p : block.positions) {
          put_xyz(text, "", p);
          text += '\n';
        }
      },
      progress);
  write_faces(out, mesh, text_faces("", true, 0, false), progress);
}

void write_ply(std::ostream& out, const MeshStream& mesh, PlyEncoding encoding,
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
          const size_t scalar = single ? 4 : 8;
          LittleEndianWriter record(bytes,
                                    block.positions.size() * (mesh.has_normals ? 6 : 3) * scalar);
          const auto put = [&](const Vec3& p) {
            if (single)
              record.put(p.cast<float>().eval());
            else
              record.put(p);
          };
          for (size_t i = 0; i < block.positions.size(); ++i) {
            put(block.positions[i]);
            if (mesh.has_normals) put(block.normals[i]);
          }
        },
        progress);
    write_faces(
        out, mesh,
        [&](const FaceBlock& block, OutputBuffer& bytes) {
          LittleEndianWriter record(
              bytes, block.sizes.size() * (byte_counts ? 1 : 4) + block.indices.size() * 4);
          for_each_face(block, [&](int size, const int* loop) {
            if (byte_counts)
              record.put(static_cast<std::uint8_t>(size));
            else
              record.put(static_cast<std::int32_t>(size));
            for (int k = 0; k < size; ++k) record.put(static_cast<std::int32_t>(loop[k]));
          });
        },
        progress);
    return;
  }
  write_vertices(
      out, mesh,
      [&](const VertexBlock& block, OutputBuffer& text) {
        text.reserve(block.positions.size() * (mesh.has_normals ? 150 : 75));
        for (size_t i = 0; i < block.positions.size(); ++i) {
          put_xyz(text, "", block.positions[i], single);
          if (mesh.has_normals) put_xyz(text, " ", block.normals[i], single);
          text += '\n';
        }
      },
      progress);
  write_faces(out, mesh, text_faces("", true, 0, false), progress);
}

void write_stl(std::ostream& out, const MeshStream& mesh, const std::vector<Vec3>& positions,
               std::string_view comment, const WriteProgress& report) {
  if (mesh.triangles > std::numeric_limits<std::uint32_t>::max())
    throw MeshError(
        fmt::format("{} triangles are more than binary STL can hold (2^32 - 1)", mesh.triangles));
  Progress progress(report, mesh.num_faces);
  std::array<char, 80> header{};
  std::memcpy(header.data(), comment.data(), std::min(comment.size(), header.size()));
  out.write(header.data(), header.size());
  OutputBuffer count;
  LittleEndianWriter(count, 4).put(static_cast<std::uint32_t>(mesh.triangles));
  out.write(count.data(), static_cast<std::streamsize>(count.size()));
  write_faces(
      out, mesh,
      [&](const FaceBlock& block, OutputBuffer& bytes) {
        size_t triangles = 0;
        for (int size : block.sizes) triangles += static_cast<size_t>(std::max(0, size - 2));
        LittleEndianWriter record(bytes, triangles * 50);
        for_each_face(block, [&](int size, const int* loop) {
          const Vec3& a = positions[loop[0]];
          for (int k = 1; k + 1 < size; ++k) {
            const Vec3& b = positions[loop[k]];
            const Vec3& c = positions[loop[k + 1]];
            const Vec3 n = (b - a).cross(c - a).stableNormalized();
            for (const Vec3* p : {&n, &a, &b, &c})
              for (int axis = 0; axis < 3; ++axis) record.put(static_cast<float>((*p)[axis]));
            record.put(std::uint16_t{0});
          }
        });
      },
      progress);
}

void write_mesh_file(const std::string& path, bool binary,
                     const std::function<void(std::ostream&)>& write) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        try {
          write(out);
        } catch (const MeshError& e) {
          // The writers do not know the file's name; every message about a file names it.
          if (std::string_view(e.what()).find(path) != std::string_view::npos) throw;
          throw MeshError(fmt::format("cannot write {}: {}", path, e.what()));
        }
      },
      binary);
}

}  // namespace stitch::io_detail
