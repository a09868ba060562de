// The limits stitch accepts, so that every computation on an accepted input stays finite and every
// allocation stays bounded. docs/reliability.md explains each number.
#pragma once

#include <string>
#include <string_view>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::limits {

/// Largest |coordinate| of a vertex. The surface's normals come from cross products of
/// differences of points, and their lengths from squares of those: fourth powers of coordinate
/// differences, (2e50)^4 = 1.6e201, far below DBL_MAX = 1.8e308 even after the K-gon scale and
/// sums over long face loops. Beyond about 1e76 these overflow and the output turns to NaN.
inline constexpr double max_coordinate = 1e50;
/// Smallest longest side of a mesh's bounding box. Below it those fourth powers underflow to zero
/// and every normal is lost (the output stays finite but is meaningless).
inline constexpr double min_extent = 1e-50;

/// Most half-edges (twice the edges), and so most vertices and faces, of a mesh: element numbers
/// are `int`, and half-edge 2e+1 and sums of counts must not overflow. A mesh this large would
/// need tens of gigabytes anyway.
inline constexpr int max_halfedges = 1 << 30;
/// Most faces of a primitive made by `stitch primitive` or the modeler (about 200 MB of mesh).
inline constexpr long long max_primitive_faces = 1'000'000;

/// The K-gon controls (command line --kgon-scale/--kgon-rotate, the modeler's `kgon`):
/// a scale of 1e-6 already shrinks a K-gon to a point for any practical purpose, and rotations
/// beyond a few turns are the same as their remainder but lose precision.
inline constexpr double min_kgon_scale = 1e-6;
inline constexpr double max_kgon_scale = 1e6;
inline constexpr double max_rotation_deg = 3600;

/// Most segments of a handle made by connect-faces (each adds a ring of vertices and quads).
inline constexpr int max_handle_segments = 1000;

/// Characters of an offending token quoted in an error message; longer tokens are cut.
inline constexpr size_t max_quoted = 60;

/// The token as it is quoted in messages: whole when short, else its first characters and the
/// number of characters left out.
std::string quoted(std::string_view token);

/// "" when every coordinate of p is finite and within ±max_coordinate, else what is wrong
/// (without saying which point: the caller names it).
std::string coordinate_problem(const Vec3& p);

/// Throws stitch::Error "<what> ..." when coordinate_problem(p) finds a problem.
void check_coordinates(const Vec3& p, std::string_view what);

/// Throws stitch::Error when the longest side of the mesh's bounding box is below min_extent.
/// Checked where a surface is built, not when a mesh is read: such a mesh is a valid mesh, which
/// stitch edits, writes and reads back, but it has no normals to build a surface from.
void check_extent(const HalfedgeMesh& mesh);

/// Throws UsageError naming `what` unless lo <= value <= hi (NaN is refused too).
void check_range(double value, double lo, double hi, std::string_view what);

/// The most segments per patch side anything samples a patch with (tessellations, the modeler's
/// live surface, surface checks, renders, analysis): 1024 gives a million samples per patch, far
/// past what any display or file of a whole surface can use, and keeps sample counts in int.
inline constexpr int max_resolution = 1024;

/// Throws UsageError "<what> must be in 1..max_resolution" otherwise.
void check_resolution(int n, std::string_view what);

}  // namespace stitch::limits
