// glTF 2.0 in and out, through tinygltf (its implementation is compiled here). In: glTF splits a
// vertex wherever one of its attributes differs (a normal or UV seam), so the triangles are
// welded by position like STL's, and TEXCOORD_0 stays per corner; node transforms are applied,
// images are not loaded. Out: one mesh of triangles with float attributes, .glb or .gltf + .bin,
// streamed block by block.
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "mesh/mesh_reader.hpp"
#include "mesh/writer_kit.hpp"
// tinygltf is header-only; this file holds its implementation. Images are never written.
#define TINYGLTF_IMPLEMENTATION
#include "mesh/tinygltf.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch::detail {

namespace {

using Triangles = std::vector<std::array<Vec3, 3>>;
using TriangleUvs = std::vector<std::array<Eigen::Vector2d, 3>>;

// glTF stores little-endian floats; they are copied as they are.
static_assert(std::endian::native == std::endian::little,
              "the glTF reader needs a little-endian host");

/// Node transforms deeper than this are refused: a node hierarchy is a forest, and a file whose
/// children lead back to an ancestor would recurse forever.
constexpr int kMostNodeDepth = 256;

class Reader {
 public:
  Reader(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

  Triangles triangles() {
    if (model_.scenes.empty()) {  // no scene: every mesh as it is
      for (size_t m = 0; m < model_.meshes.size(); ++m)
        add_mesh(static_cast<int>(m), Eigen::Affine3d::Identity());
    } else {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (scene >= static_cast<int>(model_.scenes.size()))
        throw error(fmt::format("the default scene {} does not exist", scene));
      for (int node : model_.scenes[scene].nodes) add_node(node, Eigen::Affine3d::Identity(), 0);
    }
    return std::move(triangles_);
  }

  /// TEXCOORD_0 of every triangle corner (call after triangles()); empty unless every primitive
  /// has it.
  TriangleUvs uvs(std::vector<std::string>* warnings) {
    if (primitives_with_uv_ > 0 && primitives_without_uv_ > 0) {
      if (warnings)
        warnings->push_back(
            fmt::format("{}: ignoring TEXCOORD_0: {} primitive(s) have it but {} do not", path_,
                        primitives_with_uv_, primitives_without_uv_));
      return {};
    }
    return std::move(uvs_);
  }

 private:
  InputError error(const std::string& what) const {
    return InputError(fmt::format("{}: {}", path_, what));
  }

  void add_node(int index, const Eigen::Affine3d& parent, int depth) {
    if (index < 0 || index >= static_cast<int>(model_.nodes.size()))
      throw error(fmt::format("node {} does not exist", index));
    if (depth > kMostNodeDepth)
      throw error(fmt::format("nodes nest deeper than {} (a cycle?)", kMostNodeDepth));
    const tinygltf::Node& node = model_.nodes[index];
    Eigen::Affine3d local = Eigen::Affine3d::Identity();
    if (node.matrix.size() == 16) {
      Eigen::Matrix4d m;
      for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = node.matrix[i];  // column-major
      local.matrix() = m;
    } else {
      if (node.translation.size() == 3)
        local.translate(Vec3(node.translation[0], node.translation[1], node.translation[2]));
      if (node.rotation.size() == 4)  // glTF stores x, y, z, w
        local.rotate(Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1],
                                        node.rotation[2])
                         .normalized());
      if (node.scale.size() == 3) local.scale(Vec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    const Eigen::Affine3d world = parent * local;
    if (node.mesh >= 0) add_mesh(node.mesh, world);
    for (int child : node.children) add_node(child, world, depth + 1);
  }

  void add_mesh(int index, const Eigen::Affine3d& world) {
    if (index >= static_cast<int>(model_.meshes.size()))
      throw error(fmt::format("mesh {} does not exist", index));
    const tinygltf::Mesh& mesh = model_.meshes[index];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      const std::string where = fmt::format("mesh {} primitive {}", index, p);
      if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1)
        throw error(fmt::format("{} draws mode {}; only triangles (mode 4) are read", where,
                                primitive.mode));
      const auto position = primitive.attributes.find("POSITION");
      if (position == primitive.attributes.end())
        throw error(fmt::format("{} has no POSITION", where));
      const std::vector<Vec3> points = positions(position->second, where);
      std::vector<std::int64_t> corners;
      if (primitive.indices >= 0) {
        corners = indices(primitive.indices, where);
      } else {
        corners.resize(points.size());
        for (size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<std::int64_t>(i);
      }
      if (corners.size() % 3 != 0)
        throw error(
            fmt::format("{}: {} corners do not make whole triangles", where, corners.size()));
      std::vector<Eigen::Vector2d> texcoords;
      if (const auto t = primitive.attributes.find("TEXCOORD_0"); t != primitive.attributes.end()) {
        texcoords = texcoords_of(t->second, where);
        if (texcoords.size() != points.size())
          throw error(fmt::format("{}: {} TEXCOORD_0 values for {} positions", where,
                                  texcoords.size(), points.size()));
        ++primitives_with_uv_;
      } else {
        ++primitives_without_uv_;
      }
      for (size_t t = 0; t < corners.size(); t += 3) {
        std::array<Vec3, 3> triangle;
        for (int k = 0; k < 3; ++k) {
          const std::int64_t at = corners[t + k];
          if (at < 0 || at >= static_cast<std::int64_t>(points.size()))
            throw error(
                fmt::format("{}: index {} is past its {} positions", where, at, points.size()));
          triangle[k] = world * points[static_cast<size_t>(at)];
          limits::check_coordinates(triangle[k], fmt::format("{}: {}", path_, where));
        }
        triangles_.push_back(triangle);
        if (!texcoords.empty())
          uvs_.push_back({texcoords[static_cast<size_t>(corners[t])],
                          texcoords[static_cast<size_t>(corners[t + 1])],
                          texcoords[static_cast<size_t>(corners[t + 2])]});
      }
    }
  }

  /// The bytes of element i of an accessor, checked against its buffer.
  const unsigned char* element(const tinygltf::Accessor& accessor, size_t i, size_t size,
                               const std::string& where) const {
    if (accessor.sparse.isSparse) throw error(where + ": sparse accessors are not read");
    if (accessor.bufferView < 0 ||
        accessor.bufferView >= static_cast<int>(model_.bufferViews.size()))
      throw error(where + ": an accessor without a buffer view");
    const tinygltf::BufferView& view = model_.bufferViews[accessor.bufferView];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size()))
      throw error(where + ": a buffer view without a buffer");
    const std::vector<unsigned char>& data = model_.buffers[view.buffer].data;
    const size_t stride = view.byteStride > 0 ? view.byteStride : size;
    const size_t start = view.byteOffset + accessor.byteOffset + i * stride;
    if (start + size > view.byteOffset + view.byteLength || start + size > data.size())
      throw error(where + ": an accessor reaches past its buffer");
    return data.data() + start;
  }

  /// The accessor `index`, checked to exist and to fit its buffer with elements of `size` bytes
  /// (before anything is allocated for its `count`, which the file may set to anything).
  const tinygltf::Accessor& accessor(int index, size_t size, const std::string& where) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
      throw error(fmt::format("{}: accessor {} does not exist", where, index));
    const tinygltf::Accessor& a = model_.accessors[static_cast<size_t>(index)];
    if (a.count > 0) {
      if (a.bufferView >= 0 && a.bufferView < static_cast<int>(model_.bufferViews.size()) &&
          a.count > model_.bufferViews[a.bufferView].byteLength)
        throw error(fmt::format("{}: accessor {} has more elements than bytes", where, index));
      element(a, a.count - 1, size, where);  // the last one fits, so all do
    }
    return a;
  }

  std::vector<Vec3> positions(int index, const std::string& where) const {
    const tinygltf::Accessor& a = accessor(index, sizeof(float[3]), where);
    if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      throw error(where + ": POSITION is not float VEC3");
    std::vector<Vec3> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
      std::array<float, 3> xyz;
      std::memcpy(xyz.data(), element(a, i, sizeof xyz, where), sizeof xyz);
      out[i] = Vec3(xyz[0], xyz[1], xyz[2]);
    }
    return out;
  }

  /// TEXCOORD_0 with v flipped (glTF's origin is the top left corner, OBJ's and stitch's the
  /// bottom left): float, or unsigned byte or short normalized, as the specification allows.
  std::vector<Eigen::Vector2d> texcoords_of(int index, const std::string& where) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
      throw error(fmt::format("{}: its TEXCOORD_0 accessor {} does not exist", where, index));
    const tinygltf::Accessor& head = model_.accessors[static_cast<size_t>(index)];
    const int type = head.componentType;
    const size_t size = type == TINYGLTF_COMPONENT_TYPE_FLOAT            ? 4
                        : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                        : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 1
                                                                         : 0;
    if (size == 0 || head.type != TINYGLTF_TYPE_VEC2 || (size < 4 && !head.normalized))
      throw error(where + ": TEXCOORD_0 is not float or normalized unsigned byte or short VEC2");
    const tinygltf::Accessor& a = accessor(index, 2 * size, where);
    std::vector<Eigen::Vector2d> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
      const unsigned char* bytes = element(a, i, 2 * size, where);
      std::array<double, 2> st{};
      for (int k = 0; k < 2; ++k) {
        if (size == 4) {
          float f = 0;
          std::memcpy(&f, bytes + 4 * k, 4);
          st[k] = f;
        } else {
          std::uint32_t raw = 0;
          for (size_t b = size; b-- > 0;) raw = (raw << 8) | bytes[size * k + b];
          st[k] = static_cast<double>(raw) / (size == 1 ? 255.0 : 65535.0);
        }
      }
      if (!std::isfinite(st[0]) || !std::isfinite(st[1]))
        throw error(fmt::format("{}: TEXCOORD_0 {} is not finite", where, i));
      out[i] = Eigen::Vector2d(st[0], 1.0 - st[1]);
    }
    return out;
  }

  std::vector<std::int64_t> indices(int index, const std::string& where) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
      throw error(fmt::format("{}: its indices accessor {} does not exist", where, index));
    const int type = model_.accessors[static_cast<size_t>(index)].componentType;
    const size_t size = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                        : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                        : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                         : 0;
    if (size == 0) throw error(where + ": indices are not unsigned byte, short or int");
    const tinygltf::Accessor& a = accessor(index, size, where);
    if (a.type != TINYGLTF_TYPE_SCALAR) throw error(where + ": indices are not scalars");
    std::vector<std::int64_t> out(a.count);
    for (size_t i = 0; i < a.count; ++i) {
      const unsigned char* bytes = element(a, i, size, where);
      std::uint32_t value = 0;  // little-endian, as glTF stores it
      for (size_t b = size; b-- > 0;) value = (value << 8) | bytes[b];
      out[i] = value;
    }
    return out;
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  Triangles triangles_;
  TriangleUvs uvs_;  ///< per triangle of triangles_, while every primitive so far had TEXCOORD_0
  int primitives_with_uv_ = 0, primitives_without_uv_ = 0;
};

/// tinygltf's file access for external buffers, without opening anything to test existence (a
/// pipe would block) and reading through read_regular_file: a .gltf whose buffer names a pipe or
/// a device is refused like any other input, not read forever.
bool buffer_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

bool read_buffer_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                      void*) {
  try {
    const std::string bytes = read_regular_file(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const Error& e) {
    *err = e.what();
    return false;
  }
}

}  // namespace

PolygonSoup read_gltf(std::string_view text, const std::string& path,
                      std::vector<std::string>* warnings) {
  tinygltf::TinyGLTF loader;
  // Textures have nothing to do with the surface: images are neither decoded nor refused.
  loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                           const unsigned char*, int, void*) { return true; },
                        nullptr);
  loader.SetFsCallbacks({&buffer_file_exists, &tinygltf::ExpandFilePath, &read_buffer_file,
                         &tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const std::string folder = std::filesystem::path(path).parent_path().string();
  const bool binary = text.size() >= 4 && text.substr(0, 4) == "glTF";
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(text.data()),
                                           static_cast<unsigned int>(text.size()), folder)
             : loader.LoadASCIIFromString(&model, &err, &warn, text.data(),
                                          static_cast<unsigned int>(text.size()), folder);
  if (!ok)
    throw InputError(fmt::format("{}: not a glTF 2.0 file tinygltf can read: {}", path,
                                 limits::quoted(err.empty() ? warn : err)));
  if (!warn.empty() && warnings)
    warnings->push_back(fmt::format("{}: {}", path, limits::quoted(warn)));
  Reader reader(model, path);
  const Triangles triangles = reader.triangles();
  const TriangleUvs uvs = reader.uvs(warnings);
  if (uvs.empty()) return weld_triangles(triangles, {}, path, warnings);
  // Welding drops collapsed triangles; numbering them as "lines" tells which ones are left.
  std::vector<int> numbers(triangles.size());
  for (size_t t = 0; t < numbers.size(); ++t) numbers[t] = static_cast<int>(t) + 1;
  PolygonSoup soup = weld_triangles(triangles, numbers, path, warnings);
  // glTF also splits vertices for normals: corners of one welded vertex with equal
  // coordinates share one index, so that only real UV seams part the texture.
  std::map<std::pair<int, std::pair<double, double>>, int> shared;
  soup.face_uvs.resize(soup.faces.size());
  for (size_t f = 0; f < soup.faces.size(); ++f) {
    const auto& corners = uvs[static_cast<size_t>(soup.face_lines[f] - 1)];
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] = shared.try_emplace(
          {soup.faces[f][k], {corners[k].x(), corners[k].y()}}, static_cast<int>(soup.uvs.size()));
      if (fresh) soup.uvs.push_back(corners[k]);
      soup.face_uvs[f].push_back(it->second);
    }
    soup.face_lines[f] = 0;  // glTF has no lines
  }
  return soup;
}

// --- writing ---

namespace {

/// Bytes of each of the buffer's views, in the order the buffer holds them.
struct BufferViews {
  std::int64_t positions = 0, normals = 0, texcoords = 0, indices = 0;
  [[nodiscard]] std::int64_t total() const { return positions + normals + texcoords + indices; }
};

BufferViews buffer_views(const MeshStream& mesh) {
  return {12 * mesh.num_vertices, mesh.has_normals ? 12 * mesh.num_vertices : 0,
          8 * mesh.num_texcoords, 12 * mesh.triangles};
}

/// The smallest and the largest coordinates of the positions as floats (POSITION's min and max).
using Bounds = std::array<std::array<double, 3>, 2>;

/// Reads every vertex for its bounds, blocks in parallel, folded in the blocks' order: a min of
/// 0.0 and -0.0 keeps the first, as a pass in order would.
Bounds position_bounds(const MeshStream& mesh, Progress& progress) {
  const std::int64_t blocks = (mesh.num_vertices + kVerticesPerBlock - 1) / kVerticesPerBlock;
  constexpr std::int64_t kBlocksPerRound = 256;  // then progress is told
  std::vector<Bounds> found(static_cast<size_t>(std::min(blocks, kBlocksPerRound)));
  tbb::enumerable_thread_specific<VertexBlock> scratch;
  Bounds bounds{{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}}};
  const auto fold = [](Bounds& into, int k, double x) {
    into[0][k] = std::min(into[0][k], x);
    into[1][k] = std::max(into[1][k], x);
  };
  for (std::int64_t round = 0; round < blocks; round += kBlocksPerRound) {
    const std::int64_t last = std::min(blocks, round + kBlocksPerRound);
    tbb::parallel_for(round, last, [&](std::int64_t b) {
      const std::int64_t begin = b * kVerticesPerBlock;
      const std::int64_t end = std::min(mesh.num_vertices, begin + kVerticesPerBlock);
      VertexBlock& block = scratch.local();
      mesh.vertices(begin, end, block);
      Bounds& box = found[static_cast<size_t>(b - round)];
      box = {{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}}};
      for (const Vec3& p : block.positions)
        for (int k = 0; k < 3; ++k) fold(box, k, static_cast<double>(static_cast<float>(p[k])));
    });
    for (std::int64_t b = round; b < last; ++b)
      for (int k = 0; k < 3; ++k)
        for (const double x : {found[static_cast<size_t>(b - round)][0][k],
                               found[static_cast<size_t>(b - round)][1][k]})
          fold(bounds, k, x);
    progress(std::min(mesh.num_vertices, last * kVerticesPerBlock) - round * kVerticesPerBlock);
  }
  return bounds;
}

int add_view(tinygltf::Model& model, std::int64_t& offset, std::int64_t bytes, int target) {
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = static_cast<size_t>(offset);
  view.byteLength = static_cast<size_t>(bytes);
  view.target = target;
  offset += bytes;
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, std::int64_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component;
  accessor.type = type;
  accessor.count = static_cast<size_t>(count);
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

/// The file's JSON as tinygltf writes it (one line in a .glb, indented by 2 in a .gltf), with
/// `buffer` as the buffer's entry: tinygltf describes views and accessors, the buffer's bytes
/// are written apart.
std::string gltf_json(const MeshStream& mesh, const Bounds& bounds, const nlohmann::json& buffer,
                      bool binary) {
  const BufferViews bytes = buffer_views(mesh);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "stitch (bicubic Bezier patches, modified de Casteljau)";
  model.buffers.emplace_back();
  std::int64_t offset = 0;
  const int position_view = add_view(model, offset, bytes.positions, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int normal_view =
      mesh.has_normals ? add_view(model, offset, bytes.normals, TINYGLTF_TARGET_ARRAY_BUFFER) : -1;
  const int texcoord_view = mesh.num_texcoords > 0 ? add_view(model, offset, bytes.texcoords,
                                                              TINYGLTF_TARGET_ARRAY_BUFFER)
                                                   : -1;
  const int index_view =
      add_view(model, offset, bytes.indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

  const std::int64_t nv = mesh.num_vertices;
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      add_accessor(model, position_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
  model.accessors.back().minValues.assign(bounds[0].begin(), bounds[0].end());
  model.accessors.back().maxValues.assign(bounds[1].begin(), bounds[1].end());
  if (normal_view >= 0)
    primitive.attributes["NORMAL"] =
        add_accessor(model, normal_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
  if (texcoord_view >= 0)
    primitive.attributes["TEXCOORD_0"] =
        add_accessor(model, texcoord_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, nv);
  primitive.indices = add_accessor(model, index_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                   TINYGLTF_TYPE_SCALAR, 3 * mesh.triangles);
  tinygltf::Mesh gltf_mesh;
  gltf_mesh.name = "stitch surface";
  gltf_mesh.primitives.push_back(primitive);
  model.meshes.push_back(gltf_mesh);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  std::ostringstream text;
  if (!tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, text, false, false))
    throw OutputError("glTF serialization failed");
  nlohmann::json doc = nlohmann::json::parse(text.str());
  doc["buffers"][0] = buffer;
  return binary ? doc.dump() : doc.dump(2) + '\n';
}

/// The buffer's views one after another, each streamed from the mesh: positions and normals as
/// floats (normals normalized again after rounding, so that they are unit to float precision, as
/// the specification asks), texture coordinates with v down from the top, triangle indices.
void write_buffer(OutputFile& out, const MeshStream& mesh, const std::vector<Vec3>& positions,
                  Progress& progress) {
  write_vertices(
      out, mesh,
      [](const VertexBlock& block, OutputBuffer& bytes) {
        LittleEndianWriter record(bytes, 12 * block.positions.size());
        for (const Vec3& p : block.positions) record.put(Eigen::Vector3f(p.cast<float>()));
      },
      progress);
  if (mesh.has_normals)
    write_vertices(
        out, mesh,
        [](const VertexBlock& block, OutputBuffer& bytes) {
          LittleEndianWriter record(bytes, 12 * block.normals.size());
          for (const Vec3& n : block.normals)
            record.put(Eigen::Vector3f(n.cast<float>().normalized()));
        },
        progress);
  if (mesh.num_texcoords > 0)
    write_records<std::vector<Eigen::Vector2d>>(
        out, mesh.num_texcoords, kVerticesPerBlock, mesh.texcoords,
        [](const std::vector<Eigen::Vector2d>& block, OutputBuffer& bytes) {
          LittleEndianWriter record(bytes, 8 * block.size());
          for (const Eigen::Vector2d& uv : block) {
            record.put(static_cast<float>(uv.x()));
            record.put(static_cast<float>(1.0 - uv.y()));
          }
        },
        progress);
  write_triangles(
      out, mesh, positions,
      [](const TriangleBlock& block, OutputBuffer& bytes) {
        LittleEndianWriter record(bytes, 4 * block.indices.size());
        for (const int v : block.indices) record.put(static_cast<std::uint32_t>(v));
      },
      progress);
}

/// The .glb container: a 12-byte header, the JSON chunk padded with spaces, the BIN chunk.
void write_glb(const std::string& path, const MeshStream& mesh, const std::vector<Vec3>& positions,
               const std::string& json, Progress& progress) {
  const std::int64_t bin = buffer_views(mesh).total();  // whole 4-byte words: no padding
  const std::string content = json + std::string((4 - json.size() % 4) % 4, ' ');
  const std::int64_t length = 12 + 8 + static_cast<std::int64_t>(content.size()) + 8 + bin;
  if (length > std::numeric_limits<std::uint32_t>::max())
    throw OutputError(fmt::format(
        "cannot write {}: {:.2f} GB is more than a .glb can hold (4.29 GB); write .gltf (its "
        "buffer in a .bin has no such limit) or lower the resolution",
        path, static_cast<double>(length) / 1e9));
  write_mesh_file(path, [&](OutputFile& out) {
    OutputBuffer header;
    LittleEndianWriter words(header, 20);
    for (const std::uint32_t word :
         {0x46546C67u /* "glTF" */, 2u, static_cast<std::uint32_t>(length),
          static_cast<std::uint32_t>(content.size()), 0x4E4F534Au /* "JSON" */})
      words.put(word);
    out.write(header.data(), header.size());
    out << content;
    header.clear();
    LittleEndianWriter chunk(header, 8);
    chunk.put(static_cast<std::uint32_t>(bin));
    chunk.put(0x004E4942u);  // "BIN\0"
    out.write(header.data(), header.size());
    write_buffer(out, mesh, positions, progress);
  });
}

}  // namespace

void write_gltf(const std::string& path, const MeshStream& mesh, const std::vector<Vec3>& positions,
                bool binary, const WriteProgress& report) {
  if (mesh.num_vertices == 0 || mesh.num_faces == 0)
    throw OutputError(fmt::format("cannot write {}: the surface is empty", path));
  if (mesh.num_texcoords > 0 && mesh.num_texcoords != mesh.num_vertices)
    throw OutputError(fmt::format("cannot write {}: {} texture coordinates for {} vertices", path,
                                  mesh.num_texcoords, mesh.num_vertices));
  // The bounds pass, the vertices once per attribute, the faces.
  Progress progress(
      report, (mesh.has_normals ? 3 : 2) * mesh.num_vertices + mesh.num_texcoords + mesh.num_faces);
  const Bounds bounds = position_bounds(mesh, progress);
  const std::int64_t bytes = buffer_views(mesh).total();
  if (binary) {
    write_glb(path, mesh, positions, gltf_json(mesh, bounds, {{"byteLength", bytes}}, true),
              progress);
    return;
  }
  const std::filesystem::path bin_path = std::filesystem::path(path).replace_extension(".bin");
  const std::string json = gltf_json(
      mesh, bounds, {{"byteLength", bytes}, {"uri", bin_path.filename().string()}}, false);
  // The buffer is written under a name of its own first and takes its final name only once the
  // .gltf is in place: a failure leaves neither file changed (an earlier .bin included).
  const std::filesystem::path staged =
      bin_path.parent_path() / ("." + bin_path.filename().string() + ".staged");
  write_mesh_file(
      staged.string(), [&](OutputFile& out) { write_buffer(out, mesh, positions, progress); },
      bin_path.string());
  std::error_code ec;
  try {
    write_mesh_file(path, [&](OutputFile& out) { out << json; });
  } catch (...) {
    std::filesystem::remove(staged, ec);
    throw;
  }
  std::filesystem::rename(staged, bin_path, ec);
  if (ec) {
    std::filesystem::remove(staged, ec);
    throw OutputError(fmt::format("cannot write {}: {}", bin_path.string(), ec.message()));
  }
}

}  // namespace stitch::detail
