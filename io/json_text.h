#pragma once
// JSON outputs: every number finite. nlohmann::json writes a NaN or an infinity as `null`, which would
// hide a value that went bad; values that do not exist are written as `null` on purpose instead.
#include <nlohmann/json.hpp>

#include <string>

namespace motostab::io {

/// `value` as indented JSON text (two spaces, newline-terminated). Throws ResultError (exit code 3)
/// naming `file` and the key path ("critical_speeds.weave.mean_mps", "modes[2].real") of the first
/// number that is NaN or infinite.
std::string formatJson(const nlohmann::json& value, const std::string& file);

}  // namespace motostab::io
