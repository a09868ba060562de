// What reads what among the K-gons: the rule an incremental update (IncrementalSurface, the local
// surface check) follows to rebuild only what an edit can change. It sits beside the builders
// because it restates what they read: a change to build_kgons must be made here too
// (tests/test_incremental_surface.cpp compares every update with a rebuild).
#include <algorithm>

#include "mesh/sort_unique.hpp"
#include "stitch/kgon/kgon.hpp"

namespace stitch {

namespace {

using detail::sort_unique;

template <class T>
void append_sorted(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
  sort_unique(to);
}

}  // namespace

void KgonElements::merge(const KgonElements& other) {
  append_sorted(faces, other.faces);
  append_sorted(vertices, other.vertices);
  append_sorted(edges, other.edges);
}

KgonElements kgons_reading(const HalfedgeMesh& mesh, std::vector<Face> faces) {
  std::erase_if(faces, [&](Face f) {
    return f.idx < 0 || f.idx >= mesh.face_capacity() || mesh.is_deleted(f);
  });
  sort_unique(faces);
  KgonElements out;
  out.faces = faces;
  for (Face f : faces)
    for (Halfedge h : mesh.face_loop(f)) {
      out.vertices.push_back(mesh.origin(h));
      out.edges.push_back(HalfedgeMesh::edge(h));
      out.faces.push_back(mesh.face(HalfedgeMesh::twin(h)));
    }
  sort_unique(out.faces);
  sort_unique(out.vertices);
  sort_unique(out.edges);
  return out;
}

}  // namespace stitch
