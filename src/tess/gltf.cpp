#include "tess/gltf.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "stitch/mesh/io.hpp"
#include "stitch/mesh/polygon.hpp"

// tinygltf is header-only; this file holds its implementation. Images are never written.
#define TINYGLTF_IMPLEMENTATION
#include "mesh/tinygltf.hpp"

namespace stitch {

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
tinygltf::Model make_model(const TessellatedMesh& mesh,
                           const std::vector<Eigen::Vector2f>* texcoords) {
  const size_t nv = mesh.positions.size();
  std::vector<float> positions(3 * nv), normals(3 * nv);
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  for (size_t i = 0; i < nv; ++i) {
    const Eigen::Vector3f n = mesh.normals[i].cast<float>().normalized();
    for (int k = 0; k < 3; ++k) {
      positions[3 * i + k] = static_cast<float>(mesh.positions[i][k]);
      normals[3 * i + k] = n[k];
      lo[k] = std::min(lo[k], double(positions[3 * i + k]));
      hi[k] = std::max(hi[k], double(positions[3 * i + k]));
    }
  }
  std::vector<std::uint32_t> indices;
  indices.reserve(6 * mesh.quads.size());
  for (const auto& q : mesh.quads)
    for (const auto& t : quad_triangles(q, mesh.positions))
      for (int i : t) indices.push_back(static_cast<std::uint32_t>(i));

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "stitch (bicubic Bezier patches, modified de Casteljau)";
  model.buffers.emplace_back();
  const int position_view = add_view(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int normal_view = add_view(model, normals, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int texcoord_view =
      texcoords ? add_view(model, *texcoords, TINYGLTF_TARGET_ARRAY_BUFFER) : -1;
  const int index_view = add_view(model, indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      add_accessor(model, position_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
  model.accessors.back().minValues = lo;
  model.accessors.back().maxValues = hi;
  primitive.attributes["NORMAL"] =
      add_accessor(model, normal_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
  if (texcoords)
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

void write_gltf(const std::string& path, const TessellatedMesh& mesh, bool binary,
                const std::vector<Eigen::Vector2f>* texcoords) {
  if (mesh.positions.empty() || mesh.quads.empty())
    throw OutputError(fmt::format("cannot write {}: the surface is empty", path));
  if (texcoords && texcoords->size() != mesh.positions.size())
    throw OutputError(fmt::format("cannot write {}: {} texture coordinates for {} vertices", path,
                                  texcoords->size(), mesh.positions.size()));
  tinygltf::Model model = make_model(mesh, texcoords);
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

}  // namespace stitch
