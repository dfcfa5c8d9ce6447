#include "io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>

#include "io/input_error.h"

namespace motostab::io {
namespace {

// OutputError at `path`: `what` failed for the system's reason (errno); the temporary is removed.
[[noreturn]] void failWith(const std::filesystem::path& path, const std::string& what, const std::string& tmp, int fd) {
  const std::string reason = std::strerror(errno);
  if (fd >= 0) ::close(fd);
  if (!tmp.empty()) ::unlink(tmp.c_str());
  throw OutputError(path.string(), what + ": " + reason);
}

// Opens a new temporary sibling exclusively (never an existing file), retrying on a name clash.
int openFreshSibling(const std::filesystem::path& path, std::string& tmp) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    tmp = makeTemporarySibling(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

// Flushes the folder's entry of a renamed file to disk (best effort: some file systems refuse it).
void syncFolder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// The process id in a temporary sibling's name ".NAME.tmp-PID-RANDOM", or -1 if `entry` is not one
// of `path`'s temporaries.
long parseTemporaryPid(const std::string& entry, const std::filesystem::path& path) {
  const std::string prefix = "." + path.filename().string() + ".tmp-";
  if (entry.rfind(prefix, 0) != 0) return -1;
  const std::string rest = entry.substr(prefix.size());
  const auto dash = rest.find('-');
  const std::string pid = rest.substr(0, dash), random = dash == std::string::npos ? "" : rest.substr(dash + 1);
  auto digits = [](const std::string& t) { return !t.empty() && t.size() <= 9 && t.find_first_not_of("0123456789") == std::string::npos; };
  return digits(pid) && digits(random) ? std::stol(pid) : -1;
}

// Removes the temporaries of `path` that killed writers left behind (their process is gone).
void removeKilledTemporaries(const std::filesystem::path& path) {
  const std::filesystem::path dir = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const long pid = parseTemporaryPid(entry.path().filename().string(), path);
    if (pid < 0 || isProcessAlive(pid)) continue;
    if (entry.is_regular_file(ec)) std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace

bool isProcessAlive(long pid) {
  return pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

std::string makeTemporarySibling(const std::filesystem::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  return (path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                                std::to_string(rng() % 1000000)))
      .string();
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& content) {
  writeFileAtomically(path, content, nullptr);
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& content,
                         const std::function<void(const std::filesystem::path&)>& check) {
  if (!path.parent_path().empty()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) throw OutputError(path.string(), "cannot create its folder " + path.parent_path().string() + ": " + ec.message());
  }
  removeKilledTemporaries(path);
  std::string tmp;
  const int fd = openFreshSibling(path, tmp);
  if (fd < 0) failWith(path, "cannot create a temporary file beside it (" + tmp + ")", "", -1);
  for (std::size_t done = 0; done < content.size();) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failWith(path, "failed writing", tmp, fd);
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) failWith(path, "failed writing", tmp, fd);
  if (::close(fd) != 0) failWith(path, "failed closing", tmp, -1);
  if (check) {
    try {
      check(tmp);
    } catch (...) {
      ::unlink(tmp.c_str());
      throw;
    }
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) failWith(path, "cannot rename the temporary into it", tmp, -1);
  syncFolder(path.parent_path());
}

}  // namespace motostab::io
