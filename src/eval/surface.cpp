#include "stitch/eval/surface.hpp"

#include <stdexcept>

#include "stitch/error.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch {

ChoiceTable<Method> method_table() {
  static constexpr Choice<Method> kMethods[] = {
      {"mdc", Method::mdc, "modified de Casteljau (the paper's)"},
      {"asc", Method::asc, "AS&C baseline (the same patches as plain polynomials)"},
      {"cc", Method::cc, "Catmull-Clark limit surface through OpenSubdiv"},
  };
  return kMethods;
}

std::string to_string(Method m) {
  return std::string(choice_name(method_table(), m));
}

Method parse_method(const std::string& s) {
  return parse_choice(method_table(), s, "method");
}

Surface::Surface(const HalfedgeMesh& mesh, Method method, const KgonOptions& kgon_options)
    : method_(method) {
  rebuild(mesh, kgon_options);
}

void Surface::rebuild(const HalfedgeMesh& mesh, const KgonOptions& kgon_options) {
  limits::check_extent(mesh);
  try {
    build_bezier_surface(mesh, kgon_options, bezier_);
    cc_ = method_ == Method::cc
              ? std::make_shared<const CatmullClarkSurface>(mesh, kgon_options.boundary)
              : nullptr;
  } catch (...) {
    bezier_ = {};
    cc_.reset();
    throw;
  }
}

SurfacePoint Surface::evaluate(Corner c, double u, double v) const {
  switch (method_) {
    case Method::mdc:
      return bezier_.evaluate(c, u, v, BezierRule::mdc);
    case Method::asc:
      return bezier_.evaluate(c, u, v, BezierRule::asc);
    case Method::cc:
      return cc_->evaluate(c, u, v);
  }
  return {};
}

}  // namespace stitch
