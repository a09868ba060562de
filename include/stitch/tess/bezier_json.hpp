// The Bézier JSON format: the patch set as data, for tools that want the exact surface rather
// than a tessellation. The schema is in docs/formats.md.
#pragma once

#include <string>

#include "stitch/kgon/kgon.hpp"
#include "stitch/tess/patches.hpp"

namespace stitch {

/// The version written; readers refuse files of a later major version.
inline constexpr int kBezierJsonVersion = 1;

/// Writes the patches (and, when `kgons` is given, every K-gon) to `path`. Numbers are written
/// as the shortest text that reads back as the same double. Atomic (write_file_atomically).
void write_bezier_json(const std::string& path, const PatchSet& patches,
                       const KgonSet* kgons = nullptr);

/// Reads a file written by write_bezier_json (K-gons are not read back). Throws stitch::Error
/// naming the file and the entry for anything that is not that format.
PatchSet read_bezier_json(const std::string& path);

}  // namespace stitch
