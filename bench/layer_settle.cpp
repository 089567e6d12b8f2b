// bench_layer_settle [REVOLUTIONS] [FILTER] [PHASES]: how many settling revolutions the
// layer model needs (docs/models/layer.md §Settling). The model starts from
// the N lowest cells filled and runs `model.settle_revolutions` (default 3)
// before it averages. For every case of the real-time study (the Qiu mill,
// its twelve +/-25 % variations, the 16 pilot tests) this compares the
// averages over REVOLUTIONS revolutions (default 2, the forecast's drive)
// after s = 0.5, 1, 2 and 3 settling revolutions with the spread of the same
// averages in the settled state: ten windows starting at 6, 8, .., 24
// revolutions. Outputs: net power, toe, shoulder, total shear work rate on
// the liner (abrasion's driver) and impact energy rate (impact's driver). A
// window is "settled" when each output lies within the range of the ten
// settled windows widened by a quarter of that range on each side. Prints
// one Markdown row per case. PHASES is `[model] initial_phases` ("aligned",
// the default, or "staggered").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_main.h"
#include "bench/charge_cases.h"

using namespace linerlife;

namespace {

constexpr int kOutputs = 5;
const char* kNames[kOutputs] = {"power", "toe", "shoulder", "shear work", "impact energy"};

std::vector<double> outputs(const ChargeResult& r) {
  double shear = 0, impact = 0;
  for (size_t e = 0; e < r.loads.shear_work_rate_w_per_m.size(); ++e) shear += r.loads.shear_work_rate_w_per_m[e];
  for (const auto& ev : r.loads.impacts)
    impact += ev.rate_per_s * 0.5 * ev.mass_kg *
              (ev.normal_speed_m_s * ev.normal_speed_m_s + ev.tangential_speed_m_s * ev.tangential_speed_m_s);
  return {r.indicators.net_power_kw, r.indicators.toe_deg, r.indicators.shoulder_deg, shear, impact};
}

}  // namespace

int main(int argc, char** argv) {
  return bench::guarded_main([&] {
    const double revs = argc > 1 ? std::stod(argv[1]) : 2.0;
    const std::string filter = argc > 2 ? argv[2] : "";
    const std::string phases = argc > 3 ? argv[3] : "aligned";
    const std::vector<double> settles = {0.5, 1.0, 2.0, 3.0};
    const auto model = find_charge_model("layer").make();
    fmt::print("averaging over {} revolutions; settled spread from windows starting at 6, 8, .., 24 revolutions; "
               "initial phases {}\n\n",
               revs, phases);
    fmt::print("| case |");
    for (double s : settles) fmt::print(" settle {} |", s);
    fmt::print(" settled range: power [%] / toe, shoulder [deg] / shear, impact [%] |\n|---|");
    for (size_t i = 0; i < settles.size(); ++i) fmt::print("---|");
    fmt::print("---|\n");
    int n_cases = 0;
    std::vector<int> n_settled(settles.size(), 0);
    for (auto& list : {bench::industrial_cases(), bench::pilot_cases()})
      for (const auto& c : list) {
        if (c.name.find(filter) == std::string::npos) continue;
        ++n_cases;
        const LinerSurface s = build_liner_surface(c.config.mill, c.config.liner);
        auto run = [&](double settle) {
          ChargeInput in = bench::make_input(c.config, s, "layer", "", revs);
          in.model.settle_revolutions = settle;
          in.model.initial_phases = phases;
          return outputs(model->run(in));
        };
        std::vector<double> lo(kOutputs, 1e300), hi(kOutputs, -1e300), mean(kOutputs, 0.0);
        const int n_ref = 10;
        for (int w = 0; w < n_ref; ++w) {
          const std::vector<double> o = run(6.0 + 2.0 * w);
          for (int k = 0; k < kOutputs; ++k) {
            lo[k] = std::min(lo[k], o[k]);
            hi[k] = std::max(hi[k], o[k]);
            mean[k] += o[k] / n_ref;
          }
        }
        fmt::print("| {} |", c.name);
        for (size_t i = 0; i < settles.size(); ++i) {
          const std::vector<double> o = run(settles[i]);
          std::string worst;
          double worst_excess = 0;
          for (int k = 0; k < kOutputs; ++k) {
            const double pad = 0.25 * (hi[k] - lo[k]);
            const double excess = std::max(lo[k] - pad - o[k], o[k] - hi[k] - pad);
            // relative to the settled mean for power and loads, in degrees for the angles
            const double scale = (k == 1 || k == 2) ? 1.0 : std::abs(mean[k]) / 100.0;
            if (excess > 0 && scale > 0 && excess / scale > worst_excess) {
              worst_excess = excess / scale;
              worst = kNames[k];
            }
          }
          if (worst.empty()) {
            ++n_settled[i];
            fmt::print(" settled |");
          } else {
            fmt::print(" {} off by {:.1f}{} |", worst, worst_excess, (worst == "toe" || worst == "shoulder") ? " deg" : " %");
          }
        }
        auto rel = [&](int k) { return mean[k] != 0 ? 100.0 * (hi[k] - lo[k]) / std::abs(mean[k]) : 0.0; };
        fmt::print(" {:.1f} / {:.1f}, {:.1f} / {:.1f}, {:.1f} |\n", rel(0), hi[1] - lo[1], hi[2] - lo[2], rel(3), rel(4));
        std::fflush(stdout);
      }
    fmt::print("\nsettled cases of {}:", n_cases);
    for (size_t i = 0; i < settles.size(); ++i) fmt::print(" settle {}: {};", settles[i], n_settled[i]);
    fmt::print("\n");
    return 0;
  });
}
