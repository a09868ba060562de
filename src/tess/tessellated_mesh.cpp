#include "stitch/tess/tessellated_mesh.hpp"

namespace stitch {

int first_non_finite_sample(const TessellatedMesh& mesh) {
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite() || (i < mesh.normals.size() && !mesh.normals[i].allFinite()))
      return static_cast<int>(i);
  return -1;
}

}  // namespace stitch
