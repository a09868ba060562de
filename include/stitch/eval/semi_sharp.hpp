// Semi-sharp tags as OpenSubdiv means them, for the K-gon methods: the mesh refined with Sdc's
// Catmull-Clark rules until every tag is smooth or infinitely sharp, where each point of the
// input's corner patches went, and the nets that add what the tags do to the untagged surface.
// One recipe for every surface that honours them: build_surface (the command line, Python's
// stitch.Surface) and IncrementalSurface (the modeler, Python's stitch.IncrementalSurface, the
// Blender add-on).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "stitch/eval/surface.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/net/control_net.hpp"

namespace stitch {

/// How mdc and asc take semi-sharp tags (edge or vertex sharpness s with 0 < s <
/// infinitely_sharp). cc honours them itself, so nothing is done for it.
enum class SemiSharp {
  /// As OpenSubdiv means them: the mesh is refined uniformly with Sdc's Catmull-Clark rules
  /// (creases, corners and boundaries as Far refines them, sharpness going down by one per
  /// level) for ceil(largest semi-sharp tag) levels, from min_semi_sharp_levels to
  /// max_semi_sharp_levels, after which every tag is smooth or infinitely sharp. The surface's
  /// patches are those of the refined mesh, and it is the untagged surface plus what the tags do
  /// there (semi_sharp_nets, docs/method.md).
  refine,
  /// Today's rounding, no refinement: tags from KgonOptions::sharp_from on are infinitely sharp,
  /// the others smooth.
  round,
};

/// Refinement stops before the refined mesh has more faces than this, hole quads included (each
/// face is four patches of about 1 kB, and uniform refinement multiplies them by four per
/// level): tags left semi-sharp after the last level are made smooth (the band they would
/// still round is under 2^-levels of an input face).
inline constexpr long long max_semi_sharp_faces = 250'000;

/// What honouring the semi-sharp tags takes: the levels of uniform refinement and the faces
/// that gives. levels == 0: nothing to refine (no semi-sharp tag, method cc, or rounding asked).
struct SemiSharpRefinement {
  int levels = 0;
  /// max(min_semi_sharp_levels, ceil(largest_tag)): more than `levels` when a limit above cut
  /// the refinement short (tags left semi-sharp after it are made smooth).
  int levels_wanted = 0;
  double largest_tag = 0;  ///< the largest semi-sharp tag (0: none)
  long long faces = 0;     ///< faces of the refined mesh outside holes
  long long patches = 0;   ///< its corners outside holes: the surface's patches
  /// "semi-sharp tags up to 1.5 honoured by 2 levels of uniform refinement: 96 faces, 384
  /// patches" (empty when levels == 0), for the front ends' notes.
  [[nodiscard]] std::string summary() const;
};
/// The refinement honouring the tags takes, found from the tags alone (no work on the points):
/// none for cc (which honours them itself) or when rounding is asked.
SemiSharpRefinement semi_sharp_refinement(const HalfedgeMesh& mesh, Method method,
                                          SemiSharp semi_sharp);

/// The K-gon options of the mesh the surface is built on: with tags honoured by refinement (and
/// a K-gon method), only infinitely sharp tags are creases (sharp_from): the refined mesh has
/// no others, and with nothing refined (the limits) the semi-sharp tags are smooth.
KgonOptions semi_sharp_kgons(KgonOptions kgons, Method method, SemiSharp semi_sharp);

/// A mesh refined for its semi-sharp tags, and where each point of the input's corner patches
/// went.
struct SemiSharpMesh {
  HalfedgeMesh mesh;
  /// Per level, per half-edge of the mesh above: the corners of that corner's quad in the level
  /// below (CatmullClarkRefinement::corner_quad), from the one at the corner's vertex on, in
  /// loop order; invalid for deleted half-edges.
  std::vector<std::vector<std::array<Corner, 4>>> quad_corners;
  /// The input's texture coordinates on `mesh` when they were given (empty otherwise),
  /// refined linearly in each face: a new corner takes its vertex's coordinates, the mean of
  /// its edge's two ends or of its face's corners in that face, so seams stay seams and the
  /// UV layout is the input's (OpenSubdiv's "linear all" face-varying rule).
  CornerUvs uvs;

  /// The corner of `mesh` and its (u, v) at the point (c, u, v) of an input corner's patch. Each
  /// level splits a corner's patch into the four corner patches of its quad, as Catmull-Clark's
  /// parameterization does (exact for cc, the same domain for mdc and asc).
  struct Point {
    Corner corner;
    double u = 0, v = 0;
    /// d(u, v) of `corner` / d(u, v) of the input's corner: row 0 d/du, row 1 d/dv (a rotation
    /// by quarter turns times 2^levels).
    double jacobian[2][2] = {{1, 0}, {0, 1}};
    /// The derivatives of the input corner's patch from those of the refined one.
    [[nodiscard]] SurfacePoint to_input(SurfacePoint p) const;
  };
  [[nodiscard]] Point point(Corner c, double u, double v) const;
  /// The corners of `mesh` whose patches tile corner c's patch of the input (4^levels of them).
  [[nodiscard]] std::vector<Corner> patches_of(Corner c) const;
  /// By half-edge of `mesh`: the input corner whose patch holds that corner's patch (invalid
  /// where none: hole corners included, as hole quads follow hole corners).
  [[nodiscard]] std::vector<Corner> input_corners() const;
};

/// The mesh refined `levels` times with OpenSubdiv's Catmull-Clark rules and the mesh's
/// features (topology/catmark_refinement.hpp, each step checked against Far's uniform level),
/// semi-sharp tags left after the last level made smooth, one hole face per boundary loop. Vertices
/// of `mesh` keep their numbers; faces and edges are new. Throws stitch::Error where OpenSubdiv
/// cannot refine the mesh (a vertex where boundary loops meet).
SemiSharpMesh refine_semi_sharp(const HalfedgeMesh& mesh, int levels,
                                BoundaryInterpolation boundary, const CornerUvs* uvs = nullptr);

/// The control nets of the surface honouring the tags. On each patch of the refined mesh: the
/// input's surface without its semi-sharp tags, its net split down to the patch, plus what the
/// tags do to the refined mesh's surface (the nets of refined.mesh minus those of the mesh
/// refined without the tags). Refining alone moves the K-gon methods' surface (their patches are
/// not Catmull-Clark's), so only the tags' part is taken from the refined mesh: away from the
/// tags the surface is the untagged one, and a tag going down to 0 brings it back continuously
/// (docs/method.md). Where the tags move the nets around an extraordinary vertex, whose
/// patches the two surfaces parameterize otherwise, the nets' blocks at the vertex are the
/// tagged refined mesh's, moved with the rest: flat as a K-gon's corner, so the surface stays
/// G1 and unfolded there. The input's K-gons are built with `input_options`, the refined meshes'
/// with `options`. `nets`: in, those of refined.mesh's K-gons; out, the surface's.
void semi_sharp_nets(const HalfedgeMesh& input, const KgonOptions& input_options,
                     const SemiSharpMesh& refined, const KgonOptions& options, Method method,
                     std::vector<ControlNet>& nets);

}  // namespace stitch
