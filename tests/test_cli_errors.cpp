// The command line on bad input: `stitch smooth IN -o OUT` exits with status 2, says what is wrong
// on stderr, and writes nothing.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "temp_folder.hpp"

namespace {

using stitch::testing::read_file;
using stitch::testing::TempFolder;

struct BadFile {
  std::string name;
  std::string content;
  bool strict = false;  ///< refused under --strict only (the repair fixes it otherwise)
};

void PrintTo(const BadFile& f, std::ostream* os) {
  *os << f.name;
}

class CliRefusesBadInput : public ::testing::TestWithParam<BadFile> {};

TEST_P(CliRefusesBadInput, WithStatusTwoAMessageAndNoOutput) {
  TempFolder folder;
  const std::string input = folder.write(GetParam().name, GetParam().content);
  const std::string output = folder.file("out.obj");
  const std::string errors = folder.file("stderr.txt");
  const std::string command = std::string("'") + STITCH_CLI + "' smooth '" + input + "' -o '" +
                              output + "'" + (GetParam().strict ? " --strict" : "") +
                              " > /dev/null 2> '" + errors + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status)) << command;
  EXPECT_EQ(WEXITSTATUS(status), 2) << command << "\n" << read_file(errors);
  const std::string message = read_file(errors);
  EXPECT_NE(message.find(GetParam().name), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(output));
  // Nothing else was left behind either (no temporary files).
  std::vector<std::string> expected{GetParam().name, "stderr.txt"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(folder.entries(), expected);
}

const std::string kCube =
    "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

INSTANTIATE_TEST_SUITE_P(
    Files, CliRefusesBadInput,
    ::testing::Values(BadFile{"empty.obj", ""}, BadFile{"garbage.obj", "%%% not a mesh\n"},
                      BadFile{"nan.obj", "v nan 0 0\n" + kCube},
                      BadFile{"out_of_range.obj", kCube + "f 1 2 99\n"},
                      BadFile{"bowtie.obj",  // two boundary loops touching at a vertex
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n",
                              true},
                      BadFile{"extra_face.obj", kCube + "f 1 2 4 3\n", true},
                      BadFile{"truncated.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n"},
                      BadFile{"lying_header.ply",
                              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                              "property float y\nproperty float z\nelement face 2\n"
                              "property list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
                      BadFile{"unsupported.xyz", "1 2 3\n"}),
    [](const auto& info) {
      std::string name = info.param.name;
      for (char& c : name)
        if (c == '.') c = '_';
      return name;
    });

}  // namespace
