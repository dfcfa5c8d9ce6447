#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "core/parallel.h"

namespace motostab::core {
namespace {

// A failing worker does not cut the others short: runWorkers joins them all before rethrowing, so
// data they use outlives them (the sweep's models did not, before).
TEST(Parallel, JoinsEveryWorkerBeforeRethrowing) {
  std::atomic<bool> slowFinished{false};
  try {
    runWorkers(2, [&](size_t w) {
      if (w == 0) throw std::runtime_error("worker 0");
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      slowFinished = true;
    });
    FAIL() << "the failure must reach the caller";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "worker 0");
    EXPECT_TRUE(slowFinished);
  }
}

// The first failure in time wins, and the callback runs once, before the later failures: workers
// that wait on each other are released by it.
TEST(Parallel, FirstFailureInTimeIsRethrownAndReported) {
  std::atomic<int> callbacks{0};
  std::atomic<bool> released{false};
  try {
    runWorkers(
        3,
        [&](size_t w) {
          if (w == 2) throw std::runtime_error("first");
          while (!released) std::this_thread::yield();  // waits for the failure of worker 2
          throw std::runtime_error("later");
        },
        [&]() {
          ++callbacks;
          released = true;
        });
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "first");
  }
  EXPECT_EQ(callbacks, 1);
}

TEST(Parallel, RunParallelVisitsEveryIndexOnce) {
  for (int threads : {-3, 1, 2, 5}) {
    std::vector<std::atomic<int>> seen(37);
    runParallel(seen.size(), threads, [&](size_t i) { ++seen[i]; });
    for (auto& s : seen) EXPECT_EQ(s, 1) << threads;
  }
}

}  // namespace
}  // namespace motostab::core
