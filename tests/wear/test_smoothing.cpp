// Profile smoothing (thesis §5.8): moving average, csaps, Tukey's smoothers,
// and the mass the smoothing keeps.
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>

#include "geometry/errors.h"
#include "wear/smoothing.h"

using namespace linerlife;

namespace {

double weighted(const std::vector<double>& y, const std::vector<double>& w) {
  double s = 0;
  for (size_t i = 0; i < y.size(); ++i) s += w[i] * y[i];
  return s;
}

/// A simulated worn-lifter depth field along 61 elements (thesis Fig. 5-18
/// has 61): smooth wear, deeper on the leading face, plus measurement-like
/// noise and a few impact spikes on single elements.
void simulated_profile(std::vector<double>& truth, std::vector<double>& raw, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, 0.4e-3);
  std::uniform_real_distribution<double> u(0, 1);
  truth.assign(61, 0);
  raw.assign(61, 0);
  for (int i = 0; i < 61; ++i) {
    const double x = (i - 30) / 30.0;
    truth[i] = 4e-3 * (1 + 0.6 * std::tanh(3 * x)) * std::exp(-x * x) + 1e-3;
    raw[i] = std::max(0.0, truth[i] + noise(rng));
    if (u(rng) < 0.08) raw[i] += 3e-3 * u(rng);  // impact spikes
  }
}

}  // namespace

TEST_CASE("moving average: centred, hand values, periodic sums kept", "[wear][smoothing]") {
  const std::vector<double> y{0, 0, 4, 0, 0};
  // window 3: (0 + 4 + 0)/3 at the three middle points
  const auto a = moving_average(y, 3, true);
  CHECK(a[1] == Approx(4.0 / 3));
  CHECK(a[2] == Approx(4.0 / 3));
  CHECK(a[0] == Approx(0.0).margin(1e-15));
  // window 2 (even): three samples with weights 1/2, 1, 1/2 over 2 -> 1, 2, 1
  const auto b = moving_average(y, 2, true);
  CHECK(b[1] == Approx(1.0));
  CHECK(b[2] == Approx(2.0));
  CHECK(b[3] == Approx(1.0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> r(50);
  for (double& v : r) v = u(rng);
  for (int w : {2, 5, 10}) {
    const auto m = moving_average(r, w, true);
    CHECK(std::accumulate(m.begin(), m.end(), 0.0) == Approx(std::accumulate(r.begin(), r.end(), 0.0)).epsilon(1e-12));
  }
  // open sequences keep straight lines (symmetric windows shrink at the ends)
  std::vector<double> line(20);
  for (int i = 0; i < 20; ++i) line[i] = 3 + 0.5 * i;
  const auto ml = moving_average(line, 7, false);
  for (int i = 0; i < 20; ++i) CHECK(ml[i] == Approx(line[i]).epsilon(1e-12));
}

TEST_CASE("csaps on a periodic uniform grid is the spline's Fourier filter", "[wear][smoothing][csaps]") {
  // For spacing h and equal weights (scaled to 1), the periodic cubic smoothing spline damps the
  // mode theta = 2 pi k / n by 1 / (1 + ((1 - p)/p) 6 (2 - 2 cos theta)^2 / (h^3 (4 + 2 cos theta))):
  // the spline energy of a periodic natural spline through a cosine of that mode
  // is (Q^T y)^2 / R with eigenvalues (2 - 2 cos theta)/h and h (4 + 2 cos theta)/6.
  const int n = 64;
  const double h = 0.01, p = 0.9999;
  for (int k : {1, 4, 9, 20}) {
    const double th = 2 * M_PI * k / n;
    std::vector<double> y(n), sp(n, h), w(n, h);
    for (int i = 0; i < n; ++i) y[i] = std::cos(th * i + 0.3);
    const double lam = (1 - p) / p * 6 * std::pow(2 - 2 * std::cos(th), 2) / (std::pow(h, 3) * (4 + 2 * std::cos(th)));
    const auto f = csaps(y, sp, w, p, true);
    for (int i = 0; i < n; ++i) CHECK(f[i] == Approx(y[i] / (1 + lam)).margin(1e-10));
  }
}

TEST_CASE("csaps keeps the weighted mass, lines and constants, and p = 1 interpolates", "[wear][smoothing][csaps]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const int n = 40;
  std::vector<double> y(n), sp(n), w(n);
  for (int i = 0; i < n; ++i) {
    y[i] = u(rng);
    sp[i] = 0.005 + 0.01 * u(rng);
  }
  for (int i = 0; i < n; ++i) w[i] = 0.5 * (sp[(i + n - 1) % n] + sp[i]);
  for (double p : {0.5, 0.9999, 0.999999}) {
    const auto f = csaps(y, sp, w, p, true);
    CHECK(weighted(f, w) == Approx(weighted(y, w)).epsilon(1e-12));
    std::vector<double> spo(sp.begin(), sp.end() - 1);
    const auto g = csaps(y, spo, w, p, false);
    CHECK(weighted(g, w) == Approx(weighted(y, w)).epsilon(1e-12));
  }
  // a straight line on an open sequence and a constant on a periodic one pass unchanged
  std::vector<double> x(n, 0.0), line(n), spo(sp.begin(), sp.end() - 1);
  for (int i = 1; i < n; ++i) x[i] = x[i - 1] + sp[i - 1];
  for (int i = 0; i < n; ++i) line[i] = 2 - 3 * x[i];
  const auto fl = csaps(line, spo, w, 0.3, false);
  for (int i = 0; i < n; ++i) CHECK(fl[i] == Approx(line[i]).margin(1e-10));
  const auto fc = csaps(std::vector<double>(n, 0.7), sp, w, 0.3, true);
  for (int i = 0; i < n; ++i) CHECK(fc[i] == Approx(0.7).margin(1e-12));
  CHECK(csaps(y, sp, w, 1.0, true) == y);
  // smoothing brings a noisy field closer to the truth
  std::vector<double> truth, raw;
  simulated_profile(truth, raw, 5);
  const int m = 61;
  std::vector<double> s61(m - 1, 0.01), w61(m, 0.01);
  const auto f = csaps(raw, s61, w61, 0.9999, false);
  double e_raw = 0, e_f = 0;
  for (int i = 0; i < m; ++i) {
    e_raw += std::pow(raw[i] - truth[i], 2);
    e_f += std::pow(f[i] - truth[i], 2);
  }
  CHECK(e_f < 0.6 * e_raw);
  CHECK_THROWS_AS(csaps(y, sp, w, 0.0, true), std::invalid_argument);
}

TEST_CASE("Tukey's running medians, hanning and splitting by hand", "[wear][smoothing][tukey]") {
  const std::vector<double> y{2, 9, 3, 4, 12, 5, 6, 6, 1, 7};
  // medians of 3: 3 4 4 5 6 6 6 6 inside; end-point rule: med(2, 3, 3x3 - 2x4 = 1) = 2, med(7, 6, 6) = 6
  const std::vector<double> m3{2, 3, 4, 4, 5, 6, 6, 6, 6, 6};
  CHECK(tukey_smooth(y, "3", false) == m3);
  CHECK(tukey_smooth(y, "3R", false) == m3);  // already a fixed point
  // hanning of m3: (2 + 6 + 4)/4 = 3, (3 + 8 + 4)/4 = 3.75, ...
  const std::vector<double> h{2, 3, 3.75, 4.25, 5, 5.75, 6, 6, 6, 6};
  const auto got = tukey_smooth(y, "3RH", false);
  for (size_t i = 0; i < h.size(); ++i) CHECK(got[i] == Approx(h[i]));
  // splitting a two-point peak: 5 5 between 2s -> each half re-estimated by the
  // end-point rule, med(5, 2, 3x2 - 2x1) = 4, then 3R: 1 2 4 4 2 1 1 1
  const std::vector<double> peak{1, 2, 5, 5, 2, 1, 0, 1};
  CHECK(tukey_smooth(peak, "S", false) == std::vector<double>{1, 2, 4, 4, 2, 1, 1, 1});
  // a single spike is removed by running medians
  std::vector<double> spike(15, 1.0);
  spike[7] = 50;
  CHECK(tukey_smooth(spike, "3R", true) == std::vector<double>(15, 1.0));
  // "twice" adds back the smoothed residual; constants are fixed points of everything
  CHECK(tukey_smooth(std::vector<double>(9, 2.5), "3RSSH,twice", true) == std::vector<double>(9, 2.5));
  // the thesis' 3RRSHRRSRR reads as 3R S H 3R SR
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> r(30);
  for (double& v : r) v = u(rng);
  CHECK(tukey_smooth(r, "3RRSHRRSRR", false) == tukey_smooth(r, "3RSH3RSR", false));
  CHECK_THROWS_AS(tukey_smooth(r, "3RQ", false), InputError);
  CHECK_THROWS_AS(tukey_smooth(r, "3RSSH,thrice", false), InputError);
}

TEST_CASE("smoothing a depth field never changes the mass removed (0.5 % rule)", "[wear][smoothing]") {
  std::vector<double> truth, raw;
  simulated_profile(truth, raw, 17);
  const int n = static_cast<int>(raw.size());
  std::vector<double> sp(n, 0.01), w(n, 0.01);
  for (SmoothingMethod m : {SmoothingMethod::None, SmoothingMethod::MovingAverage, SmoothingMethod::Csaps,
                            SmoothingMethod::Tukey, SmoothingMethod::TukeyCsaps}) {
    SmoothingSpec spec;
    spec.method = m;
    for (bool periodic : {true, false}) {
      std::vector<double> spc = periodic ? sp : std::vector<double>(sp.begin(), sp.end() - 1);
      const SmoothingResult r = smooth_depth(raw, spc, w, spec, periodic);
      INFO(smoothing_method_name(m) << (periodic ? " periodic" : " open"));
      CHECK(weighted(r.values, w) == Approx(weighted(raw, w)).epsilon(1e-12));
      for (double v : r.values) CHECK(v >= 0);
    }
  }
  // the default smoother, csaps, needs no correction at all before clipping
  SmoothingSpec def;
  const SmoothingResult r = smooth_depth(raw, std::vector<double>(sp.begin(), sp.end() - 1), w, def, false);
  CHECK(std::abs(r.relative_change) < 1e-12);
  CHECK(std::abs(r.relative_change_clipped) < 5e-3);
  CHECK(smoothing_method_from_name("csaps") == SmoothingMethod::Csaps);
  CHECK_THROWS_AS(smoothing_method_from_name("spline"), InputError);
}
