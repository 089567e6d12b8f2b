// bench_charge_validation CSV [DEM_CASES] [--unheld-mu MU] [--pocket-balls P] [--lifter-slide on|off]
//                         [--beta-iterate N]:
// the cross-model comparison of
// docs/validation/charge.md. Runs the empirical model (Morrell's C-model) and
// the layer model in versions 1.0, 1.1 and 1.2 on the Qiu mill and the 16
// pilot tests of thesis Table 4.1 (each configuration as checked in, default
// revolutions), and the DEM on the cases whose name contains one of the
// comma-separated DEM_CASES (e.g. "qiu,pilot 05"; the DEM takes ~30 s for the
// Qiu mill). Writes one CSV row per run; bench/charge_validation.py turns it
// into the tables of thesis Tables 4.3/4.4. The two options set the layer
// model's study parameters ModelSpec::unheld_friction_coefficient and
// held_pocket_balls, --lifter-slide its lifter_slide, for every mill;
// --beta-iterate N runs each layer case N more times, each with
// ModelSpec::inner_radius_beta = 1 - the previous run's airborne fraction, and
// writes the last (docs/models/layer-worn.md, "The en-masse share of eq. 4.14")
// (docs/models/layer.md §3, "The release study";
// bench/charge_release.py compares such runs with the DEM).
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bench/charge_cases.h"
#include "geometry/errors.h"

using namespace linerlife;

int main(int argc, char** argv) {
  std::vector<std::string> pos;
  std::vector<std::pair<std::string, std::string>> study;  // set on every layer run, over each mill's own
  int beta_passes = 0;
  bool bad = false;
  for (int i = 1; i < argc && !bad; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--", 0) != 0) {
      pos.push_back(a);
      continue;
    }
    if (i + 1 >= argc) {
      bad = true;
      break;
    }
    const std::string v = argv[++i];
    ModelSpec check;
    if (a == "--beta-iterate")
      beta_passes = std::stoi(v);
    else if (a != "--beta" && bench::set_study_option(check, a, v))
      study.emplace_back(a, v);
    else
      bad = true;
  }
  if (bad || pos.empty() || pos.size() > 2) {
    std::fprintf(stderr, "usage: %s CSV [DEM_CASES] [--unheld-mu MU] [--pocket-balls P] [--lifter-slide on|off] "
                 "[--beta-iterate N]\n",
                 argv[0]);
    return 2;
  }
  std::vector<std::string> dem_cases;
  if (pos.size() > 1) {
    std::stringstream ss(pos[1]);
    for (std::string t; std::getline(ss, t, ',');)
      if (!t.empty()) dem_cases.push_back(t);
  }
  std::FILE* csv = std::fopen(pos[0].c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "cannot write %s\n", pos[0].c_str());
    return 2;
  }
  fmt::print(csv, "case,rotation,fraction_critical,filling,model,variant,toe_deg,shoulder_deg,com_deg,com_r_m,"
                  "net_power_kw,alt_net_power_kw,no_load_kw,charge_area_m2,n_layers,n_trajectories,inner_radius_m,"
                  "simulated_s,wall_s,airborne_fraction,inner_radius_beta\n");
  std::vector<bench::Case> cases{bench::industrial_cases().front()};
  for (auto& c : bench::pilot_cases()) cases.push_back(c);
  struct Run {
    std::string model, variant;
  };
  for (const auto& c : cases) {
    const LinerSurface s = build_liner_surface(c.config.mill, c.config.liner);
    std::vector<Run> runs{{"empirical", ""}, {"layer", "1.0"}, {"layer", "1.1"}, {"layer", "1.2"}};
    for (const auto& d : dem_cases)
      if (c.name.find(d) != std::string::npos) {
        runs.push_back({"dem", ""});
        break;
      }
    for (const Run& run : runs) {
      ChargeInput in = bench::make_input(c.config, s, run.model, run.variant, 0);
      for (const auto& [k, v] : study) bench::set_study_option(in.model, k, v);
      ChargeResult r;
      try {
        r = find_charge_model(run.model).make()->run(in);
        for (int pass = 0; pass < beta_passes && run.model == "layer"; ++pass) {
          in.model.inner_radius_beta = 1.0 - r.stats.airborne_fraction;
          r = find_charge_model(run.model).make()->run(in);
        }
      } catch (const InputError& e) {
        std::fprintf(stderr, "%s %s %s: %s\n", c.name.c_str(), run.model.c_str(), run.variant.c_str(), e.what());
        std::fclose(csv);
        return 2;
      }
      const Indicators& I = r.indicators;
      fmt::print(csv, "{},{},{:.5f},{},{},{},{:.4f},{:.4f},{:.4f},{:.5f},{:.6g},{:.6g},{:.6g},{:.6g},{},{},{:.5f},{:.4f},{:.4f},{:.5f},{:.5f}\n",
                 c.name, c.config.mill.rotation == Rotation::Ccw ? "ccw" : "cw", I.fraction_critical,
                 c.config.charge.filling, run.model, run.model == "layer" ? run.variant : "-", I.toe_deg,
                 I.shoulder_deg, I.com_angle_deg, I.com_radius_m, I.net_power_kw, I.alt_net_power_kw,
                 I.no_load_power_kw, I.charge_area_m2, I.n_layers, I.n_trajectories, I.inner_radius_m,
                 r.stats.simulated_s, r.stats.wall_s, r.stats.airborne_fraction, r.stats.inner_radius_beta);
      std::fflush(csv);
      fmt::print("{} {} {}: toe {:.1f} shoulder {:.1f} com {:.1f} power {:.4g} kW ({:.2f} s)\n", c.name, run.model,
                 run.variant, I.toe_deg, I.shoulder_deg, I.com_angle_deg, I.net_power_kw, r.stats.wall_s);
      std::fflush(stdout);
    }
  }
  std::fclose(csv);
  return 0;
}
