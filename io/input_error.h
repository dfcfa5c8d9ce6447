#pragma once
// Errors in user input (scenarios, test descriptions, CSV files), located by file, line, column and key.
#include <stdexcept>
#include <string>

namespace motostab::io {

/// Where a value came from: file, 1-based line and column, and the dotted key path ("rear_frame.mass_kg").
struct InputLocation {
  std::string file;
  int line = 0;    ///< 1-based; 0 if unknown
  int column = 0;  ///< 1-based; 0 if unknown
  std::string key;
  /// "file:line:column: key" with the unknown parts left out.
  std::string describe() const;
};

/// What is wrong with the input: a value (or its absence), or a key no reader knows.
enum class InputProblem { Value, UnknownKey };

/// Bad input: the message names the file, line, column and key. Never a crash or a silent default.
class InputError : public std::runtime_error {
 public:
  InputError(const InputLocation& where, const std::string& what, InputProblem problem = InputProblem::Value);
  const InputLocation& getLocation() const { return where_; }
  const std::string& getReason() const { return reason_; }
  InputProblem getProblem() const { return problem_; }
  /// The same error with `more` after its reason (where the value came from, what else was tried).
  InputError withReasonAdded(const std::string& more) const;

 private:
  InputLocation where_;
  std::string reason_;
  InputProblem problem_;
};

/// Output the user asked for cannot be written where they asked (a folder that is a file, no permission,
/// a full disk): theirs to fix, as bad input (exit code 2), not a bug. The location's file is the path;
/// the reason names the step and the system's reason.
class OutputError : public InputError {
 public:
  OutputError(const std::string& path, const std::string& what) : InputError({path, 0, 0, ""}, what) {}
};

}  // namespace motostab::io
