#pragma once
// Worker threads for sweeps and mode tracking.
#include <cstddef>
#include <functional>

namespace motostab::core {

/// Runs task(w) for w in [0, workers) on `workers` new threads and joins every one of them before
/// returning, also when one throws (no worker outlives the data it uses). The first exception in
/// time is rethrown after the join; `onFirstFailure`, if set, runs once as soon as it happens (for
/// releasing workers that wait on each other, or stopping them early). A thread that fails to
/// start counts as a failure.
void runWorkers(size_t workers, const std::function<void(size_t)>& task,
                const std::function<void()>& onFirstFailure = {});

/// f(i) for i in [0, count) on up to `threads` workers, each taking the next index as it finishes one
/// (tasks of unequal cost balance); the calling thread alone when one suffices.
void runParallel(size_t count, int threads, const std::function<void(size_t)>& f);

}  // namespace motostab::core
