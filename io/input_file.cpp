#include "io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <mutex>

#include "io/input_error.h"

namespace motostab::io {
namespace fs = std::filesystem;
namespace {

std::mutex gInputsLock;
std::vector<fs::path> gInputs;  // guarded by gInputsLock

std::string describeBytes(std::uintmax_t n) {
  return n >= (1u << 20) ? std::to_string(n >> 20) + " MiB" : std::to_string(n) + " bytes";
}

// What kind of entry `st` is, for "not a regular file" messages.
std::string describeKind(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  if (S_ISFIFO(st.st_mode)) return "a pipe (FIFO)";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void fail(const fs::path& path, const std::string& why) { throw InputError({path.string(), 0, 0, ""}, why); }

// Opens `path` for reading without blocking on a FIFO; checks it is a regular file within `maxBytes`.
int openChecked(const fs::path& path, std::uintmax_t maxBytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot open file: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string kind = describeKind(st);
    ::close(fd);
    fail(path, "is " + kind + ", not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > maxBytes) {
    ::close(fd);
    fail(path, "is " + describeBytes(static_cast<std::uintmax_t>(st.st_size)) + ", more than the " +
                   describeBytes(maxBytes) + " an input file of this kind may have");
  }
  recordInputFile(path);
  return fd;
}

}  // namespace

void recordInputFile(const fs::path& path) {
  std::error_code ec;
  fs::path whole = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec || whole.empty()) return;
  std::lock_guard<std::mutex> guard(gInputsLock);
  if (std::find(gInputs.begin(), gInputs.end(), whole) == gInputs.end()) gInputs.push_back(std::move(whole));
}

std::vector<fs::path> getInputFiles() {
  std::lock_guard<std::mutex> guard(gInputsLock);
  return gInputs;
}

void requireInputFile(const fs::path& path, std::uintmax_t maxBytes) { ::close(openChecked(path, maxBytes)); }

std::string readInputFile(const fs::path& path, std::uintmax_t maxBytes) {
  const int fd = openChecked(path, maxBytes);
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      fail(path, "cannot read file: " + why);
    }
    if (n == 0) break;
    text.append(buffer, static_cast<size_t>(n));
    if (text.size() > maxBytes) {  // grew while being read
      ::close(fd);
      fail(path, "is more than the " + describeBytes(maxBytes) + " an input file of this kind may have");
    }
  }
  ::close(fd);
  return text;
}

std::string_view stripByteOrderMark(std::string_view text) {
  return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

}  // namespace motostab::io
