// Running the built `stitch` executable from a test, as a user would.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "temp_folder.hpp"

namespace stitch::testing {

struct CliRun {
  int status = -1;  ///< exit status, -1 when the process did not exit normally
  std::string out, err;
};

/// Runs `stitch ARGS` in the folder, capturing stdout and stderr.
inline CliRun stitch_cli(const TempFolder& folder, const std::string& args) {
  const std::string out = folder.file("stdout.txt"), err = folder.file("stderr.txt");
  const std::string command = "cd '" + folder.path().string() + "' && '" + STITCH_CLI + "' " +
                              args + " > '" + out + "' 2> '" + err + "'";
  const int status = std::system(command.c_str());
  CliRun r;
  if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace stitch::testing
