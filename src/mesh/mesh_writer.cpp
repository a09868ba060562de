#include "mesh/mesh_writer.hpp"

#include <fmt/format.h>
#include <tbb/concurrent_queue.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>

#include "mesh/writer_kit.hpp"
#include "stitch/mesh/io.hpp"

namespace stitch::detail {

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

void write_triangles(OutputFile& out, const MeshStream& mesh, const std::vector<Vec3>& positions,
                     const TriangleFormat& format, Progress& progress) {
  struct Faces {
    FaceBlock faces;
    TriangleBlock triangles;
  };
  write_records<Faces>(
      out, mesh.num_faces, kFacesPerBlock,
      [&](std::int64_t begin, std::int64_t end, Faces& block) {
        TriangleBlock& t = block.triangles;
        if (mesh.triangulated) {
          mesh.triangulated(begin, end, t);
          return;
        }
        mesh.faces(begin, end, block.faces);
        t.indices.clear();
        t.corners.clear();
        for_each_triangle(block.faces, positions, [&](int a, int b, int c) {
          for (const int v : {a, b, c}) {
            t.indices.push_back(v);
            t.corners.push_back(positions[static_cast<size_t>(v)]);
          }
        });
      },
      [&](const Faces& block, OutputBuffer& bytes) { format(block.triangles, bytes); }, progress);
}

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

void write_mesh_file(const std::string& path, const std::function<void(OutputFile&)>& write,
                     const std::string& name) {
  const std::string& named = name.empty() ? path : name;
  write_file_atomically_at(path, [&](const std::string& temporary) {
    OutputFile out(temporary);
    try {
      write(out);
      out.close();
    } catch (const Error& e) {
      // The writers do not know the file's name; every message about a file names it.
      if (std::string_view(e.what()).find(named) != std::string_view::npos) throw;
      throw_with_message(e, fmt::format("cannot write {}: {}", named, e.what()));
    }
  });
}

}  // namespace stitch::detail
