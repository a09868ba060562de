// libFuzzer target for the operation lines of `stitch edit` and the modeler: the first byte picks
// a primitive, every following line is applied to it as the modeler does (without the read-back
// check of the full census). An operation must either be refused with a MeshError, leaving the
// mesh as it was, or give a valid mesh with coordinates in range that reads back from a file.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"

namespace {

stitch::HalfedgeMesh start(std::uint8_t choice) {
  switch (choice % 7) {
    case 0:
      return stitch::make_tetrahedron();
    case 1:
      return stitch::make_cube();
    case 2:
      return stitch::make_octahedron();
    case 3:
      return stitch::make_dodecahedron();
    case 4:
      return stitch::make_icosahedron();
    case 5:
      return stitch::make_prism(3);
    default:
      return stitch::make_torus(3, 4);
  }
}

/// Remeshings multiply the mesh; beyond this the input says nothing new and only costs time.
constexpr int kMostHalfedges = 20'000;
constexpr int kMostLines = 32;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace stitch;
  if (size == 0) return 0;
  HalfedgeMesh mesh = start(data[0]);
  std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  for (int line = 0; line < kMostLines && !text.empty(); ++line) {
    const size_t end = text.find('\n');
    const std::string_view op = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    const HalfedgeMesh before = mesh;
    try {
      apply_operation(mesh, op, Census::counts_only);
    } catch (const MeshError&) {
      if (!(mesh == before)) std::abort();  // a refusal must change nothing
      continue;
    }
    if (!find_problems(mesh).empty()) std::abort();
    for (Vertex v : mesh.vertices())
      if (!limits::coordinate_problem(mesh.position(v)).empty()) std::abort();
    try {
      check_reads_back(mesh);
    } catch (const MeshError&) {
      std::abort();
    }
    if (mesh.halfedge_capacity() > kMostHalfedges) break;
  }
  return 0;
}
