// Runs the Khronos glTF validator (npm gltf-validator, installed on first use by
// scripts/install-gltf-validator.sh into the build folder) from the stitch-tests binary.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "temp_folder.hpp"

namespace stitch::test {

/// The validator's report on the files, with its exit status in `status`; empty when node is
/// missing.
inline std::string validate_gltf(const std::vector<std::string>& files, int* status) {
  if (std::system("node --version > /dev/null 2>&1") != 0) return "";
  const std::string folder = std::string(STITCH_GLTF_VALIDATOR_DIR);
  const std::string install = "bash '" + std::string(STITCH_SOURCE_DIR) +
                              "/scripts/install-gltf-validator.sh' '" + folder + "'";
  EXPECT_EQ(std::system(install.c_str()), 0) << "npm install gltf-validator failed";
  std::string command =
      "node '" + std::string(STITCH_SOURCE_DIR) + "/tests/gltf/validate.js' '" + folder + "'";
  for (const auto& f : files) command += " '" + f + "'";
  const std::string out = files.front() + ".report";
  *status = std::system((command + " > '" + out + "' 2>&1").c_str());
  return testing::read_file(out);
}

}  // namespace stitch::test
