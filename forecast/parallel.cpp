#include "forecast/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace linerlife {

void parallel_for(int n, int jobs, const std::function<void(int)>& f) {
  if (n <= 0) return;
  std::vector<std::exception_ptr> failed(static_cast<size_t>(n));
  std::atomic<int> next{0};
  std::atomic<bool> stop{false};
  auto worker = [&] {
    while (!stop.load()) {
      const int i = next.fetch_add(1);  // an i taken is called
      if (i >= n) return;
      try {
        f(i);
      } catch (...) {
        failed[static_cast<size_t>(i)] = std::current_exception();
        stop = true;
      }
    }
  };
  const int threads = std::min(jobs, n);
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(static_cast<size_t>(threads));
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

int default_jobs(int n, bool exclusive) {
  if (exclusive) return 1;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(cores, n));
}

}  // namespace linerlife
