// parallel.h - independent forecasts at once (the cases of `linerlife
// compare`, the finite differences of a calibration), each on one thread.
// Every forecast owns its state (its rate provider, its CVODE context), so
// running them at once gives the results of running them one after the other.
#pragma once

#include <functional>

namespace linerlife {

/// Calls f(i) for i = 0 .. n - 1 on up to `jobs` threads (this one among
/// them), each taking the next i in order (jobs <= 1: in this thread, in
/// order). After an exception at i no i above it starts; once the calls under
/// way have ended, the exception of the lowest i is rethrown: every i below it
/// has been called, so it is the one a loop one after the other would throw.
/// If the system gives fewer threads, the ones it gives do the work.
void parallel_for(int n, int jobs, const std::function<void(int)>& f);

/// The cores this process may run on (its CPU affinity, so taskset and
/// container limits count), at least 1.
int available_cores();

/// Forecasts at once by default: one per available core, at most n; one if
/// `exclusive` (a charge model that spreads its own work over the cores: the
/// DEM).
int default_jobs(int n, bool exclusive);

}  // namespace linerlife
