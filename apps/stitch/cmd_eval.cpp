// stitch eval IN --at FILE: exact evaluation at given points, for comparing surfaces.
#include <fmt/format.h>

#include <charconv>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "options.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/topology/operation.hpp"

namespace stitch::cli {

namespace {

struct EvalArgs {
  InputOptions in;
  std::string at;
  std::string method{method_table().front().name};
  std::string format = "csv";
  KgonCliOptions kgon;
};

struct Query {
  int line = 0;
  Corner corner;
  double u = 0, v = 0;
};

double parameter(std::string_view token, const std::string& where) {
  double x = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
  if (ec != std::errc() || end != token.data() + token.size() || !(x >= 0 && x <= 1))
    throw InputError(
        fmt::format("{}: '{}' is not a parameter from 0 to 1", where, limits::quoted(token)));
  return x;
}

/// `patch u v` (patch = corner number, 0-based, as in --unwelded PLY, or the corner's name V@F),
/// or `face vertex u v` (1-based, as everywhere on the command line); blank lines and # comments
/// are skipped.
std::vector<Query> read_queries(const std::string& path, const HalfedgeMesh& mesh) {
  const std::string text = read_regular_file(path);
  std::vector<Query> queries;
  int line_number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++line_number;
    const std::vector<std::string_view> words = split_words(without_comment(line));
    if (words.empty()) continue;
    const std::string where = fmt::format("{}, line {}", path, line_number);
    Query q;
    q.line = line_number;
    if (words.size() == 3 && words[0].find('@') != std::string_view::npos) {
      try {
        q.corner = parse_corner(mesh, words[0]);
      } catch (const Error& e) {
        throw_with_message(e, fmt::format("{}: {}", where, e.what()));
      }
    } else if (words.size() == 3) {
      int h = -1;
      const auto [p, ec] = std::from_chars(words[0].data(), words[0].data() + words[0].size(), h);
      if (ec != std::errc() || p != words[0].data() + words[0].size() || h < 0 ||
          h >= mesh.halfedge_capacity() || mesh.is_deleted(Halfedge(h)))
        throw InputError(fmt::format("{}: '{}' is not a patch number (0 to {})", where,
                                     limits::quoted(words[0]), mesh.halfedge_capacity() - 1));
      q.corner = Corner(h);
    } else if (words.size() == 4) {
      try {
        q.corner = parse_corner(mesh, fmt::format("{}@{}", words[1], words[0]));
      } catch (const Error& e) {
        throw_with_message(e, fmt::format("{}: {}", where, e.what()));
      }
    } else {
      throw InputError(fmt::format("{}: expected 'patch u v' or 'face vertex u v', got {} words",
                                   where, words.size()));
    }
    q.u = parameter(words[words.size() - 2], where);
    q.v = parameter(words[words.size() - 1], where);
    queries.push_back(q);
  }
  if (queries.empty()) throw InputError(fmt::format("{}: no points to evaluate", path));
  return queries;
}

void run_eval(const EvalArgs& a) {
  if (a.format != "csv" && a.format != "json")
    throw InputError(
        fmt::format("--format must be csv or json, not '{}'", limits::quoted(a.format)));
  const HalfedgeMesh mesh = load_input(a.in);
  const std::vector<Query> queries = read_queries(a.at, mesh);
  const Method method = parse_method(a.method);
  const BuiltSurface built = build_cli_surface(a.kgon, mesh, method, a.in.path);
  // Points are asked for by the input's corners; refined for semi-sharp tags, each is found on
  // the refined patch that holds it, its derivatives taken back to the input corner's (u, v).
  auto evaluate = [&built](const Query& q) {
    if (!built.refined) return built.surface.evaluate(q.corner, q.u, q.v);
    const SemiSharpMesh::Point p = built.refined->point(q.corner, q.u, q.v);
    return p.to_input(built.surface.evaluate(p.corner, p.u, p.v));
  };
  // Full precision: {} and nlohmann both print the shortest text that reads back exactly.
  if (a.format == "csv") {
    fmt::print(
        "line,patch,face,vertex,u,v,x,y,z,du_x,du_y,du_z,dv_x,dv_y,dv_z,normal_x,normal_y,"
        "normal_z,level,corner\n");
    for (const Query& q : queries) {
      const SurfacePoint p = evaluate(q);
      fmt::print("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", q.line,
                 q.corner.idx, mesh.face(q.corner).idx + 1, mesh.origin(q.corner).idx + 1, q.u, q.v,
                 p.position.x(), p.position.y(), p.position.z(), p.du.x(), p.du.y(), p.du.z(),
                 p.dv.x(), p.dv.y(), p.dv.z(), p.normal.x(), p.normal.y(), p.normal.z(), p.level,
                 corner_name(mesh, q.corner));
    }
    return;
  }
  auto vec = [](const Vec3& x) { return nlohmann::json::array({x.x(), x.y(), x.z()}); };
  nlohmann::json points = nlohmann::json::array();
  for (const Query& q : queries) {
    const SurfacePoint p = evaluate(q);
    points.push_back({{"line", q.line},
                      {"patch", q.corner.idx},
                      {"corner", corner_name(mesh, q.corner)},
                      {"face", mesh.face(q.corner).idx + 1},
                      {"vertex", mesh.origin(q.corner).idx + 1},
                      {"u", q.u},
                      {"v", q.v},
                      {"position", vec(p.position)},
                      {"du", vec(p.du)},
                      {"dv", vec(p.dv)},
                      {"normal", vec(p.normal)},
                      {"level", p.level}});
  }
  fmt::print("{}\n", nlohmann::json{{"method", a.method}, {"points", points}}.dump(1));
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand(
      "eval",
      "Evaluate the surface exactly at given points: position, du, dv and unit normal, full "
      "precision");
  add_input_options(cmd, args->in);
  cmd->add_option("--at", args->at,
                  "file of points, one per line: 'patch u v' (patch = corner number from 0, as "
                  "in --unwelded PLY, or the corner's name V@F as in Bezier JSON and STEP) or "
                  "'face vertex u v' (1-based); u, v from 0 to 1; the output names each corner "
                  "V@F")
      ->required();
  add_method_option(cmd, args->method, false, &args->in);
  cmd->add_option("--format", args->format, "csv or json")->capture_default_str();
  add_kgon_options(cmd, args->kgon, &args->in);
  cmd->callback([args] { run_eval(*args); });
}

}  // namespace stitch::cli
