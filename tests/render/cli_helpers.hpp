// Shared by the render tests that run the stitch tool: running it, and reading the PNGs it
// writes (with stb_image, which defines the format's reading for us).
#pragma once

#include <stb_image.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "../temp_folder.hpp"
#include "stitch/render/image.hpp"

namespace stitch::test {

/// Runs `stitch ARGS` (stdout and stderr to files in `folder`) and returns the exit status.
/// `environment` (e.g. "VAR=value") is put before the command.
inline int run_stitch(const testing::TempFolder& folder, const std::string& args,
                      const std::string& environment = "") {
  const std::string command = environment + " '" + STITCH_CLI + "' " + args + " > '" +
                              folder.file("stdout.txt") + "' 2> '" + folder.file("stderr.txt") +
                              "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The PNG's pixels as RGBA, or an empty image when it cannot be read.
inline Image load_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (pixels == nullptr) return {};
  Image im(w, h);
  im.rgba.assign(pixels, pixels + static_cast<size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return im;
}

}  // namespace stitch::test
