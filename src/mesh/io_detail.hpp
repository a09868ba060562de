// Private helpers shared by the mesh readers and writers (and the surface export): number
// parsing with file/line context, line splitting, and the per-format writers, which are
// templates over the face container so polygon soups and quad meshes share them.
#pragma once

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::io_detail {

/// Where a problem is, for messages: "file.obj, line 12".
std::string at_line(const std::string& path, int line);

/// Parses a whole token as a finite double; throws MeshError naming `where` otherwise.
double parse_double(std::string_view token, const std::string& where);
/// Parses a whole token as an integer; throws MeshError naming `where` otherwise.
long long parse_integer(std::string_view token, const std::string& where);

/// Whitespace-separated tokens of a line, with a trailing `#` comment removed.
std::vector<std::string_view> tokens(std::string_view line);

/// Iterates over the lines of a text, counting them from 1; strips a trailing '\r'.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  /// False at the end of the text.
  bool next(std::string_view& line);
  [[nodiscard]] int line_number() const { return line_; }
  /// Byte offset just past the last line returned.
  [[nodiscard]] size_t offset() const { return pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int line_ = 0;
};

/// Throws MeshError naming the line when the line holds a byte that cannot be in a text file.
void require_text(std::string_view line, const std::string& path, int line_number);

PolygonSoup read_obj(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings);
PolygonSoup read_off(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings);
PolygonSoup read_ply(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings);

/// Shortest text that reads back as exactly the same double.
inline std::string exact(double x) {
  return fmt::format("{}", x);
}

template <class Loop>
int loop_size(const Loop& loop) {
  return static_cast<int>(std::size(loop));
}

/// OBJ: `v` lines, optional `vn` lines (one per vertex, referenced as `a//a`), 1-based faces.
template <class Faces>
void write_obj(std::ostream& out, const std::vector<Vec3>& positions,
               const std::vector<Vec3>* normals, const Faces& faces, std::string_view comment) {
  out << "# " << comment << '\n';
  for (const Vec3& p : positions)
    out << "v " << exact(p.x()) << ' ' << exact(p.y()) << ' ' << exact(p.z()) << '\n';
  if (normals)
    for (const Vec3& n : *normals)
      out << "vn " << exact(n.x()) << ' ' << exact(n.y()) << ' ' << exact(n.z()) << '\n';
  for (const auto& loop : faces) {
    out << 'f';
    for (int v : loop) {
      out << ' ' << v + 1;
      if (normals) out << "//" << v + 1;
    }
    out << '\n';
  }
}

/// OFF with `nv nf 0` counts; faces as `n i0 ... i(n-1)`, 0-based.
template <class Faces>
void write_off(std::ostream& out, const std::vector<Vec3>& positions, const Faces& faces,
               std::string_view comment) {
  out << "OFF\n# " << comment << '\n' << positions.size() << ' ' << std::size(faces) << " 0\n";
  for (const Vec3& p : positions)
    out << exact(p.x()) << ' ' << exact(p.y()) << ' ' << exact(p.z()) << '\n';
  for (const auto& loop : faces) {
    out << loop_size(loop);
    for (int v : loop) out << ' ' << v;
    out << '\n';
  }
}

/// ASCII PLY with double coordinates (exact round trip) and optional double normals.
template <class Faces>
void write_ply_ascii(std::ostream& out, const std::vector<Vec3>& positions,
                     const std::vector<Vec3>* normals, const Faces& faces,
                     std::string_view comment) {
  int max_degree = 0;
  for (const auto& loop : faces) max_degree = std::max(max_degree, loop_size(loop));
  out << "ply\nformat ascii 1.0\ncomment " << comment << "\nelement vertex " << positions.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n";
  if (normals) out << "property double nx\nproperty double ny\nproperty double nz\n";
  out << "element face " << std::size(faces) << "\nproperty list "
      << (max_degree > 255 ? "int" : "uchar") << " int vertex_indices\nend_header\n";
  for (size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    out << exact(p.x()) << ' ' << exact(p.y()) << ' ' << exact(p.z());
    if (normals) {
      const Vec3& n = (*normals)[i];
      out << ' ' << exact(n.x()) << ' ' << exact(n.y()) << ' ' << exact(n.z());
    }
    out << '\n';
  }
  for (const auto& loop : faces) {
    out << loop_size(loop);
    for (int v : loop) out << ' ' << v;
    out << '\n';
  }
}

/// Appends the little-endian bytes of a number.
template <class T>
void put_le(std::ostream& out, T value) {
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big)
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out.write(bytes.data(), sizeof(T));
}

/// Binary STL; every polygon is fanned from its first vertex into triangles.
template <class Faces>
void write_stl(std::ostream& out, const std::vector<Vec3>& positions, const Faces& faces,
               std::string_view comment) {
  std::array<char, 80> header{};
  std::memcpy(header.data(), comment.data(), std::min(comment.size(), header.size()));
  out.write(header.data(), header.size());
  std::uint32_t triangles = 0;
  for (const auto& loop : faces)
    triangles += static_cast<std::uint32_t>(std::max(0, loop_size(loop) - 2));
  put_le(out, triangles);
  for (const auto& loop : faces) {
    const auto* first = std::data(loop);
    for (int i = 1; i + 1 < loop_size(loop); ++i) {
      const Vec3& a = positions[first[0]];
      const Vec3& b = positions[first[i]];
      const Vec3& c = positions[first[i + 1]];
      const Vec3 n = (b - a).cross(c - a).stableNormalized();
      for (const Vec3* p : {&n, &a, &b, &c})
        for (int k = 0; k < 3; ++k) put_le(out, static_cast<float>((*p)[k]));
      put_le(out, std::uint16_t{0});
    }
  }
}

}  // namespace stitch::io_detail
