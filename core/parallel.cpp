#include "core/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace motostab::core {

void runWorkers(size_t workers, const std::function<void(size_t)>& task, const std::function<void()>& onFirstFailure) {
  std::mutex lock;
  std::exception_ptr first;
  auto fail = [&](std::exception_ptr e) {
    bool isFirst = false;
    {
      std::lock_guard<std::mutex> guard(lock);
      isFirst = !first;
      if (isFirst) first = e;
    }
    if (isFirst && onFirstFailure) onFirstFailure();
  };
  std::vector<std::thread> threads;
  threads.reserve(workers);
  for (size_t w = 0; w < workers; ++w) {
    try {
      threads.emplace_back([&, w]() {
        try {
          task(w);
        } catch (...) {
          fail(std::current_exception());
        }
      });
    } catch (...) {
      fail(std::current_exception());
      break;
    }
  }
  for (auto& t : threads) t.join();
  if (first) std::rethrow_exception(first);
}

void runParallel(size_t count, int threads, const std::function<void(size_t)>& f) {
  const size_t workers = std::min<size_t>(static_cast<size_t>(std::max(1, threads)), count);
  if (workers <= 1) {
    for (size_t i = 0; i < count; ++i) f(i);
    return;
  }
  std::atomic<size_t> next{0};  // each worker takes the next index: tasks of unequal cost balance
  runWorkers(workers, [&](size_t) {
    for (size_t i; (i = next++) < count;) f(i);
  });
}

}  // namespace motostab::core
