// Draws a tessellated surface and its overlays into the current OpenGL 3.3 core context.
//
// The Renderer owns GPU buffers and shaders but no context and no framebuffer: it draws into
// whatever framebuffer is bound (an offscreen target from image.hpp, or the modeler's window).
// Create, use and destroy it with the same context current.
//
// Surface buffers are laid out for partial updates: the vertex buffer is the TessellatedMesh's own
// vertex array, so a tessellation with one contiguous vertex block per patch (tessellate with
// welded = false) lets an editor re-upload only the patches it changed (patch_vertex_ranges +
// update_surface_vertices). A block surface (set_block_surface) also gives each block its own
// range of the index buffer, so blocks can appear and disappear (update_surface_blocks).
// A surface too large to hold is drawn from SurfaceBlocks instead: tessellated, uploaded and drawn
// one block at a time, the depth buffer making the result independent of the blocks.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stitch/choices.hpp"
#include "stitch/render/camera.hpp"
#include "stitch/render/overlays.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

enum class ShadingMode {
  shaded,    ///< Blinn-Phong from the analytic normals
  zebra,     ///< reflection lines of an environment of parallel stripes
  isophote,  ///< bands of constant angle between normal and light
  levels,    ///< colour by hierarchy level of the sub-patch a sample came from
  patches,   ///< colour by patch
  /// shaded, on a checkerboard over the texture's unit square (Renderer::set_surface_texcoords);
  /// a surface without texture coordinates is drawn as in `shaded`
  checker,
};

/// The shading modes by name (shaded first: the default), for `render --mode`, the modeler's
/// menu and its `mode` line.
ChoiceTable<ShadingMode> shading_mode_table();
/// Parses a name of shading_mode_table(); throws UsageError naming the known ones.
ShadingMode parse_shading_mode(const std::string& name);
std::string to_string(ShadingMode mode);

enum class Overlay { mesh, kgons, nets, tessellation };
inline constexpr int num_overlays = 4;

struct RenderStyle {
  ShadingMode mode = ShadingMode::shaded;
  bool draw_surface = true;
  /// Clear colour and depth first; an application drawing its own things underneath turns
  /// this off (depth must then be cleared by it).
  bool clear = true;
  std::array<bool, num_overlays> overlays{};  ///< indexed by Overlay
  bool markers = false;  ///< extraordinary points and the sharp curves (MarkerSet::curves)
  int stripes = 16;      ///< zebra stripes around the full circle / isophote bands
  int checks = 8;        ///< checker squares along each side of the texture's unit square
  Colour background{1.0f, 1.0f, 1.0f};
  Colour surface_colour{0.80f, 0.82f, 0.86f};
  /// The checker's other squares (surface_colour are the first): far from it in hue and
  /// brightness, so the two stay apart in shadow and highlight alike.
  Colour checker_colour{0.85f, 0.38f, 0.12f};
  float line_width_px = 1.5f;
  float marker_size_px = 9.0f;
  /// Opacity of overlay parts hidden behind the surface (0 hides them).
  float hidden_alpha = 0.25f;

  [[nodiscard]] bool shows(Overlay o) const { return overlays[static_cast<int>(o)]; }
  void show(Overlay o, bool on = true) { overlays[static_cast<int>(o)] = on; }
};

/// Vertex ranges of a tessellation, one per maximal run of equal TessellatedMesh::patch values.
struct PatchRange {
  int patch = -1;
  int first_vertex = 0;
  int num_vertices = 0;
};
std::vector<PatchRange> patch_vertex_ranges(const TessellatedMesh& surface);

/// Called for each block of a SurfaceBlocks: the block (its quads numbering its own vertices,
/// with patch ids and levels for those modes) and its texture coordinates (empty, or one per
/// vertex).
using SurfaceBlockVisitor = std::function<void(const TessellatedMesh& block,
                                               const std::vector<Eigen::Vector2d>& texcoords)>;

/// A surface produced block by block each time it is drawn (Renderer::draw), so that neither it
/// nor its GPU buffers are ever held whole: blocks are drawn in the order given, with the same
/// triangles in the same order as one upload of them all would draw, hence the same pixels.
struct SurfaceBlocks {
  /// Calls the visitor for each block, in order.
  std::function<void(const SurfaceBlockVisitor&)> for_each;
  /// Shade the blocks in place of the uploaded surface (RenderStyle::draw_surface); false: the
  /// uploaded surface is shaded (e.g. the input polygons) and the blocks give the tessellation
  /// overlay only.
  bool shaded = true;
};

class Renderer {
 public:
  /// Compiles the shaders; needs a current GL >= 3.3 core context. Throws RenderError.
  Renderer();
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Uploads vertices and quads (replacing any previous surface).
  void set_surface(const TessellatedMesh& surface);
  /// Re-uploads vertices [first, first + count) of `surface`, which must have the same vertex
  /// count and quads as the one given to set_surface. Throws std::out_of_range.
  void update_surface_vertices(const TessellatedMesh& surface, int first, int count);
  /// Uploads a surface made of equal blocks (`quads_per_block` quads over `vertices_per_block`
  /// vertices each, in block order: IncrementalSurface's layout) so that blocks can later
  /// be replaced one at a time: every quad keeps both triangles in the index buffer (the
  /// degenerate quads of an empty block draw nothing), and the buffers keep room to grow.
  /// Throws std::invalid_argument when the sizes do not divide into blocks.
  void set_block_surface(const TessellatedMesh& surface, int vertices_per_block,
                         int quads_per_block);
  /// Brings the uploaded block surface to `surface` by re-uploading the listed blocks (vertices
  /// and triangles) and any blocks added at the end; blocks removed at the end stop being
  /// drawn. Past the room kept it uploads everything again, with more room. Throws
  /// std::logic_error without a block surface, std::invalid_argument when the block sizes
  /// differ, std::out_of_range for a block the surface does not have.
  void update_surface_blocks(const TessellatedMesh& surface, std::vector<int> blocks);
  /// Texture coordinates of the uploaded surface's vertices, for ShadingMode::checker. They live
  /// in a buffer of their own, so the surface's vertex layout, its partial updates and the other
  /// modes do not change. set_surface, set_block_surface and update_surface_blocks drop them
  /// (the vertices they describe may be gone). Throws std::invalid_argument when the count is
  /// not the uploaded surface's vertex count.
  void set_surface_texcoords(const std::vector<Eigen::Vector2d>& texcoords);
  void set_overlay(Overlay overlay, const LineSet& lines);
  void set_markers(const MarkerSet& markers);

  /// Clears and draws into the currently bound framebuffer, viewport (0, 0, width, height).
  /// `pixel_scale` multiplies line widths and marker sizes (for supersampled targets). With
  /// `blocks`, the surface (when blocks->shaded) and the tessellation overlay are drawn from them
  /// block by block, each block uploaded into buffers kept for the purpose and replaced by the
  /// next, in place of the uploaded ones.
  void draw(const Camera& camera, const RenderStyle& style, int width, int height,
            float pixel_scale = 1.0f, const SurfaceBlocks* blocks = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stitch
