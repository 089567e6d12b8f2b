#include "forecast/parallel.h"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace linerlife {

void parallel_for(int n, int jobs, const std::function<void(int)>& f) {
  if (n <= 0) return;
  std::vector<std::exception_ptr> failed(static_cast<size_t>(n));
  std::atomic<int> next{0};
  std::atomic<int> lowest_failed{n};  // no i above a failure starts
  auto worker = [&] {
    for (;;) {
      const int i = next.fetch_add(1);  // in increasing order: every i below a taken one is taken too
      if (i >= n || i > lowest_failed.load()) return;
      try {
        f(i);
      } catch (...) {
        failed[static_cast<size_t>(i)] = std::current_exception();
        int low = lowest_failed.load();
        while (i < low && !lowest_failed.compare_exchange_weak(low, i)) {
        }
      }
    }
  };
  const int threads = std::min(jobs, n);
  std::vector<std::thread> pool;
  if (threads > 1) {
    pool.reserve(static_cast<size_t>(threads) - 1);
    try {
      for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    } catch (const std::system_error&) {
      // no more threads: the ones started and this one share the work
    }
  }
  worker();  // this thread is a worker too
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

int available_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

int default_jobs(int n, bool exclusive) {
  if (exclusive) return 1;
  return std::max(1, std::min(available_cores(), n));
}

}  // namespace linerlife
