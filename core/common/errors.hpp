// Typed exceptions thrown by the core; the extension maps each to an SQLSTATE.
#pragma once

#include <stdexcept>
#include <string>

namespace arg {

// Base of every error the core throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The input bytes are not a valid mesh, image, ARG or weights text. The message names the
// format and, where known, the line or byte offset.
class InputError : public Error {
 public:
  using Error::Error;
};

// The input is well formed but larger than a configured cap (vertices, faces, bytes, pixels).
class LimitError : public Error {
 public:
  using Error::Error;
};

// A build that would take, or has taken, more memory than its cap (Limits::max_build_bytes).
// The message gives the figures in MB; the caller names its own setting.
class MemoryLimitError : public LimitError {
 public:
  using LimitError::LimitError;
};

// Two ARGs made by builders of another major or minor version, or with other build options,
// whose comparison would rank by how they were built as much as by shape
// (graph/comparable.hpp). The message names both versions and both options.
class Incomparable : public Error {
 public:
  using Error::Error;
};

// The caller asked the computation to stop (query cancel, statement timeout, Ctrl-C).
class Interrupted : public Error {
 public:
  Interrupted() : Error("interrupted") {}
};

}  // namespace arg
