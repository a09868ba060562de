// The errors stitch throws. Every one derives from stitch::Error and says, in its message, what
// is wrong and where; the kind tells a caller what to do about it without reading the text (the
// command line maps kinds to exit statuses in apps/stitch/main.cpp, Python to exception types).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace stitch {

/// The base of every error stitch throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file, stream or mesh that is not valid input: malformed text, counts that do not fit the
/// file, non-manifold or non-orientable polygons, NaN coordinates.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A topology operation refused because of the mesh it would apply to: the edge would be a loop,
/// the result would not be a manifold, there is no such element. The mesh is left as it was.
class TopologyError : public Error {
 public:
  using Error::Error;
};

/// A caller's request that cannot mean anything: an unknown operation or option value, a number
/// out of its range, an unknown file extension.
class UsageError : public Error {
 public:
  using Error::Error;
};

/// Writing failed: the folder is not writable, the disk is full. Nothing was left half-written.
class OutputError : public Error {
 public:
  using Error::Error;
};

/// Throws an error of e's kind with another message (a caller adding where it happened).
[[noreturn]] inline void throw_with_message(const Error& e, std::string message) {
  if (dynamic_cast<const InputError*>(&e)) throw InputError(std::move(message));
  if (dynamic_cast<const TopologyError*>(&e)) throw TopologyError(std::move(message));
  if (dynamic_cast<const UsageError*>(&e)) throw UsageError(std::move(message));
  if (dynamic_cast<const OutputError*>(&e)) throw OutputError(std::move(message));
  throw Error(std::move(message));
}

/// Error's name in stitch 0.1, kept so that code written against it still compiles; stitch itself
/// throws the kinds above.
using MeshError = Error;

}  // namespace stitch
