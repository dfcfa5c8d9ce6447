#include "io/input_store.h"

#include "io/input_file.h"

namespace motostab::io {

std::string InputStore::readText(const std::string& path, std::uintmax_t maxBytes) {
  std::lock_guard<std::mutex> guard(lock_);  // held while reading: concurrent first requests read once
  const auto it = texts_.find(path);
  if (it != texts_.end()) return it->second;
  std::string text = readInputFile(path, maxBytes);
  ++reads_[path];
  return texts_.emplace(path, std::move(text)).first->second;
}

void InputStore::addWarning(const InputLocation& where, const std::string& message) {
  std::lock_guard<std::mutex> guard(lock_);
  for (const InputWarning& w : warnings_)
    if (w.message == message) return;
  warnings_.push_back({where, message});
}

std::vector<InputWarning> InputStore::getWarnings() const {
  std::lock_guard<std::mutex> guard(lock_);
  return warnings_;
}

long InputStore::getReadCount(const std::string& path) const {
  std::lock_guard<std::mutex> guard(lock_);
  const auto it = reads_.find(path);
  return it == reads_.end() ? 0 : it->second;
}

}  // namespace motostab::io
