#include "stitch/mesh/limits.hpp"

#include <fmt/format.h>

#include <cmath>

namespace stitch::limits {

std::string quoted(std::string_view token) {
  if (token.size() <= max_quoted) return std::string(token);
  return fmt::format("{}... ({} more characters)", token.substr(0, max_quoted),
                     token.size() - max_quoted);
}

std::string coordinate_problem(const Vec3& p) {
  if (!p.allFinite())
    return fmt::format("has a non-finite coordinate ({}, {}, {})", p.x(), p.y(), p.z());
  if (p.cwiseAbs().maxCoeff() > max_coordinate)
    return fmt::format(
        "has a coordinate beyond the limit ±{:g} ({:g}, {:g}, {:g}); past it, products of "
        "coordinates overflow",
        max_coordinate, p.x(), p.y(), p.z());
  return {};
}

void check_coordinates(const Vec3& p, std::string_view what) {
  if (const std::string problem = coordinate_problem(p); !problem.empty())
    throw InputError(fmt::format("{} {}", what, problem));
}

void check_range(double value, double lo, double hi, std::string_view what) {
  if (!(value >= lo && value <= hi))
    throw UsageError(
        fmt::format("{} must be a number from {:g} to {:g}, not {:g}", what, lo, hi, value));
}

void check_resolution(int n, std::string_view what) {
  if (n < 1 || n > max_resolution)
    throw UsageError(fmt::format("{} must be in 1..{}, not {}", what, max_resolution, n));
}

void check_extent(const HalfedgeMesh& mesh) {
  Vec3 lo = Vec3::Constant(max_coordinate), hi = -lo;
  for (Vertex v : mesh.vertices()) {
    lo = lo.cwiseMin(mesh.position(v));
    hi = hi.cwiseMax(mesh.position(v));
  }
  const double side = (hi - lo).maxCoeff();
  if (side < min_extent)
    throw InputError(fmt::format(
        "the mesh is too small: the longest side of its bounding box is {:g}, below {:g}, where "
        "normals can no longer be computed; scale the model up",
        side, min_extent));
}

}  // namespace stitch::limits
