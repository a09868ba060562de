// stitch primitive NAME [PARAMS] -o OUT: writes a primitive solid (numbering: docs/editing.md).
#include <fmt/format.h>

#include <memory>

#include "commands.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch::cli {

namespace {

struct PrimitiveArgs {
  std::string name;
  std::vector<int> params;
  std::string out;
};

void run_primitive(const PrimitiveArgs& a) {
  const HalfedgeMesh mesh = make_primitive(a.name, a.params);
  write_mesh(a.out, mesh);
  const TopologyStats s = topology_stats(mesh);
  fmt::print("{}: {} vertices, {} edges, {} faces, Euler {}, genus {}\n", a.out, s.vertices,
             s.edges, s.faces, s.euler, s.genus);
}

}  // namespace

void add_primitive_command(CLI::App& app) {
  auto args = std::make_shared<PrimitiveArgs>();
  std::string names;
  for (const std::string& n : primitive_names()) names += (names.empty() ? "" : ", ") + n;
  auto* cmd = app.add_subcommand("primitive", "write a primitive solid: " + names);
  cmd->add_option("NAME", args->name,
                  "tetrahedron, cube, octahedron, dodecahedron, icosahedron, "
                  "prism, torus")
      ->required();
  cmd->add_option("PARAMS", args->params, "prism: N sides; torus: M N segments");
  cmd->add_option("-o,--output", args->out,
                  "output mesh (" + extension_list(kMeshWriteExtensions) + ")")
      ->required();
  cmd->callback([args] { run_primitive(*args); });
}

}  // namespace stitch::cli
