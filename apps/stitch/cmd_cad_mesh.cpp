// stitch cad-mesh IN.step -o OUT.obj: a STEP or IGES file triangulated by OpenCASCADE, to look
// at what a CAD program reads from stitch's files (`stitch render OUT.obj --draw input`).
#include <fmt/format.h>

#include <memory>

#include "commands.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
// after stitch's headers (OCCT defines a macro Handle, see cad.hpp)
// clang-format off
#include "stitch/cad/cad.hpp"
// clang-format on

namespace stitch::cli {

namespace {

struct CadMeshArgs {
  std::string in, out;
  double deflection = 1e-3;
};

void run_cad_mesh(const CadMeshArgs& a) {
  limits::check_range(a.deflection, 1e-12, limits::max_coordinate, "--deflection");
  cad::quiet_opencascade();  // stdout is for the summary below
  const PolygonSoup soup = cad::triangulate(cad::read_cad(a.in), a.deflection);
  write_polygon_soup(a.out, soup);
  fmt::print("wrote {} ({} vertices, {} triangles)\n", a.out, soup.positions.size(),
             soup.faces.size());
}

}  // namespace

void add_cad_mesh_command(CLI::App& app) {
  auto args = std::make_shared<CadMeshArgs>();
  CLI::App* cmd = app.add_subcommand(
      "cad-mesh", "Triangulate a STEP or IGES file with OpenCASCADE (to view what CAD reads)");
  cmd->add_option("input", args->in, fmt::format("input CAD file ({})", cad::kCadExtensions))
      ->required();
  cmd->add_option("-o,--output", args->out, "output mesh: " + extension_list(kMeshWriteExtensions))
      ->required();
  cmd->add_option("--deflection", args->deflection,
                  "largest distance of the triangles from the faces, in the file's units (mm)")
      ->capture_default_str();
  cmd->callback([args] { run_cad_mesh(*args); });
}

}  // namespace stitch::cli
