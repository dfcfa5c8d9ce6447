#include "diagnosis/sweep_cache.h"

#include <algorithm>
#include <cstdio>

namespace motostab::diagnosis {

using analysis::SweepResult;

SweepCache::SweepCache(size_t maxBytes) : maxBytes_(maxBytes) {}

std::string SweepCache::makeKey(const std::string& kind, const scenario::ParameterOverrides& changes,
                                const std::vector<double>& speeds) {
  std::string key = kind;
  for (const auto& c : changes.getItems()) key += '\n' + c.format();
  key += "\n@";
  char buf[32];
  for (double v : speeds) {
    std::snprintf(buf, sizeof buf, " %a", v);  // hexadecimal: the exact double
    key += buf;
  }
  return key;
}

std::shared_ptr<const SweepResult> SweepCache::get(const std::string& key, size_t numSpeeds,
                                                   const std::function<SweepResult()>& compute) {
  std::promise<std::shared_ptr<const SweepResult>> promise;
  std::shared_future<std::shared_ptr<const SweepResult>> result;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++counters_.lookups;
    const auto it = entries_.find(key);
    if (it != entries_.end()) {
      ++counters_.hits;
      counters_.savedLinearisations += static_cast<long>(numSpeeds);
      recent_.splice(recent_.begin(), recent_, it->second.age);
      result = it->second.result;
    } else {
      ++counters_.builds;
      counters_.linearisations += static_cast<long>(numSpeeds);
      recent_.push_front(key);
      Entry& e = entries_[key];
      e.result = promise.get_future().share();
      e.age = recent_.begin();
    }
  }
  if (result.valid()) return result.get();  // rethrows a stored failure
  std::shared_ptr<const SweepResult> value;
  try {
    value = std::make_shared<const SweepResult>(compute());
  } catch (...) {
    promise.set_exception(std::current_exception());
    account(key, kEntryOverhead);
    throw;
  }
  promise.set_value(value);
  account(key, calcSweepBytes(*value) + kEntryOverhead);
  return value;
}

// Counts the size of the entry just filled (key and bookkeeping included) and evicts past the bound.
void SweepCache::account(const std::string& key, size_t bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end() || it->second.bytes != 0) return;  // evicted meanwhile
  it->second.bytes = bytes + 2 * key.size();  // the map's key and the age list's copy
  counters_.bytes += it->second.bytes;
  counters_.peakBytes = std::max(counters_.peakBytes, counters_.bytes);
  evict();
}

void SweepCache::evict() {
  while (counters_.bytes > maxBytes_ && recent_.size() > 1) {
    const auto it = entries_.find(recent_.back());
    counters_.bytes -= it->second.bytes;
    entries_.erase(it);
    recent_.pop_back();
  }
}

SweepCache::Counters SweepCache::getCounters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  Counters c = counters_;
  c.entries = entries_.size();
  return c;
}

size_t calcSweepBytes(const SweepResult& sweep) {
  size_t bytes = sizeof(SweepResult) + sweep.speeds.size() * sizeof(double);
  for (const auto& m : sweep.models) {
    bytes += sizeof(m) + sizeof(double) * static_cast<size_t>(m.A.size() + m.B.size());
    bytes += 2 * sizeof(double) * static_cast<size_t>(m.eigenvalues.size() + m.eigenvectors.size());
    bytes += m.states.size() * (sizeof(analysis::LinearState) + 16);
    for (const auto& c : m.removedColumns) bytes += 32 + sizeof(double) * static_cast<size_t>(c.second.size());
    for (const auto& r : m.removedRows) bytes += 32 + sizeof(double) * static_cast<size_t>(r.second.size());
  }
  for (const auto& t : sweep.trims) bytes += sizeof(t) + sizeof(double) * static_cast<size_t>(t.y.size() + t.inputs.size());
  for (const auto& b : sweep.branches)
    bytes += sizeof(b) + b.index.size() * (sizeof(int) + sizeof(analysis::ModeLabel) + 2 * sizeof(double));
  return bytes;
}

}  // namespace motostab::diagnosis
