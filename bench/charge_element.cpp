// bench_charge_element [REVOLUTIONS] [CSV]: agglomerated elements as a speed
// lever (docs/models/layer.md §1, "Agglomerated elements"). The layer model's
// element is one media diameter square by default; the thesis (§4.4.5)
// agglomerates balls into elements of equivalent volume, and a larger element
// means fewer elements, columns and relaxation calls. For the Qiu mill, its
// twelve +/-25 % variations and the 16 pilot tests (version 1.2, each
// configuration's step), runs element edges of 1, 1.25, 1.5 and 2 media
// diameters, three realisations each (1, 1.5 and 2 settling revolutions,
// REVOLUTIONS averaged, default 10), and prints per case and edge the mean
// net power, toe and shoulder, their change against one diameter, and the
// real-time ratio by CPU time (simulated s of the whole run / CPU s, median of
// the three). A summary per edge follows. With CSV, one row per run for the
// chart (bench/plot_charge_element.py).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/bench_main.h"
#include "bench/charge_cases.h"
#include "geometry/errors.h"

using namespace linerlife;
using bench::median;

namespace {

double angle_diff(double a, double b) { return std::remainder(a - b, 360.0); }

struct Mean {
  bool ok = false;
  double power = 0, toe = 0, shoulder = 0, ratio = 0;
  std::string why;
};

}  // namespace

int main(int argc, char** argv) {
  const double revs = argc > 1 ? std::stod(argv[1]) : 10;
  std::FILE* csv = argc > 2 ? std::fopen(argv[2], "w") : nullptr;
  if (csv)
    fmt::print(csv, "case,industrial,element_diameters,settle_revolutions,net_power_kw,toe_deg,shoulder_deg,"
                    "simulated_s,cpu_s\n");
  const double ks[] = {1.0, 1.25, 1.5, 2.0};
  const double settles[] = {1.0, 1.5, 2.0};
  const auto model = find_charge_model("layer").make();
  // summary per edge: worst and mean |power change|, worst |toe change|, smallest ratio (industrial / pilots)
  struct Sum {
    double worst_p[2] = {0, 0}, sum_p[2] = {0, 0}, worst_toe[2] = {0, 0}, min_ratio[2] = {1e300, 1e300};
    int n[2] = {0, 0}, refused = 0;
  };
  std::map<double, Sum> sum;
  fmt::print("| case | edge [diameters] | net power [kW] | vs 1 diameter [%] | toe [deg] | change [deg] | shoulder "
             "[deg] | change [deg] | real-time ratio, CPU |\n|---|---|---|---|---|---|---|---|---|\n");
  int list_no = 0;
  for (const auto& list : {bench::industrial_cases(), bench::pilot_cases()}) {
    const int ind = list_no++ == 0 ? 0 : 1;  // 0: industrial, 1: pilot
    for (const auto& c : list) {
      const LinerSurface s = build_liner_surface(c.config.mill, c.config.liner);
      Mean ref;
      for (const double k : ks) {
        Mean m;
        std::vector<double> ratio;
        try {
          for (const double settle : settles) {
            ChargeInput in = bench::make_input(c.config, s, "layer", "", revs);
            in.model.element_size_diameters = k;
            in.model.settle_revolutions = settle;
            const std::clock_t c0 = std::clock();
            const ChargeResult r = model->run(in);
            const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
            const Indicators& I = r.indicators;
            m.power += I.net_power_kw / 3;
            m.toe += I.toe_deg / 3;  // the three are within a few degrees: no wrap-around
            m.shoulder += I.shoulder_deg / 3;
            ratio.push_back(r.stats.simulated_s / std::max(cpu, 1e-6));
            if (csv)
              fmt::print(csv, "{},{},{},{},{:.6g},{:.4f},{:.4f},{:.4f},{:.5f}\n", c.name, 1 - ind, k, settle,
                         I.net_power_kw, I.toe_deg, I.shoulder_deg, r.stats.simulated_s, cpu);
          }
          m.ok = true;
          m.ratio = median(ratio);
        } catch (const InputError& e) {
          m.why = e.what();
        }
        if (k == ks[0]) ref = m;
        Sum& S = sum[k];
        if (!m.ok || !ref.ok) {
          ++S.refused;
          fmt::print("| {} | {} | refused: {} | | | | | | |\n", c.name, k, m.why);
          continue;
        }
        const double dp = 100.0 * (m.power / ref.power - 1.0);
        const double dt = angle_diff(m.toe, ref.toe), ds = angle_diff(m.shoulder, ref.shoulder);
        S.worst_p[ind] = std::max(S.worst_p[ind], std::abs(dp));
        S.sum_p[ind] += std::abs(dp);
        S.worst_toe[ind] = std::max(S.worst_toe[ind], std::abs(dt));
        S.min_ratio[ind] = std::min(S.min_ratio[ind], m.ratio);
        ++S.n[ind];
        fmt::print("| {} | {} | {:.4g} | {:+.1f} | {:.1f} | {:+.1f} | {:.1f} | {:+.1f} | {:.0f} |\n", c.name, k, m.power,
                   dp, m.toe, dt, m.shoulder, ds, m.ratio);
        std::fflush(stdout);
      }
    }
  }
  fmt::print("\n| edge [diameters] | industrial: smallest ratio | mean / worst abs. power change [%] | worst abs. toe "
             "change [deg] | pilots: smallest ratio | mean / worst abs. power change [%] | worst abs. toe change [deg] | "
             "refused |\n|---|---|---|---|---|---|---|---|\n");
  for (const double k : ks) {
    const Sum& S = sum[k];
    fmt::print("| {} | {:.0f} | {:.1f} / {:.1f} | {:.1f} | {:.0f} | {:.1f} / {:.1f} | {:.1f} | {} |\n", k, S.min_ratio[0],
               S.n[0] ? S.sum_p[0] / S.n[0] : 0.0, S.worst_p[0], S.worst_toe[0], S.min_ratio[1],
               S.n[1] ? S.sum_p[1] / S.n[1] : 0.0, S.worst_p[1], S.worst_toe[1], S.refused);
  }
  if (csv) std::fclose(csv);
  return 0;
}
