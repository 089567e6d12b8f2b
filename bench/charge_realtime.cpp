// bench_charge_realtime [RUNS] [REVOLUTIONS] [FILTER]: the real-time study of
// thesis §3.2.2 (Figs. 3-3/3-4) for the layer model (version 1.2, each
// configuration's time step): the Qiu mill, its twelve +/-25 % variations and
// the 16 pilot tests, liner-load accumulation on (the layer model always
// accumulates the loads and impacts), single thread. Prints one Markdown table
// row per case with the median over RUNS runs (default 5) of the real-time
// ratio by wall clock (simulated s / wall s) and by CPU time (simulated s /
// CPU s of this process), and the median 1-minute load average while it ran.
// The machine is shared, so the runs go round all cases in turn (a burst of
// other work spreads over the cases instead of spoiling one). REVOLUTIONS 0
// keeps the default (2 averaged after the settling ones); FILTER runs only the
// cases whose name contains it. Used by bench/charge_bench.sh for
// docs/benchmarks.md (## Charge models).
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_main.h"
#include "bench/charge_cases.h"

using namespace linerlife;
using bench::median;

namespace {

double load1() {
  std::ifstream f("/proc/loadavg");
  double l = -1;
  f >> l;
  return l;
}

struct Row {
  bench::Case c;
  LinerSurface s;
  std::vector<double> wall_ratio, cpu_ratio, load;
  ChargeResult last;
};

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::stoi(argv[1]) : 5;
  const double revs = argc > 2 ? std::stod(argv[2]) : 0;
  const std::string filter = argc > 3 ? argv[3] : "";
  std::vector<Row> rows;
  for (auto& list : {bench::industrial_cases(), bench::pilot_cases()})
    for (const auto& c : list)
      if (c.name.find(filter) != std::string::npos) rows.push_back({c, build_liner_surface(c.config.mill, c.config.liner), {}, {}, {}, {}});
  const auto model = find_charge_model("layer").make();
  fmt::print(stderr, "load average at the start: {:.2f}\n", load1());
  for (int i = 0; i < runs; ++i)
    for (Row& r : rows) {
      const ChargeInput in = bench::make_input(r.c.config, r.s, "layer", "", revs);
      r.load.push_back(load1());
      const std::clock_t c0 = std::clock();
      r.last = model->run(in);
      const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      r.wall_ratio.push_back(r.last.stats.realtime_ratio);
      r.cpu_ratio.push_back(r.last.stats.simulated_s / cpu);
    }
  fmt::print("| case | D_eff [m] | phi [-] | elements | time step [ms] x substeps | simulated [s] | impacts | "
             "real-time ratio, wall (median of {}) | real-time ratio, CPU (median) | load average (median) |\n",
             runs);
  fmt::print("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const ChargeResult& x = r.last;
    fmt::print("| {} | {:.3f} | {:.3f} | {} | {:.3g} x {} | {:.1f} | {} | {:.0f} | {:.0f} | {:.2f} |\n", r.c.name,
               x.indicators.diameter_eff_m, x.indicators.fraction_critical, x.stats.elements,
               1000.0 * x.stats.time_step_s * x.stats.substeps, x.stats.substeps, x.stats.simulated_s,
               x.loads.impacts.size(), median(r.wall_ratio), median(r.cpu_ratio), median(r.load));
  }
  fmt::print(stderr, "load average at the end: {:.2f}\n", load1());
  return 0;
}
