// Private helpers of the mesh readers: number parsing with file/line context, line splitting.
// The writers are in mesh_writer.hpp.
#pragma once

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::detail {

/// Where a problem is, for messages: "file.obj, line 12".
std::string at_line(const std::string& path, int line);

/// Where a problem is, as at_line(path, line) or any text, made into text only when a message
/// needs it: the readers name a line for every number they parse, and formatting it each time
/// cost as much as parsing the line. Refers to the strings it is given, so it does not take
/// temporaries. Formats with fmt as its text.
class Where {
 public:
  Where(const std::string& text) : text_(&text) {}  // NOLINT(google-explicit-constructor)
  Where(std::string&&) = delete;
  Where(const std::string& path, int line) : path_(&path), line_(line) {}
  Where(std::string&&, int) = delete;
  [[nodiscard]] std::string text() const { return text_ ? *text_ : at_line(*path_, line_); }

 private:
  const std::string* text_ = nullptr;
  const std::string* path_ = nullptr;
  int line_ = 0;
};

/// A number as from_chars reads it (a leading '+' allowed), NaN and infinity included; throws
/// stitch::Error naming `where` otherwise.
double parse_number(std::string_view token, const Where& where);

/// Parses a whole token as a finite double; throws stitch::Error naming `where` otherwise.
double parse_double(std::string_view token, const Where& where);
/// Parses a whole token as an integer; throws stitch::Error naming `where` otherwise.
long long parse_integer(std::string_view token, const Where& where);

/// Whitespace-separated tokens of a line, with a trailing `#` comment removed.
std::vector<std::string_view> tokens(std::string_view line);
/// The same into `out` (cleared first), whose storage a reader reuses from line to line.
void tokens(std::string_view line, std::vector<std::string_view>& out);

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

/// Throws stitch::Error naming the line when the line holds a byte that cannot be in a text file.
void require_text(std::string_view line, const std::string& path, int line_number);

/// `progress` (optional) gets the fraction of the text parsed, every so many lines.
PolygonSoup read_obj(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings,
                     const std::function<void(double)>& progress = {});
PolygonSoup read_off(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings);
PolygonSoup read_ply(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings);
/// Triangles given corner by corner, welded: corners within 1e-6 of the bounding box diagonal
/// become one vertex; triangles that collapse are dropped (one warning). `lines` (empty, or one
/// per triangle) are the file lines for messages.
PolygonSoup weld_triangles(const std::vector<std::array<Vec3, 3>>& triangles,
                           const std::vector<int>& lines, const std::string& path,
                           std::vector<std::string>* warnings);
/// glTF 2.0, binary (.glb) or text (.gltf, whose external buffers are read from beside it): the
/// triangles of every mesh the default scene places, in scene coordinates, welded.
PolygonSoup read_gltf(std::string_view text, const std::string& path,
                      std::vector<std::string>* warnings);
/// ASCII or binary STL (told apart by the binary size 84 + 50 n), coincident corners welded.
PolygonSoup read_stl(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings);

}  // namespace stitch::detail

template <>
struct fmt::formatter<stitch::detail::Where> : fmt::formatter<std::string> {
  template <class FormatContext>
  auto format(const stitch::detail::Where& where, FormatContext& ctx) const {
    return fmt::formatter<std::string>::format(where.text(), ctx);
  }
};
