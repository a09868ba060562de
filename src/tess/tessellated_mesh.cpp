#include "stitch/tess/tessellated_mesh.hpp"

#include <algorithm>

#include "support/finite.hpp"

namespace stitch {

int first_non_finite_sample(const TessellatedMesh& mesh) {
  // The fast scan first; sample by sample only to name the bad one. A mesh made by hand may have
  // fewer normals than positions.
  const auto n = static_cast<std::int64_t>(mesh.positions.size());
  const auto m = std::min(n, static_cast<std::int64_t>(mesh.normals.size()));
  if (detail::all_finite(mesh.positions.data(), n) && detail::all_finite(mesh.normals.data(), m))
    return -1;
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite() || (i < mesh.normals.size() && !mesh.normals[i].allFinite()))
      return static_cast<int>(i);
  return -1;
}

}  // namespace stitch
