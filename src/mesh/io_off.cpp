// Object File Format: `OFF`, counts, one vertex per line, one face per line (`n i0 ... i(n-1)`,
// 0-based, optionally followed by a colour). Written the same way without colours (write_off, at
// the end).
#include <algorithm>
#include <limits>

#include "mesh/mesh_reader.hpp"
#include "mesh/writer_kit.hpp"

namespace stitch::detail {

namespace {

/// The header keyword: OFF with the optional prefixes that only add per-vertex data (texture
/// coordinates, colour, normal), which is skipped.
bool is_off_keyword(std::string_view word) {
  if (word.starts_with("ST")) word.remove_prefix(2);
  if (word.starts_with("C")) word.remove_prefix(1);
  if (word.starts_with("N")) word.remove_prefix(1);
  return word == "OFF";
}

}  // namespace

PolygonSoup read_off(std::string_view text, const std::string& path,
                     std::vector<std::string>* warnings) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  LineReader lines(text);
  std::string_view line;
  // The next line with content (comments and blank lines skipped), or empty at the end.
  std::vector<std::string_view> buffer;  // reused from line to line
  auto next_words = [&]() -> const std::vector<std::string_view>& {
    while (lines.next(line)) {
      require_text(line, path, lines.line_number());
      tokens(line, buffer);
      if (!buffer.empty()) return buffer;
    }
    buffer.clear();
    return buffer;
  };

  std::vector<std::string_view> words = next_words();
  if (words.empty() || !is_off_keyword(words[0]))
    throw InputError(fmt::format("{}: not an OFF file (the first line must be 'OFF')",
                                 at_line(path, lines.line_number())));
  if (words.size() > 1 && words[1] == "BINARY")
    throw InputError(
        fmt::format("{}: binary OFF is not supported", at_line(path, lines.line_number())));
  words.erase(words.begin());
  if (words.empty()) words = next_words();
  const std::string counts_where = at_line(path, lines.line_number());
  if (words.size() < 2 || words.size() > 3)
    throw InputError(fmt::format("{}: expected the counts 'vertices faces [edges]'", counts_where));
  const long long nv = parse_integer(words[0], counts_where);
  const long long nf = parse_integer(words[1], counts_where);
  if (nv < 0 || nf < 0 || nv > std::numeric_limits<int>::max() ||
      nf > std::numeric_limits<int>::max())
    throw InputError(fmt::format("{}: invalid counts {} {}", counts_where, nv, nf));

  auto truncated = [&](const char* what, long long done, long long declared) {
    return InputError(fmt::format("{}: the file ends after {} of the {} {} declared (truncated?)",
                                  at_line(path, lines.line_number()), done, declared, what));
  };

  PolygonSoup soup;
  // The header may lie about the counts, so only reserve what the file could hold.
  soup.positions.reserve(std::min<size_t>(nv, text.size() / 6));
  for (long long v = 0; v < nv; ++v) {
    words = next_words();
    if (words.empty()) throw truncated("vertices", v, nv);
    const Where where(path, lines.line_number());
    if (words.size() < 3)
      throw InputError(
          fmt::format("{}: a vertex needs 3 coordinates, found {}", where, words.size()));
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = parse_double(words[k], where);
    for (size_t k = 3; k < words.size(); ++k) parse_double(words[k], where);
    soup.positions.push_back(p);
    soup.vertex_lines.push_back(lines.line_number());
  }
  for (long long f = 0; f < nf; ++f) {
    words = next_words();
    if (words.empty()) throw truncated("faces", f, nf);
    const Where where(path, lines.line_number());
    const long long n = parse_integer(words[0], where);
    if (n < 0 || static_cast<size_t>(n) + 1 > words.size())
      throw InputError(
          fmt::format("{}: face declares {} vertices but lists {}", where, n, words.size() - 1));
    std::vector<int> loop;
    loop.reserve(n);
    for (long long k = 1; k <= n; ++k) {
      const long long index = parse_integer(words[k], where);
      if (index < 0 || index >= nv)
        throw InputError(
            fmt::format("{}: face refers to vertex {} (0-based), but the file has {} vertices",
                        where, index, nv));
      loop.push_back(static_cast<int>(index));
    }
    // Optional colour after the indices.
    for (size_t k = n + 1; k < words.size(); ++k) parse_double(words[k], where);
    soup.faces.push_back(std::move(loop));
    soup.face_lines.push_back(lines.line_number());
  }
  if (!next_words().empty() && warnings)
    warnings->push_back(fmt::format("{}: ignoring content after the last declared face",
                                    at_line(path, lines.line_number())));
  return soup;
}

// --- writing ---

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

}  // namespace stitch::detail
