#include "stitch/render/overlays.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>

#include "stitch/analysis/sectors.hpp"
#include "stitch/error.hpp"
#include "stitch/mesh/polygon.hpp"

namespace stitch {

void LineSet::add_loop(std::span<const Vec3> loop, const Colour& c) {
  for (size_t i = 0; i < loop.size(); ++i) add(loop[i], loop[(i + 1) % loop.size()], c);
}

std::vector<ExtraordinaryPoint> extraordinary_points(const HalfedgeMesh& mesh,
                                                     const KgonSet& kgons) {
  // The extent is the size of the patches meeting at the point: the mean distance to their
  // opposite corners, which are the centroids of the K-gons of the neighbouring faces (for a
  // vertex) or vertices (for a face).
  std::vector<ExtraordinaryPoint> points;
  const auto extent_at = [&](const Vec3& at, const std::vector<Corner>& corners) {
    double extent = 0.0;
    for (const Corner c : corners) extent += (kgons.face[mesh.face(c).idx].centroid - at).norm();
    return extent / static_cast<double>(corners.size());
  };
  for (const Vertex v : mesh.vertices()) {
    const Kgon& kgon = kgons.vertex[v.idx];
    if (sharp_spokes(mesh, v, kgons.sharp_edge) < 2) {
      if (kgon.size() == 4) continue;
      points.push_back({kgon.centroid, kgon.normal, kgon.size(), KgonKind::vertex, v.idx,
                        extent_at(kgon.centroid, mesh.vertex_fan(v))});
      continue;
    }
    for (const std::vector<Corner>& sector : vertex_sectors(mesh, v, kgons.sharp_edge)) {
      const int k = kgons.vertex_k[sector.front().idx];
      if (k == 4) continue;
      // The sector's K-gon is flat and passes through the curve point (its centroid), so its
      // points closed through that point span its plane; a sector of one patch spans none, and
      // its face says which way the surface faces.
      std::vector<Vec3> loop{kgon.centroid};
      Vec3 faces = Vec3::Zero();
      for (const Corner c : sector) {
        loop.push_back(kgon.points[kgons.in_vertex[c.idx]]);
        faces += newell_normal(face_points(mesh, mesh.face(c)));
      }
      Vec3 normal = newell_normal(loop);
      if (normal.norm() <= 1e-12 * faces.norm()) normal = faces;
      if (normal.dot(faces) < 0) normal = -normal;
      normal = normal.norm() > 0 ? normal.normalized() : Vec3::UnitZ();
      points.push_back(
          {kgon.centroid, normal, k, KgonKind::vertex, v.idx, extent_at(kgon.centroid, sector)});
    }
  }
  for (const Face f : mesh.surface_faces()) {
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
    throw UsageError(
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
    const Vec3& a = mesh.position(mesh.origin(h));
    const Vec3& b = mesh.position(mesh.target(h));
    if (mesh.is_boundary(e)) {
      lines.add(a, b, palette::boundary, sharp_line_width);
    } else if (mesh.sharpness(e) > 0) {
      // Methods differ in the sharpness from which a crease is sharp, so the line shows the
      // tag itself: its width grows with it, to the full width at infinitely sharp.
      const double s = std::min(mesh.sharpness(e), infinitely_sharp) / infinitely_sharp;
      lines.add(a, b, palette::crease, 1.0f + (sharp_line_width - 1.0f) * static_cast<float>(s));
    } else {
      lines.add(a, b, palette::mesh);
    }
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

namespace {

/// The closed loop through `loop` without its zero-length segments (points a hole side or a
/// sector leaves at the centroid).
void add_distinct_loop(LineSet& lines, std::span<const Vec3> loop, const Colour& c) {
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % loop.size()];
    if (a != b) lines.add(a, b, c);
  }
}

}  // namespace

LineSet kgon_lines(const HalfedgeMesh& mesh, const KgonSet& kgons) {
  LineSet lines;
  for (const Edge e : mesh.edges())
    add_distinct_loop(lines, kgons.edge[e.idx].points, palette::edge_kgon);
  for (const Vertex v : mesh.vertices()) {
    const Kgon& kgon = kgons.vertex[v.idx];
    if (sharp_spokes(mesh, v, kgons.sharp_edge) < 2) {
      add_distinct_loop(lines, kgon.points, palette::vertex_kgon);
      continue;
    }
    for (const std::vector<Corner>& sector : vertex_sectors(mesh, v, kgons.sharp_edge)) {
      std::vector<Vec3> loop{kgon.centroid};
      for (const Corner c : sector) loop.push_back(kgon.points[kgons.in_vertex[c.idx]]);
      add_distinct_loop(lines, loop, palette::vertex_kgon);
    }
  }
  for (const Face f : mesh.surface_faces())
    add_distinct_loop(lines, kgons.face[f.idx].points, palette::face_kgon);
  return lines;
}

LineSet sharp_curve_lines(const HalfedgeMesh& mesh, const Surface& surface, int segments) {
  LineSet lines;
  if (!mesh.has_features() || segments < 1) return lines;
  const std::vector<std::uint8_t> sharp = sharp_edges(mesh, surface);
  for (const Edge e : mesh.edges()) {
    if (sharp[static_cast<size_t>(e.idx)] == 0) continue;
    // Both sides of a crease carry the same curve, so one side that makes patches is enough.
    Halfedge h = HalfedgeMesh::halfedge(e, 0);
    if (mesh.is_hole(h)) h = HalfedgeMesh::twin(h);
    if (mesh.is_hole(h)) continue;
    const Colour& colour = mesh.is_boundary(e) ? palette::boundary : palette::crease;
    // The half at origin(h) is side 0 of h's patch, the half at target(h) side 3 of next(h)'s;
    // both run from their vertex to the edge midpoint.
    for (const auto& [corner, along_u] : {std::pair{h, true}, std::pair{mesh.next(h), false}}) {
      Vec3 previous = surface.evaluate(corner, 0.0, 0.0).position;
      for (int i = 1; i <= segments; ++i) {
        const double t = static_cast<double>(i) / segments;
        const Vec3 p = surface.evaluate(corner, along_u ? t : 0.0, along_u ? 0.0 : t).position;
        lines.add(previous, p, colour, sharp_line_width);
        previous = p;
      }
    }
  }
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

LineSet surface_mesh_lines(const TessellatedMesh& surface) {
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

TessellatedMesh input_faces(const HalfedgeMesh& mesh) {
  TessellatedMesh out;
  const auto add_vertex = [&](const Vec3& p, const Vec3& n, int face) {
    out.positions.push_back(p);
    out.normals.push_back(n);
    out.uv.emplace_back(0.0, 0.0);
    out.patch.push_back(face);
    out.level.push_back(0);
    return out.num_vertices() - 1;
  };
  for (const Face f : mesh.surface_faces()) {
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

std::vector<Eigen::Vector2d> input_face_texcoords(const HalfedgeMesh& mesh, const CornerUvs& uvs) {
  std::vector<Eigen::Vector2d> out;
  const int nuv = static_cast<int>(uvs.uv.size());
  for (const Face f : mesh.surface_faces()) {
    const std::vector<Halfedge> loop = mesh.face_loop(f);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    const size_t at_centre = out.size();  // input_faces puts the centre first
    out.emplace_back();
    for (const Halfedge h : loop) {
      const int i = static_cast<size_t>(h.idx) < uvs.index.size() ? uvs.index[h.idx] : -1;
      if (i < 0 || i >= nuv)
        throw InputError(fmt::format("face {} has no texture coordinates", f.idx + 1));
      out.push_back(uvs.uv[i]);
      centre += uvs.uv[i];
    }
    out[at_centre] = centre / static_cast<double>(loop.size());
  }
  return out;
}

}  // namespace stitch
