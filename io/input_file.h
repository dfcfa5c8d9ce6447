#pragma once
// The one way input files are opened: regular files only (not a folder, a device such as /dev/zero,
// a FIFO or a socket), of bounded size, read whole. Every file read this way is recorded as an input
// of the run, so that an output folder that would replace it is refused (io/output_folder.h).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace motostab::io {

/// Size bounds of input files, bytes: text inputs (YAML scenarios and tests, parameter files, tyre
/// property files) and tables (CSV records).
constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t(16) << 20;    // 16 MiB
constexpr std::uintmax_t kMaxTableFileBytes = std::uintmax_t(512) << 20;  // 512 MiB

/// The whole content of the input file `path`. InputError naming the file if it is missing,
/// unreadable, not a regular file, or larger than `maxBytes`. Records the file (getInputFiles).
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes = kMaxTextFileBytes);

/// The checks of readInputFile without reading, for files opened by other means (plugin libraries);
/// records the file.
void requireInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes = kMaxTextFileBytes);

/// Records `path` as an input of this run without opening it.
void recordInputFile(const std::filesystem::path& path);

/// Every input file recorded in this process (absolute, symbolic links resolved), in the order read.
std::vector<std::filesystem::path> getInputFiles();

/// `text` without a leading UTF-8 byte order mark (EF BB BF).
std::string_view stripByteOrderMark(std::string_view text);

}  // namespace motostab::io
