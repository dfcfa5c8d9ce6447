#include "io/output_folder.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/input_file.h"

namespace motostab::io {
namespace fs = std::filesystem;

namespace {

// ".NAME.KIND-PID" beside `target`.
fs::path makeSibling(const fs::path& target, const std::string& kind, long pid) {
  return target.parent_path() / ("." + target.filename().string() + "." + kind + "-" + std::to_string(pid));
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
      const long pid = parseSiblingPid(e, "." + name + "." + kind + "-");
      if (pid < 0 || isProcessAlive(pid)) continue;
      if (std::string(kind) == "backup" && !fs::exists(target)) fs::rename(entry.path(), target, ec);
      else fs::remove_all(entry.path(), ec);
    }
  }
}

[[noreturn]] void refuse(const fs::path& target, const std::string& why) {
  throw InputError({"command line", 0, 0, "--out"}, "'" + target.string() + "' " + why);
}

// `inside` lies in folder `folder` (or is it); both absolute and normalised.
bool isWithin(const fs::path& inside, const fs::path& folder) {
  return std::mismatch(folder.begin(), folder.end(), inside.begin(), inside.end()).first == folder.end();
}

bool isEmptyFolder(const fs::path& folder) {
  std::error_code ec;
  return fs::directory_iterator(folder, ec) == fs::directory_iterator() && !ec;
}

}  // namespace

std::string describeBadFolderName(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name == "." || name == "..") return "is '" + name + "', which names a folder that exists already, not a name";
  if (name.size() > 200) return "is longer than 200 characters";
  if (name.find('/') != std::string::npos) return "holds a path separator '/': a name is not a path";
  for (const char c : name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "holds a control character";
  return "";
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
}

OutputFolder::OutputFolder(fs::path target) : target_(std::move(target)) {
  if (target_.empty()) throw InputError({"command line", 0, 0, "--out"}, "the output folder name is empty");
  if (!target_.has_filename()) target_ = target_.parent_path();  // "out/" -> "out"
  std::error_code ec;
  const fs::path whole = fs::weakly_canonical(fs::absolute(target_), ec);
  const fs::path here = fs::current_path(ec);
  const bool holdsHere = !whole.empty() && std::mismatch(whole.begin(), whole.end(), here.begin(), here.end()).first == whole.end();
  if (target_.filename() == "." || target_.filename() == ".." || holdsHere)
    throw InputError({"command line", 0, 0, "--out"},
                     "'" + target_.string() + "' is the current folder or holds it; name a folder of its own");
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
  if (!fs::create_directory(temporary_, ec) || ec)
    throw std::runtime_error("cannot create the output folder " + temporary_.string() + ": " + ec.message());
  writeFileAtomically(temporary_ / kOutputMarker,
                      "This folder was written by motostab. The next motostab run that writes into it replaces it "
                      "whole;\nmotostab replaces only folders that hold this file.\n");
}

OutputFolder::~OutputFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(temporary_, ec);
}

void OutputFolder::commit() {
  if (committed_) throw std::logic_error("OutputFolder::commit called twice for " + target_.string());
  checkReplaceable(target_);  // inputs read since the constructor, or a folder put in its place
  std::error_code ec;
  if (!fs::exists(target_)) {
    fs::rename(temporary_, target_, ec);
    if (ec) throw std::runtime_error("cannot move the outputs into " + target_.string() + ": " + ec.message());
  } else if (renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(temporary_, ec);  // now the old outputs
  } else {
    // No atomic exchange on this file system: keep the old folder as a backup until the rename.
    const fs::path backup = makeSibling(target_, "backup", getpid());
    fs::remove_all(backup, ec);
    fs::rename(target_, backup, ec);
    if (ec) throw std::runtime_error("cannot set aside the old outputs in " + target_.string() + ": " + ec.message());
    fs::rename(temporary_, target_, ec);
    if (ec) {
      std::error_code restore;
      fs::rename(backup, target_, restore);
      throw std::runtime_error("cannot move the outputs into " + target_.string() + ": " + ec.message());
    }
    fs::remove_all(backup, ec);
  }
  committed_ = true;
}

}  // namespace motostab::io
