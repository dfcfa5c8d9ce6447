#pragma once
// Linear models already computed in one diagnosis, shared by everything that predicts with it: the
// stepwise and pair searches, the noise iterations, cross-validation folds, profile likelihoods and
// the robustness reruns.
//
// A prediction is one chain of warm-started trims and linearisations (analysis/sweep.h runSweep at a
// list of speeds) of the scenario with typed changes. Its result is a pure function of the changes
// (in order) and of the list of speeds: the chain runs on one thread, and each trim starts from the
// previous speed's, so a speed's linear model depends on the speeds before it too. The key is
// therefore the exact changes (each "path=value", numbers in the shortest text that reads back to the
// same double) and the exact speeds (bit patterns): a hit returns what the evaluation would have
// returned, bit for bit, whichever thread filled the entry and in whichever order. A failed chain
// (no valid vehicle, a trim that fails) is kept as its exception and rethrown on a hit.
//
// Repeats come from the fits' structure: a Levenberg-Marquardt fit ends with the Jacobian at its
// solution, and the next noise iteration, the candidate's RMS, its folds' first step and the next
// search step's baseline start from that same point; the robustness reruns share the reference sweep
// and node choice, and start their fits where the full data's did. Memory is bounded by the results'
// approximate size (least recently used evicted first; a result evicted and asked for again is
// computed again, identical); the counters say how much work was done and saved.
#include <atomic>
#include <cstddef>
#include <functional>
#include <future>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "analysis/sweep.h"
#include "scenario/parameter_overrides.h"

namespace motostab::diagnosis {

/// Thread-safe store of sweep results keyed by exact typed changes and speeds.
class SweepCache {
 public:
  /// Work done and saved, totals over the cache's life.
  struct Counters {
    long lookups = 0;         ///< results asked for
    long hits = 0;            ///< answered from the store (or from a computation under way)
    long builds = 0;          ///< vehicle models built (one per chain computed)
    long linearisations = 0;  ///< speeds trimmed, linearised and eigen-decomposed in computed chains
    long savedLinearisations = 0;  ///< speeds the hits did not compute again
    size_t entries = 0;       ///< results held now
    size_t bytes = 0;         ///< their approximate size (matrices, eigenvectors, trims), bytes
    size_t peakBytes = 0;     ///< the most held at once
  };

  /// Keeps results of at most about `maxBytes` together (calcSweepBytes; least recently used evicted
  /// first, the newest always kept).
  explicit SweepCache(size_t maxBytes = kDefaultBytes);

  /// The result for `key` (makeKey), computing it with `compute` (which builds one model and runs one
  /// chain of `numSpeeds` speeds) when it is not held. Concurrent calls with one key compute once;
  /// `compute`'s exception is stored and rethrown to every caller of that key.
  std::shared_ptr<const analysis::SweepResult> get(const std::string& key, size_t numSpeeds,
                                                   const std::function<analysis::SweepResult()>& compute);

  Counters getCounters() const;

  /// The exact key of a chain: `kind` (what the speeds mean), every change in order and the speeds'
  /// bit patterns.
  static std::string makeKey(const std::string& kind, const scenario::ParameterOverrides& changes,
                             const std::vector<double>& speeds);

  /// 16 MiB: about 750 chains of 10 speeds of the Kooijman bicycle (22 kB each). The Kooijman
  /// diagnosis keeps 98 % of the hits it would have with no bound (its search and reruns ask again
  /// mostly for recent chains; docs/performance.md).
  static constexpr size_t kDefaultBytes = size_t{16} << 20;

 private:
  struct Entry {
    std::shared_future<std::shared_ptr<const analysis::SweepResult>> result;
    std::list<std::string>::iterator age;  ///< place in recent_
    size_t bytes = 0;
  };
  void account(const std::string& key, size_t bytes);
  void evict();  // under mutex_
  static constexpr size_t kEntryOverhead = 256;  ///< bytes of a map node, list node and shared state

  size_t maxBytes_;
  mutable std::mutex mutex_;
  std::unordered_map<std::string, Entry> entries_;
  std::list<std::string> recent_;  ///< keys, most recently used first
  Counters counters_;
};

/// Approximate memory of a sweep result, bytes.
size_t calcSweepBytes(const analysis::SweepResult& sweep);

}  // namespace motostab::diagnosis
