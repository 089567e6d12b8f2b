// The smoothing comparison of thesis Fig. 5-18 on a simulated profile, with
// the truth known (issue 4 §5; docs/validation/wear.md §5).
//
// Truth: the recession depth along the 61 elements of one Qiu liner around its
// lifter (thesis Fig. 5-18 has 61), from the synthetic test-double loads
// (bench/synthetic_charge.h) over 1.5 revolutions at amplification 1e6.
// Raw: what a particle-based charge model delivers, the same depth made of
// discrete wear events whose expectation is the truth: node i gets
// Poisson(0.02) large impacts of 3 x the mean depth and Poisson(lambda_i)
// small events, lambda_i = (truth_i - 0.06 mean) / event (20 small events on
// the mean node). Each smoother is applied to the raw depth along arc length
// (open sequence) and compared with the raw data (the thesis' residuals) and
// with the truth, over 400 draws; "corrected" is after smooth_depth()'s
// clipping and rescaling to the raw mass, which is what the wear run applies.
//
// Usage: bench_wear_smoothing [csv]   with csv: also prints one draw element by element
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench/synthetic_charge.h"
#include "bench/wear_common.h"

using namespace linerlife;

namespace {

struct Smoother {
  std::string name;
  SmoothingSpec spec;
};

std::vector<double> apply(const Smoother& s, const std::vector<double>& y, const std::vector<double>& sp,
                          const std::vector<double>& w) {
  switch (s.spec.method) {
    case SmoothingMethod::None:
      return y;
    case SmoothingMethod::MovingAverage:
      return moving_average(y, s.spec.window, false);
    case SmoothingMethod::Csaps:
      return csaps(y, sp, w, s.spec.csaps_p, false);
    case SmoothingMethod::Tukey:
      return tukey_smooth(y, s.spec.tukey, false);
    case SmoothingMethod::TukeyCsaps:
      return csaps(tukey_smooth(y, s.spec.tukey, false), sp, w, s.spec.csaps_p, false);
  }
  return y;
}

}  // namespace

int main(int argc, char** argv) {
  const bool csv = argc > 1 && std::strcmp(argv[1], "csv") == 0;
  // the truth: recession depth per node of liner 0 from the synthetic loads
  const Config c = load_default_config();
  WearRunInput in = bench::wear_input(c);
  const LinerSurface& s = in.surface;
  const ChargeResult cr = bench::SyntheticCharge().run([&] {
    ChargeInput ci;
    ci.mill = in.mill;
    ci.charge = in.charge;
    ci.model = in.model;
    ci.surface = &s;
    ci.revolutions = 1;
    return ci;
  }());
  const WearModel wm = make_wear_model(in.wear, bench::synthetic_entry());
  const RecessionRates rr = recession_rates(wm, cr.loads, s, in.material);
  const double time = 1.5 * 60 / in.mill.speed_rpm, amp = 1e6;
  std::vector<double> elem(s.n_elements());
  for (int i = 0; i < s.n_elements(); ++i) elem[i] = amp * rr.total[i] * time;
  const std::vector<double> node = element_to_node_depth(s, elem);
  // 61 nodes centred on the lifter of liner 0
  const int b = s.segment_begin[0], n0 = s.segment_size(0);
  const int first = b + (n0 - 61) / 2;
  std::vector<double> truth(61), sp(60), w(61);
  for (int q = 0; q < 61; ++q) truth[q] = node[first + q];
  for (int q = 0; q < 60; ++q) sp[q] = s.length[first + q];
  for (int q = 0; q < 61; ++q) w[q] = 0.5 * ((q > 0 ? sp[q - 1] : 0) + (q < 60 ? sp[q] : 0));
  double mean = 0;
  for (double v : truth) mean += v / 61;

  std::vector<Smoother> sm;
  sm.push_back({"raw (no smoothing)", SmoothingSpec{SmoothingMethod::None}});
  sm.push_back({"moving average 10 (thesis)", SmoothingSpec{SmoothingMethod::MovingAverage, 0.9999, 10}});
  sm.push_back({"moving average 5", SmoothingSpec{SmoothingMethod::MovingAverage, 0.9999, 5}});
  for (double p : {0.999, 0.9999, 0.99999, 0.999999})
    sm.push_back({"csaps p = " + std::to_string(p).substr(0, 8), SmoothingSpec{SmoothingMethod::Csaps, p}});
  sm.push_back({"Tukey 3RRSHRRSRR (thesis)", SmoothingSpec{SmoothingMethod::Tukey, 0.9999, 10, "3RRSHRRSRR"}});
  sm.push_back({"Tukey 3RSSH,twice", SmoothingSpec{SmoothingMethod::Tukey, 0.9999, 10, "3RSSH,twice"}});
  sm.push_back({"Tukey 3RRSHRRSRR + csaps 0.9999 (thesis' choice)",
                SmoothingSpec{SmoothingMethod::TukeyCsaps, 0.9999, 10, "3RRSHRRSRR"}});

  const int draws = 400;
  std::mt19937 rng(2004);
  const double event = mean / 20;  // [m] depth of one wear event
  std::vector<double> rms_raw(sm.size()), rms_truth(sm.size()), mass(sm.size()), worst(sm.size()), corrected(sm.size());
  std::vector<std::vector<double>> example(sm.size());
  std::vector<double> example_raw;
  for (int d = 0; d < draws; ++d) {
    std::vector<double> raw(61);
    std::poisson_distribution<int> big(0.02);
    for (int q = 0; q < 61; ++q) {
      std::poisson_distribution<int> small(std::max(0.0, truth[q] - 0.06 * mean) / event);
      raw[q] = small(rng) * event + big(rng) * 3 * mean;
    }
    double raw_mass = 0;
    for (int q = 0; q < 61; ++q) raw_mass += w[q] * raw[q];
    for (size_t k = 0; k < sm.size(); ++k) {
      const std::vector<double> f = apply(sm[k], raw, sp, w);
      double e_raw = 0, e_truth = 0, m = 0;
      for (int q = 0; q < 61; ++q) {
        e_raw += std::pow(f[q] - raw[q], 2) / 61;
        e_truth += std::pow(f[q] - truth[q], 2) / 61;
        m += w[q] * f[q];
        worst[k] = std::max(worst[k], std::abs(f[q] - truth[q]) / mean);
      }
      // what the wear run applies: clipped and rescaled to the raw mass
      std::vector<double> g = f;
      double gm = 0;
      for (int q = 0; q < 61; ++q) gm += w[q] * (g[q] = std::max(0.0, g[q]));
      double e_corr = 0;
      for (int q = 0; q < 61; ++q) e_corr += std::pow(g[q] * raw_mass / gm - truth[q], 2) / 61;
      corrected[k] += std::sqrt(e_corr) / mean / draws;
      rms_raw[k] += std::sqrt(e_raw) / mean / draws;
      rms_truth[k] += std::sqrt(e_truth) / mean / draws;
      mass[k] += std::abs(m / raw_mass - 1) / draws;
      if (d == 0) example[k] = f;
    }
    if (d == 0) example_raw = raw;
  }
  std::printf("# thesis Fig. 5-18 on a simulated profile: 61 nodes of Qiu liner 0, mean depth %.4f m, %d draws\n", mean,
              draws);
  std::printf("# errors as a fraction of the mean depth; mass = mean |change of sum w y| before any correction\n");
  std::printf("%-50s %11s %12s %12s %12s %12s\n", "smoother", "rms_vs_raw", "rms_vs_truth", "max_vs_truth",
              "mass_change", "corrected");
  for (size_t k = 0; k < sm.size(); ++k)
    std::printf("%-50s %11.4f %12.4f %12.4f %12.5f %12.4f\n", sm[k].name.c_str(), rms_raw[k], rms_truth[k], worst[k],
                mass[k], corrected[k]);
  if (csv) {
    std::printf("\n# one draw, element by element\nnode,truth,raw");
    for (size_t k = 1; k < sm.size(); ++k) {
      std::string name = sm[k].name;
      for (char& ch : name)
        if (ch == ',') ch = ' ';
      std::printf(",%s", name.c_str());
    }
    std::printf("\n");
    for (int q = 0; q < 61; ++q) {
      std::printf("%d,%.6e,%.6e", q + 1, truth[q], example_raw[q]);
      for (size_t k = 1; k < sm.size(); ++k) std::printf(",%.6e", example[k][q]);
      std::printf("\n");
    }
  }
  return 0;
}
