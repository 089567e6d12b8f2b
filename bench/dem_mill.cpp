// One DEM run of a mill, with every figure the run derives and measures:
// particles, time step, speed (particle-steps and contacts per second,
// real-time ratio) and the indicators. The speed rows of docs/benchmarks.md
// (## DEM) come from this program through bench/dem_bench.sh.
//
// Usage: bench_dem_mill CONFIG.toml [key=value ...]
//   keys: any [dem] key of the configuration (threads=2, coarse_grain=2,
//   revolutions=1, settle_revolutions=0.5, steps_per_collision=15, ...)
//   and json=1 for one JSON line instead of the table, profile=1 for the
//   occupancy of the liner band (the profile toe and shoulder come from).
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "app/config.h"
#include "bench/bench_main.h"
#include "charge/dem/dem_model.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"

using namespace linerlife;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_dem_mill CONFIG.toml [dem_key=value ...] [json=1]\n");
    return 2;
  }
  return bench::guarded_main([&] {
    Config c = load_config_file(argv[1]);
    bool json = false, profile = false;
    for (int a = 2; a < argc; ++a) {
      const std::string kv = argv[a];
      const auto eq = kv.find('=');
      if (eq == std::string::npos) throw InputError(kv, "expected key=value: " + kv);
      const std::string k = kv.substr(0, eq), v = kv.substr(eq + 1);
      if (k == "json") {
        json = v == "1";
        continue;
      }
      if (k == "profile") {
        profile = v == "1";
        continue;
      }
      bench::set_dem_key(c, k, v);
    }
    const LinerSurface surface = build_liner_surface(c.mill, c.liner);
    ChargeInput in;
    in.mill = c.mill;
    in.charge = c.charge;
    in.model = c.model;
    in.surface = &surface;
    DemRunInfo info;
    const ChargeResult r = run_dem(in, &info);
    const Indicators& I = r.indicators;
    if (json) {
      std::printf(
          "{\"config\": \"%s\", \"particles\": %d, \"threads\": %d, \"coarse_grain\": %g, \"time_step_s\": %.6g, "
          "\"collision_time_s\": %.6g, \"simulated_s\": %.6g, \"wall_s\": %.6g, \"integrate_wall_s\": %.6g, "
          "\"realtime_ratio\": %.6g, \"particle_steps_per_s\": %.6g, \"contacts_per_s\": %.6g, \"mean_contacts\": %.4g, "
          "\"list_builds\": %lld, \"steps\": %lld, \"toe_deg\": %.4g, \"shoulder_deg\": %.4g, \"power_w_per_m\": %.6g, "
          "\"net_power_kw\": %.6g, \"com_angle_deg\": %.4g, \"com_radius_m\": %.4g, \"charge_area_m2\": %.4g, "
          "\"n_layers\": %d, \"n_trajectories\": %d, \"impacts\": %lld, \"direct_impact_fraction\": %.4g, "
          "\"max_overlap_ratio\": %.4g, \"max_wall_overlap_ratio\": %.4g}\n",
          argv[1], info.particles, info.threads, info.coarse_grain, info.time_step_s, info.collision_time_s,
          r.stats.simulated_s, info.wall_s, info.integrate_wall_s, r.stats.realtime_ratio, info.particle_steps_per_s,
          info.contacts_per_s, info.mean_contacts, info.list_builds, info.steps, I.toe_deg, I.shoulder_deg,
          I.net_power_w_per_m, I.net_power_kw, I.com_angle_deg, I.com_radius_m, I.charge_area_m2, I.n_layers,
          I.n_trajectories, info.impacts, I.direct_impact_fraction, info.max_overlap_ratio, info.max_wall_overlap_ratio);
      return 0;
    }
    fmt::print("{}: {} discs ({} balls, {} rocks), coarse_grain {}, {} threads\n", argv[1], info.particles, info.balls,
               info.rocks, info.coarse_grain, info.threads);
    fmt::print("  collision time {:.4g} s, time step {:.4g} s ({:.1f} steps a collision), k_n {:.4g} N/m per m\n",
               info.collision_time_s, info.time_step_s, info.steps_per_collision, info.particle_stiffness);
    fmt::print("  simulated {:.3f} s (settle {:.3f}, average {:.3f}) in {:.3f} s wall ({:.3f} stepping): real-time "
               "ratio {:.3f}\n",
               r.stats.simulated_s, info.settle_s, info.average_s, info.wall_s, info.integrate_wall_s,
               r.stats.realtime_ratio);
    fmt::print("  {:.4g} particle-steps/s, {:.4g} contacts/s, coordination {:.2f}, {} list builds in {} steps, "
               "max overlap {:.3f} of the radius ({:.3f} at the liner)\n",
               info.particle_steps_per_s, info.contacts_per_s, info.mean_contacts, info.list_builds, info.steps,
               info.max_overlap_ratio, info.max_wall_overlap_ratio);
    fmt::print("  toe {:.1f} deg, shoulder {:.1f} deg, CoM {:.1f} deg at {:.3f} m, area {:.3f} m2, layers {}, "
               "trajectories {}\n",
               I.toe_deg, I.shoulder_deg, I.com_angle_deg, I.com_radius_m, I.charge_area_m2, I.n_layers,
               I.n_trajectories);
    fmt::print("  power {:.4g} W/m (2D), {:.4g} kW net for {} m, gross {:.4g} kW; phi {:.3f}, D_eff {:.3f} m\n",
               I.net_power_w_per_m, I.net_power_kw, c.mill.length_m, I.gross_power_kw, I.fraction_critical,
               I.diameter_eff_m);
    fmt::print("  impacts {} (direct mass share {:.3f})\n  layer speeds [rpm]:", info.impacts,
               I.direct_impact_fraction);
    for (double v : I.layer_speed_rpm) fmt::print(" {:.1f}", v);
    fmt::print("\n");
    if (profile) {
      fmt::print("  liner band occupancy (angle deg, occupancy):\n");
      for (const auto& [a, o] : info.band_occupancy) fmt::print("    {:.1f} {:.4f}\n", a, o);
    }
    return 0;
  });
}
