#pragma once
// A computation that ran on valid input but could not deliver its result (e.g. no mode identified).
// The command line exits with code 3 for it, so scripts can tell it from bad input (2) and crashes (1).
#include <stdexcept>
#include <string>

namespace motostab::io {

/// Valid input, no result: the message says what was tried and what to set (exit code 3).
class ResultError : public std::runtime_error {
 public:
  explicit ResultError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace motostab::io
