#include "stitch/render/overlays.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

#include "stitch/mesh/polygon.hpp"

namespace stitch {

void LineSet::add_loop(const std::vector<Vec3>& loop, const Colour& c) {
  for (size_t i = 0; i < loop.size(); ++i) add(loop[i], loop[(i + 1) % loop.size()], c);
}

std::vector<ExtraordinaryPoint> extraordinary_points(const HalfedgeMesh& mesh,
                                                     const KgonSet& kgons) {
  // The extent is the size of the patches meeting at the point: the mean distance to their
  // opposite corners, which are the centroids of the K-gons of the neighbouring faces (for a
  // vertex) or vertices (for a face).
  std::vector<ExtraordinaryPoint> points;
  for (const Vertex v : mesh.vertices()) {
    const Kgon& kgon = kgons.vertex[v.idx];
    if (kgon.size() == 4) continue;
    double extent = 0.0;
    const auto fan = mesh.vertex_fan(v);
    for (const Halfedge h : fan)
      extent += (kgons.face[mesh.face(h).idx].centroid - kgon.centroid).norm();
    points.push_back({kgon.centroid, kgon.normal, kgon.size(), KgonKind::vertex, v.idx,
                      extent / static_cast<double>(fan.size())});
  }
  for (const Face f : mesh.faces()) {
    const Kgon& kgon = kgons.face[f.idx];
    if (kgon.size() == 4) continue;
    const auto loop = mesh.face_loop(f);
    double extent = 0.0;
    for (const Halfedge h : loop)
      extent += (kgons.vertex[mesh.origin(h).idx].centroid - kgon.centroid).norm();
    points.push_back({kgon.centroid, kgon.normal, kgon.size(), KgonKind::face, f.idx,
                      extent / static_cast<double>(loop.size())});
  }
  return points;
}

const ExtraordinaryPoint& highest_valence_point(const std::vector<ExtraordinaryPoint>& points) {
  if (points.empty()) {
    throw std::invalid_argument(
        "the mesh has no extraordinary point (every vertex has valence 4 and every face 4 sides)");
  }
  const ExtraordinaryPoint* best = &points.front();
  for (const ExtraordinaryPoint& p : points) {
    if (p.k > best->k) best = &p;
  }
  return *best;
}

LineSet mesh_lines(const HalfedgeMesh& mesh) {
  LineSet lines;
  for (const Edge e : mesh.edges()) {
    const Halfedge h = HalfedgeMesh::halfedge(e, 0);
    lines.add(mesh.position(mesh.origin(h)), mesh.position(mesh.target(h)), palette::mesh);
  }
  return lines;
}

LineSet kgon_lines(const KgonSet& kgons) {
  LineSet lines;
  // Edge K-gons first so the face and vertex K-gons (the shape handles) are drawn over them.
  for (const Kgon& k : kgons.edge) lines.add_loop(k.points, palette::edge_kgon);
  for (const Kgon& k : kgons.vertex) lines.add_loop(k.points, palette::vertex_kgon);
  for (const Kgon& k : kgons.face) lines.add_loop(k.points, palette::face_kgon);
  return lines;
}

LineSet control_net_lines(const std::vector<ControlNet>& nets, const std::vector<Corner>& corners) {
  LineSet lines;
  for (const Corner c : corners) {
    const ControlNet& net = nets[c.idx];
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 3; ++j) {
        lines.add(net.at(i, j), net.at(i, j + 1), palette::net);
        lines.add(net.at(j, i), net.at(j + 1, i), palette::net);
      }
    }
  }
  return lines;
}

LineSet surface_mesh_lines(const SurfaceMesh& surface) {
  LineSet lines;
  for (const auto& q : surface.quads) {
    for (int i = 0; i < 4; ++i) {
      const int a = q[i], b = q[(i + 1) % 4];
      if (a != b) lines.add(surface.positions[a], surface.positions[b], palette::tessellation);
    }
  }
  return lines;
}

MarkerSet extraordinary_markers(const std::vector<ExtraordinaryPoint>& points) {
  MarkerSet markers;
  for (const ExtraordinaryPoint& p : points) {
    markers.positions.push_back(p.position);
    markers.colours.push_back(palette::extraordinary);
  }
  return markers;
}

SurfaceMesh input_faces(const HalfedgeMesh& mesh) {
  SurfaceMesh out;
  const auto add_vertex = [&](const Vec3& p, const Vec3& n, int face) {
    out.positions.push_back(p);
    out.normals.push_back(n);
    out.uv.emplace_back(0.0, 0.0);
    out.patch.push_back(face);
    out.level.push_back(0);
    return out.num_vertices() - 1;
  };
  for (const Face f : mesh.faces()) {
    const std::vector<Vec3> p = face_points(mesh, f);
    // Newell's normal: the area vector, meaningful for non-planar loops too.
    Vec3 normal = newell_normal(p);
    normal = normal.norm() > 0 ? normal.normalized() : Vec3::UnitZ();
    const int c = add_vertex(centroid(p), normal, f.idx);
    const int first = out.num_vertices();
    for (const Vec3& q : p) add_vertex(q, normal, f.idx);
    const int n = static_cast<int>(p.size());
    for (int i = 0; i < n; ++i) {
      const int b = first + (i + 1) % n;
      out.quads.push_back({c, first + i, b, b});
    }
  }
  return out;
}

}  // namespace stitch
