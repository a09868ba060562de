#include "stitch/eval/uv_surface.hpp"

#include <fmt/format.h>

#include <map>
#include <stdexcept>
#include <utility>

#include "eval/patch_sampler.hpp"
#include "stitch/error.hpp"

namespace stitch {

ChoiceTable<UvMode> uv_mode_table() {
  static constexpr Choice<UvMode> kModes[] = {
      {"smooth", UvMode::smooth, "the UV layout smoothed like the mesh, seams kept"},
      {"linear", UvMode::linear, "bilinear per patch"},
  };
  return kModes;
}

std::string to_string(UvMode mode) {
  return std::string(choice_name(uv_mode_table(), mode));
}

UvMode parse_uv_mode(const std::string& text) {
  return parse_choice(uv_mode_table(), text, "UV mode");
}

/// The UV layout as a mesh of its own and its surface; the mesh is kept because the surface is
/// built from it.
struct UvSurface::Smooth {
  HalfedgeMesh mesh;
  std::unique_ptr<Surface> surface;
  std::vector<int> corner;  ///< by half-edge of the input mesh: the UV mesh's corner (-1: none)
};

namespace {

/// The UV layout: the input's faces in order, each UV mesh vertex one (mesh vertex, UV index)
/// pair. Keying by the mesh vertex too keeps two vertices apart that a file gave the same UV
/// index (an atlas reusing a coordinate), as OpenSubdiv's face-varying channels do. The tags of
/// the input go along, so the UV map is interpolated the way the positions are.
struct UvLayout {
  PolygonSoup soup;
  std::vector<Face> faces;  ///< soup face k is faces[k] of the input
};

UvLayout uv_layout(const HalfedgeMesh& mesh, const CornerUvs& uvs) {
  UvLayout out;
  std::map<std::pair<int, int>, int> vertex;  // (mesh vertex, UV index) -> UV mesh vertex
  std::vector<int> uv_vertex(mesh.halfedge_capacity(), -1);
  for (Face f : mesh.surface_faces()) {
    std::vector<int> loop;
    for (Halfedge h : mesh.face_loop(f)) {
      const int index = uvs.index[h.idx];
      const auto [it, fresh] = vertex.try_emplace({mesh.origin(h).idx, index},
                                                  static_cast<int>(out.soup.positions.size()));
      if (fresh) {
        out.soup.positions.emplace_back(uvs.uv[index].x(), uvs.uv[index].y(), 0.0);
        const double s = mesh.sharpness(mesh.origin(h));
        if (s > 0) out.soup.corners.push_back({it->second, s, 0});
      }
      uv_vertex[h.idx] = it->second;
      loop.push_back(it->second);
    }
    out.soup.faces.push_back(std::move(loop));
    out.faces.push_back(f);
  }
  for (Face f : out.faces)
    for (Halfedge h : mesh.face_loop(f))
      if (const double s = mesh.sharpness(HalfedgeMesh::edge(h)); s > 0)
        out.soup.creases.push_back({uv_vertex[h.idx], uv_vertex[mesh.next(h).idx], s, 0});
  return out;
}

/// `options` with its per-element controls moved to the UV mesh's elements (its numbering
/// differs: seams split vertices and edges).
KgonOptions uv_kgon_options(const HalfedgeMesh& mesh, const HalfedgeMesh& uv_mesh,
                            const std::vector<int>& corner, const KgonOptions& options) {
  KgonOptions out = options;
  out.face.clear();
  out.vertex.clear();
  out.edge.clear();
  if (options.face.empty() && options.vertex.empty() && options.edge.empty()) return out;
  for (Corner c : mesh.patch_corners()) {
    const Corner d(corner[c.idx]);
    if (auto it = options.face.find(mesh.face(c).idx); it != options.face.end())
      out.face[uv_mesh.face(d).idx] = it->second;
    if (auto it = options.vertex.find(mesh.origin(c).idx); it != options.vertex.end())
      out.vertex[uv_mesh.origin(d).idx] = it->second;
    if (auto it = options.edge.find(HalfedgeMesh::edge(c).idx); it != options.edge.end())
      out.edge[HalfedgeMesh::edge(d).idx] = it->second;
  }
  return out;
}

bool finite_nets(const Surface& surface) {
  for (Corner c : surface.corners())
    for (const Vec3& p : surface.bezier().nets[c.idx].p)
      if (!p.allFinite()) return false;
  return true;
}

}  // namespace

UvSurface::UvSurface(const HalfedgeMesh& mesh, const CornerUvs& uvs, UvMode mode,
                     const KgonOptions& kgon_options)
    : mode_(mode) {
  if (uvs.index.size() < static_cast<size_t>(mesh.halfedge_capacity()))
    throw InputError(fmt::format("the texture coordinates cover {} half-edges, the mesh has {}",
                                 uvs.index.size(), mesh.halfedge_capacity()));
  const std::vector<Corner> corners = mesh.patch_corners();
  const int nuv = static_cast<int>(uvs.uv.size());
  for (Corner c : corners)
    if (const int i = uvs.index[c.idx]; i < 0 || i >= nuv)
      throw InputError(fmt::format(
          "face {} has no texture coordinates (a face --fill-holes added, or one made by an edit)",
          mesh.face(c).idx + 1));

  if (mode_ == UvMode::smooth) {
    try {
      const UvLayout layout = uv_layout(mesh, uvs);
      BuildOptions options;
      options.allow_two_gons = true;  // as the input may have them
      options.repair = false;         // its faces are matched to the layout's by index
      auto smooth = std::make_unique<Smooth>();
      smooth->mesh = build_mesh(layout.soup, options);
      // UV soup face k is UV mesh Face(k), its loop starting at the first corner (build_mesh),
      // as face_loop starts the input's face.
      smooth->corner.assign(mesh.halfedge_capacity(), -1);
      for (size_t k = 0; k < layout.faces.size(); ++k) {
        const auto input = mesh.face_loop(layout.faces[k]);
        const auto uv = smooth->mesh.face_loop(Face(static_cast<int>(k)));
        for (size_t i = 0; i < input.size(); ++i) smooth->corner[input[i].idx] = uv[i].idx;
      }
      smooth->surface = std::make_unique<Surface>(
          smooth->mesh, Method::mdc,
          uv_kgon_options(mesh, smooth->mesh, smooth->corner, kgon_options));
      if (!finite_nets(*smooth->surface))
        throw InputError("its smooth surface is not finite (faces of zero area in UV?)");
      smooth_ = std::move(smooth);
    } catch (const Error& e) {
      warnings_.push_back(fmt::format(
          "the UV layout does not make a smooth surface ({}); UVs are interpolated linearly per "
          "patch instead",
          e.what()));
      mode_ = UvMode::linear;
    }
  }
  if (mode_ == UvMode::linear) {
    linear_.assign(mesh.halfedge_capacity(), {});
    for (Face f : mesh.surface_faces()) {
      const std::vector<Halfedge> loop = mesh.face_loop(f);
      Eigen::Vector2d centre = Eigen::Vector2d::Zero();
      for (Halfedge h : loop) centre += uvs.uv[uvs.index[h.idx]];
      centre /= static_cast<double>(loop.size());
      for (Halfedge h : loop) {
        const Eigen::Vector2d& at = uvs.uv[uvs.index[h.idx]];
        const Eigen::Vector2d& next = uvs.uv[uvs.index[mesh.next(h).idx]];
        const Eigen::Vector2d& prev = uvs.uv[uvs.index[mesh.prev(h).idx]];
        linear_[h.idx] = {at, 0.5 * (at + next), centre, 0.5 * (at + prev)};
      }
    }
  }
}

UvSurface::~UvSurface() = default;
UvSurface::UvSurface(UvSurface&&) noexcept = default;
UvSurface& UvSurface::operator=(UvSurface&&) noexcept = default;

Eigen::Vector2d UvSurface::evaluate(Corner c, double u, double v) const {
  if (smooth_)
    return smooth_->surface->evaluate(Corner(smooth_->corner[c.idx]), u, v).position.head<2>();
  const auto& p = linear_[c.idx];
  return (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
}

void UvSurface::evaluate_grid(Corner c, int resolution, Eigen::Vector2d* out) const {
  const int n = resolution;
  if (!smooth_) {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        out[i * (n + 1) + j] = evaluate(c, static_cast<double>(i) / n, static_cast<double>(j) / n);
    return;
  }
  PatchSampler sampler(*smooth_->surface, n);
  const Corner d(smooth_->corner[c.idx]);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      out[i * (n + 1) + j] = sampler.evaluate_grid(d, i, j).position.head<2>();
}

}  // namespace stitch
