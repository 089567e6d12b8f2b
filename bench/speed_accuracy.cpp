// One charge run of a mill with any model, for the speed-against-accuracy
// study (docs/validation/speed-accuracy.md, bench/speed_accuracy.py): the
// indicators, the wall time, and the wear distribution along one liner
// segment (the recession rates of the configuration's wear laws on the run's
// LinerLoads, the mean over the segments of the ring), as one JSON line.
//
// Usage: bench_speed_accuracy CONFIG.toml [key=value ...]
//   model=empirical|layer|dem, variant=1.0|1.1|1.2, revolutions=N (averaged,
//   after the model's settling), and any [dem] key (seed=N, coarse_grain=2,
//   steps_per_collision=15, settle_revolutions=1, threads=2, ...).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "app/config.h"
#include "bench/bench_main.h"
#include "charge/charge_model.h"
#include "charge/dem/dem_model.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "wear/recession.h"

using namespace linerlife;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_speed_accuracy CONFIG.toml [model=... variant=... revolutions=... dem_key=...]\n");
    return 2;
  }
  return bench::guarded_main([&] {
    Config c = load_config_file(argv[1]);
    double revolutions = 0;
    for (int a = 2; a < argc; ++a) {
      const std::string kv = argv[a];
      const auto eq = kv.find('=');
      if (eq == std::string::npos) throw InputError(kv, "expected key=value: " + kv);
      const std::string k = kv.substr(0, eq), v = kv.substr(eq + 1);
      if (k == "model") {
        c.model.charge = v;
      } else if (k == "variant") {
        c.model.variant = v;
      } else if (k == "revolutions") {
        revolutions = std::atof(v.c_str());
      } else {
        bench::set_dem_key(c, k, v);  // any [dem] key
      }
    }
    const LinerSurface surface = build_liner_surface(c.mill, c.liner);
    const ChargeModelEntry& entry = find_charge_model(c.model.charge);
    auto model = entry.make();
    ChargeInput in;
    in.mill = c.mill;
    in.charge = c.charge;
    in.model = c.model;
    in.surface = &surface;
    in.revolutions = revolutions;
    const auto t0 = std::chrono::steady_clock::now();
    const ChargeResult r = model->run(in);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Indicators& I = r.indicators;

    // the wear distribution, folded onto segment 0 (a new ring repeats its segment)
    std::string wear_json = "null", s_json = "null";
    double mass_rate = 0, impact_share = 0;
    if (entry.resolves_abrasion && r.loads.n_elements > 0) {  // Morrell's model gives no loads
      const WearModel wear = make_wear_model(c.wear, entry);
      const RecessionRates rr = recession_rates(wear, r.loads, surface, c.material);
      const int n0 = surface.segment_begin[1] - surface.segment_begin[0];
      std::vector<double> fold(static_cast<size_t>(n0), 0.0), s(static_cast<size_t>(n0), 0.0);
      for (int k = 0; k < surface.segments; ++k) {
        if (surface.segment_begin[k + 1] - surface.segment_begin[k] != n0)
          throw std::logic_error("segments of the new ring differ in element count");
        for (int j = 0; j < n0; ++j) fold[j] += rr.total[surface.segment_begin[k] + j] / surface.segments;
      }
      double acc = 0;
      for (int j = 0; j < n0; ++j) {
        s[j] = acc + 0.5 * surface.length[surface.segment_begin[0] + j];
        acc += surface.length[surface.segment_begin[0] + j];
      }
      wear_json = "[";
      s_json = "[";
      for (int j = 0; j < n0; ++j) {
        wear_json += fmt::format("{}{:.6g}", j ? ", " : "", fold[j]);
        s_json += fmt::format("{}{:.6g}", j ? ", " : "", s[j]);
      }
      wear_json += "]";
      s_json += "]";
      mass_rate = rr.mass_rate_kg_s_per_m;
      impact_share = mass_rate > 0 ? rr.impact_mass_rate_kg_s_per_m / mass_rate : 0;
    }
    fmt::print(
        "{{\"config\": \"{}\", \"model\": \"{}\", \"variant\": \"{}\", \"particles\": {}, \"time_step_s\": {:.6g}, "
        "\"simulated_s\": {:.6g}, \"wall_s\": {:.6g}, \"toe_deg\": {:.6g}, \"shoulder_deg\": {:.6g}, "
        "\"com_angle_deg\": {:.6g}, \"net_power_kw\": {:.6g}, \"mass_rate_kg_s_per_m\": {:.6g}, "
        "\"impact_share\": {:.6g}, \"element_s_m\": {}, \"recession_m_s\": {}}}\n",
        argv[1], c.model.charge, c.model.variant, r.stats.elements, r.stats.time_step_s, r.stats.simulated_s, wall,
        I.toe_deg, I.shoulder_deg, I.com_angle_deg, I.net_power_kw, mass_rate, impact_share, s_json, wear_json);
    return 0;
  });
}
