// Choosing the K-gon controls of a tube that folds (docs/method.md, "Tubes that still fold").
//
// The openings construction places the K-gons of a face with two openings by rules fitted on
// regular prisms and a few solids. Off those (uneven rims, long or tapered tubes, prism 16's half
// twist) the surface over some of these faces folds, while a setting of the paper's own controls
// on that face's K-gon (scale and rotation in its plane, and a stretch along the tube) and on its
// bridge's edge K-gon (scale) makes it clean. unfold_tubes looks for such a setting, first on a
// fixed grid and then by a descent from the fitted placement (which may also move the face K-gon
// and stretch it across the tube), where the fitted placement folds (or is clean but pushes the
// hole off the tube's axis, as on the half twists of prisms 16 to 24), judged by the local check
// (local_check.hpp) on the patches those two K-gons reach, and records it as per-element controls:
// the surface stays the one the method builds from its K-gons, C1 along every edge and G1 at the
// face's extraordinary point (the K-gons stay planar), and a tube that is clean and open already is
// left exactly as it was.
#pragma once

#include <string>
#include <vector>

#include "stitch/analysis/local_check.hpp"
#include "stitch/eval/bezier_surface.hpp"
#include "stitch/kgon/kgon.hpp"

namespace stitch {

struct UnfoldTubesOptions {
  /// The check that decides whether a setting is clean (resolution 16, as the tube tests).
  LocalCheckOptions check;
  /// The method whose surface is judged (mdc and asc share the nets but not the surface); with
  /// cc nothing is searched, since its surface does not come from the K-gons.
  Method method = Method::mdc;
  /// Settings the descent may score (docs/method.md, "The descent") where no setting of
  /// tube_settings() is clean and open: 0 searches the grid alone. Most tubes measured took 17
  /// to 85, the half twist of prism 6 half as high about 110 (a quarter of this per start); a
  /// tube that none of them cleans costs this many local checks.
  int descent_evaluations = 600;
};

/// What the search found for one face with two openings whose surface folded (or was clean with
/// its axis blocked, and was opened).
struct TubeUnfolding {
  Face face;
  Edge bridge;
  LocalCheckReport fitted;  ///< the check with the fitted placement
  LocalCheckReport chosen;  ///< the check with the chosen setting (the fitted one if none)
  /// The setting chosen: scale, rotation, stretch of the face K-gon (and from the descent the
  /// stretch's direction across the tube and an offset).
  KgonControl face_control;
  KgonControl bridge_control;  ///< and scale of the bridge's edge K-gon
  int settings_tried = 0;      ///< settings checked, the fitted one included
  /// Whether the setting was found by the descent, past the grid of tube_settings(): then the
  /// face K-gon may also be stretched across the tube and moved (its offset).
  bool descended = false;
  int resolution = 0;  ///< of the checks
  /// Whether the line through the two rims' centres (3 times their distance beyond each) misses
  /// the tube's patches with the chosen setting. A clean setting that closes the tube is chosen
  /// only when no clean one leaves it open and the fitted K-gons close it too (the line is not a
  /// bent tube's axis, so it may meet the wall of a clean one).
  bool axis_open = true;
  [[nodiscard]] bool unfolded() const { return chosen.clean(); }
};

/// The settings tried, nearest to the fitted placement (no control) first, as (face scale, face
/// rotation in degrees, face stretch along the tube, bridge scale). Face scale 0.4 to 1.5,
/// rotation -30 to 30 degrees in steps of 10 and ±45, ±60, stretch 1 or 1.5, bridge scale 0.5 to
/// 1.5: the ranges where the folding tubes measured in docs/method.md found their clean settings.
struct TubeSetting {
  double face_scale, face_rotate_deg, face_stretch, bridge_scale;
};
const std::vector<TubeSetting>& tube_settings();

/// For every face of `faces` with two openings (the openings construction) whose patches or
/// their neighbours fold or cross, or which is clean but whose axis (the line through the rims'
/// centres, where it runs along both rims' normals) meets its wall, and on which the user set no
/// control (neither on the face nor on its bridge): tries tube_settings() in order and keeps the
/// first that the local check finds clean and that leaves the line through the rims' centres
/// open; if none does, the first setting of the descent that is (unfold.descent_evaluations);
/// if that finds none, for a folding tube the grid's first clean one if the fitted K-gons close
/// the line too. The setting kept is added to options.face and options.edge.
/// `surface` is the Bézier surface built for `mesh` with `options`; it is left built with the
/// options as they are on return (only the K-gons and nets of the faces searched are touched, so
/// the cost follows the tubes, not the mesh). Returns one entry per folding face, unfolded or not,
/// and one per clean face whose axis a setting opened, in the order of `faces`.
std::vector<TubeUnfolding> unfold_tubes(const HalfedgeMesh& mesh, KgonOptions& options,
                                        BezierSurface& surface, const std::vector<Face>& faces,
                                        const UnfoldTubesOptions& unfold = {});

/// The same over every face of the mesh, building the surface itself; nothing is built when no
/// face has two openings.
std::vector<TubeUnfolding> unfold_tubes(const HalfedgeMesh& mesh, KgonOptions& options,
                                        const UnfoldTubesOptions& unfold = {});

/// One line for people: "the tube of face 1 (bridge 1 25) folds with its fitted K-gons (18 folded
/// and 0 crossing pairs of triangles at resolution 16); chosen instead: face K-gon scale 1.2
/// rotate -30, bridge K-gon scale 1 (clean)", or that none of the settings tried is clean. Faces
/// and vertices 1-based, as operation lines number them.
std::string describe(const HalfedgeMesh& mesh, const TubeUnfolding& tube);

/// The faces of the mesh whose K-gons the openings construction builds (two openings).
std::vector<Face> faces_with_two_openings(const HalfedgeMesh& mesh, const KgonOptions& options);
/// The same among `faces` (e.g. those an edit touched; deleted ones skipped), sorted, without
/// repeats: a cost that follows the list, not the mesh.
std::vector<Face> faces_with_two_openings(const HalfedgeMesh& mesh, const KgonOptions& options,
                                          const std::vector<Face>& faces);

}  // namespace stitch
