#include "io/input_error.h"

namespace motostab::io {

std::string InputLocation::describe() const {
  std::string s = file.empty() ? std::string("<input>") : file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  if (!key.empty()) s += ": " + key;
  return s;
}

InputError::InputError(const InputLocation& where, const std::string& what, InputProblem problem)
    : std::runtime_error(where.describe() + ": " + what), where_(where), reason_(what), problem_(problem) {}

InputError InputError::withReasonAdded(const std::string& more) const { return InputError(where_, reason_ + more, problem_); }

}  // namespace motostab::io
