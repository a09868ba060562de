// Writing polygon meshes at the speed of the disk: vertices and faces are produced and formatted
// in blocks on every core and written in order, so a mesh can be written while it is computed
// (the smooth surface of a large mesh never has to be held whole) and the bytes do not depend on
// the number of threads. Numbers go through std::to_chars (shortest text that reads back
// exactly), binary values into bulk buffers. write_mesh_stream is the one dispatch by format;
// each format's writer is in its own file beside its reader (io_obj.cpp, ...). Internal to the
// library.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/output_file.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::detail {

/// One block of vertices: positions, and normals when the mesh has them.
struct VertexBlock {
  std::vector<Vec3> positions, normals;
};

/// One block of faces: the size of each face and all their vertex indices (0-based), in order.
struct FaceBlock {
  std::vector<int> sizes;
  std::vector<int> indices;
  /// With texture coordinates: per corner like `indices`, an index into them (0-based).
  std::vector<int> texcoords;
};

/// Faces as the triangles of the formats made of triangles (STL, glTF): three vertex indices per
/// triangle (0-based) and the positions of those three corners.
struct TriangleBlock {
  std::vector<int> indices;
  std::vector<Vec3> corners;
};

/// A mesh as a writer reads it. The callbacks may run for several blocks at once on different
/// threads; each fills its block from scratch (resize, then assign).
struct MeshStream {
  std::int64_t num_vertices = 0;
  std::int64_t num_faces = 0;
  bool has_normals = false;
  int max_face_degree = 3;     ///< the PLY face list's count type: uchar up to 255, else int
  std::int64_t triangles = 0;  ///< sum over faces of (size - 2): STL's triangle count
  std::function<void(std::int64_t begin, std::int64_t end, VertexBlock&)> vertices;
  std::function<void(std::int64_t begin, std::int64_t end, FaceBlock&)> faces;
  /// Texture coordinates (0: none, and FaceBlock::texcoords stays empty). OBJ numbers them on
  /// their own (`vt`: a seam needs two at one vertex) and reads FaceBlock::texcoords; glTF has one
  /// per vertex (num_texcoords == num_vertices) and no use for FaceBlock::texcoords. The other
  /// formats have no place for them.
  std::int64_t num_texcoords = 0;
  std::function<void(std::int64_t begin, std::int64_t end, std::vector<Eigen::Vector2d>&)>
      texcoords;
  /// Faces [begin, end) as triangles (`triangles` of them for all faces, face after face), for a
  /// stream that cannot hand the writers every position to split its faces by: a tessellation
  /// evaluated block by block. Null: the writers split the faces themselves (for_each_triangle
  /// over the `positions` write_mesh_stream is given).
  std::function<void(std::int64_t begin, std::int64_t end, TriangleBlock&)> triangulated;
};

/// Called with the fraction (0..1) of the file written so far.
using WriteProgress = std::function<void(double)>;

enum class PlyEncoding { ascii, binary_little_endian };
/// double: exact (a file that reads back as the same numbers); single: float, half the bytes,
/// about 7 significant digits (enough to render or print).
enum class PlyPrecision { double_precision, single };

/// How write_mesh_stream writes a file besides its format.
struct MeshFileOptions {
  PlyEncoding ply_encoding = PlyEncoding::binary_little_endian;
  PlyPrecision ply_precision = PlyPrecision::double_precision;
  /// In the header: OBJ and OFF comment lines, a PLY comment, STL's 80 bytes (glTF names its
  /// generator instead).
  std::string_view comment;
  WriteProgress progress;
  /// OBJ only: statements written after the faces (write_polygon_soup's crease and corner tags).
  std::function<void(OutputFile&)> obj_statements;
};

/// Writes `mesh` to `path` in `format` (whatever the path's extension), atomically
/// (write_mesh_file). `positions` are every vertex's, for the formats made of triangles (STL,
/// glTF: quads are split by their shorter diagonal) of a stream without `triangulated`; the
/// others may get an empty vector.
void write_mesh_stream(const std::string& path, MeshFileFormat format, const MeshStream& mesh,
                       const std::vector<Vec3>& positions, const MeshFileOptions& options);

/// OBJ: `v` (and `vn`) lines block by block, the `vt` lines, then 1-based faces (`a//a` with
/// normals, `a/t/a` with texture coordinates too, `a/t` with texture coordinates only).
/// io_obj.cpp.
void write_obj(OutputFile& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& progress = {});
/// OFF with `nv nf 0` counts; faces as `n i0 ... i(n-1)`, 0-based; no normals. io_off.cpp.
void write_off(OutputFile& out, const MeshStream& mesh, std::string_view comment,
               const WriteProgress& progress = {});
/// PLY with x y z (and nx ny nz) as double (an exact round trip in either encoding) or float.
/// io_ply.cpp.
void write_ply(OutputFile& out, const MeshStream& mesh, PlyEncoding encoding,
               PlyPrecision precision, std::string_view comment,
               const WriteProgress& progress = {});
/// Binary STL; every polygon is fanned from its first vertex into triangles (quads split by
/// their shorter diagonal), whose corners are looked up in `positions` (STL repeats them per
/// triangle), or the stream's own triangles with their corners (MeshStream::triangulated).
/// io_stl.cpp.
void write_stl(OutputFile& out, const MeshStream& mesh, const std::vector<Vec3>& positions,
               std::string_view comment, const WriteProgress& progress = {});
/// glTF 2.0, one mesh of triangles (split as write_stl splits them) with float POSITION,
/// NORMAL (with the stream's normals, normalized again after rounding) and TEXCOORD_0 (with its
/// texture coordinates, one per vertex; v flipped to glTF's, down from the top). `binary`: one
/// .glb file. Otherwise a .gltf file and its buffer beside it, named like the .gltf with the
/// extension .bin (written first, so the .gltf never refers to a missing file). Streamed: the
/// JSON (which holds the positions' bounds) is written before the buffer, so the vertices are
/// read once for their bounds and then once for each attribute, every pass block by block.
/// Atomic. io_gltf.cpp.
void write_gltf(const std::string& path, const MeshStream& mesh, const std::vector<Vec3>& positions,
                bool binary, const WriteProgress& progress = {});

/// Bytes a block is formatted into. Unlike std::string it neither zero-fills what it is about to
/// overwrite nor gives its memory back when cleared, so the few buffers the writers cycle through
/// are allocated (and their pages touched) once per file, not once per block.
class OutputBuffer {
 public:
  [[nodiscard]] const char* data() const { return data_.get(); }
  [[nodiscard]] size_t size() const { return size_; }
  void clear() { size_ = 0; }
  void reserve(size_t capacity);
  /// Room for at most n more bytes, written from the pointer returned and ended by commit():
  /// numbers go straight into the buffer, with no size check each.
  char* claim(size_t n) {
    if (size_ + n > capacity_) reserve(std::max(2 * capacity_, size_ + n));
    return data_.get() + size_;
  }
  /// Makes room for exactly n more bytes and returns where they go.
  char* extend(size_t n) {
    char* at = claim(n);
    size_ += n;
    return at;
  }
  /// Ends what was written since claim() at `end`.
  void commit(const char* end) { size_ = static_cast<size_t>(end - data_.get()); }

 private:
  std::unique_ptr<char[]> data_;
  size_t size_ = 0, capacity_ = 0;
};

/// Formats [0, count) in blocks of `block` items, format(begin, end, text) for several blocks at
/// once on all cores, and writes the texts to `out` in block order; written(items) after each.
/// Throws stitch::Error when the file cannot take them.
void write_blocks(OutputFile& out, std::int64_t count, std::int64_t block,
                  const std::function<void(std::int64_t, std::int64_t, OutputBuffer&)>& format,
                  const std::function<void(std::int64_t)>& written = {});

/// Little-endian values into a buffer sized once up front (binary formats write millions of
/// small values: one append each would cost more than the values).
class LittleEndianWriter {
 public:
  /// Appends `size` bytes to `bytes`, to be filled by put().
  LittleEndianWriter(OutputBuffer& bytes, size_t size) : at_(bytes.extend(size)) {}
  template <class T>
  void put(T value) {
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw.begin(), raw.end());
    std::memcpy(at_, raw.data(), sizeof(T));
    at_ += sizeof(T);
  }
  template <class Scalar>
  void put(const Eigen::Matrix<Scalar, 3, 1>& p) {
    put(p.x());
    put(p.y());
    put(p.z());
  }

 private:
  char* at_;
};

/// Runs `write` on a temporary file that replaces `path` when it returns
/// (write_file_atomically_at), with a message naming `name` (empty: `path`) when it fails.
void write_mesh_file(const std::string& path, const std::function<void(OutputFile&)>& write,
                     const std::string& name = {});

/// A stream over vertex and face arrays held in memory (`normals` may be null). Faces is any
/// container of index loops (std::vector<int>, std::array<int, 4>, ...). `texcoords`, if given,
/// are one per vertex (each corner's is its vertex's).
template <class Faces>
MeshStream stream_arrays(const std::vector<Vec3>& positions, const std::vector<Vec3>* normals,
                         const Faces& faces,
                         const std::vector<Eigen::Vector2d>* texcoords = nullptr) {
  MeshStream s;
  s.num_vertices = static_cast<std::int64_t>(positions.size());
  s.num_faces = static_cast<std::int64_t>(std::size(faces));
  s.has_normals = normals != nullptr;
  s.max_face_degree = 0;
  for (const auto& loop : faces) {
    const int size = static_cast<int>(std::size(loop));
    s.max_face_degree = std::max(s.max_face_degree, size);
    s.triangles += std::max(0, size - 2);
  }
  s.vertices = [&positions, normals](std::int64_t begin, std::int64_t end, VertexBlock& block) {
    block.positions.assign(positions.begin() + begin, positions.begin() + end);
    if (normals) block.normals.assign(normals->begin() + begin, normals->begin() + end);
  };
  s.faces = [&faces, texcoords](std::int64_t begin, std::int64_t end, FaceBlock& block) {
    block.sizes.clear();
    block.indices.clear();
    for (std::int64_t f = begin; f < end; ++f) {
      const auto& loop = faces[static_cast<size_t>(f)];
      block.sizes.push_back(static_cast<int>(std::size(loop)));
      block.indices.insert(block.indices.end(), std::begin(loop), std::end(loop));
    }
    if (texcoords) block.texcoords = block.indices;
  };
  if (texcoords) {
    s.num_texcoords = static_cast<std::int64_t>(texcoords->size());
    s.texcoords = [texcoords](std::int64_t begin, std::int64_t end,
                              std::vector<Eigen::Vector2d>& block) {
      block.assign(texcoords->begin() + begin, texcoords->begin() + end);
    };
  }
  return s;
}

}  // namespace stitch::detail
