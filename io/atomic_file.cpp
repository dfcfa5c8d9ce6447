#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>

namespace motostab::io {
namespace {

[[noreturn]] void failWith(const std::string& what, const std::string& tmp, int fd) {
  const std::string reason = std::strerror(errno);
  if (fd >= 0) ::close(fd);
  if (!tmp.empty()) ::unlink(tmp.c_str());
  throw std::runtime_error(what + ": " + reason);
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

}  // namespace

std::string makeTemporarySibling(const std::filesystem::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  return (path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(rng() % 1000000)))
      .string();
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& content) {
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  std::string tmp;
  const int fd = openFreshSibling(path, tmp);
  if (fd < 0) failWith("cannot write " + tmp, "", -1);
  for (std::size_t done = 0; done < content.size();) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failWith("failed writing " + path.string(), tmp, fd);
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) failWith("failed writing " + path.string(), tmp, fd);
  if (::close(fd) != 0) failWith("failed closing " + path.string(), tmp, -1);
  if (::rename(tmp.c_str(), path.c_str()) != 0) failWith("cannot rename into " + path.string(), tmp, -1);
  syncFolder(path.parent_path());
}

}  // namespace motostab::io
