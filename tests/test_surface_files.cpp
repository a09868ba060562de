// Writing the smooth surface: the streamed writer gives the same bytes as tessellating first, the
// bytes do not depend on the number of threads, and every format reads back.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <tbb/global_control.h>

#include <array>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "cli_run.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace stitch {
namespace {

using testing::read_file;
using testing::TempFolder;

/// The streamed formats with the extensions their files get.
constexpr std::array<std::pair<MeshFileFormat, const char*>, 6> kStreamed{{
    {MeshFileFormat::obj, ".obj"},
    {MeshFileFormat::ply, ".ply"},
    {MeshFileFormat::off, ".off"},
    {MeshFileFormat::stl, ".stl"},
    {MeshFileFormat::glb, ".glb"},
    {MeshFileFormat::gltf, ".gltf"},
}};

/// `name` in the subfolder `sub` of the folder (made if need be): files of one run keep the
/// names of another's, as a .gltf names its .bin.
std::string file_in(const TempFolder& folder, const std::string& sub, const std::string& name) {
  std::filesystem::create_directories(folder.file(sub));
  return folder.file(sub + "/" + name);
}

/// The bytes of a written surface file, a .gltf's followed by its buffer's.
std::string surface_bytes(const std::string& path) {
  std::string bytes = read_file(path);
  if (path.ends_with(".gltf"))
    bytes += read_file(std::filesystem::path(path).replace_extension(".bin").string());
  return bytes;
}

/// A mesh with every kind of element the layout numbers: extraordinary vertices and faces, a
/// face that runs along one edge twice (a hole made by insert-edge), and deleted elements.
HalfedgeMesh mixed_mesh() {
  HalfedgeMesh mesh = make_cube();
  apply_operation(mesh, "insert-edge 1@1 5@2");
  apply_operation(mesh, "insert-edge 2@3 5@3");
  return mesh;
}

/// The files of every format, written with `threads` threads, by the streamed writer.
std::vector<std::string> written_with(int threads, const HalfedgeMesh& mesh, const Surface& surface,
                                      const TempFolder& folder, bool ascii) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::vector<std::string> files;
  for (const auto& [format, ext] : kStreamed) {
    const std::string path =
        file_in(folder, "threads" + std::to_string(threads), "surface" + std::string(ext));
    SurfaceFileOptions options;
    options.ascii_ply = ascii;
    write_smooth_surface(path, format, mesh, surface, 5, options);
    files.push_back(surface_bytes(path));
  }
  return files;
}

TEST(SmoothSurfaceFile, SameBytesWithOneOrTwoThreadsAndAsTessellatingFirst) {
  const HalfedgeMesh mesh = mixed_mesh();
  ASSERT_TRUE(mesh.has_garbage()) << "the mesh should have deleted elements";
  for (const Method method : {Method::mdc, Method::asc, Method::cc}) {
    const Surface surface(mesh, method);
    TempFolder folder;
    for (const bool ascii : {false, true}) {
      const auto one = written_with(1, mesh, surface, folder, ascii);
      const auto two = written_with(2, mesh, surface, folder, ascii);
      EXPECT_EQ(one, two) << to_string(method);
      // Tessellating first (in memory) and writing that gives the same files.
      const TessellatedMesh tessellated = tessellate(mesh, surface, {5, true});
      SurfaceFileOptions options;
      options.ascii_ply = ascii;
      size_t i = 0;
      for (const auto& [format, ext] : kStreamed) {
        const std::string path = file_in(folder, "memory", "surface" + std::string(ext));
        write_surface_mesh(path, format, tessellated, options);
        EXPECT_EQ(surface_bytes(path), one[i++]) << to_string(method) << ext;
      }
    }
  }
}

TEST(SmoothSurfaceFile, TessellationDoesNotDependOnThreads) {
  const HalfedgeMesh mesh = mixed_mesh();
  const Surface surface(mesh, Method::mdc);
  const auto run = [&](int threads, bool welded) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return tessellate(
        mesh, surface,
        {.resolution = 7, .welded = welded, .uv = true, .patch = true, .level = true});
  };
  for (const bool welded : {true, false}) {
    const TessellatedMesh a = run(1, welded), b = run(2, welded);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.quads, b.quads);
    EXPECT_EQ(a.patch, b.patch);
    EXPECT_EQ(a.level, b.level);
  }
}

TEST(SmoothSurfaceFile, KgonsAndNetsDoNotDependOnThreads) {
  const HalfedgeMesh mesh = mixed_mesh();
  KgonOptions options;
  options.global.scale = 0.8;
  options.global.rotate_deg = 10;
  const auto build = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return build_bezier_surface(mesh, options);
  };
  const BezierSurface one = build(1), two = build(2);
  EXPECT_EQ(one.nets, two.nets);
  EXPECT_EQ(one.kgons.corner_point, two.kgons.corner_point);
  for (size_t f = 0; f < one.kgons.face.size(); ++f)
    EXPECT_EQ(one.kgons.face[f].points, two.kgons.face[f].points) << "face " << f;
  for (size_t v = 0; v < one.kgons.vertex.size(); ++v)
    EXPECT_EQ(one.kgons.vertex[v].points, two.kgons.vertex[v].points) << "vertex " << v;
}

TEST(SmoothSurfaceFile, EveryFormatReadsBackAsTheSurface) {
  const HalfedgeMesh mesh = mixed_mesh();
  const Surface surface(mesh, Method::mdc);
  const TessellatedMesh expected = tessellate(mesh, surface, {4, true});
  const TopologyStats input = topology_stats(mesh);
  TempFolder folder;
  for (const bool ascii : {false, true})
    for (const auto& [format, ext] : {kStreamed[0], kStreamed[1], kStreamed[2]}) {
      const std::string path = folder.file(std::string("surface") + ext);
      SurfaceFileOptions options;
      options.ascii_ply = ascii;
      const SurfaceFileCounts counts =
          write_smooth_surface(path, format, mesh, surface, 4, options);
      EXPECT_EQ(counts.vertices, expected.num_vertices());
      EXPECT_EQ(counts.quads, static_cast<std::int64_t>(expected.quads.size()));
      // Text and binary keep every double exactly.
      const PolygonSoup soup = read_polygon_soup(path);
      EXPECT_EQ(soup.positions, expected.positions) << ext;
      ASSERT_EQ(soup.faces.size(), expected.quads.size()) << ext;
      for (size_t q = 0; q < soup.faces.size(); ++q)
        ASSERT_EQ(soup.faces[q],
                  std::vector<int>(expected.quads[q].begin(), expected.quads[q].end()))
            << ext << " quad " << q;
      // Welded by construction: a closed surface with the input's genus.
      const TopologyStats stats = topology_stats(read_mesh(path));
      EXPECT_EQ(stats.genus, input.genus) << ext;
    }
  // STL stores floats and repeats vertices; the reader welds them again.
  const std::string stl = folder.file("surface.stl");
  write_smooth_surface(stl, MeshFileFormat::stl, mesh, surface, 4);
  EXPECT_EQ(read_file(stl).size(), 84u + 50u * 2u * expected.quads.size());
}

TEST(SmoothSurfaceFile, GltfReadsBackAsTheWeldedSurface) {
  const HalfedgeMesh mesh = mixed_mesh();
  const Surface surface(mesh, Method::mdc);
  const TessellatedMesh expected = tessellate(mesh, surface, {4, true});
  TempFolder folder;
  for (const auto& [format, ext] :
       {std::pair{MeshFileFormat::glb, ".glb"}, std::pair{MeshFileFormat::gltf, ".gltf"}}) {
    const std::string path = folder.file(std::string("surface") + ext);
    write_smooth_surface(path, format, mesh, surface, 4);
    // Quads become two triangles each; glTF keeps float positions, welded again on reading.
    const PolygonSoup soup = read_polygon_soup(path);
    EXPECT_EQ(soup.positions.size(), expected.positions.size()) << ext;
    EXPECT_EQ(soup.faces.size(), 2 * expected.quads.size()) << ext;
    for (size_t i = 0; i < soup.positions.size(); i += 97) {
      double nearest = INFINITY;
      for (const Vec3& p : expected.positions)
        nearest = std::min(nearest, (p - soup.positions[i]).norm());
      EXPECT_LT(nearest, 1e-6) << ext << " vertex " << i;  // float precision of a unit-size model
    }
    EXPECT_EQ(topology_stats(read_mesh(path)).genus, topology_stats(mesh).genus) << ext;
  }
  const std::string bad = folder.file("bad.glb");
  { std::ofstream(bad) << "glTF but not really"; }
  const std::string message = test::error_of([&] { read_polygon_soup(bad); });
  EXPECT_NE(message.find("bad.glb: not a glTF 2.0 file"), std::string::npos) << message;
  // Found by fuzz-gltf: an accessor number past the list escaped as std::out_of_range.
  const std::string fuzzed = test::error_of([] {
    read_polygon_soup(std::string(STITCH_TEST_DATA_DIR) +
                      "/regressions/gltf_accessor_out_of_range.glb");
  });
  EXPECT_NE(fuzzed.find("mesh 0 primitive 0: accessor 5 does not exist"), std::string::npos)
      << fuzzed;
  // A .gltf whose buffer is a pipe is refused, not read forever (nor opened: that would block).
  const std::string text = testing::read_file(folder.file("surface.gltf"));
  const std::string device = folder.file("pipe.gltf");
  ASSERT_EQ(::mkfifo(folder.file("pipe.bin").c_str(), 0600), 0);
  {
    std::string redirected = text;
    const size_t at = redirected.find("surface.bin");
    ASSERT_NE(at, std::string::npos);
    redirected.replace(at, std::string("surface.bin").size(), "pipe.bin");
    std::ofstream(device) << redirected;
  }
  const std::string refused = test::error_of([&] { read_polygon_soup(device); });
  EXPECT_NE(refused.find("pipe.gltf: not a glTF 2.0 file tinygltf can read: File read error"),
            std::string::npos)
      << refused;
}

TEST(SmoothSurfaceFile, WriteErrorsNameTheFileAndLeaveNothing) {
  const HalfedgeMesh mesh = make_cube();
  const Surface surface(mesh, Method::mdc);
  const std::string message = test::error_of(
      [&] { write_smooth_surface("/dev/full", MeshFileFormat::ply, mesh, surface, 8); });
  EXPECT_NE(message.find("/dev/full"), std::string::npos) << message;
}

TEST(SmoothSurfaceFile, AFileThatCannotGrowIsAClearErrorAndLeavesNothing) {
  // A file size limit (RLIMIT_FSIZE, with SIGXFSZ ignored so that write() fails with EFBIG)
  // stops the writers mid-file as a full disk would, in an ordinary folder.
  const HalfedgeMesh mesh = make_cube();
  const Surface surface(mesh, Method::mdc);
  TempFolder folder;
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto saved_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limit = saved;
  limit.rlim_cur = 64 * 1024;  // the files below are 0.5 to 3 MB
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
  std::vector<std::string> messages;
  for (const auto& [format, ext] : kStreamed) {
    const std::string path = folder.file(std::string("surface") + ext);
    const MeshFileFormat f = format;  // clang before 16 captures no structured binding
    messages.push_back(test::error_of([&] { write_smooth_surface(path, f, mesh, surface, 32); }));
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, saved_handler);
  for (const std::string& message : messages) {
    EXPECT_NE(message.find(folder.file("surface")), std::string::npos) << message;
    EXPECT_NE(message.find("write error: File too large"), std::string::npos) << message;
  }
  EXPECT_TRUE(std::filesystem::is_empty(folder.path()));
}

TEST(SmoothCommand, BinaryPlyByDefaultAsciiOnRequestAndQuietIsQuiet) {
  TempFolder folder;
  ASSERT_EQ(testing::stitch_cli(folder, "primitive cube -o cube.obj").status, 0);
  const auto binary = testing::stitch_cli(folder, "smooth cube.obj -o b.ply --progress");
  ASSERT_EQ(binary.status, 0) << binary.err;
  EXPECT_NE(binary.err.find("writing b.ply"), std::string::npos) << binary.err;
  EXPECT_NE(read_file(folder.file("b.ply")).find("format binary_little_endian 1.0\n"),
            std::string::npos);
  const auto ascii = testing::stitch_cli(folder, "smooth cube.obj -o a.ply --ascii --quiet");
  ASSERT_EQ(ascii.status, 0) << ascii.err;
  EXPECT_EQ(ascii.err, "");
  EXPECT_NE(read_file(folder.file("a.ply")).find("format ascii 1.0\n"), std::string::npos);
  // -q as for stitch edit.
  const auto short_flag = testing::stitch_cli(folder, "smooth cube.obj -o q.ply -q --progress");
  ASSERT_EQ(short_flag.status, 0) << short_flag.err;
  EXPECT_EQ(short_flag.err, "");
  const auto doubles = read_polygon_soup(folder.file("b.ply")).positions;
  EXPECT_EQ(read_polygon_soup(folder.file("a.ply")).positions, doubles);
  // --float: half the vertex bytes, each coordinate the nearest float (binary), or the shortest
  // text that reads back as that float (ASCII).
  for (const char* flags : {"", " --ascii"}) {
    const auto single =
        testing::stitch_cli(folder, std::string("smooth cube.obj -o f.ply --float") + flags);
    ASSERT_EQ(single.status, 0) << single.err;
    EXPECT_NE(read_file(folder.file("f.ply")).find("property float x\n"), std::string::npos);
    const auto floats = read_polygon_soup(folder.file("f.ply")).positions;
    ASSERT_EQ(floats.size(), doubles.size());
    for (size_t i = 0; i < floats.size(); ++i)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(static_cast<float>(floats[i][k]), static_cast<float>(doubles[i][k]))
            << flags << " vertex " << i;
  }
}

TEST(SmoothCommand, RefusesUpFrontWhatWouldNotFitInMemory) {
  TempFolder folder;
  ASSERT_EQ(testing::stitch_cli(folder, "primitive torus 20 20 -o torus.obj").status, 0);
  // 1600 corners need about 1.6 MB (1 kB each); an unwelded tessellation at resolution 64 adds
  // about 500 MB. A limit of 0.1 GB takes the first and refuses the second.
  const auto fits = testing::stitch_cli(folder, "smooth torus.obj -o s.ply --max-memory 0.1");
  EXPECT_EQ(fits.status, 0) << fits.err;
  const auto refused = testing::stitch_cli(
      folder, "smooth torus.obj -o u.ply --unwelded --resolution 64 --max-memory 0.1");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("needs about 0."), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("more than the 0.10 GB allowed by --max-memory"), std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(folder.file("u.ply")));
  // glTF and STL are streamed like PLY: a resolution whose whole tessellation (about 0.2 GB)
  // would not fit is written.
  for (const char* out : {"s.glb", "s.stl"}) {
    const auto streamed = testing::stitch_cli(
        folder, fmt::format("smooth torus.obj -o {} --resolution 32 --max-memory 0.1", out));
    EXPECT_EQ(streamed.status, 0) << streamed.err;
  }
}

}  // namespace
}  // namespace stitch
