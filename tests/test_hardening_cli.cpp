// The reproductions of issue #10 (found by fuzzing), run as a user runs them: each ends with exit
// status 2, a short message saying what is wrong and where, and no output file; or succeeds with
// finite output that reads back.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/limits.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/primitives.hpp"

namespace stitch {
namespace {

using stitch::testing::CliRun;
using stitch::testing::read_file;
using stitch::testing::stitch_cli;
using stitch::testing::TempFolder;

/// The cube of `stitch primitive cube`, every coordinate multiplied by `scale`.
std::string scaled_cube(double scale) {
  PolygonSoup soup = to_polygon_soup(make_cube());
  std::string text;
  for (const Vec3& p : soup.positions)
    text += fmt::format("v {} {} {}\n", p.x() * scale, p.y() * scale, p.z() * scale);
  for (const auto& loop : soup.faces) {
    text += "f";
    for (int v : loop) text += fmt::format(" {}", v + 1);
    text += "\n";
  }
  return text;
}

/// Runs the command, which must be refused: status 2, a message with every one of `words`, no
/// file `out` (nor a temporary one) left in the folder.
void expect_refused(const TempFolder& folder, const std::string& args,
                    const std::vector<std::string>& words, const std::string& out = "out.obj") {
  const std::vector<std::string> before = folder.entries();
  const CliRun r = stitch_cli(folder, args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  for (const std::string& w : words)
    EXPECT_NE(r.err.find(w), std::string::npos) << args << "\n" << r.err;
  // Short: one line, the offending value quoted at most limits::max_quoted characters.
  EXPECT_LT(r.err.size(), 600U) << args;
  EXPECT_FALSE(std::filesystem::exists(folder.file(out))) << args;
  EXPECT_EQ(folder.entries(), before) << args;
}

/// Runs a command that must succeed.
CliRun succeed(const TempFolder& folder, const std::string& args) {
  CliRun r = stitch_cli(folder, args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return r;
}

/// Every number in an OBJ/OFF/PLY text file that parses is finite (no "nan", no "inf").
bool text_is_finite(const std::string& text) {
  for (const char* bad : {"nan", "inf", "NaN", "Inf"})
    if (text.find(bad) != std::string::npos) return false;
  return true;
}

TEST(HardeningCli, RefusesCoordinatesWhoseProductsOverflow) {
  TempFolder folder;
  folder.write("huge.obj", scaled_cube(1e155));
  expect_refused(folder, "smooth huge.obj -o out.obj", {"huge.obj", "vertex 1", "1e+50"});
  std::string one_far = scaled_cube(1);
  one_far.replace(0, one_far.find('\n'), "v -1e308 -1 -1");
  folder.write("far.obj", one_far);
  expect_refused(folder, "smooth far.obj -o out.obj", {"far.obj", "vertex 1"});
  folder.write("tiny.obj", scaled_cube(1e-200));
  expect_refused(folder, "smooth tiny.obj -o out.obj", {"too small"});
}

TEST(HardeningCli, CoordinatesAtTheLimitGiveFiniteOutputThatReadsBack) {
  TempFolder folder;
  // The cube spans [-1, 1], so this puts its corners exactly at the limits.
  for (const double scale : {limits::max_coordinate, limits::min_extent}) {
    folder.write("edge.obj", scaled_cube(scale));
    succeed(folder, "smooth edge.obj -o out.obj --resolution 2");
    EXPECT_TRUE(text_is_finite(read_file(folder.file("out.obj")))) << scale;
    EXPECT_EQ(topology_stats(read_mesh(folder.file("out.obj"))).genus, 0) << scale;
  }
}

TEST(HardeningCli, RefusesNumericOptionsOutsideTheirRange) {
  TempFolder folder;
  folder.write("cube.obj", scaled_cube(1));
  for (const char* option : {"--kgon-rotate nan", "--kgon-rotate 1e308", "--kgon-scale 1e300",
                             "--kgon-scale nan", "--kgon-scale 0", "--kgon-rotate=-inf"})
    expect_refused(folder, fmt::format("smooth cube.obj -o out.obj {}", option),
                   {std::string(option).substr(0, std::string(option).find_first_of(" ="))});
  expect_refused(folder, "check-surface cube.obj --fold-angle nan", {"--fold-angle"});
  expect_refused(folder, "check-surface cube.obj --through 0 0 nan 0 0 1", {"--through"});
}

TEST(HardeningCli, RefusesRenderOptionsOutsideTheirRange) {
  TempFolder folder;
  // Listed among the sub-commands only when built (an unknown "render --help" is the tool's help).
  if (stitch_cli(folder, "--help").out.find("\n  render ") == std::string::npos)
    GTEST_SKIP() << "stitch is built without the renderer (STITCH_BUILD_RENDER=OFF)";
  folder.write("cube.obj", scaled_cube(1));
  expect_refused(folder, "render cube.obj -o out.png --focus-ev --zoom nan", {"--zoom"}, "out.png");
  expect_refused(folder, "render cube.obj -o out.png --eye 1e300,0,0", {"--eye"}, "out.png");
  expect_refused(folder, "compare cube.obj -o out --zoom 1e300", {"--zoom"}, "out");
}

TEST(HardeningCli, RefusesExtrusionsBeyondTheCoordinateLimit) {
  TempFolder folder;
  succeed(folder, "primitive cube -o cube.obj");
  succeed(folder, "primitive torus 4 4 -o torus.obj");
  expect_refused(folder, "edit cube.obj --op \"extrude-face 1 1e308 1e308\" -o out.obj",
                 {"--op 1", "extrude-face", "face 1", "1e+50"});
  expect_refused(folder,
                 "edit torus.obj --op \"extrude-face 3 1.7e308 1e-308\" --op doo-sabin -o out.obj",
                 {"--op 1", "face 3"});
  expect_refused(folder, "edit cube.obj --op \"extrude-face 1 nan\" -o out.obj", {"distance"});
}

TEST(HardeningCli, AnExtrusionToAPointStaysFinite) {
  // The smallest positive scale collapses the top face onto its centre: degenerate but finite.
  TempFolder folder;
  succeed(folder, "primitive torus 4 4 -o torus.obj");
  succeed(folder, "edit torus.obj --op \"extrude-face 3 1 1e-308\" -o x.obj");
  succeed(folder, "smooth x.obj -o s.obj --resolution 2");
  EXPECT_TRUE(text_is_finite(read_file(folder.file("s.obj"))));
}

TEST(HardeningCli, ConnectingNeighbouringFacesReadsBack) {
  TempFolder folder;
  succeed(folder, "primitive cube -o cube.obj");
  succeed(folder, "edit cube.obj --op \"connect-faces 1 3 1\" -o out.obj");
  const CliRun r = succeed(folder, "info out.obj --json");
  EXPECT_NE(r.out.find("\"genus\": 1"), std::string::npos) << r.out;
}

TEST(HardeningCli, TheSmallestTwistIsTheSameAsItsRemainder) {
  // -2147483648 = 0 (mod 4): once (twist - i) no longer overflows, it is twist 0.
  TempFolder folder;
  succeed(folder, "primitive cube -o cube.obj");
  succeed(folder, "edit cube.obj --op \"connect-faces 1 2 -2147483648\" -o a.obj");
  succeed(folder, "edit cube.obj --op \"connect-faces 1 2 0\" -o b.obj");
  EXPECT_EQ(read_file(folder.file("a.obj")), read_file(folder.file("b.obj")));
}

/// A tetrahedron as binary little-endian PLY whose first face's list length is `count` (uint).
std::string ply_with_list_count(std::uint32_t count) {
  std::string text =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement face 4\n"
      "property list uint int vertex_indices\nend_header\n";
  auto put = [&](auto value) {
    std::array<char, sizeof(value)> bytes;
    std::memcpy(bytes.data(), &value, sizeof(value));
    text.append(bytes.data(), bytes.size());
  };
  const float points[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (const auto& p : points)
    for (float x : p) put(x);
  const std::int32_t faces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  for (int f = 0; f < 4; ++f) {
    put(f == 0 ? count : std::uint32_t{3});
    for (std::int32_t v : faces[f]) put(v);
  }
  return text;
}

TEST(HardeningCli, RefusesPlyListLengthsBeyondAnInt) {
  static_assert(std::endian::native == std::endian::little, "the file is written in host order");
  TempFolder folder;
  folder.write("binary.ply", ply_with_list_count(4294967295U));
  expect_refused(folder, "info binary.ply", {"binary.ply", "face element 0", "list length"});
  folder.write("ascii.ply",
               "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
               "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
               "end_header\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n99999999999999 0 1 2\n3 0 2 3\n"
               "3 0 3 1\n3 1 3 2\n");
  expect_refused(folder, "info ascii.ply", {"ascii.ply", "line 14", "list length"});
}

TEST(HardeningCli, HeaderCountsAreCheckedAgainstTheFileSize) {
  TempFolder folder;
  // Two billion elements without properties take no bytes: nothing to read, at once.
  std::string junk = ply_with_list_count(3);
  junk.insert(junk.find("end_header"), "element junk 2147483647\n");
  folder.write("junk.ply", junk);
  const auto start = std::chrono::steady_clock::now();
  succeed(folder, "info junk.ply");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // It took about 11 minutes; now milliseconds. 30 s leaves room for sanitizer builds.
  EXPECT_LT(seconds, 30.0);
  // Elements with properties cannot outnumber the bytes that could hold them.
  std::string lying = ply_with_list_count(3);
  lying.insert(lying.find("end_header"), "element junk 2147483647\nproperty uchar a\n");
  folder.write("lying.ply", lying);
  expect_refused(folder, "info lying.ply", {"lying.ply", "line 9", "2147483647", "bytes"});
}

TEST(HardeningCli, ATorusWithEveryFaceAlsoReversedIsReadInLinearTime) {
  // Every edge is then shared by four faces, two in each direction: which are twins is searched.
  TempFolder folder;
  const PolygonSoup torus = to_polygon_soup(make_torus(60, 60));
  PolygonSoup both = torus;
  for (auto loop : torus.faces) {
    std::reverse(loop.begin(), loop.end());
    both.faces.push_back(loop);
  }
  write_polygon_soup(folder.file("both.obj"), both);
  const auto start = std::chrono::steady_clock::now();
  const CliRun r = succeed(folder, "info both.obj --json");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(r.out.find("\"faces\": 7200"), std::string::npos) << r.out;
  // It took 75 s (a whole rebuild per ambiguous edge); now well under a second.
  EXPECT_LT(seconds, 30.0);
}

TEST(HardeningCli, RefusesPrimitivesTooLargeToBuild) {
  TempFolder folder;
  expect_refused(folder, "primitive torus 100000 100000 -o out.obj", {"torus", "at most"});
  expect_refused(folder, "primitive prism 2147483647 -o out.obj", {"prism", "at most"});
}

TEST(HardeningCli, ReadsOnlyRegularFiles) {
  TempFolder folder;
  const std::string fifo = folder.file("fifo.obj");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  std::filesystem::create_symlink("/dev/zero", folder.file("zero.obj"));
  expect_refused(folder, "info fifo.obj", {"fifo.obj", "not a regular file"});
  expect_refused(folder, "info zero.obj", {"zero.obj", "not a regular file"});
  expect_refused(folder, "edit zero.obj --ops fifo.obj -o out.obj", {"fifo.obj"});
}

TEST(HardeningCli, QuotesAtMostSixtyCharactersOfABadToken) {
  TempFolder folder;
  const std::string token(2'000'000, '1');
  folder.write("long.obj", "v " + token + " 0 0\n");
  folder.write("long.ply", "ply\nformat ascii 1.0\n" + std::string(100'000, 'x') + "\n");
  expect_refused(folder, "info long.obj", {"long.obj", "line 1", "more characters"});
  expect_refused(folder, "info long.ply", {"long.ply", "line 3", "more characters"});
  folder.write("cube.obj", scaled_cube(1));
  expect_refused(folder,
                 "edit cube.obj --op \"extrude-face 1 " + std::string(5000, '9') + "x\" -o out.obj",
                 {"distance", "more characters"});
}

}  // namespace
}  // namespace stitch
