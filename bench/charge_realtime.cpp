// bench_charge_realtime [RUNS] [REVOLUTIONS] [FILTER]: the real-time study of thesis
// §3.2.2 (Figs. 3-3/3-4) for the layer model: the Qiu mill, its twelve +/-25 %
// variations and the 16 pilot tests, liner-load accumulation on (it always
// is), single thread. Prints one Markdown table row per case with the median
// over RUNS runs (default 5) of the real-time ratio (simulated s / wall s) and
// of simulated s / CPU s. Used for docs/benchmarks.md. REVOLUTIONS 0 keeps
// the default (2 averaged after the settling ones); FILTER runs only the
// cases whose name contains it.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/charge_cases.h"

using namespace linerlife;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void run_case(const bench::Case& c, int runs, double revs) {
  const LinerSurface s = build_liner_surface(c.config.mill, c.config.liner);
  ChargeInput in = bench::make_input(c.config, s, "layer", "", revs);
  const auto model = find_charge_model("layer").make();
  std::vector<double> wall_ratio, cpu_ratio;
  ChargeResult r;
  for (int i = 0; i < runs; ++i) {
    const std::clock_t c0 = std::clock();
    r = model->run(in);
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    wall_ratio.push_back(r.stats.realtime_ratio);
    cpu_ratio.push_back(r.stats.simulated_s / cpu);
  }
  fmt::print("| {} | {:.3f} | {:.3f} | {} | {} | {:.1f} | {:.0f} | {:.0f} |\n", c.name, r.indicators.diameter_eff_m,
             r.indicators.fraction_critical, r.stats.elements, r.stats.steps, r.stats.simulated_s, median(wall_ratio),
             median(cpu_ratio));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::stoi(argv[1]) : 5;
  const double revs = argc > 2 ? std::stod(argv[2]) : 0;
  const std::string filter = argc > 3 ? argv[3] : "";
  fmt::print("| case | D_eff [m] | phi [-] | elements | steps | simulated [s] | real-time ratio (wall, median of {}) | sim s / CPU s (median) |\n", runs);
  fmt::print("|---|---|---|---|---|---|---|---|\n");
  for (const auto& c : bench::industrial_cases())
    if (c.name.find(filter) != std::string::npos) run_case(c, runs, revs);
  for (const auto& c : bench::pilot_cases())
    if (c.name.find(filter) != std::string::npos) run_case(c, runs, revs);
  return 0;
}
