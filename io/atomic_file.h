#pragma once
// Output files are written completely or not at all.
#include <filesystem>
#include <string>

namespace motostab::io {

/// Writes `content` to `path` through a temporary file in the same folder and a rename, so a reader
/// never sees a partial file: the temporary is created exclusively, written, synced to disk and closed
/// (each step checked) before the rename, and the folder is synced after it. Creates missing parent
/// folders. On failure the temporary is removed, an existing `path` keeps its old content, and
/// std::runtime_error names the path and the system's reason.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

/// A fresh hidden temporary path beside `path` (same folder, so a rename is atomic).
std::string makeTemporarySibling(const std::filesystem::path& path);

}  // namespace motostab::io
