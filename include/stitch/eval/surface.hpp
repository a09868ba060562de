// One smooth surface of a mesh for a chosen method: the entry point of evaluation.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "stitch/choices.hpp"
#include "stitch/eval/bezier_surface.hpp"
#include "stitch/eval/catmull_clark.hpp"

namespace stitch {

enum class Method {
  mdc,  ///< modified de Casteljau, hierarchical (the paper's)
  asc,  ///< AS&C: the same patches as plain polynomials
  cc,   ///< Catmull-Clark limit surface through OpenSubdiv
};

/// The methods by name (mdc first: the default), for every front end's options and menus.
ChoiceTable<Method> method_table();
std::string to_string(Method m);
/// Parses a name of method_table(); throws UsageError naming the known ones otherwise.
Method parse_method(const std::string& s);

/// Patches are indexed by corner for every method; evaluate(c, u, v) uses the conventions of
/// control_net.hpp.
class Surface {
 public:
  Surface(const HalfedgeMesh& mesh, Method method, const KgonOptions& kgon_options = {});

  /// Makes this the surface Surface(mesh, method(), kgon_options) would be, in this object's
  /// storage: the control nets (about 400 bytes per corner, most of a surface's memory) are
  /// rebuilt in place where their array is large enough, as tessellate(..., out) reuses its
  /// arrays, so that the next frame of an animation touches no fresh memory for them. A mesh
  /// too large or too small to build on (limits::check_extent) is refused before anything
  /// changes; any later exception leaves a surface with no patches.
  void rebuild(const HalfedgeMesh& mesh, const KgonOptions& kgon_options = {});

  /// Hands the control nets (one per half-edge, as bezier().nets) to `edit(nets)`, which may
  /// move their points: those of a surface honouring semi-sharp tags are not its mesh's K-gons'
  /// alone (semi_sharp_nets). cc evaluates the limit surface, which no net changes.
  template <class Edit>
  void edit_nets(Edit&& edit) {
    edit(bezier_.nets);
  }

  [[nodiscard]] Method method() const { return method_; }
  [[nodiscard]] const std::vector<Corner>& corners() const { return bezier_.corners; }
  /// The Bézier patches (also built for cc, for overlays).
  [[nodiscard]] const BezierSurface& bezier() const { return bezier_; }
  [[nodiscard]] SurfacePoint evaluate(Corner c, double u, double v) const;

 private:
  Method method_;
  BezierSurface bezier_;
  std::shared_ptr<const CatmullClarkSurface> cc_;
};

}  // namespace stitch
