#include "stitch/project/kgon_controls.hpp"

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "project/kgon_control_json.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch {

using nlohmann::json;

namespace {

std::string kind_name(KgonKind kind) {
  return kind == KgonKind::face ? "face" : kind == KgonKind::vertex ? "vertex" : "edge";
}

/// A 1-based element number as the file gives it, checked against the mesh; 0-based result.
int element_number(const HalfedgeMesh& m, KgonKind kind, const json& j) {
  if (kind == KgonKind::edge && j.is_string()) {
    // "V W" or "V W@F", as in operation lines.
    const std::string text = j.get<std::string>();
    const auto words = split_words(text);
    if (words.size() != 2)
      throw InputError(
          fmt::format("edge \"{}\" is not \"V W\" or \"V W@F\"", limits::quoted(text)));
    return parse_edge(m, words[0], words[1]).idx;
  }
  if (!j.is_number_integer())
    throw InputError(fmt::format("\"{}\" must be a whole number{}", kind_name(kind),
                                 kind == KgonKind::edge ? " or \"V W\"" : ""));
  const long long n = j.get<long long>();
  const int count = kind == KgonKind::face     ? m.face_capacity()
                    : kind == KgonKind::vertex ? m.vertex_capacity()
                                               : m.edge_capacity();
  const int i = n >= 1 && n <= count ? static_cast<int>(n - 1) : -1;
  const bool exists = i >= 0 && (kind == KgonKind::face     ? !m.is_deleted(Face(i))
                                 : kind == KgonKind::vertex ? !m.is_deleted(Vertex(i))
                                                            : !m.is_deleted(Edge(i)));
  if (!exists)
    throw InputError(fmt::format("there is no {} {} (the mesh has {} {}s, numbered from 1)",
                                 kind_name(kind), n, count, kind_name(kind)));
  if (kind == KgonKind::face && m.is_hole(Face(i)))
    throw InputError(
        fmt::format("face {} is a hole (a boundary loop of the input): it has no K-gon", n));
  return i;
}

}  // namespace

void parse_kgon_controls(const std::string& text, const std::string& source,
                         const HalfedgeMesh& mesh, KgonOptions& kgons) {
  std::string where;  // the entry being read, for messages
  try {
    const json j = json::parse(text);
    if (!j.is_object() || !j.contains("controls"))
      throw InputError("expected an object with a \"controls\" array (docs/modeler.md)");
    for (const auto& [key, value] : j.items()) {
      if (key == "format") {
        if (value != "stitch-kgon-controls")
          throw InputError("\"format\" must be \"stitch-kgon-controls\"");
      } else if (key != "controls") {
        throw InputError(fmt::format("unknown member \"{}\" (format, controls)", key));
      }
    }
    const json& list = j["controls"];
    if (!list.is_array()) throw InputError("\"controls\" must be an array");
    KgonOptions out = kgons;
    // Which entry set each element's control, so a repeated element can name both.
    std::map<std::pair<KgonKind, int>, size_t> seen;
    for (size_t n = 0; n < list.size(); ++n) {
      where = fmt::format("control {}: ", n + 1);
      const json& e = list[n];
      if (!e.is_object()) throw InputError("an entry must be an object");
      std::optional<KgonKind> kind;
      int element = -1;
      KgonControl c;
      for (const auto& [key, value] : e.items()) {
        if (key == "face" || key == "vertex" || key == "edge") {
          if (kind) throw InputError("name one element: face, vertex or edge");
          kind = key == "face"     ? KgonKind::face
                 : key == "vertex" ? KgonKind::vertex
                                   : KgonKind::edge;
          element = element_number(mesh, *kind, value);
          where = fmt::format("control {} ({} {}): ", n + 1, key,
                              value.is_string() ? value.get<std::string>() : value.dump());
        } else if (!detail::read_kgon_control_member(key, value, c)) {
          throw InputError(fmt::format("unknown member \"{}\" (face, vertex, edge, {})", key,
                                       kgon_control_field_names()));
        }
      }
      if (!kind) throw InputError("name the element: \"face\", \"vertex\" or \"edge\"");
      check_kgon_control(c);
      if (const auto [it, fresh] = seen.try_emplace({*kind, element}, n + 1); !fresh)
        throw InputError(
            fmt::format("control {} already sets this {}", it->second, kind_name(*kind)));
      auto& map = *kind == KgonKind::face     ? out.face
                  : *kind == KgonKind::vertex ? out.vertex
                                              : out.edge;
      map[element] = c;
    }
    kgons = std::move(out);
  } catch (const json::exception& e) {  // syntax errors name the line and column
    std::string what = e.what();
    // "[json.exception.parse_error.101] parse error at line 2, ...": the tag means nothing to a
    // user.
    if (what.rfind("[json.exception.", 0) == 0) what.erase(0, what.find("] ") + 2);
    throw InputError(fmt::format("{}: {}{}", source, where, what));
  } catch (const Error& e) {
    throw_with_message(e, fmt::format("{}: {}{}", source, where, e.what()));
  }
}

void read_kgon_controls(const std::string& path, const HalfedgeMesh& mesh, KgonOptions& kgons) {
  parse_kgon_controls(read_regular_file(path), path, mesh, kgons);
}

}  // namespace stitch
