// Running the real stitch-modeler under Xvfb (Mesa's software renderer) and reading what it
// wrote: shared by the end-to-end tests.
#pragma once

#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace stitch::modeler {

inline bool have_xvfb_run() {
  return std::system("command -v xvfb-run > /dev/null 2>&1") == 0;
}

/// Runs the modeler under a fresh virtual X server; returns its exit status. The server number
/// search starts at a number from the process id, so tests run in parallel (ctest -j) do not
/// race for the same display (`xvfb-run -a` alone can). `environment`: "NAME=value ..." for the
/// modeler's environment.
inline int run_modeler(const std::string& args, const std::string& log,
                       const std::string& screen = "1280x1024x24",
                       const std::string& environment = "") {
  const std::string server = std::to_string(100 + ::getpid() % 800);
  const std::string command = environment + " LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -n " + server +
                              " -s '-screen 0 " + screen + "' " + std::string(STITCH_MODELER) +
                              " " + args + " > '" + log + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
};

inline Png load_png(const std::string& path) {
  Png p;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &p.width, &p.height, &channels, 4);
  if (!data) return p;
  p.rgba.assign(data, data + static_cast<size_t>(p.width) * p.height * 4);
  stbi_image_free(data);
  return p;
}

/// Number of distinct colours: a blank (one-colour) image has 1.
inline size_t colours(const Png& p) {
  std::set<unsigned> seen;
  for (size_t i = 0; i + 3 < p.rgba.size(); i += 4)
    seen.insert(p.rgba[i] << 16 | p.rgba[i + 1] << 8 | p.rgba[i + 2]);
  return seen.size();
}

}  // namespace stitch::modeler
