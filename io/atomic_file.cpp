#include "io/atomic_file.h"

#include <fstream>
#include <random>
#include <stdexcept>

namespace motostab::io {

std::string makeTemporarySibling(const std::filesystem::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  return (path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(rng() % 1000000)))
      .string();
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& content) {
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  const std::string tmp = makeTemporarySibling(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp);
    out << content;
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      throw std::runtime_error("failed writing " + path.string());
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw std::runtime_error("cannot rename into " + path.string() + ": " + ec.message());
  }
}

}  // namespace motostab::io
