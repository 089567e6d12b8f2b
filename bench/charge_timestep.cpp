// bench_charge_timestep [REVOLUTIONS] [CSV]: the time-step study of thesis
// §3.2.1 (Fig. 3-1) for the layer model (version from each configuration,
// 1.2). For the Qiu mill and two pilot tests, runs time steps from 1 ms to
// 100 ms twice: once as given (sub-stepping switched off, max_courant huge),
// to show where the model stops converging, and once as a user gets it (the
// model sub-steps a step beyond kLayerMaxCourant). Prints power, toe,
// shoulder and centre of mass against the step (Markdown), with the Courant
// number (shell travel per step / media diameter) and the deviation from the
// 1 ms run; with CSV, also writes one row per run for the chart
// (bench/plot_charge_timestep.py). Used for docs/models/layer.md §Time step.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include <fmt/format.h>

#include "bench/charge_cases.h"
#include "charge/layer_model.h"

using namespace linerlife;

int main(int argc, char** argv) {
  const double revs = argc > 1 ? std::stod(argv[1]) : 10;
  std::FILE* csv = argc > 2 ? std::fopen(argv[2], "w") : nullptr;
  if (csv)
    fmt::print(csv, "mill,mode,step_ms,courant,substeps,dt_used_s,net_power_kw,toe_deg,shoulder_deg,com_deg,com_r_m,"
                    "flights,cpu_s\n");
  const char* files[] = {"qiu2001_sag.toml", "pilot_test_10.toml", "pilot_test_05.toml"};
  const double steps_ms[] = {1.0, 2.0, 3.0, 5.0, 7.5, 10.0, 15.0, 20.0, 30.0, 50.0, 75.0, 100.0};
  for (const char* file : files) {
    const Config c = load_config_file(bench::source_dir() + "/data/mills/" + file);
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    fmt::print("\n### {} ({} rpm, media {} m, version {}, {} revolutions averaged after {} settling)\n\n", file,
               c.mill.speed_rpm, c.charge.ball_diameter_m, c.model.variant, revs, c.model.settle_revolutions);
    fmt::print("| step [ms] | Courant | as given: net power [kW] | toe [deg] | shoulder [deg] | CoM [deg] | "
               "power vs 1 ms [%] | CPU [s] | sub-stepped: substeps | net power [kW] | toe [deg] | shoulder [deg] |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    double p_ref = 0;
    for (const double ms : steps_ms) {
      Indicators I[2];
      RunStats st[2];
      double cpu[2] = {0, 0};
      double courant = 0;
      for (int mode = 0; mode < 2; ++mode) {
        ChargeInput in = bench::make_input(c, s, "layer", "", revs);
        in.model.time_step_s = ms / 1000.0;
        in.model.max_courant = mode == 0 ? 1e9 : 0;  // 0: the model's own limit (kLayerMaxCourant)
        const std::clock_t c0 = std::clock();
        const ChargeResult r = find_charge_model("layer").make()->run(in);
        cpu[mode] = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
        I[mode] = r.indicators;
        st[mode] = r.stats;
        courant = in.mill.omega_rad_s() * 0.5 * r.indicators.diameter_eff_m * in.model.time_step_s /
                  c.charge.ball_diameter_m;
        if (csv)
          fmt::print(csv, "{},{},{},{:.4f},{},{:.6g},{:.6g},{:.4f},{:.4f},{:.4f},{:.5f},{},{:.4f}\n", file,
                     mode == 0 ? "as_given" : "substepped", ms, courant, r.stats.substeps, r.stats.time_step_s,
                     I[mode].net_power_kw, I[mode].toe_deg, I[mode].shoulder_deg, I[mode].com_angle_deg,
                     I[mode].com_radius_m, r.stats.flights, cpu[mode]);
      }
      if (ms == steps_ms[0]) p_ref = I[0].net_power_kw;
      fmt::print("| {} | {:.2f} | {:.4g} | {:.1f} | {:.1f} | {:.1f} | {:+.2f} | {:.2f} | {} | {:.4g} | {:.1f} | {:.1f} |\n",
                 ms, courant, I[0].net_power_kw, I[0].toe_deg, I[0].shoulder_deg, I[0].com_angle_deg,
                 100.0 * (I[0].net_power_kw / p_ref - 1.0), cpu[0], st[1].substeps, I[1].net_power_kw, I[1].toe_deg,
                 I[1].shoulder_deg);
      std::fflush(stdout);
      if (csv) std::fflush(csv);
    }
  }
  if (csv) std::fclose(csv);
  return 0;
}
