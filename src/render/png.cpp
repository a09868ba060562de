// PNG output, apart from image.cpp so that rendering does not depend on file I/O.
#include <fmt/format.h>

#include <ostream>

#include "stitch/mesh/io.hpp"
#include "stitch/render/gl_context.hpp"
#include "stitch/render/image.hpp"

namespace stitch {

void write_png(const std::string& path, const Image& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

}  // namespace stitch
