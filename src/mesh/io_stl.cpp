// STL in (ASCII and binary), welded into a polygon soup, and out (binary, write_stl at the end).
// STL stores every triangle with its own three corners, so shared vertices are found again by
// position: corners closer than kWeldTolerance times the bounding box diagonal become one vertex
// (weld_triangles, which the glTF reader shares: glTF splits vertices wherever an attribute
// differs).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "mesh/mesh_reader.hpp"
#include "mesh/writer_kit.hpp"

namespace stitch::detail {

namespace {

/// Relative to the bounding box diagonal. Writers round a shared corner to the same float, so
/// equal corners are equal bits; the tolerance also joins corners that other tools computed
/// twice (float round-off, 6e-8 of a coordinate) and is far below any sensible sample spacing.
constexpr double kWeldTolerance = 1e-6;

/// The little-endian 32-bit word at `at`.
std::uint32_t word_le(std::string_view text, size_t at) {
  std::uint32_t w = 0;
  for (int k = 3; k >= 0; --k) w = (w << 8) | static_cast<unsigned char>(text[at + k]);
  return w;
}

bool looks_binary(std::string_view text) {
  if (text.size() < 84) return false;
  const std::uint32_t count = word_le(text, 80);
  return text.size() == 84 + 50 * std::uint64_t{count};
}

std::vector<std::array<Vec3, 3>> read_binary(std::string_view text, const std::string& path) {
  const size_t count = (text.size() - 84) / 50;
  std::vector<std::array<Vec3, 3>> triangles(count);
  for (size_t t = 0; t < count; ++t)
    for (int corner = 0; corner < 3; ++corner)
      for (int k = 0; k < 3; ++k) {
        // Skip the facet normal (12 bytes); corners follow, 12 bytes each.
        const size_t at = 84 + 50 * t + 12 + 12 * corner + 4 * k;
        const auto value = std::bit_cast<float>(word_le(text, at));
        if (!std::isfinite(value))
          throw InputError(
              fmt::format("{}: triangle {} has a coordinate that is not finite", path, t + 1));
        triangles[t][corner][k] = value;
      }
  return triangles;
}

std::vector<std::array<Vec3, 3>> read_ascii(std::string_view text, const std::string& path,
                                            std::vector<int>* lines) {
  std::vector<std::array<Vec3, 3>> triangles;
  LineReader reader(text);
  std::string_view line;
  std::vector<Vec3> loop;
  int loop_line = 0;
  bool in_loop = false;
  std::vector<std::string_view> words;
  while (reader.next(line)) {
    require_text(line, path, reader.line_number());
    tokens(line, words);
    if (words.empty()) continue;
    const Where where(path, reader.line_number());
    if (words[0] == "outer") {
      if (in_loop) throw InputError(fmt::format("{}: 'outer loop' inside a loop", where));
      in_loop = true;
      loop.clear();
      loop_line = reader.line_number();
    } else if (words[0] == "vertex") {
      if (!in_loop) throw InputError(fmt::format("{}: 'vertex' outside 'outer loop'", where));
      if (words.size() != 4) throw InputError(fmt::format("{}: 'vertex' needs x y z", where));
      loop.emplace_back(parse_double(words[1], where), parse_double(words[2], where),
                        parse_double(words[3], where));
    } else if (words[0] == "endloop") {
      if (!in_loop) throw InputError(fmt::format("{}: 'endloop' without 'outer loop'", where));
      if (loop.size() != 3)
        throw InputError(fmt::format("{}: a facet has {} vertices, STL facets have 3",
                                     at_line(path, loop_line), loop.size()));
      triangles.push_back({loop[0], loop[1], loop[2]});
      lines->push_back(loop_line);
      in_loop = false;
    } else if (words[0] != "solid" && words[0] != "facet" && words[0] != "endfacet" &&
               words[0] != "endsolid") {
      throw InputError(fmt::format("{}: '{}' is not an STL keyword", where, words[0]));
    }
  }
  if (in_loop) throw InputError(fmt::format("{}: the last facet is not closed", path));
  return triangles;
}

/// One vertex per cluster of corners within `tolerance`, found through a hash of grid cells of
/// that size (a corner's twin may lie in a neighbouring cell).
class Welder {
 public:
  explicit Welder(double tolerance) : tolerance_(tolerance) {}

  int index(const Vec3& p, std::vector<Vec3>& positions) {
    const std::array<long long, 3> cell = cell_of(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.equal_range(key({cell[0] + dx, cell[1] + dy, cell[2] + dz}));
          for (auto it = found.first; it != found.second; ++it)
            if ((positions[it->second] - p).norm() <= tolerance_) return it->second;
        }
    positions.push_back(p);
    const int i = static_cast<int>(positions.size()) - 1;
    cells_.emplace(key(cell), i);
    return i;
  }

 private:
  std::array<long long, 3> cell_of(const Vec3& p) const {
    return {std::llround(std::floor(p.x() / tolerance_)),
            std::llround(std::floor(p.y() / tolerance_)),
            std::llround(std::floor(p.z() / tolerance_))};
  }
  static std::uint64_t key(const std::array<long long, 3>& c) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the three cell numbers
    for (long long x : c) {
      h ^= static_cast<std::uint64_t>(x);
      h *= 1099511628211ull;
    }
    return h;
  }

  double tolerance_;
  std::unordered_multimap<std::uint64_t, int> cells_;
};

}  // namespace

PolygonSoup read_stl(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings) {
  std::vector<int> lines;
  const bool binary = looks_binary(text);
  // Blank text has no first word: npos must not reach substr (found by fuzz/, issue #10).
  const size_t first_word = std::min(text.find_first_not_of(" \t\r\n"), text.size());
  if (!binary && text.substr(first_word, 5) != "solid")
    throw InputError(fmt::format(
        "{}: neither ASCII STL (which starts with 'solid') nor binary STL (84 + 50 n bytes for n "
        "triangles; this file has {} bytes)",
        path, text.size()));
  const auto triangles = binary ? read_binary(text, path) : read_ascii(text, path, &lines);
  return weld_triangles(triangles, lines, path, warnings);
}

PolygonSoup weld_triangles(const std::vector<std::array<Vec3, 3>>& triangles,
                           const std::vector<int>& lines, const std::string& path,
                           std::vector<std::string>* warnings) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const auto& t : triangles)
    for (const Vec3& p : t) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const double diagonal = triangles.empty() ? 0.0 : (hi - lo).norm();
  // A zero diagonal (every corner at one point) still needs a cell size above zero.
  Welder welder(diagonal > 0 ? kWeldTolerance * diagonal : 1.0);
  PolygonSoup soup;
  int degenerate = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    std::vector<int> face;
    for (const Vec3& p : triangles[t]) face.push_back(welder.index(p, soup.positions));
    if (face[0] == face[1] || face[1] == face[2] || face[2] == face[0]) {
      ++degenerate;  // two corners welded into one: no area left
      continue;
    }
    soup.faces.push_back(std::move(face));
    soup.face_lines.push_back(lines.empty() ? 0 : lines[t]);
  }
  if (degenerate > 0 && warnings)
    warnings->push_back(fmt::format(
        "{}: dropped {} triangle(s) whose corners weld together (closer than {} of the size)", path,
        degenerate, kWeldTolerance));
  return soup;
}

// --- writing ---

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
  write_triangles(
      out, mesh, positions,
      [](const TriangleBlock& block, OutputBuffer& bytes) {
        LittleEndianWriter record(bytes, block.corners.size() / 3 * 50);
        for (size_t t = 0; t < block.corners.size(); t += 3) {
          const Vec3 &a = block.corners[t], &b = block.corners[t + 1], &c = block.corners[t + 2];
          const Vec3 n = (b - a).cross(c - a).stableNormalized();
          for (const Vec3* p : {&n, &a, &b, &c})
            for (int axis = 0; axis < 3; ++axis) record.put(static_cast<float>((*p)[axis]));
          record.put(std::uint16_t{0});
        }
      },
      progress);
}

}  // namespace stitch::detail
