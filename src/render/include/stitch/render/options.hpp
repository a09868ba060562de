// Parsing the renderer's command-line values, shared by `stitch render`, `stitch compare` and
// anything else that takes them. Every function throws stitch::UsageError with a message
// naming the bad value and what was expected.
#pragma once

#include <string>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/render/renderer.hpp"

namespace stitch {

struct ImageSize {
  int width = 0;
  int height = 0;
};

/// "WxH" with 1 <= W, H <= max_side.
ImageSize parse_image_size(const std::string& text, int max_side = 8192);
/// "x,y,z" of finite numbers; `what` names the option in messages.
Vec3 parse_point(const std::string& text, const std::string& what);
/// A comma-separated list of mesh, kgons, nets, ev, tess (the tessellation's quads); switches
/// those overlays on in `style`. An empty list shows nothing.
void parse_overlays(const std::string& list, RenderStyle& style);

}  // namespace stitch
