#include "stitch/eval/surface.hpp"

#include <stdexcept>

#include "stitch/error.hpp"
#include "stitch/mesh/limits.hpp"

namespace stitch {

std::string to_string(Method m) {
  switch (m) {
    case Method::mdc:
      return "mdc";
    case Method::asc:
      return "asc";
    case Method::cc:
      return "cc";
  }
  return "?";
}

Method parse_method(const std::string& s) {
  if (s == "mdc") return Method::mdc;
  if (s == "asc") return Method::asc;
  if (s == "cc") return Method::cc;
  throw UsageError("unknown method '" + s + "' (expected mdc, asc or cc)");
}

namespace {

// The mesh, once limits::check_extent has found it large enough to build a surface on.
const HalfedgeMesh& extent_checked(const HalfedgeMesh& mesh) {
  limits::check_extent(mesh);
  return mesh;
}

}  // namespace

Surface::Surface(const HalfedgeMesh& mesh, Method method, const KgonOptions& kgon_options)
    : method_(method), bezier_(build_bezier_surface(extent_checked(mesh), kgon_options)) {
  if (method == Method::cc)
    cc_ = std::make_shared<const CatmullClarkSurface>(mesh, kgon_options.boundary);
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
