// libFuzzer target for one mesh reader (STITCH_FUZZ_READ: read_obj, read_off, read_ply, read_gltf
// or read_stl) on arbitrary bytes, then build_mesh with the repair (as stitch reads files) and
// without it (--strict). A file must either be refused with a MeshError or give a mesh that is
// valid and, written out, reads back as the same surface. Anything else (a crash, a sanitizer
// report, another exception, a broken invariant) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh_reader.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/validate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stitch;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  PolygonSoup soup;
  try {
    std::vector<std::string> warnings;
    soup = detail::STITCH_FUZZ_READ(text, "fuzz", &warnings);
  } catch (const MeshError&) {
    return 0;
  }
  for (const int variant : {0, 1, 2}) {
    BuildOptions options;
    options.allow_two_gons = true;
    options.fill_holes = variant == 1;
    options.repair = variant < 2;
    HalfedgeMesh mesh;
    try {
      mesh = build_mesh(soup, options);
    } catch (const MeshError&) {
      continue;
    }
    // abort() is what libFuzzer records as a crash, with the input that caused it.
    if (!find_problems(mesh).empty()) std::abort();
    try {
      check_reads_back(mesh);
    } catch (const MeshError&) {
      std::abort();
    }
  }
  return 0;
}
