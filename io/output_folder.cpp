#include "io/output_folder.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/input_file.h"

namespace motostab::io {
namespace fs = std::filesystem;

namespace {

// The file systems' limit on one name, bytes (NAME_MAX).
constexpr size_t kMaxNameBytes = 255;

// ".NAME.KIND-" for a sibling of the folder NAME: NAME itself when the whole sibling name fits in
// kMaxNameBytes, else its first 160 bytes (cut at a UTF-8 character) and a hash of the whole name, so
// that every run into NAME, and the clean-up after a killed one, names its siblings alike.
std::string makeSiblingPrefix(const std::string& name, const std::string& kind) {
  const std::string whole = "." + name + "." + kind + "-";
  if (whole.size() + 10 <= kMaxNameBytes) return whole;  // 10: digits of a process id
  size_t cut = 160;
  while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a, 64 bits: the same in every build
  for (const unsigned char c : name) hash = (hash ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return "." + name.substr(0, cut) + "~" + hex + "." + kind + "-";
}

// ".NAME.KIND-PID" beside `target` (makeSiblingPrefix).
fs::path makeSibling(const fs::path& target, const std::string& kind, long pid) {
  return target.parent_path() / (makeSiblingPrefix(target.filename().string(), kind) + std::to_string(pid));
}

// The pid in a sibling's name ".NAME.KIND-PID", or -1 when the name is not one of ours.
long parseSiblingPid(const std::string& entry, const std::string& prefix) {
  if (entry.rfind(prefix, 0) != 0) return -1;
  const std::string digits = entry.substr(prefix.size());
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return -1;
  return std::stol(digits);
}

// Removes what killed runs into `target` left behind: their partial folders, and restores a backup
// when the target itself is missing (a kill between the two renames of the fallback commit).
void cleanUpAfterKilledRuns(const fs::path& target) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const std::string name = target.filename().string();
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string e = entry.path().filename().string();
    for (const char* kind : {"partial", "backup"}) {
      const long pid = parseSiblingPid(e, makeSiblingPrefix(name, kind));
      if (pid < 0 || isProcessAlive(pid)) continue;
      if (std::string(kind) == "backup" && !fs::exists(target)) fs::rename(entry.path(), target, ec);
      else fs::remove_all(entry.path(), ec);
    }
  }
}

[[noreturn]] void refuse(const fs::path& target, const std::string& why) {
  throw InputError({"command line", 0, 0, "--out"}, "'" + target.string() + "' " + why);
}

// What the system said when an output could not be put in place: bad input at --out (a folder the user
// may not write, a name too long), with the system's reason.
[[noreturn]] void refuseOs(const fs::path& target, const std::string& what, const std::error_code& ec) {
  refuse(target, what + ": " + ec.message() + " (name an --out you may write)");
}

// `inside` lies in folder `folder` (or is it); both absolute and normalised.
bool isWithin(const fs::path& inside, const fs::path& folder) {
  return std::mismatch(folder.begin(), folder.end(), inside.begin(), inside.end()).first == folder.end();
}

bool isEmptyFolder(const fs::path& folder) {
  std::error_code ec;
  return fs::directory_iterator(folder, ec) == fs::directory_iterator() && !ec;
}

// The marker's line before the list of what motostab wrote (one relative path a line, '/'-separated).
constexpr const char* kWrittenHeader = "entries written:";

// Every entry below `folder` but the marker at its top, as '/'-separated paths relative to it, sorted;
// with `written`, only those not in it, and nothing below such a folder.
std::vector<std::string> listEntries(const fs::path& folder, const std::set<std::string>* written = nullptr) {
  std::vector<std::string> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string rel = it->path().lexically_relative(folder).generic_string();
    if (rel == kOutputMarker) continue;
    if (written && written->count(rel)) continue;
    out.push_back(rel);
    if (written) it.disable_recursion_pending();
  }
  if (ec) throw InputError({"command line", 0, 0, "--out"}, "cannot list '" + folder.string() + "': " + ec.message());
  std::sort(out.begin(), out.end());
  return out;
}

// The entries a marker lists; nullopt for a marker without a list (written before markers had one).
std::optional<std::set<std::string>> readWrittenEntries(const fs::path& marker) {
  std::ifstream in(marker);
  std::string line;
  while (std::getline(in, line))
    if (line == kWrittenHeader) {
      std::set<std::string> written;
      while (std::getline(in, line))
        if (!line.empty()) written.insert(line);
      return written;
    }
  return std::nullopt;
}

std::string makeMarkerText(const std::vector<std::string>& entries) {
  std::string text =
      "This folder was written by motostab. The next motostab run that writes into it replaces it whole;\n"
      "motostab replaces only folders that hold this file and nothing but the entries listed below.\n";
  text += std::string(kWrittenHeader) + "\n";
  for (const auto& e : entries) text += e + "\n";
  return text;
}

// Refuses a marked folder that holds entries its marker does not list (the user's own files).
void checkOnlyWrittenEntries(const fs::path& target) {
  const auto written = readWrittenEntries(target / kOutputMarker);
  if (!written) return;
  const std::vector<std::string> extra = listEntries(target, &*written);
  if (extra.empty()) return;
  std::string names;
  for (size_t i = 0; i < extra.size() && i < 5; ++i) names += (i ? ", " : "") + extra[i];
  if (extra.size() > 5) names += " and " + std::to_string(extra.size() - 5) + " more";
  refuse(target, "holds entries motostab did not write (" + names +
                     "): the run would replace the folder whole and lose them. Move them away yourself, or name "
                     "another --out");
}

// The code point of the UTF-8 sequence at name[i] (i advanced past it), or -1 when it is not valid UTF-8.
long decodeUtf8(const std::string& name, size_t& i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(name[k]); };
  const unsigned char b = byte(i);
  const int extra = b < 0x80 ? 0 : (b >> 5) == 0x6 ? 1 : (b >> 4) == 0xE ? 2 : (b >> 3) == 0x1E ? 3 : -1;
  if (extra < 0 || i + extra >= name.size()) return ++i, -1;
  long cp = extra == 0 ? b : b & (0x3F >> extra);
  for (int k = 1; k <= extra; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return ++i, -1;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  i += extra + 1;
  return cp;
}

// Why `name` cannot be shown as it is ("" if it can): a control character (C0, DEL, C1), a bidirectional
// control or line separator (U+202E shows the rest of a name reversed), or bytes that are not UTF-8.
std::string describeHiddenCharacter(const std::string& name) {
  for (size_t i = 0; i < name.size();) {
    const long cp = decodeUtf8(name, i);
    if (cp < 0) return "is not valid UTF-8 text";
    if (cp < 0x20 || (cp >= 0x7F && cp <= 0x9F)) return "holds a control character";
    if (cp == 0x061C || cp == 0x200E || cp == 0x200F || (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069))
      return "holds a bidirectional-text control or line separator (U+" + [cp] {
        char hex[8];
        std::snprintf(hex, sizeof hex, "%04lX", cp);
        return std::string(hex);
      }() + "), which hides how the name reads";
  }
  return "";
}

}  // namespace

std::string describeBadFolderName(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name == "." || name == "..") return "is '" + name + "', which names a folder that exists already, not a name";
  if (name.size() > 200) return "is longer than 200 characters";
  if (name.find('/') != std::string::npos) return "holds a path separator '/': a name is not a path";
  return describeHiddenCharacter(name);
}

void checkFileReplaceable(const fs::path& file, const std::string& header) {
  std::error_code ec;
  const fs::path whole = fs::weakly_canonical(fs::absolute(file), ec);
  for (const fs::path& input : getInputFiles())
    if (input == whole) refuse(file, "is an input of this run: write the output to another file");
  const fs::file_status status = fs::symlink_status(file, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_regular_file(status)) refuse(file, "exists and is not a regular file");
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  if (first.rfind(header, 0) != 0)
    refuse(file, "exists and was not written by motostab (its first line is not '" + header +
                     "...'): name another output file, or move it away yourself");
}

void checkReplaceable(const fs::path& target) {
  std::error_code ec;
  const fs::path whole = fs::weakly_canonical(fs::absolute(target), ec);
  for (const fs::path& input : getInputFiles())
    if (!whole.empty() && isWithin(input, whole))
      refuse(target, "holds " + input.string() + ", an input of this run: write the outputs to another folder");
  const fs::file_status status = fs::symlink_status(target, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) refuse(target, fs::is_symlink(status) ? "is a symbolic link; name a folder" : "exists and is not a folder");
  if (!fs::is_regular_file(target / kOutputMarker) && !isEmptyFolder(target))
    refuse(target, "exists and was not written by motostab (it has no " + std::string(kOutputMarker) +
                       " file): the run would replace it whole. Name another --out, or move the folder away yourself");
  if (fs::is_regular_file(target / kOutputMarker)) checkOnlyWrittenEntries(target);
}

OutputFolder::OutputFolder(fs::path target) : target_(std::move(target)) {
  if (target_.empty()) throw InputError({"command line", 0, 0, "--out"}, "the output folder name is empty");
  if (!target_.has_filename()) target_ = target_.parent_path();  // "out/" -> "out"
  std::error_code ec;
  const fs::path whole = fs::weakly_canonical(fs::absolute(target_), ec);
  const fs::path here = fs::current_path(ec);
  const bool holdsHere = !whole.empty() && std::mismatch(whole.begin(), whole.end(), here.begin(), here.end()).first == whole.end();
  if (target_.filename() == "." || target_.filename() == "..")
    refuse(target_, "ends in '" + target_.filename().string() +
                        "', a step of a path, not a folder's name: name the output folder itself");
  if (holdsHere) refuse(target_, "is the current folder or holds it; name a folder of its own");
  if (target_.filename().string().size() > kMaxNameBytes)
    refuse(target_, "has a name of " + std::to_string(target_.filename().string().size()) + " bytes; file systems allow " +
                        std::to_string(kMaxNameBytes));
  const fs::file_status status = fs::status(target_, ec);
  if (ec && status.type() != fs::file_type::not_found)
    throw InputError({"command line", 0, 0, "--out"}, "'" + target_.string() + "': " + ec.message());
  checkReplaceable(target_);
  if (!target_.parent_path().empty() && (fs::create_directories(target_.parent_path(), ec), ec))
    throw InputError({"command line", 0, 0, "--out"},
                     "cannot create '" + target_.parent_path().string() + "': " + ec.message());
  cleanUpAfterKilledRuns(target_);
  temporary_ = makeSibling(target_, "partial", getpid());
  fs::remove_all(temporary_, ec);
  if (!fs::create_directory(temporary_, ec) || ec) refuseOs(target_, "cannot be written: creating " + temporary_.string(), ec);
  writeFileAtomically(temporary_ / kOutputMarker, makeMarkerText({}));
}

OutputFolder::~OutputFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(temporary_, ec);
}

void OutputFolder::commit() {
  if (committed_) throw std::logic_error("OutputFolder::commit called twice for " + target_.string());
  writeFileAtomically(temporary_ / kOutputMarker, makeMarkerText(listEntries(temporary_)));
  checkReplaceable(target_);  // inputs read since the constructor, or a folder put in its place
  std::error_code ec;
  if (!fs::exists(target_)) {
    fs::rename(temporary_, target_, ec);
    if (ec) refuseOs(target_, "cannot take the outputs", ec);
  } else if (renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(temporary_, ec);  // now the old outputs
  } else {
    // No atomic exchange on this file system: keep the old folder as a backup until the rename.
    const fs::path backup = makeSibling(target_, "backup", getpid());
    fs::remove_all(backup, ec);
    fs::rename(target_, backup, ec);
    if (ec) refuseOs(target_, "cannot be set aside for the new outputs", ec);
    fs::rename(temporary_, target_, ec);
    if (ec) {
      std::error_code restore;
      fs::rename(backup, target_, restore);
      refuseOs(target_, "cannot take the outputs", ec);
    }
    fs::remove_all(backup, ec);
  }
  committed_ = true;
}

}  // namespace motostab::io
