// Shared by the rendering tests: a hand-made tessellated sphere and image comparisons.
#pragma once

#include <cmath>
#include <cstdlib>

#include "stitch/render/image.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch::test {

/// A unit sphere as six patches (the faces of a cube projected outwards), each its own
/// (n + 1)^2 vertex block as an unwelded tessellation has; level = ring distance from the
/// patch's corner (0, 0), so every level colour appears.
inline TessellatedMesh cube_sphere(int n) {
  TessellatedMesh s;
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const double sign = face % 2 == 0 ? 1.0 : -1.0;
    const int first = s.num_vertices();
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const double a = 2.0 * i / n - 1.0, b = 2.0 * j / n - 1.0;
        Vec3 p;
        p[axis] = sign;
        p[(axis + 1) % 3] = sign * a;
        p[(axis + 2) % 3] = b;
        p.normalize();
        s.positions.push_back(p);
        s.normals.push_back(p);
        s.uv.emplace_back(double(i) / n, double(j) / n);
        s.patch.push_back(face);
        s.level.push_back(std::min(std::max(i, j), 7));
      }
    }
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const int v00 = first + i * (n + 1) + j;
        s.quads.push_back({v00, v00 + n + 1, v00 + n + 2, v00 + 1});
      }
    }
  }
  return s;
}

/// Pixels whose colour differs from `background` by more than `threshold` in some channel.
inline int count_non_background(const Image& im, int threshold = 8, int background = 255) {
  int count = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        if (std::abs(int(p[c]) - background) > threshold) {
          ++count;
          break;
        }
      }
    }
  }
  return count;
}

/// Mean absolute difference per channel, in 0..255.
inline double mean_difference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
  return sum / static_cast<double>(a.rgba.size());
}

}  // namespace stitch::test
