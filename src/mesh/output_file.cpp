#include "mesh/output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch::detail {

namespace {

// Pieces smaller than this are gathered into one write.
constexpr size_t kGather = 64 * 1024;
// Handing over less at a time costs more calls; more lets the disk sit idle longer at the start
// and leaves more for the final fsync.
constexpr std::int64_t kHandOver = 32 * 1024 * 1024;

OutputError write_error() {
  return OutputError(fmt::format("write error: {}", std::strerror(errno)));
}

}  // namespace

OutputFile::OutputFile(const std::string& path)
    : fd_(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666)) {
  if (fd_ < 0) throw OutputError(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
}

void OutputFile::write(const char* data, size_t size) {
  if (gathered_.size() + size <= kGather) {
    gathered_.append(data, size);
    return;
  }
  write_through(gathered_.data(), gathered_.size());
  gathered_.clear();
  write_through(data, size);
}

void OutputFile::close() {
  write_through(gathered_.data(), gathered_.size());
  gathered_.clear();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw write_error();
}

void OutputFile::write_through(const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd_, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;  // a regular file takes no byte only when it cannot grow
      throw write_error();
    }
    data += n;
    size -= static_cast<size_t>(n);
    written_ += n;
  }
#ifdef __linux__
  if (written_ - handed_ >= kHandOver) {
    // Starts the write-out and returns; a file system that cannot (or a device) is left to the
    // final fsync, which reports any error.
    ::sync_file_range(fd_, handed_, written_ - handed_, SYNC_FILE_RANGE_WRITE);
    handed_ = written_;
  }
#endif
}

}  // namespace stitch::detail
