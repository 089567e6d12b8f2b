// bench_charge_run CONFIG [MODEL] [VARIANT] [REVOLUTIONS] [TIME_STEP_S]:
// runs one charge model on one mill and prints every indicator; a
// development and inspection tool (not a benchmark).
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "bench/charge_cases.h"

using namespace linerlife;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s CONFIG [MODEL] [VARIANT] [REVOLUTIONS] [TIME_STEP_S]\n", argv[0]);
    return 2;
  }
  Config c = load_config_file(argv[1]);
  const std::string model = argc > 2 ? argv[2] : "layer";
  const std::string variant = argc > 3 ? argv[3] : "";
  const double revs = argc > 4 ? std::stod(argv[4]) : 0;
  if (argc > 5) c.model.time_step_s = std::stod(argv[5]);
  if (std::getenv("NO_SUBSTEP")) c.model.max_courant = 1e9;
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = bench::make_input(c, s, model, variant, revs);
  const char* dump = std::getenv("CHARGE_DUMP");
  in.record_snapshot = dump != nullptr;
  const ChargeResult r = find_charge_model(model).make()->run(in);
  const Indicators& I = r.indicators;
  fmt::print("model {} variant {} D_eff {:.4f} phi {:.4f}\n", r.model, in.model.variant, I.diameter_eff_m, I.fraction_critical);
  fmt::print("toe {:.2f} shoulder {:.2f} com {:.2f} deg r {:.3f} area {:.3f} layers {} traj {} r_i {:.3f}\n", I.toe_deg,
             I.shoulder_deg, I.com_angle_deg, I.com_radius_m, I.charge_area_m2, I.n_layers, I.n_trajectories, I.inner_radius_m);
  fmt::print("net {:.1f} kW  alt {:.1f} kW  noload {:.1f}  gross {:.1f}  pool {:.1f}\n", I.net_power_kw, I.alt_net_power_kw,
             I.no_load_power_kw, I.gross_power_kw, I.slurry_pool_power_kw);
  fmt::print("layer speeds rpm:");
  for (double v : I.layer_speed_rpm) fmt::print(" {:.2f}", v);
  fmt::print("\nsim {:.2f} s wall {:.4f} s ratio {:.0f} steps {} dt {} substeps {} elements {} flights {} impacts {}\n",
             r.stats.simulated_s, r.stats.wall_s, r.stats.realtime_ratio, r.stats.steps, r.stats.time_step_s,
             r.stats.substeps, r.stats.elements, r.stats.flights, r.loads.impacts.size());
  for (const auto& n : r.notes) fmt::print("note: {}\n", n);
  if (dump && !r.snapshots.empty()) {
    std::FILE* f = std::fopen(dump, "w");
    for (size_t k = 0; k < r.snapshots.size(); ++k)
      for (size_t i = 0; i < r.snapshots[k].position.size(); ++i)
        fmt::print(f, "{},{},{},{}\n", k, r.snapshots[k].position[i].x(), r.snapshots[k].position[i].y(), r.snapshots[k].state[i]);
    std::fclose(f);
  }
  return 0;
}
