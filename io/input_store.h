#pragma once
// What the readers of one scenario's sections share: the files the sections name (a .tir file, an
// identified swingarm fragment), read once when the scenario is loaded and kept for every later
// build, worker copy, sample and candidate; and the warnings the readers found, each kept once.
// Libraries never print: the command that loaded the scenario reports the warnings.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "io/input_error.h"

namespace motostab::io {

/// A warning a section reader found: where (the key that gives the value) and what it means.
struct InputWarning {
  InputLocation where;
  std::string message;
};

/// Thread-safe: sweep workers and parallel samples build their models from one store.
class InputStore {
 public:
  /// The text of the input file `path` (io/input_file.h readInputFile, at most `maxBytes`): read on
  /// the first request, kept after that (the file may change or go once the scenario is loaded).
  std::string readText(const std::string& path, std::uintmax_t maxBytes);
  /// Records a warning at `where`; one with the message of a recorded one is not added again (two
  /// sections naming one file give one warning, at the first).
  void addWarning(const InputLocation& where, const std::string& message);
  /// The warnings recorded, in the order first found.
  std::vector<InputWarning> getWarnings() const;
  /// How many times `path` was read from disk (0 or 1; for tests).
  long getReadCount(const std::string& path) const;

 private:
  mutable std::mutex lock_;
  std::map<std::string, std::string> texts_;
  std::map<std::string, long> reads_;
  std::vector<InputWarning> warnings_;
};

}  // namespace motostab::io
