#include "stitch/render/renderer.hpp"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "shaders.hpp"
#include "stitch/error.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/tess/incremental_surface.hpp"

namespace stitch {

namespace {

struct SurfaceVertex {
  float position[3];
  float normal[3];
  std::int32_t patch;
  std::int32_t level;
};
static_assert(sizeof(SurfaceVertex) == 32);

struct LineVertex {
  float position[3];
  float colour[3];
  float width;  ///< factor of the line width (lines only; markers ignore it)
};

GLuint compile(GLenum type, const char* source, const char* name) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::array<char, 4096> log{};
    glGetShaderInfoLog(shader, log.size(), nullptr, log.data());
    glDeleteShader(shader);
    throw RenderError(fmt::format("compiling the {} shader failed: {}", name, log.data()));
  }
  return shader;
}

GLuint link(const char* name, const char* vertex, const char* fragment,
            const char* geometry = nullptr) {
  const GLuint program = glCreateProgram();
  std::array<GLuint, 3> shaders{compile(GL_VERTEX_SHADER, vertex, name),
                                compile(GL_FRAGMENT_SHADER, fragment, name),
                                geometry ? compile(GL_GEOMETRY_SHADER, geometry, name) : 0};
  for (const GLuint s : shaders) {
    if (s != 0) glAttachShader(program, s);
  }
  glLinkProgram(program);
  for (const GLuint s : shaders) {
    if (s != 0) glDeleteShader(s);
  }
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::array<char, 4096> log{};
    glGetProgramInfoLog(program, log.size(), nullptr, log.data());
    glDeleteProgram(program);
    throw RenderError(fmt::format("linking the {} shader program failed: {}", name, log.data()));
  }
  return program;
}

SurfaceVertex surface_vertex(const TessellatedMesh& s, int i) {
  SurfaceVertex v{};
  for (int k = 0; k < 3; ++k) {
    v.position[k] = static_cast<float>(s.positions[i][k]);
    v.normal[k] = static_cast<float>(s.normals[i][k]);
  }
  v.patch = i < static_cast<int>(s.patch.size()) ? s.patch[i] : 0;
  v.level = i < static_cast<int>(s.level.size()) ? s.level[i] : 0;
  return v;
}

void check_attributes(const TessellatedMesh& s) {
  const size_t n = s.positions.size();
  if (s.normals.size() != n || (!s.patch.empty() && s.patch.size() != n) ||
      (!s.level.empty() && s.level.size() != n)) {
    throw std::invalid_argument(
        fmt::format("surface mesh attributes disagree: {} positions, {} normals, {} patch ids, "
                    "{} levels",
                    n, s.normals.size(), s.patch.size(), s.level.size()));
  }
}

struct Buffer {
  GLuint vao = 0, vbo = 0, ebo = 0;
  GLsizei count = 0;

  void create(bool indexed) {
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    if (indexed) glGenBuffers(1, &ebo);
  }
  void destroy() {
    if (ebo != 0) glDeleteBuffers(1, &ebo);
    if (vbo != 0) glDeleteBuffers(1, &vbo);
    if (vao != 0) glDeleteVertexArrays(1, &vao);
    vao = vbo = ebo = 0;
  }
};

void upload_lines(Buffer& buffer, const std::vector<Vec3>& points,
                  const std::vector<Colour>& colours, bool per_segment_colour,
                  const std::vector<float>& widths = {}) {
  std::vector<LineVertex> data(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const size_t item = per_segment_colour ? i / 2 : i;
    const Colour& c = colours[item];
    for (int k = 0; k < 3; ++k) {
      data[i].position[k] = static_cast<float>(points[i][k]);
      data[i].colour[k] = c[k];
    }
    data[i].width = item < widths.size() ? widths[item] : 1.0f;
  }
  glBindVertexArray(buffer.vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(LineVertex)),
               data.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                        reinterpret_cast<void*>(offsetof(LineVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                        reinterpret_cast<void*>(offsetof(LineVertex, colour)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                        reinterpret_cast<void*>(offsetof(LineVertex, width)));
  glBindVertexArray(0);
  buffer.count = static_cast<GLsizei>(data.size());
}

void set_uniform(GLuint program, const char* name, const Eigen::Vector3f& v) {
  glUniform3f(glGetUniformLocation(program, name), v.x(), v.y(), v.z());
}
void set_uniform(GLuint program, const char* name, float v) {
  glUniform1f(glGetUniformLocation(program, name), v);
}

}  // namespace

ChoiceTable<ShadingMode> shading_mode_table() {
  static constexpr Choice<ShadingMode> kModes[] = {
      {"shaded", ShadingMode::shaded, "Blinn-Phong from the exact normals"},
      {"zebra", ShadingMode::zebra,
       "reflection lines of parallel stripes: kinks show breaks in G1"},
      {"isophote", ShadingMode::isophote, "bands of constant angle between normal and light"},
      {"levels", ShadingMode::levels, "colour by the hierarchy level a sample came from"},
      {"patches", ShadingMode::patches, "colour by patch"},
      {"checker", ShadingMode::checker,
       "shaded, on a checkerboard over the texture coordinates' unit square"},
  };
  return kModes;
}

ShadingMode parse_shading_mode(const std::string& name) {
  return parse_choice(shading_mode_table(), name, "mode");
}

std::string to_string(ShadingMode mode) {
  return std::string(choice_name(shading_mode_table(), mode));
}

std::vector<PatchRange> patch_vertex_ranges(const TessellatedMesh& surface) {
  std::vector<PatchRange> ranges;
  for (int i = 0; i < static_cast<int>(surface.patch.size()); ++i) {
    if (ranges.empty() || ranges.back().patch != surface.patch[i]) {
      ranges.push_back({surface.patch[i], i, 0});
    }
    ++ranges.back().num_vertices;
  }
  return ranges;
}

struct Renderer::Impl {
  GLuint surface_program = 0, line_program = 0, marker_program = 0;
  Buffer surface;
  // Texture coordinates beside the surface's vertex buffer (set_surface_texcoords), attribute 4
  // of its vertex array while `textured`.
  GLuint texcoord_vbo = 0;
  bool textured = false;
  int surface_vertices = 0;
  // A block surface (set_block_surface): block sizes and the blocks the buffers have room for;
  // zero for a plain surface.
  int block_vertices = 0, block_quads = 0, block_capacity = 0;
  std::array<Buffer, num_overlays> overlays;
  Buffer markers, marker_curves;
  // Where draw() puts each block of a SurfaceBlocks, and its tessellation lines: replaced block
  // after block, so they hold one block.
  Buffer block_surface, block_lines;
  GLuint block_texcoord_vbo = 0;

  Impl() {
    if (epoxy_gl_version() < 33) {
      throw RenderError("the renderer needs a current OpenGL 3.3 core context");
    }
    surface_program = link("surface", shaders::surface_vertex, shaders::surface_fragment);
    line_program =
        link("line", shaders::line_vertex, shaders::line_fragment, shaders::line_geometry);
    marker_program = link("marker", shaders::marker_vertex, shaders::marker_fragment);
    surface.create(true);
    glGenBuffers(1, &texcoord_vbo);
    for (Buffer& b : overlays) b.create(false);
    markers.create(false);
    marker_curves.create(false);
    block_surface.create(true);
    block_lines.create(false);
    glGenBuffers(1, &block_texcoord_vbo);
  }
  ~Impl() {
    surface.destroy();
    glDeleteBuffers(1, &texcoord_vbo);
    for (Buffer& b : overlays) b.destroy();
    markers.destroy();
    marker_curves.destroy();
    block_surface.destroy();
    block_lines.destroy();
    glDeleteBuffers(1, &block_texcoord_vbo);
    glDeleteProgram(surface_program);
    glDeleteProgram(line_program);
    glDeleteProgram(marker_program);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void drop_texcoords() {
    textured = false;
    glBindVertexArray(surface.vao);
    glDisableVertexAttribArray(4);
    glBindVertexArray(0);
  }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

namespace {

void check_quads(const TessellatedMesh& s) {
  for (const auto& q : s.quads)
    for (const int i : q)
      if (i < 0 || i >= s.num_vertices())
        throw std::out_of_range(
            fmt::format("surface quad refers to vertex {} of {}", i, s.num_vertices()));
}

std::vector<SurfaceVertex> surface_vertices(const TessellatedMesh& s, int first, int count) {
  std::vector<SurfaceVertex> vertices(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) vertices[i] = surface_vertex(s, first + i);
  return vertices;
}

// Both triangles of quads [first, first + count), degenerate ones included, split as every file
// and check splits them (quad_triangles). The split follows the positions given;
// update_surface_vertices moves vertices without rewriting it.
std::vector<std::uint32_t> block_triangles(const TessellatedMesh& s, int first, int count) {
  std::vector<std::uint32_t> indices;
  indices.reserve(static_cast<size_t>(count) * 6);
  for (int k = first; k < first + count; ++k)
    for (const auto& t : quad_triangles(s.quads[k], s.positions))
      for (const int i : t) indices.push_back(static_cast<std::uint32_t>(i));
  return indices;
}

// DYNAMIC_DRAW: the modeler rewrites ranges of edited patches. `capacity` bytes are allocated,
// the data fills the start.
void buffer_data(GLenum target, size_t capacity, size_t size, const void* data) {
  glBufferData(target, static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_DRAW);
  if (size > 0) glBufferSubData(target, 0, static_cast<GLsizeiptr>(size), data);
}

void set_surface_attributes() {
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(SurfaceVertex),
                        reinterpret_cast<void*>(offsetof(SurfaceVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(SurfaceVertex),
                        reinterpret_cast<void*>(offsetof(SurfaceVertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribIPointer(2, 1, GL_INT, sizeof(SurfaceVertex),
                         reinterpret_cast<void*>(offsetof(SurfaceVertex, patch)));
  glEnableVertexAttribArray(3);
  glVertexAttribIPointer(3, 1, GL_INT, sizeof(SurfaceVertex),
                         reinterpret_cast<void*>(offsetof(SurfaceVertex, level)));
}

// Vertices and triangles of `s` into `b`, exactly sized. Degenerate quads (a repeated index: the
// fans of input_faces) give one triangle.
void upload_surface(Buffer& b, const TessellatedMesh& s) {
  check_attributes(s);
  check_quads(s);
  const std::vector<SurfaceVertex> vertices = surface_vertices(s, 0, s.num_vertices());
  std::vector<std::uint32_t> indices;
  indices.reserve(s.quads.size() * 6);
  for (const auto& q : s.quads) {
    for (const auto& t : quad_triangles(q, s.positions)) {
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
      indices.insert(indices.end(), t.begin(), t.end());
    }
  }
  glBindVertexArray(b.vao);
  glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
  const size_t vertex_bytes = vertices.size() * sizeof(SurfaceVertex);
  buffer_data(GL_ARRAY_BUFFER, vertex_bytes, vertex_bytes, vertices.data());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ebo);
  const size_t index_bytes = indices.size() * sizeof(std::uint32_t);
  buffer_data(GL_ELEMENT_ARRAY_BUFFER, index_bytes, index_bytes, indices.data());
  set_surface_attributes();
  glBindVertexArray(0);
  b.count = static_cast<GLsizei>(indices.size());
}

// Texture coordinates as attribute 4 of the vertex array `vao`, from `vbo`.
void upload_texcoords(GLuint vao, GLuint vbo, const std::vector<Eigen::Vector2d>& texcoords) {
  std::vector<float> data(texcoords.size() * 2);
  for (size_t i = 0; i < texcoords.size(); ++i) {
    data[2 * i] = static_cast<float>(texcoords[i].x());
    data[2 * i + 1] = static_cast<float>(texcoords[i].y());
  }
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(4);
  glVertexAttribPointer(4, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glBindVertexArray(0);
}

}  // namespace

void Renderer::set_surface(const TessellatedMesh& s) {
  upload_surface(impl_->surface, s);
  impl_->surface_vertices = s.num_vertices();
  impl_->block_vertices = impl_->block_quads = impl_->block_capacity = 0;
  impl_->drop_texcoords();
}

void Renderer::set_block_surface(const TessellatedMesh& s, int vertices_per_block,
                                 int quads_per_block) {
  check_attributes(s);
  check_quads(s);
  if (vertices_per_block < 1 || quads_per_block < 1 || s.num_vertices() % vertices_per_block != 0 ||
      static_cast<int>(s.quads.size()) != s.num_vertices() / vertices_per_block * quads_per_block)
    throw std::invalid_argument(fmt::format(
        "a block surface of {} vertices and {} quads cannot have blocks of {} vertices and {} "
        "quads",
        s.num_vertices(), s.quads.size(), vertices_per_block, quads_per_block));
  const int blocks = s.num_vertices() / vertices_per_block;
  // Room for as many blocks as the incremental surface keeps room for: growing past it
  // re-uploads everything, so over a session that cost is spread thin, as for a std::vector.
  const int capacity = slot_capacity_for(blocks);
  const std::vector<SurfaceVertex> vertices = surface_vertices(s, 0, s.num_vertices());
  const std::vector<std::uint32_t> indices =
      block_triangles(s, 0, static_cast<int>(s.quads.size()));
  Buffer& b = impl_->surface;
  glBindVertexArray(b.vao);
  glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
  buffer_data(GL_ARRAY_BUFFER,
              static_cast<size_t>(capacity) * vertices_per_block * sizeof(SurfaceVertex),
              vertices.size() * sizeof(SurfaceVertex), vertices.data());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ebo);
  buffer_data(GL_ELEMENT_ARRAY_BUFFER,
              static_cast<size_t>(capacity) * quads_per_block * 6 * sizeof(std::uint32_t),
              indices.size() * sizeof(std::uint32_t), indices.data());
  set_surface_attributes();
  glBindVertexArray(0);
  b.count = static_cast<GLsizei>(indices.size());
  impl_->surface_vertices = s.num_vertices();
  impl_->block_vertices = vertices_per_block;
  impl_->block_quads = quads_per_block;
  impl_->block_capacity = capacity;
  impl_->drop_texcoords();
}

void Renderer::update_surface_blocks(const TessellatedMesh& s, std::vector<int> blocks) {
  Impl& r = *impl_;
  if (r.block_vertices == 0)
    throw std::logic_error("update_surface_blocks: no block surface has been uploaded");
  check_attributes(s);
  const int per_v = r.block_vertices, per_q = r.block_quads;
  if (s.num_vertices() % per_v != 0 ||
      static_cast<int>(s.quads.size()) != s.num_vertices() / per_v * per_q)
    throw std::invalid_argument("update_surface_blocks: the surface's blocks changed size");
  const int count = s.num_vertices() / per_v, old_count = r.surface_vertices / per_v;
  if (count > r.block_capacity) {
    set_block_surface(s, per_v, per_q);
    return;
  }
  for (int k = old_count; k < count; ++k) blocks.push_back(k);  // new blocks: all of them
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  glBindVertexArray(r.surface.vao);
  glBindBuffer(GL_ARRAY_BUFFER, r.surface.vbo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r.surface.ebo);
  for (size_t i = 0; i < blocks.size();) {  // one upload per run of consecutive blocks
    const int first = blocks[i];
    if (first < 0 || first >= count)
      throw std::out_of_range(
          fmt::format("update_surface_blocks: no block {} in a surface of {}", first, count));
    size_t n = 1;
    while (i + n < blocks.size() && blocks[i + n] == first + static_cast<int>(n)) ++n;
    const int run = static_cast<int>(std::min<size_t>(n, static_cast<size_t>(count - first)));
    const auto vertices = surface_vertices(s, first * per_v, run * per_v);
    glBufferSubData(
        GL_ARRAY_BUFFER,
        static_cast<GLintptr>(static_cast<size_t>(first) * per_v * sizeof(SurfaceVertex)),
        static_cast<GLsizeiptr>(vertices.size() * sizeof(SurfaceVertex)), vertices.data());
    const auto indices = block_triangles(s, first * per_q, run * per_q);
    glBufferSubData(
        GL_ELEMENT_ARRAY_BUFFER,
        static_cast<GLintptr>(static_cast<size_t>(first) * per_q * 6 * sizeof(std::uint32_t)),
        static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data());
    i += n;
  }
  glBindVertexArray(0);
  r.surface.count = static_cast<GLsizei>(static_cast<size_t>(count) * per_q * 6);
  r.surface_vertices = s.num_vertices();
  r.drop_texcoords();
}

void Renderer::set_surface_texcoords(const std::vector<Eigen::Vector2d>& texcoords) {
  Impl& r = *impl_;
  if (texcoords.size() != static_cast<size_t>(r.surface_vertices))
    throw std::invalid_argument(fmt::format("{} texture coordinates for a surface of {} vertices",
                                            texcoords.size(), r.surface_vertices));
  upload_texcoords(r.surface.vao, r.texcoord_vbo, texcoords);
  r.textured = true;
}

void Renderer::update_surface_vertices(const TessellatedMesh& s, int first, int count) {
  check_attributes(s);
  if (s.num_vertices() != impl_->surface_vertices || first < 0 || count < 0 ||
      first + count > s.num_vertices()) {
    throw std::out_of_range(
        fmt::format("cannot update vertices [{}, {}) of a surface of {} vertices (uploaded: {})",
                    first, first + count, s.num_vertices(), impl_->surface_vertices));
  }
  const std::vector<SurfaceVertex> vertices = surface_vertices(s, first, count);
  glBindBuffer(GL_ARRAY_BUFFER, impl_->surface.vbo);
  glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first * sizeof(SurfaceVertex)),
                  static_cast<GLsizeiptr>(count * sizeof(SurfaceVertex)), vertices.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::set_overlay(Overlay overlay, const LineSet& lines) {
  upload_lines(impl_->overlays[static_cast<int>(overlay)], lines.points, lines.colours, true,
               lines.widths);
}

void Renderer::set_markers(const MarkerSet& markers) {
  upload_lines(impl_->markers, markers.positions, markers.colours, false);
  upload_lines(impl_->marker_curves, markers.curves.points, markers.curves.colours, true,
               markers.curves.widths);
}

void Renderer::draw(const Camera& camera, const RenderStyle& style, int width, int height,
                    float pixel_scale, const SurfaceBlocks* blocks) const {
  // Non-const for the block buffers only, which hold nothing between calls.
  Impl& r = *impl_;
  const double aspect = static_cast<double>(width) / std::max(height, 1);
  const Eigen::Matrix4f view_projection = projection_matrix(camera, aspect) * view_matrix(camera);

  glViewport(0, 0, width, height);
  if (style.clear) {
    glClearColor(style.background.x(), style.background.y(), style.background.z(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);

  // Camera frame in world space, for lights and the zebra environment.
  const Eigen::Matrix4f view = view_matrix(camera);
  const Eigen::Vector3f right = view.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3f up = view.block<1, 3>(1, 0).transpose();
  const Eigen::Vector3f back = view.block<1, 3>(2, 0).transpose();

  const bool shade_blocks = blocks != nullptr && blocks->shaded;
  if (style.draw_surface && (shade_blocks || r.surface.count > 0)) {
    glUseProgram(r.surface_program);
    glUniformMatrix4fv(glGetUniformLocation(r.surface_program, "u_view_projection"), 1, GL_FALSE,
                       view_projection.data());
    glUniform1i(glGetUniformLocation(r.surface_program, "u_mode"), static_cast<int>(style.mode));
    set_uniform(r.surface_program, "u_eye", camera.eye.cast<float>());
    // Key light above-left of the camera.
    set_uniform(r.surface_program, "u_light", (back + 0.5f * up - 0.35f * right).normalized());
    // Stripe cylinder axis: the image's horizontal, tilted so that stripes are never parallel
    // to the axis-aligned edges of boxy models. Its poles (reflected rays along the axis) then
    // only appear near the left and right silhouettes, and close-ups tilted up or down (as
    // focus_camera makes) stay clear of them. x points at the viewer so the atan seam lies
    // behind the surface.
    const Eigen::Vector3f axis = (right + 0.35f * up).normalized();
    const Eigen::Vector3f sx = (back - back.dot(axis) * axis).normalized();
    set_uniform(r.surface_program, "u_stripe_x", sx);
    set_uniform(r.surface_program, "u_stripe_y", axis.cross(sx));
    set_uniform(r.surface_program, "u_stripes", static_cast<float>(style.stripes));
    set_uniform(r.surface_program, "u_base", style.surface_colour);
    set_uniform(r.surface_program, "u_checks", static_cast<float>(style.checks));
    set_uniform(r.surface_program, "u_checker", style.checker_colour);
    const GLint textured = glGetUniformLocation(r.surface_program, "u_textured");
    if (shade_blocks) {
      blocks->for_each(
          [&](const TessellatedMesh& block, const std::vector<Eigen::Vector2d>& texcoords) {
            upload_surface(r.block_surface, block);
            const bool has_texcoords = !texcoords.empty();
            if (has_texcoords) {
              if (texcoords.size() != block.positions.size())
                throw std::invalid_argument(
                    fmt::format("{} texture coordinates for a block of {} vertices",
                                texcoords.size(), block.positions.size()));
              upload_texcoords(r.block_surface.vao, r.block_texcoord_vbo, texcoords);
            } else {
              glBindVertexArray(r.block_surface.vao);
              glDisableVertexAttribArray(4);
            }
            glUniform1i(textured, has_texcoords ? 1 : 0);
            glBindVertexArray(r.block_surface.vao);
            glDrawElements(GL_TRIANGLES, r.block_surface.count, GL_UNSIGNED_INT, nullptr);
            // A driver may queue every block's draw with its data (llvmpipe did: 2.9 GB instead of
            // 0.6 GB for a 100k-quad torus at resolution 8), so each is done before the next.
            glFinish();
          });
    } else {
      glUniform1i(textured, r.textured ? 1 : 0);
      glBindVertexArray(r.surface.vao);
      glDrawElements(GL_TRIANGLES, r.surface.count, GL_UNSIGNED_INT, nullptr);
    }
  }

  // Overlays: parts behind the surface faintly, then the visible parts; no depth writes, so
  // overlays never hide each other.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glEnable(GL_PROGRAM_POINT_SIZE);
  const float depth_bias = 1e-3f;
  for (const bool hidden_pass : {true, false}) {
    const float alpha = hidden_pass ? style.hidden_alpha : 1.0f;
    if (alpha <= 0.0f) continue;
    glDepthFunc(hidden_pass ? GL_GREATER : GL_LEQUAL);
    glUseProgram(r.line_program);
    glUniformMatrix4fv(glGetUniformLocation(r.line_program, "u_view_projection"), 1, GL_FALSE,
                       view_projection.data());
    set_uniform(r.line_program, "u_depth_bias", depth_bias);
    glUniform2f(glGetUniformLocation(r.line_program, "u_viewport"), static_cast<float>(width),
                static_cast<float>(height));
    set_uniform(r.line_program, "u_alpha", alpha);
    for (int o = 0; o < num_overlays; ++o) {
      const bool tessellation = o == static_cast<int>(Overlay::tessellation);
      const bool from_blocks = tessellation && blocks != nullptr;
      if (!style.overlays[o] || (!from_blocks && r.overlays[o].count == 0)) continue;
      // The tessellation's quads are dense: thinner lines keep the surface visible.
      set_uniform(r.line_program, "u_width",
                  style.line_width_px * pixel_scale * (tessellation ? 0.6f : 1.0f));
      if (from_blocks) {
        blocks->for_each([&](const TessellatedMesh& block, const std::vector<Eigen::Vector2d>&) {
          const LineSet lines = surface_mesh_lines(block);
          upload_lines(r.block_lines, lines.points, lines.colours, true, lines.widths);
          glBindVertexArray(r.block_lines.vao);
          glDrawArrays(GL_LINES, 0, r.block_lines.count);
          glFinish();  // as for the surface's blocks
        });
        continue;
      }
      glBindVertexArray(r.overlays[o].vao);
      glDrawArrays(GL_LINES, 0, r.overlays[o].count);
    }
    if (style.markers && r.marker_curves.count > 0) {
      set_uniform(r.line_program, "u_width", style.line_width_px * pixel_scale);
      glBindVertexArray(r.marker_curves.vao);
      glDrawArrays(GL_LINES, 0, r.marker_curves.count);
    }
    if (style.markers && r.markers.count > 0) {
      glUseProgram(r.marker_program);
      glUniformMatrix4fv(glGetUniformLocation(r.marker_program, "u_view_projection"), 1, GL_FALSE,
                         view_projection.data());
      set_uniform(r.marker_program, "u_depth_bias", depth_bias);
      set_uniform(r.marker_program, "u_size", style.marker_size_px * pixel_scale);
      set_uniform(r.marker_program, "u_alpha", alpha);
      glBindVertexArray(r.markers.vao);
      glDrawArrays(GL_POINTS, 0, r.markers.count);
    }
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_BLEND);
}

}  // namespace stitch
