#pragma once
// Output files are written completely or not at all.
#include <filesystem>
#include <functional>
#include <string>

namespace motostab::io {

/// Writes `content` to `path` through a temporary file in the same folder and a rename, so a reader
/// never sees a partial file: the temporary is created exclusively, written, synced to disk and closed
/// (each step checked) before the rename, and the folder is synced after it. Creates missing parent
/// folders. On failure the temporary is removed, an existing `path` keeps its old content, and
/// OutputError (io/input_error.h) names the path and the system's reason. Temporaries of `path` left by killed
/// writers (makeTemporarySibling's names, with a process id no longer running) are removed first.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

/// As above, and `check` (if set) is called with the complete temporary file before the rename: an
/// exception from it removes the temporary, leaves `path` as it was, and propagates.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content,
                         const std::function<void(const std::filesystem::path& temporary)>& check);

/// A fresh hidden temporary path beside `path` (same folder, so a rename is atomic):
/// ".NAME.tmp-PID-RANDOM", PID this process's id.
std::string makeTemporarySibling(const std::filesystem::path& path);

/// Whether the process `pid` still runs (the writer of a temporary or partial output).
bool isProcessAlive(long pid);

}  // namespace motostab::io
