// bench_charge_relax [REVOLUTIONS] [CSV]: the relaxation-interval study of
// the layer model (docs/models/layer.md §9, "The relaxation interval"). The
// support sweep and the surface relaxation (foot stability) run every
// `relaxation_interval_cells` outer cells of shell travel; between two runs
// the charge surface steepens past the angle of repose. For the Qiu mill and
// three pilot tests (version 1.2, each configuration's time step, which the
// model sub-steps to at most one interval), runs intervals from 1/64 to 2
// outer cells, each for three realisations of the start (1, 1.5 and 2
// settling revolutions), and prints the mean net power, toe, shoulder and
// centre of mass, the spread of the power over the realisations, the
// deviation of the mean power from the finest interval's, and the CPU time of
// one run (median of the three). With CSV, one row per run for the chart
// (bench/plot_charge_relax.py).
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/charge_cases.h"

using namespace linerlife;

int main(int argc, char** argv) {
  const double revs = argc > 1 ? std::stod(argv[1]) : 10;
  std::FILE* csv = argc > 2 ? std::fopen(argv[2], "w") : nullptr;
  if (csv)
    fmt::print(csv, "mill,interval_cells,interval_s,settle_revolutions,dt_used_s,substeps,net_power_kw,toe_deg,"
                    "shoulder_deg,com_deg,flights,cpu_s\n");
  const char* files[] = {"qiu2001_sag.toml", "pilot_test_10.toml", "pilot_test_02.toml", "pilot_test_05.toml"};
  const double cells[] = {1.0 / 64, 1.0 / 32, 1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2, 1.0, 2.0};
  const double settles[] = {1.0, 1.5, 2.0};
  for (const char* file : files) {
    const Config c = load_config_file(bench::source_dir() + "/data/mills/" + file);
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    fmt::print("\n### {} ({} rpm, media {} m, version {}, time step {} s, {} revolutions averaged)\n\n", file,
               c.mill.speed_rpm, c.charge.ball_diameter_m, c.model.variant, c.model.time_step_s, revs);
    fmt::print("| interval [outer cells] | interval [ms] | step used [ms] | net power [kW] (mean of 3) | spread "
               "(max - min) [%] | power vs 1/64 [%] | toe [deg] | shoulder [deg] | CoM [deg] | CPU per run [s] |\n"
               "|---|---|---|---|---|---|---|---|---|---|\n");
    double p_ref = 0;
    for (const double cell : cells) {
      double p = 0, toe = 0, sh = 0, com = 0, p_lo = 1e300, p_hi = -1e300, interval = 0, dt = 0;
      std::vector<double> cpu;
      for (const double settle : settles) {
        ChargeInput in = bench::make_input(c, s, "layer", "", revs);
        in.model.relaxation_interval_cells = cell;
        in.model.settle_revolutions = settle;
        const std::clock_t c0 = std::clock();
        const ChargeResult r = find_charge_model("layer").make()->run(in);
        cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
        const Indicators& I = r.indicators;
        interval = r.stats.relaxation_interval_s;
        dt = r.stats.time_step_s;
        p += I.net_power_kw / 3;
        toe += I.toe_deg / 3;
        sh += I.shoulder_deg / 3;
        com += I.com_angle_deg / 3;
        p_lo = std::min(p_lo, I.net_power_kw);
        p_hi = std::max(p_hi, I.net_power_kw);
        if (csv)
          fmt::print(csv, "{},{:.6g},{:.6g},{},{:.6g},{},{:.6g},{:.4f},{:.4f},{:.4f},{},{:.4f}\n", file, cell, interval,
                     settle, r.stats.time_step_s, r.stats.substeps, I.net_power_kw, I.toe_deg, I.shoulder_deg,
                     I.com_angle_deg, r.stats.flights, cpu.back());
      }
      std::sort(cpu.begin(), cpu.end());
      if (cell == cells[0]) p_ref = p;
      fmt::print("| {:.4g} | {:.2f} | {:.3g} | {:.4g} | {:.2f} | {:+.2f} | {:.1f} | {:.1f} | {:.1f} | {:.3f} |\n", cell,
                 1000 * interval, 1000 * dt, p, 100.0 * (p_hi - p_lo) / p, 100.0 * (p / p_ref - 1.0), toe, sh, com,
                 cpu[1]);
      std::fflush(stdout);
      if (csv) std::fflush(csv);
    }
  }
  if (csv) std::fclose(csv);
  return 0;
}
