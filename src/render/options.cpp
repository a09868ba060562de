#include "stitch/render/options.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "stitch/error.hpp"

namespace stitch {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

bool parse_whole(const std::string& s, int& value) {
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  return error == std::errc() && end == s.data() + s.size();
}

bool parse_whole(const std::string& s, double& value) {
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  return error == std::errc() && end == s.data() + s.size() && std::isfinite(value);
}

}  // namespace

ImageSize parse_image_size(const std::string& text, int max_side) {
  const auto x = text.find_first_of("xX");
  ImageSize size;
  if (x == std::string::npos || !parse_whole(text.substr(0, x), size.width) ||
      !parse_whole(text.substr(x + 1), size.height) || size.width < 1 || size.height < 1 ||
      size.width > max_side || size.height > max_side) {
    throw UsageError("image size '" + text + "' is not WxH with whole numbers from 1 to " +
                     std::to_string(max_side) + " (e.g. 800x600)");
  }
  return size;
}

Vec3 parse_point(const std::string& text, const std::string& what) {
  const auto parts = split(text, ',');
  Vec3 p;
  bool ok = parts.size() == 3;
  for (size_t i = 0; ok && i < 3; ++i) ok = parse_whole(parts[i], p[static_cast<int>(i)]);
  if (!ok) {
    throw UsageError(what + " '" + text + "' is not three finite numbers x,y,z (e.g. 1.5,0,-2)");
  }
  return p;
}

void parse_overlays(const std::string& list, RenderStyle& style) {
  if (list.empty()) return;
  for (const std::string& name : split(list, ',')) {
    if (name == "mesh") {
      style.show(Overlay::mesh);
    } else if (name == "kgons") {
      style.show(Overlay::kgons);
    } else if (name == "nets") {
      style.show(Overlay::nets);
    } else if (name == "tess") {
      style.show(Overlay::tessellation);
    } else if (name == "ev") {
      style.markers = true;
    } else {
      throw UsageError("unknown overlay '" + name + "' in --show '" + list +
                       "' (expected a comma-separated list of mesh, kgons, nets, ev, "
                       "tess)");
    }
  }
}

}  // namespace stitch
