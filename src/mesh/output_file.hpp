// The file a mesh writer fills from front to back, through its descriptor. Small pieces (headers)
// are gathered, blocks written at once, and every few tens of megabytes written are handed to the
// disk straight away (sync_file_range), so the disk works while the next blocks are computed
// and the fsync that makes the file durable (write_file_atomically_at) has little left to wait
// for: with the whole file left to the final fsync, that wait took longer than computing it.
// Internal to the library.
#pragma once

#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>

namespace stitch::detail {

class OutputFile {
 public:
  /// Creates `path` or truncates it. Throws stitch::Error naming `path` when it cannot.
  explicit OutputFile(const std::string& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Appends bytes. Throws stitch::Error with the system's reason (a full disk: "No space left on
  /// device") when they cannot be written.
  void write(const char* data, size_t size);
  OutputFile& operator<<(std::string_view text) {
    write(text.data(), text.size());
    return *this;
  }
  OutputFile& operator<<(char c) {
    write(&c, 1);
    return *this;
  }
  template <std::integral Integer>
  OutputFile& operator<<(Integer value) {
    return *this << std::string_view(std::to_string(value));
  }
  /// Writes what is still gathered and closes the file; throws like write().
  void close();

 private:
  void write_through(const char* data, size_t size);

  int fd_ = -1;
  std::string gathered_;
  std::int64_t written_ = 0;  ///< bytes in the file
  std::int64_t handed_ = 0;   ///< of those, handed to the disk
};

}  // namespace stitch::detail
