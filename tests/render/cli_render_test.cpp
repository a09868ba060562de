// `stitch render` and `stitch compare` end to end, headless: sizes, content, the asc/mdc
// difference near a 3-valent point, atomic output and refusal of bad options (exit 2).
#include <gtest/gtest.h>
#include <stb_image.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "../temp_folder.hpp"
#include "cli_helpers.hpp"
#include "test_helpers.hpp"

namespace stitch {
namespace {

using stitch::testing::read_file;
using stitch::testing::TempFolder;
using test::load_png;
using test::run_stitch;

const std::string kCube = std::string(STITCH_EXAMPLES_DIR) + "/cube.obj";
const std::string kTetrahedron = std::string(STITCH_EXAMPLES_DIR) + "/tetrahedron.obj";

TEST(CliRender, WritesAPngOfTheRequestedSizeAndNothingElse) {
  TempFolder folder;
  const std::string out = folder.file("tet.png");
  ASSERT_EQ(run_stitch(folder, "render '" + kTetrahedron + "' -o '" + out +
                                   "' --size 96x64 --show mesh,kgons,nets,ev,tess"),
            0)
      << read_file(folder.file("stderr.txt"));
  const Image im = load_png(out);
  EXPECT_EQ(im.width, 96);
  EXPECT_EQ(im.height, 64);
  // The tetrahedron's surface covers a good part of the frame (iso view).
  EXPECT_GT(test::count_non_background(im), 96 * 64 / 8);
  // Atomic write: no temporary file left beside the image.
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"stderr.txt", "stdout.txt", "tet.png"}));
}

TEST(CliRender, ModesAndViewsGiveDifferentImages) {
  TempFolder folder;
  std::vector<Image> images;
  for (const std::string options :
       {"--mode shaded", "--mode zebra", "--mode isophote", "--mode levels", "--mode patches",
        "--view front", "--eye 4,1,2 --target 0,0,0", "--draw input --show mesh"}) {
    const std::string out = folder.file("im.png");
    ASSERT_EQ(run_stitch(folder, "render '" + kCube + "' -o '" + out + "' --size 64x64 " + options),
              0)
        << options << ": " << read_file(folder.file("stderr.txt"));
    images.push_back(load_png(out));
    ASSERT_EQ(images.back().width, 64) << options;
  }
  for (size_t i = 0; i < images.size(); ++i) {
    for (size_t j = i + 1; j < images.size(); ++j) {
      // 1 of 255 on average: any real change of picture is far above it.
      EXPECT_GT(test::mean_difference(images[i], images[j]), 1.0) << i << " vs " << j;
    }
  }
}

// The AS&C patches meet with a normal jump of several degrees along the edges leaving a cube
// corner (method.md, section 6), which bends the reflection lines; the modified de Casteljau
// surface is smooth there. The two close-ups must differ well beyond antialiasing noise.
TEST(CliRender, ZebraOfAscDiffersFromMdcAtACubeCorner) {
  TempFolder folder;
  const auto zebra = [&](const std::string& options) {
    const std::string out = folder.file("zebra.png");
    EXPECT_EQ(
        run_stitch(folder, "render '" + kCube + "' -o '" + out +
                               "' --mode zebra --focus-ev --size 96x96 --stripes 32 " + options),
        0)
        << read_file(folder.file("stderr.txt"));
    return load_png(out);
  };
  const Image asc = zebra("--method asc --resolution 16"),
              mdc = zebra("--method mdc --resolution 16");
  // The control: the same mdc surface tessellated twice as finely. Its difference is what
  // sampling and antialiasing alone change; the asc/mdc difference (stripes shifted where
  // the AS&C normal jumps) must stand well above it.
  const Image mdc_fine = zebra("--method mdc --resolution 32");
  ASSERT_EQ(asc.width, 96);
  ASSERT_EQ(mdc.width, 96);
  ASSERT_EQ(mdc_fine.width, 96);
  const double method_difference = test::mean_difference(asc, mdc);
  const double sampling_difference = test::mean_difference(mdc, mdc_fine);
  RecordProperty("asc_vs_mdc", std::to_string(method_difference));
  RecordProperty("mdc_vs_finer_mdc", std::to_string(sampling_difference));
  EXPECT_GT(method_difference, 3.0 * sampling_difference)
      << method_difference << " vs " << sampling_difference;
}

struct BadOptions {
  std::string args;  // after "render IN -o OUT"
  std::string expected_in_message;
};

void PrintTo(const BadOptions& b, std::ostream* os) {
  *os << b.args;
}

class CliRenderRefuses : public ::testing::TestWithParam<BadOptions> {};

TEST_P(CliRenderRefuses, WithStatusTwoAndLeavesTheOutputAlone) {
  TempFolder folder;
  const std::string out = folder.write("out.png", "previous content");
  const std::string input =
      GetParam().args.find("missing.obj") != std::string::npos ? folder.file("missing.obj") : kCube;
  std::string args = GetParam().args;
  if (const auto at = args.find("missing.obj"); at != std::string::npos) args.erase(at, 11);
  const std::string output = args.find("-o ") != std::string::npos ? "" : " -o '" + out + "'";
  EXPECT_EQ(run_stitch(folder, "render '" + input + "'" + output + " " + args), 2) << args;
  const std::string message = read_file(folder.file("stderr.txt"));
  EXPECT_NE(message.find(GetParam().expected_in_message), std::string::npos) << message;
  EXPECT_EQ(read_file(out), "previous content");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out.png", "stderr.txt", "stdout.txt"}));
}

INSTANTIATE_TEST_SUITE_P(Options, CliRenderRefuses,
                         ::testing::Values(BadOptions{"--size 0x64", "0x64"},
                                           BadOptions{"--size big", "big"},
                                           BadOptions{"--size 64x", "64x"},
                                           BadOptions{"--mode wireframe", "wireframe"},
                                           BadOptions{"--method bezier", "bezier"},
                                           BadOptions{"--show mesh,normals", "normals"},
                                           BadOptions{"--view diagonal", "diagonal"},
                                           BadOptions{"--eye 1,2 --target 0,0,0", "1,2"},
                                           BadOptions{"--eye 0,0,0 --target 0,0,0", "same point"},
                                           BadOptions{"--view top --focus-ev", "one camera"},
                                           BadOptions{"--target 0,0,0", "--target needs --eye"},
                                           BadOptions{"--resolution 0", "resolution"},
                                           BadOptions{"-o out.jpg", "out.jpg"},
                                           BadOptions{"missing.obj", "missing.obj"}));

TEST(CliRender, FocusOnAMeshWithoutExtraordinaryPointsIsRefused) {
  TempFolder folder;
  const std::string out = folder.file("torus.png");
  EXPECT_EQ(run_stitch(folder, "render '" + std::string(STITCH_EXAMPLES_DIR) + "/torus.obj' -o '" +
                                   out + "' --focus-ev --size 32x32"),
            2);
  EXPECT_NE(read_file(folder.file("stderr.txt")).find("no extraordinary point"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliCompare, WritesImagesPlotAndIndex) {
  TempFolder folder;
  const std::string dir = folder.file("cmp");
  ASSERT_EQ(run_stitch(folder, "compare '" + kTetrahedron + "' -o '" + dir +
                                   "' --size 64x64 --resolution 4"),
            0)
      << read_file(folder.file("stderr.txt"));
  for (const char* name :
       {"zebra_whole.png", "zebra_closeup.png", "zebra_whole_asc.png", "zebra_whole_mdc.png",
        "zebra_whole_cc.png", "index.html", "jump_by_distance.dat"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  }
  // Three 64-pixel panels side by side with gaps of 4 pixels.
  const Image whole = load_png(dir + "/zebra_whole.png");
  EXPECT_EQ(whole.width, 3 * 64 + 2 * 4);
  EXPECT_EQ(whole.height, 64);
  const std::string html = read_file(dir + "/index.html");
  for (const char* text : {"asc", "mdc", "cc", "zebra_closeup.png", "max jump touching EV"}) {
    EXPECT_NE(html.find(text), std::string::npos) << text;
  }
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/jump_by_distance.png"));
    EXPECT_NE(html.find("jump_by_distance.png"), std::string::npos);
  }
}

TEST(CliCompare, WithoutGnuplotSaysSoAndWritesTheRest) {
  TempFolder folder;
  const std::string dir = folder.file("cmp");
  // No gnuplot on this PATH (stitch itself is started by its full path).
  ASSERT_EQ(
      run_stitch(folder,
                 "compare '" + kTetrahedron + "' -o '" + dir + "' --size 32x32 --resolution 2",
                 "PATH=" + folder.path().string()),
      0)
      << read_file(folder.file("stderr.txt"));
  EXPECT_NE(read_file(folder.file("stderr.txt")).find("gnuplot was not found"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir + "/jump_by_distance.png"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/zebra_whole.png"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/jump_by_distance.dat"));
  EXPECT_NE(read_file(dir + "/index.html").find("gnuplot was not found"), std::string::npos);
}

TEST(CliCompare, OnATorusSaysThereIsNoExtraordinaryPoint) {
  TempFolder folder;
  const std::string dir = folder.file("cmp");
  ASSERT_EQ(run_stitch(folder, "compare '" + std::string(STITCH_EXAMPLES_DIR) + "/torus.obj' -o '" +
                                   dir + "' --size 32x32 --resolution 2"),
            0)
      << read_file(folder.file("stderr.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/zebra_whole.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/zebra_closeup.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/jump_by_distance.png"));
  EXPECT_NE(read_file(dir + "/index.html").find("no extraordinary point"), std::string::npos);
}

TEST(CliCompare, RefusesAnOutputThatIsAFile) {
  TempFolder folder;
  const std::string file = folder.write("taken", "x");
  EXPECT_EQ(run_stitch(folder, "compare '" + kTetrahedron + "' -o '" + file + "'"), 2);
  EXPECT_EQ(read_file(file), "x");
}

}  // namespace
}  // namespace stitch
