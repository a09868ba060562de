// glTF 2.0 in and out, through tinygltf (its implementation is compiled here). In: glTF splits a
// vertex wherever one of its attributes differs (a normal or UV seam), so the triangles are
// welded by position like STL's, and TEXCOORD_0 stays per corner; node transforms are applied,
// images are not loaded. Out: one mesh of triangles with float attributes, .glb or .gltf + .bin.
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
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

/// Appends the bytes of `values` to the buffer as a new view and returns the view's index.
template <class T>
int add_view(tinygltf::Model& model, const std::vector<T>& values, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  data.resize(data.size() + view.byteLength);
  std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

/// glTF stores 32-bit floats; the normals are normalized again after rounding so that they are
/// unit to float precision, as the specification asks.
tinygltf::Model make_model(const MeshStream& mesh, const std::vector<Vec3>& points) {
  const auto nv = static_cast<size_t>(mesh.num_vertices);
  std::vector<float> positions(3 * nv), normals(mesh.has_normals ? 3 * nv : 0);
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  VertexBlock vertices;
  for (std::int64_t begin = 0; begin < mesh.num_vertices; begin += kVerticesPerBlock) {
    const std::int64_t end = std::min(mesh.num_vertices, begin + kVerticesPerBlock);
    mesh.vertices(begin, end, vertices);
    for (std::int64_t v = begin; v < end; ++v) {
      const auto i = static_cast<size_t>(v), b = static_cast<size_t>(v - begin);
      for (int k = 0; k < 3; ++k) {
        positions[3 * i + k] = static_cast<float>(vertices.positions[b][k]);
        lo[k] = std::min(lo[k], double(positions[3 * i + k]));
        hi[k] = std::max(hi[k], double(positions[3 * i + k]));
      }
      if (!mesh.has_normals) continue;
      const Eigen::Vector3f n = vertices.normals[b].cast<float>().normalized();
      for (int k = 0; k < 3; ++k) normals[3 * i + k] = n[k];
    }
  }
  std::vector<Eigen::Vector2f> texcoords;
  if (mesh.num_texcoords > 0) {
    std::vector<Eigen::Vector2d> uvs;
    mesh.texcoords(0, mesh.num_texcoords, uvs);
    texcoords.reserve(uvs.size());
    for (const Eigen::Vector2d& uv : uvs)
      texcoords.emplace_back(static_cast<float>(uv.x()), static_cast<float>(1.0 - uv.y()));
  }
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * static_cast<size_t>(mesh.triangles));
  FaceBlock faces;
  for (std::int64_t begin = 0; begin < mesh.num_faces; begin += kFacesPerBlock) {
    mesh.faces(begin, std::min(mesh.num_faces, begin + kFacesPerBlock), faces);
    for_each_triangle(faces, points, [&](int a, int b, int c) {
      for (int i : {a, b, c}) indices.push_back(static_cast<std::uint32_t>(i));
    });
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "stitch (bicubic Bezier patches, modified de Casteljau)";
  model.buffers.emplace_back();
  const int position_view = add_view(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int normal_view =
      mesh.has_normals ? add_view(model, normals, TINYGLTF_TARGET_ARRAY_BUFFER) : -1;
  const int texcoord_view =
      texcoords.empty() ? -1 : add_view(model, texcoords, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int index_view = add_view(model, indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      add_accessor(model, position_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
  model.accessors.back().minValues = lo;
  model.accessors.back().maxValues = hi;
  if (normal_view >= 0)
    primitive.attributes["NORMAL"] =
        add_accessor(model, normal_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
  if (texcoord_view >= 0)
    primitive.attributes["TEXCOORD_0"] =
        add_accessor(model, texcoord_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, nv);
  primitive.indices = add_accessor(model, index_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                   TINYGLTF_TYPE_SCALAR, indices.size());
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
  return model;
}

}  // namespace

void write_gltf(const std::string& path, const MeshStream& mesh, const std::vector<Vec3>& positions,
                bool binary) {
  if (mesh.num_vertices == 0 || mesh.num_faces == 0)
    throw OutputError(fmt::format("cannot write {}: the surface is empty", path));
  if (mesh.num_texcoords > 0 && mesh.num_texcoords != mesh.num_vertices)
    throw OutputError(fmt::format("cannot write {}: {} texture coordinates for {} vertices", path,
                                  mesh.num_texcoords, mesh.num_vertices));
  tinygltf::Model model = make_model(mesh, positions);
  tinygltf::TinyGLTF writer;
  if (binary) {
    write_file_atomically(
        path,
        [&](std::ostream& out) {
          if (!writer.WriteGltfSceneToStream(&model, out, false, true))
            throw OutputError(fmt::format("cannot write {}: glTF serialization failed", path));
        },
        true);
    return;
  }
  // tinygltf embeds buffers when writing to a stream; the buffer goes to its own file instead
  // and the .gltf refers to it by name.
  const std::filesystem::path bin_path = std::filesystem::path(path).replace_extension(".bin");
  const std::vector<unsigned char> bytes = std::move(model.buffers[0].data);
  model.buffers[0].data.clear();
  std::ostringstream text;
  if (!writer.WriteGltfSceneToStream(&model, text, true, false))
    throw OutputError(fmt::format("cannot write {}: glTF serialization failed", path));
  nlohmann::json doc = nlohmann::json::parse(text.str());
  doc["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", bin_path.filename().string()}};
  // The buffer is written under a name of its own first and takes its final name only once the
  // .gltf is in place: a failure leaves neither file changed (an earlier .bin included).
  const std::filesystem::path staged =
      bin_path.parent_path() / ("." + bin_path.filename().string() + ".staged");
  write_file_atomically(
      staged.string(),
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
      },
      true);
  std::error_code ec;
  try {
    write_file_atomically(path, [&](std::ostream& out) { out << doc.dump(2) << '\n'; });
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
