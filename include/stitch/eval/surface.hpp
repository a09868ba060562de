// One smooth surface of a mesh for a chosen method: the entry point of evaluation.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "stitch/eval/bezier_surface.hpp"
#include "stitch/eval/catmull_clark.hpp"

namespace stitch {

enum class Method {
  mdc,  ///< modified de Casteljau, hierarchical (the paper's)
  asc,  ///< AS&C: the same patches as plain polynomials
  cc,   ///< Catmull-Clark limit surface through OpenSubdiv
};

std::string to_string(Method m);
/// Parses "mdc", "asc" or "cc"; throws UsageError otherwise.
Method parse_method(const std::string& s);

/// Patches are indexed by corner for every method; evaluate(c, u, v) uses the conventions of
/// control_net.hpp.
class Surface {
 public:
  Surface(const HalfedgeMesh& mesh, Method method, const KgonOptions& kgon_options = {});

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
