// Texture coordinates on the smooth surface: the UV of any point (corner, u, v) of a patch, so
// that every tessellation of the surface can carry the input's UV map.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"

namespace stitch {

enum class UvMode {
  /// The UV layout's own smooth surface: the mesh's faces with the UV indices as vertices and
  /// the UVs as positions, smoothed with mdc like the geometry. A UV seam is a boundary of that
  /// mesh, so the seam stays where it is and each side keeps its own UVs (OpenSubdiv's
  /// face-varying boundary rule does the same). Reproduces UV maps that are affine in the
  /// positions, since the construction commutes with affine maps.
  smooth,
  /// Per patch, bilinear between the UVs of its four corners: the corner's own UV at the vertex,
  /// the mean of the edge's two UVs in this face at the edge midpoints, the mean of the face's
  /// UVs at its centre. Continuous across seams' sides by construction, but not smooth.
  linear,
};

/// The UV modes by name (smooth first: the default).
ChoiceTable<UvMode> uv_mode_table();
std::string to_string(UvMode mode);
/// Parses a name of uv_mode_table(); throws UsageError naming the known ones otherwise.
UvMode parse_uv_mode(const std::string& text);

class UvSurface {
 public:
  /// Throws stitch::Error when a corner that makes a patch has no UV (a face --fill-holes added) or
  /// `uvs` does not belong to the mesh. Under `smooth`, a UV layout that is not a manifold mesh
  /// (build_mesh refuses it) or whose surface is not finite falls back to `linear`, with a
  /// warning saying why.
  UvSurface(const HalfedgeMesh& mesh, const CornerUvs& uvs, UvMode mode = UvMode::smooth,
            const KgonOptions& kgon_options = {});
  ~UvSurface();
  UvSurface(UvSurface&&) noexcept;
  UvSurface& operator=(UvSurface&&) noexcept;

  /// The mode evaluated: `linear` after a fallback.
  [[nodiscard]] UvMode mode() const { return mode_; }
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }

  /// The UV of point (u, v) of corner c's patch (the parameterization of control_net.hpp).
  [[nodiscard]] Eigen::Vector2d evaluate(Corner c, double u, double v) const;
  /// evaluate(c, i / n, j / n) for i, j = 0 .. n into out[i * (n + 1) + j], the order of the
  /// unwelded tessellation's grid; faster than point by point.
  void evaluate_grid(Corner c, int resolution, Eigen::Vector2d* out) const;

 private:
  struct Smooth;
  UvMode mode_;
  std::vector<std::string> warnings_;
  /// linear: by half-edge, the UVs at the patch corners 00, 30, 33, 03.
  std::vector<std::array<Eigen::Vector2d, 4>> linear_;
  std::unique_ptr<Smooth> smooth_;
};

}  // namespace stitch
