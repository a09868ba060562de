// Project files: a mesh together with its K-gon controls, in JSON. The modeler saves its
// documents this way (`.stitch`), adding its view and display settings, and every `stitch`
// command that smooths a mesh reads them, so the per-element controls shaped in the modeler
// reach the command line.
//
// Format (version 1):
//   { "format": "stitch-modeler-project", "version": 1,
//     "mesh": { "positions": [[x, y, z], ...], "faces": [[i, j, k, ...], ...],    // 0-based
//               "creases": [[i, j, s], ...], "corners": [[i, s], ...],  // sharpness tags
//               "crease_method": "chaikin" },   // the last three optional (none, uniform)
//     "kgons": { "global": CONTROL,
//                "faces": [{"face": F, CONTROL...}], "vertices": [{"vertex": V, ...}],
//                "edges": [{"face": F, "corner": K, ...}] },  // the edge of face F's K-th side
//     "view": { "target": [x, y, z], "distance": d, "yaw": deg, "pitch": deg, "fov": deg },
//     "display": { "method": "mdc", "resolution": 8, "mode": "shaded", "input": false,
//                  "overlays": ["mesh", ...], "markers": false, "split": null | "asc" } }
// where CONTROL is the fields of kgon_control_fields() that differ from no change: "scale",
// "rotate" (degrees), "offset" [x, y, z], "regularize", "stretch", "stretch_along" [x, y, z]
// (an unknown member is refused, so a misspelt one does not silently do nothing). Numbers are
// those of the mesh as saved (deleted elements compacted away), all 0-based. "view" and
// "display" belong to the modeler (stitch/modeler/project.hpp); of them the core reads only the
// display's method.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "stitch/eval/surface.hpp"
#include "stitch/kgon/kgon.hpp"
#include "stitch/mesh/build.hpp"

namespace stitch {

struct ProjectFile {
  HalfedgeMesh mesh;
  /// The global and per-element controls; the other members keep their defaults.
  KgonOptions kgons;
  /// The method the project shows ("display"."method"), if it names one.
  std::optional<Method> method;
  /// The top-level members other than format, version, mesh and kgons (the modeler's "view" and
  /// "display"), each as JSON text, so that a reader that knows them can parse them.
  std::map<std::string, std::string> sections;
};

/// The extensions of project files, the usual one first.
inline constexpr std::array<std::string_view, 2> kProjectExtensions{".stitch", ".json"};
/// ".stitch" and ".json" files are projects.
bool is_project_path(const std::string& path);

/// The project as JSON text; `sections` are added as top-level members (each must be valid
/// JSON). Per-element controls are written in the numbers the mesh gets when it is read back.
std::string write_project_json(const HalfedgeMesh& mesh, const KgonOptions& kgons,
                               const std::map<std::string, std::string>& sections = {});
/// Throws stitch::Error naming `source` and what is wrong. 2-sided faces are always allowed (the
/// topology operators make them); `build` adds e.g. fill_holes.
ProjectFile parse_project_json(const std::string& text, const std::string& source,
                               BuildOptions build = {}, BuildReport* report = nullptr);
ProjectFile read_project_file(const std::string& path, const BuildOptions& build = {},
                              BuildReport* report = nullptr);

}  // namespace stitch
