// bench_charge_timestep [REVOLUTIONS]: the time-step study of thesis §3.2.1
// (Fig. 3-1) for the layer model. For the Qiu mill and two pilot tests, runs
// time steps from 1 ms to 100 ms with the sub-stepping switched off, and
// prints power, toe, shoulder and centre of mass against the step (Markdown),
// with the Courant number (shell travel per step / media diameter). Used for
// docs/models/layer.md §Time step.
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "bench/charge_cases.h"

using namespace linerlife;

int main(int argc, char** argv) {
  const double revs = argc > 1 ? std::stod(argv[1]) : 10;
  const char* files[] = {"qiu2001_sag.toml", "pilot_test_10.toml", "pilot_test_05.toml"};
  for (const char* file : files) {
    const Config c = load_config_file(bench::source_dir() + "/data/mills/" + file);
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    fmt::print("\n### {} ({} rpm, media {} m, {} revolutions averaged after {} settling)\n\n", file, c.mill.speed_rpm,
               c.charge.ball_diameter_m, revs, c.model.settle_revolutions);
    fmt::print("| step [ms] | Courant | net power [kW] | toe [deg] | shoulder [deg] | CoM [deg] | CoM r [m] | "
               "flights | wall [s] |\n|---|---|---|---|---|---|---|---|---|\n");
    for (double ms : {1.0, 2.0, 3.0, 5.0, 7.5, 10.0, 15.0, 20.0, 30.0, 50.0, 75.0, 100.0}) {
      ChargeInput in = bench::make_input(c, s, "layer", "", revs);
      in.model.time_step_s = ms / 1000.0;
      in.model.max_courant = 1e9;  // the study runs the step as given
      const ChargeResult r = find_charge_model("layer").make()->run(in);
      const double courant = in.mill.omega_rad_s() * 0.5 * r.indicators.diameter_eff_m * in.model.time_step_s /
                             c.charge.ball_diameter_m;
      const Indicators& I = r.indicators;
      fmt::print("| {} | {:.2f} | {:.3f} | {:.1f} | {:.1f} | {:.1f} | {:.3f} | {} | {:.3f} |\n", ms, courant,
                 I.net_power_kw, I.toe_deg, I.shoulder_deg, I.com_angle_deg, I.com_radius_m, r.stats.flights,
                 r.stats.wall_s);
      std::fflush(stdout);
    }
  }
  return 0;
}
