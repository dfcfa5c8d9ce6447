#pragma once
// Output files are written completely or not at all.
#include <filesystem>
#include <string>

namespace motostab::io {

/// Writes `content` to `path` through a temporary file in the same folder and a rename, so a reader
/// never sees a partial file. Creates missing parent folders. Throws std::runtime_error on failure.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

/// A fresh hidden temporary path beside `path` (same folder, so a rename is atomic).
std::string makeTemporarySibling(const std::filesystem::path& path);

}  // namespace motostab::io
