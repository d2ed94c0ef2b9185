#pragma once
// The Monte Carlo pool: independent runs on a few std::threads, results by index. Header-only so the
// light ThreadSanitizer test of CI (tests/core/common/tst_parallel_runs.cpp) builds it without the
// engine (docs/robustness.md, "Sanitizers").
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

namespace reckoner {

/// Calls fn(i) for every i in [0, runs), each exactly once, on `threads` threads (>= 1; the caller's
/// thread is one of them). Indices are handed out in order from one atomic counter; fn must not share
/// unsynchronised state between indices (each run writes its own result slot). After every run has
/// finished, rethrows the exception of the lowest index that threw, if any.
inline void parallelRuns(int runs, int threads, const std::function<void(int)>& fn) {
  if (runs <= 0) return;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(runs));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i = next++; i < runs; i = next++) {
      try {
        fn(i);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(std::max(0, std::min(threads, runs) - 1)));
  for (int k = 1; k < std::min(threads, runs); ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace reckoner
