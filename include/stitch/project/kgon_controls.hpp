// K-gon controls files: per-element controls for a mesh file, which has no place for them
// (`stitch smooth/render/analyze ... --kgon-controls FILE`; docs/modeler.md describes the
// format):
//   { "format": "stitch-kgon-controls",           // optional
//     "controls": [ {"face": 2, "scale": 0.5},
//                   {"vertex": 7, "rotate": 30, "offset": [0, 0, 0.1]},
//                   {"edge": "1 5", "regularize": true}, {"edge": 13, "scale": 2} ] }
// Numbers are 1-based, as on the command line and in the mesh file: faces and vertices in file
// order, edges as the library numbers them (`stitch edit` prints them) or as "V W" / "V W@F"
// (operation lines). An entry names exactly one element; its other members are the fields of
// kgon_control_fields(), and the ones it leaves out keep their defaults (scale 1, rotate 0,
// offset 0, regularize false, stretch 1 along no direction).
#pragma once

#include <string>

#include "stitch/kgon/kgon.hpp"

namespace stitch {

/// Adds the file's per-element controls, numbered for `mesh`, to `kgons` (an entry replaces a
/// control its element already has). Throws stitch::Error naming `source`, the entry and what is
/// wrong; `kgons` is then unchanged.
void parse_kgon_controls(const std::string& text, const std::string& source,
                         const HalfedgeMesh& mesh, KgonOptions& kgons);
void read_kgon_controls(const std::string& path, const HalfedgeMesh& mesh, KgonOptions& kgons);

}  // namespace stitch
