// Calibration against measured profiles: recovery of known coefficients from
// synthetic scans, and refusal of bad measurement files.
#include <atomic>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "forecast/calibrate.h"
#include "forecast/parallel.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "geometry/measured_profile.h"

using namespace linerlife;
using V = Eigen::Vector2d;

namespace {

Mill qiu() {
  Mill m;
  m.diameter_m = 10.36;
  m.speed_rpm = 10.36;
  return m;
}

LinerDesign liner() {
  LinerDesign d;
  d.segments = 64;
  d.design = {0.075, 0.25, 0.15, 20, 20, 0};
  d.element_size_m = 0.01;
  d.density_kg_m3 = 7800;
  return d;
}

/// Two wear mechanisms with their own coefficients: a uniform "abrasion" of
/// everything, and an "impact" wear of the upper leading side of the lifter.
class TwoPartRates : public RateProvider {
 public:
  TwoPartRates(double ka, double ki) : ka_(ka), ki_(ki) {}
  RateSample sample(const LinerSurface& s, double) override {
    RateSample r;
    r.element_rate_m_s.resize(static_cast<size_t>(s.n_elements()));
    for (int i = 0; i < s.n_elements(); ++i) {
      const V& c = s.midpoint[i];
      const double t = s.shell_radius_m - c.norm();
      const double lead = s.normal[i].dot(V(-c.y(), c.x()).normalized()) > 0.3 ? 1.0 : 0.0;
      r.element_rate_m_s[i] = ka_ * 1.5e-9 + ki_ * 4e-9 * lead * std::max(0.0, t - 0.1) / 0.225;
    }
    return r;
  }

 private:
  double ka_, ki_;
};

ForecastSpec spec() {
  ForecastSpec s;
  s.calendar.start = {2027, 1, 1};
  s.output_interval_h = 200;
  return s;
}

/// Synthetic scans: the forecast with the true coefficients, recorded at
/// `hours`, every second node of segment 0, in the unrolled frame.
MeasuredHistory scans(const LinerSurface& s, double ka, double ki, const std::vector<double>& hours) {
  TwoPartRates p(ka, ki);
  ForecastSpec sp = spec();
  sp.min_lifter_height_m = -1;
  sp.max_face_angle_leading_deg = 1e9;
  sp.min_plate_thickness_m = 1e-6;
  sp.extra_output_hours = hours;
  sp.max_operating_hours = hours.back() + 1;
  ForecastInput in;
  in.initial = &s;
  const ForecastResult f = run_forecast(in, p, sp);
  MeasuredHistory h;
  h.source = "synthetic";
  for (double hr : hours)
    for (const auto& pr : f.profiles)
      if (std::abs(pr.hours - hr) < 1e-6) {
        MeasuredSnapshot m;
        m.hours = hr;
        const auto xy = segment_to_profile_xy(pr.nodes, 5.18, 0.0, 2 * M_PI / 64);
        for (size_t i = 0; i < xy.size(); i += 2) m.points.push_back(xy[i]);
        h.snapshots.push_back(m);
      }
  REQUIRE(h.snapshots.size() == hours.size());
  return h;
}

/// The two-factor fit (abrasion, impact of TwoPartRates) on surface s,
/// without its scans.
CalibrationProblem two_factor_problem(const LinerSurface& s) {
  CalibrationProblem p;
  p.names = {"abrasion", "impact"};
  p.initial = {1.0, 1.0};
  p.make_provider = [](const std::vector<double>& k) { return std::make_unique<TwoPartRates>(k[0], k[1]); };
  p.input.initial = &s;
  p.spec = spec();
  p.segments = 64;
  return p;
}

/// The one-factor fit (both parts of TwoPartRates scaled by k) on surface s,
/// without its scans.
CalibrationProblem one_factor_problem(const LinerSurface& s) {
  CalibrationProblem p;
  p.names = {"k"};
  p.initial = {1.0};
  p.make_provider = [](const std::vector<double>& k) { return std::make_unique<TwoPartRates>(k[0], k[0]); };
  p.input.initial = &s;
  p.spec = spec();
  p.segments = 64;
  return p;
}

}  // namespace

TEST_CASE("calibrate recovers a known wear coefficient from synthetic profiles", "[forecast][calibrate]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = one_factor_problem(s);
  p.measured = scans(s, 1.3, 1.3, {1500, 3000, 4500});
  const CalibrationResult r = calibrate(p);
  INFO("fitted k = " << r.params[0] << ", rms " << r.rms_m << " m from " << r.rms_initial_m << " m, " << r.forecasts
                     << " forecasts");
  CHECK(r.params[0] == Approx(1.3).epsilon(0.02));
  CHECK(r.rms_m < 0.1 * r.rms_initial_m);
  CHECK(r.sigma_log[0] < 0.02);
}

// The side of a measured point is that of the forecast surface's inward
// normal; where the nearest point is a node, the sum of its two segments'
// normals (the pseudo-normal). A worn profile can carry a thin spike (2 mm
// segments in and back out in the fit below); beyond its tip the normal of
// whichever segment came first gave a point on the charge side either sign,
// and the fit's Jacobian with it (a scan fitted in the wrong direction).
TEST_CASE("profile residuals are signed by the pseudo-normal at a spike's tip", "[forecast][calibrate]") {
  // along x with the charge side up (an anticlockwise surface's left), and a
  // spike standing 0.5 into the charge at x = 1.05
  const std::vector<V> sim = {V(0, 0), V(1, 0), V(1.05, 0.5), V(1.1, 0), V(2, 0)};
  const double d = std::hypot(0.25, 0.1);  // to the tip from either point below
  CHECK(profile_residuals({V(1.3, 0.6)}, sim)[0] == Approx(d));  // before: -d
  CHECK(profile_residuals({V(0.8, 0.6)}, sim)[0] == Approx(d));
  CHECK(profile_residuals({V(1.05, 0.9)}, sim)[0] == Approx(0.4));
  // away from the tip: the segments' own normals
  CHECK(profile_residuals({V(0.5, 0.2)}, sim)[0] == Approx(0.2));
  CHECK(profile_residuals({V(0.5, -0.2)}, sim)[0] == Approx(-0.2));
  CHECK(profile_residuals({V(1.5, -0.3)}, sim)[0] == Approx(-0.3));
}

// A scan dated past the life the starting factors give (a 4,500 h profile
// labelled 40,000 h, where the liner wears through at about 14,000 h): the fit
// compared it with the worn-through liner's last profile, which hardly moves
// with the factor, and stopped far from the answer calling it converged (the
// bundled mill: a 4,400 h scan labelled 20,000 h fitted 10.5 with an rms of
// 0.125 m). The fit now starts from factors that keep the liner to the last
// scan, and a fit whose forecast ends before a scan is refused.
TEST_CASE("calibrate fits a scan dated past the starting factors' life", "[forecast][calibrate]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = one_factor_problem(s);
  p.measured = scans(s, 1.3, 1.3, {4500});
  // the rates do not depend on time, so a factor scales time: the profile of
  // factor 1.3 at 4,500 h is that of factor 1.3 * 4,500 / 40,000 at 40,000 h
  p.measured.snapshots[0].hours = 40000;
  const CalibrationResult r = calibrate(p);
  INFO("fitted k = " << r.params[0] << ", rms " << r.rms_m << " m from " << r.rms_initial_m << " m");
  CHECK(r.params[0] == Approx(1.3 * 4500 / 40000).epsilon(0.02));
  CHECK(r.rms_m < 1e-3);
  SECTION("a scan no factor's forecast reaches is refused") {
    // wear that hardly changes with the factor: the liner wears through at
    // about 14,000 h whatever it is
    p.make_provider = [](const std::vector<double>& k) {
      return std::make_unique<TwoPartRates>(1 + 1e-3 * k[0], 1 + 1e-3 * k[0]);
    };
    try {
      const CalibrationResult bad = calibrate(p);
      FAIL("fitted " << bad.params[0] << " with rms " << bad.rms_m);
    } catch (const InputError& e) {
      CHECK(e.key() == "synthetic");
      CHECK_THAT(e.what(), Catch::Contains("before the profile measured at 40000 h"));
    }
  }
}

// "No step lowers the misfit" was taken for a minimum: a review's scan of the
// bundled mill dated far past the liner's life stalled at its starting factor
// (rms 97 mm, where about 4 mm was reachable) and reported it as converged,
// exit 0. Here the misfit is smooth only at the start and its fine
// finite-difference step (2 %): every step lands on a provider that wears
// twice as fast as the truth, so none lowers the misfit, though the fine
// slope promises most of it away. (The coarse slope over 10 % lands there
// too: it finds no step in the first iteration, the fine one none in the
// second, and the coarse one, which failed at this very point, promises a
// gain too: stalled.)
TEST_CASE("a fit that no step improves where its slope promises a gain is stalled, not converged",
          "[forecast][calibrate]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = one_factor_problem(s);
  p.measured = scans(s, 1.5, 1.5, {3000});
  p.make_provider = [](const std::vector<double>& k) {
    const double u = std::log(k[0]);
    const double k_eff = std::abs(u) < 1e-12 || std::abs(u - 0.02) < 1e-12 ? k[0] : 3.0;
    return std::make_unique<TwoPartRates>(k_eff, k_eff);
  };
  const CalibrationResult r = calibrate(p);
  INFO("k = " << r.params[0] << ", rms " << r.rms_m << " m from " << r.rms_initial_m << " m, promised "
              << r.promised_rms_m << " m");
  CHECK_FALSE(r.converged);
  CHECK(r.stalled);
  CHECK(r.iterations == 2);
  CHECK(r.params[0] == 1.0);
  CHECK(r.rms_m == r.rms_initial_m);
  CHECK(r.promised_rms_m < 0.5 * r.rms_m);
  try {
    require_converged(p, r);
    FAIL("a stalled fit passed require_converged");
  } catch (const SimulationError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("synthetic: the fit stalled at the factors k 1 after 2 iteration(s): no "
                                           "step lowers the misfit"));
  }
  // out of iterations right after the coarse slope found no step: still
  // stalled (nothing moves), not "did not converge ... the factors still move"
  CalibrationProblem one = p;
  one.max_iterations = 1;
  const CalibrationResult r1 = calibrate(one);
  CHECK(r1.iterations == 1);
  CHECK(r1.stalled);
  CHECK_FALSE(r1.converged);
  CHECK(r1.params[0] == 1.0);
  // the same scan with the smooth provider: converged, and require_converged passes it
  CalibrationProblem smooth = one_factor_problem(s);
  smooth.measured = p.measured;
  const CalibrationResult ok = calibrate(smooth);
  CHECK(ok.converged);
  CHECK_FALSE(ok.stalled);
  CHECK(ok.params[0] == Approx(1.5).epsilon(0.02));
  CHECK_NOTHROW(require_converged(smooth, ok));
  // out of iterations far from the minimum (one iteration from 0.2, a step
  // at most a factor e): not converged, whatever the step achieved
  smooth.initial = {0.2};
  smooth.max_iterations = 1;
  const CalibrationResult cut = calibrate(smooth);
  INFO("cut short at k = " << cut.params[0] << ", rms " << cut.rms_m << " m, promised " << cut.promised_rms_m << " m");
  CHECK(cut.rms_m < cut.rms_initial_m);
  CHECK(cut.params[0] < 1.0);
  CHECK_FALSE(cut.converged);
  CHECK_FALSE(cut.stalled);
  CHECK_THROWS_WITH(require_converged(smooth, cut),
                    Catch::StartsWith("synthetic: the fit did not converge in 1 iteration(s): the factors k 0."));
}

// A real mill's forecast profiles move with the factors in small steps (its
// charge drives and remeshes fall at other hours), so a slope taken over 2 %
// of a factor follows that ruggedness, not the trend: on the bundled example
// scans, made at every factor 1.3, such slopes alone stopped at impact 0.886
// with rms 0.87 mm and called it a minimum; with coarse slopes first the fit
// ends at abrasion 1.300, impact 1.310, rms 0.08 mm. Here the
// wear rate carries a ripple in ln(k) of period 0.04, steep enough that the
// rate falls as k rises over part of each period: the misfit has a local
// minimum in every period. Slopes over 10 % see past the ripple to the true
// factor (implicit filtering); with 2 % ones alone (a build with
// kCoarseStep = 0.02) the fit ended at k = 1.353, rms 1.36 mm, converged.
TEST_CASE("calibrate follows the trend of a rippled misfit to the true factor", "[forecast][calibrate]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = one_factor_problem(s);
  auto rippled = [](double k) {
    const double u = std::log(k);
    return std::exp(u + 0.012 * std::sin(2 * M_PI * u / 0.04));  // d ln(rate) / d ln(k) = 1 + 1.88 cos(...)
  };
  p.make_provider = [rippled](const std::vector<double>& k) {
    return std::make_unique<TwoPartRates>(rippled(k[0]), rippled(k[0]));
  };
  p.measured = scans(s, rippled(1.3), rippled(1.3), {1500, 3000, 4500});
  const CalibrationResult r = calibrate(p);
  INFO("fitted k = " << r.params[0] << ", rms " << r.rms_m << " m from " << r.rms_initial_m << " m, "
                     << r.iterations << " iterations, " << r.forecasts << " forecasts");
  CHECK(r.converged);
  // within a ripple's period of 1.3, where the rate is that of 1.3
  CHECK(std::abs(std::log(r.params[0] / 1.3)) < 0.04);
  CHECK(std::abs(rippled(r.params[0]) / rippled(1.3) - 1) < 0.01);
  CHECK(r.rms_m < 1e-4);  // 0.1 mm
}

TEST_CASE("serial_covariance is the independent-point covariance where neighbours do not miss together",
          "[forecast][calibrate]") {
  // residuals that alternate in sign have a negative lag-1 correlation,
  // taken as 0: the sandwich is then s^2 (J^T J)^-1
  const int n = 12;
  Eigen::MatrixXd J(2 * n, 2);
  Eigen::VectorXd r(2 * n);
  for (int i = 0; i < 2 * n; ++i) {
    J(i, 0) = 1.0 + 0.1 * i;
    J(i, 1) = std::sin(0.3 * i);
    r(i) = (i % 2 ? 1.0 : -1.0) * (1e-3 + 1e-4 * i);
  }
  const SerialCovariance c = serial_covariance(J, r, {n, n});
  CHECK(c.lag1 == 0.0);
  const double s2 = r.squaredNorm() / (2 * n - 2);
  const Eigen::MatrixXd naive = s2 * (J.transpose() * J).inverse();
  CHECK((c.covariance - naive).norm() < 1e-12 * naive.norm());
  CHECK((c.covariance_independent - naive).norm() < 1e-12 * naive.norm());
  CHECK_THROWS_AS(serial_covariance(J, r, {n, n - 1}), std::invalid_argument);
}

TEST_CASE("serial_covariance of a mean is the closed form for first-order autoregressive errors",
          "[forecast][calibrate]") {
  // one parameter that shifts every point alike (J = 1): the variance of the
  // mean of m points in independent runs of n, correlations rho^|i-k| within
  // a run, is s^2 / m^2 sum_runs (n + 2 sum_k (n - k) rho^k)
  // (Wooldridge, ch. 12.1)
  const std::vector<int> runs = {15, 9};
  const int m = 24;
  Eigen::MatrixXd J = Eigen::MatrixXd::Ones(m, 1);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) r(i) = std::cos(0.4 * i) + 0.2;  // smooth: positively correlated neighbours
  double num = 0;
  for (int i = 1; i < 15; ++i) num += r(i) * r(i - 1);
  for (int i = 16; i < m; ++i) num += r(i) * r(i - 1);
  const double rho = num / r.squaredNorm();
  REQUIRE(rho > 0.5);
  const SerialCovariance c = serial_covariance(J, r, runs);
  CHECK(c.lag1 == Approx(rho).epsilon(1e-14));
  const double s2 = r.squaredNorm() / (m - 1);
  double sum = 0;  // sum over both runs of sum_ik rho^|i-k|
  for (int n : runs) {
    sum += n;
    for (int k = 1; k < n; ++k) sum += 2.0 * (n - k) * std::pow(rho, k);
  }
  CHECK(c.covariance(0, 0) == Approx(s2 * sum / (m * m)).epsilon(1e-12));
  CHECK(c.covariance_independent(0, 0) == Approx(s2 / m).epsilon(1e-12));
}

TEST_CASE("serial_covariance's sigma covers the true slope under correlated errors where independent points' does not",
          "[forecast][calibrate]") {
  // y = a x + u along two runs of 40 points, x smooth along the run (a wear
  // depth growing along the profile), u first-order autoregressive with
  // rho 0.8 (a misfit that neighbours share); 2,000 draws (std::mt19937,
  // seed 11): how often the least-squares a lies within 1.96 sigma of the
  // true one, for each sigma. The sandwich's nominal 95 % comes out at 87 %
  // (rho and s^2 are estimated from the 80 residuals, both low); the
  // independent-point sigma, about a third of the spread, covers 49 %.
  const int n = 40, m = 2 * n, draws = 2000;
  const double a = 0.7, rho = 0.8;
  std::mt19937 rng(11);
  std::normal_distribution<double> z(0.0, 1.0);
  Eigen::MatrixXd J(m, 1);
  for (int i = 0; i < m; ++i) J(i, 0) = 0.5 + (i % n) / double(n);
  int in_sandwich = 0, in_independent = 0;
  for (int d = 0; d < draws; ++d) {
    Eigen::VectorXd y(m);
    for (int k = 0; k < 2; ++k) {
      double u = z(rng);  // stationary start: variance 1 / (1 - rho^2) below
      u /= std::sqrt(1 - rho * rho);
      for (int i = 0; i < n; ++i) {
        if (i > 0) u = rho * u + z(rng);
        y(k * n + i) = a * J(k * n + i, 0) + u;
      }
    }
    const double ahat = J.col(0).dot(y) / J.col(0).squaredNorm();
    const Eigen::VectorXd r = y - ahat * J.col(0);
    const SerialCovariance c = serial_covariance(J, r, {n, n});
    const double err = std::abs(ahat - a);
    in_sandwich += err <= 1.96 * std::sqrt(c.covariance(0, 0));
    in_independent += err <= 1.96 * std::sqrt(c.covariance_independent(0, 0));
  }
  const double cov_s = double(in_sandwich) / draws, cov_i = double(in_independent) / draws;
  INFO("coverage of the 1.96-sigma interval: sandwich " << cov_s << ", independent points " << cov_i);
  CHECK(cov_s > 0.83);
  CHECK(cov_s < 0.97);
  CHECK(cov_i < 0.65);
}

TEST_CASE("calibrate widens the factor's sigma for a misfit shared along a scan, not for a scanner's noise",
          "[forecast][calibrate]") {
  // The same scans at k = 1.3 twice: with each point's depth off by an
  // independent normal deviate of 0.3 mm (std::mt19937, seed 5), and off by
  // a wave of 0.3 mm amplitude along the scan (a profile the wear model
  // cannot make: neighbouring points miss together).
  const LinerSurface s = build_liner_surface(qiu(), liner());
  const MeasuredHistory exact = scans(s, 1.3, 1.3, {1500, 3000, 4500});
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 3e-4);
  CalibrationProblem white = one_factor_problem(s), wave = one_factor_problem(s);
  white.measured = wave.measured = exact;
  for (auto& m : white.measured.snapshots)
    for (auto& q : m.points) q.y() += noise(rng);
  for (auto& m : wave.measured.snapshots)
    for (size_t i = 0; i < m.points.size(); ++i) m.points[i].y() += 3e-4 * std::sin(2 * M_PI * i / m.points.size());
  const CalibrationResult rw = calibrate(white), rv = calibrate(wave);
  const double widen_w = rw.sigma_log[0] / rw.sigma_log_independent[0];
  const double widen_v = rv.sigma_log[0] / rv.sigma_log_independent[0];
  INFO("noise: k " << rw.params[0] << ", rms " << rw.rms_m << " m, lag-1 " << rw.residual_lag1 << ", sigma_ln "
                   << rw.sigma_log[0] << " (independent " << rw.sigma_log_independent[0] << ")");
  INFO("wave: k " << rv.params[0] << ", rms " << rv.rms_m << " m, lag-1 " << rv.residual_lag1 << ", sigma_ln "
                  << rv.sigma_log[0] << " (independent " << rv.sigma_log_independent[0] << ")");
  REQUIRE(rw.converged);
  REQUIRE(rv.converged);
  CHECK(rw.residual_lag1 < 0.3);
  CHECK(widen_w < 1.4);
  CHECK(rv.residual_lag1 > 0.8);
  CHECK(widen_v > 3.0);
  // the true factor: within two sigma of the fit with the widened sigma,
  // outside it with the independent points' (1.3011: 0.7 and 3.1 sigma)
  const double miss_v = std::abs(std::log(rv.params[0] / 1.3));
  CHECK(miss_v < 2 * rv.sigma_log[0]);
  CHECK(miss_v > 2 * rv.sigma_log_independent[0]);
  CHECK(std::abs(std::log(rw.params[0] / 1.3)) < 3 * rw.sigma_log[0]);
  // the covariance the life spread takes is the widened one
  CHECK(std::sqrt(rv.covariance_log(0, 0)) == Approx(rv.sigma_log[0]).epsilon(1e-12));
}

TEST_CASE("a 10 % slope tried again where the 2 % one finds no step can go on to the true rate",
          "[forecast][calibrate]") {
  // A rate rippled in ln(k) with period 0.03 and amplitude 0.02 (d ln(rate)
  // / d ln(k) = 1 + 4.19 cos(...): it falls with k over a good part of each
  // period) about k = 1.5: the 2 % slope at some point promises a gain that
  // no step along it finds, the 10 % slope tried again there finds one, and
  // the fit goes on to the rate of 1.5 (a period or so away in k: the rate
  // is not monotone in k, so the rate, not k, is what the scans fix).
  // The only one of the 30 fits of the hidden study below through this path.
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = one_factor_problem(s);
  auto rippled = [](double k) {
    const double u = std::log(k);
    return std::exp(u + 0.02 * std::sin(2 * M_PI * u / 0.03));
  };
  p.make_provider = [rippled](const std::vector<double>& k) {
    return std::make_unique<TwoPartRates>(rippled(k[0]), rippled(k[0]));
  };
  p.measured = scans(s, rippled(1.5), rippled(1.5), {1500, 3000, 4500});
  const CalibrationResult r = calibrate(p);
  INFO("fitted k = " << r.params[0] << " (rate x" << rippled(r.params[0]) / rippled(1.5) << "), rms " << r.rms_m
                     << " m, promised " << r.promised_rms_m << " m, " << r.iterations << " iterations, "
                     << r.recheck_steps << " recheck steps, " << r.forecasts << " forecasts");
  CHECK(r.recheck_steps >= 1);
  CHECK(r.converged);
  CHECK(std::abs(rippled(r.params[0]) / rippled(1.5) - 1) < 0.005);  // 1.0035 when written
  CHECK(r.rms_m < 3e-4);                                            // 0.18 mm
}

// A study, hidden from the default run (3.7 min; `test_forecast "calibrate
// over a sweep of rippled rates*"`): 30 rippled rates as in the two tests above
// (periods 0.03-0.08 in ln k, amplitudes 0.006-0.02, true k 1.3 and 1.5).
// Each fit either converges to the true rate or says it stalled; none
// converges elsewhere. It printed which fits took the 10 % slope again.
TEST_CASE("calibrate over a sweep of rippled rates converges to the true rate or stalls", "[.][forecast][calibrate]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  int stalled = 0, rechecked = 0;
  for (double period : {0.03, 0.04, 0.05, 0.06, 0.08})
    for (double amp : {0.006, 0.012, 0.02})
      for (double k0 : {1.3, 1.5}) {
        CalibrationProblem p = one_factor_problem(s);
        auto rippled = [=](double k) {
          const double u = std::log(k);
          return std::exp(u + amp * std::sin(2 * M_PI * u / period));
        };
        p.make_provider = [rippled](const std::vector<double>& k) {
          return std::make_unique<TwoPartRates>(rippled(k[0]), rippled(k[0]));
        };
        p.measured = scans(s, rippled(k0), rippled(k0), {1500, 3000, 4500});
        const CalibrationResult r = calibrate(p);
        const double rate = rippled(r.params[0]) / rippled(k0);
        WARN("period " << period << ", amplitude " << amp << ", k " << k0 << ": fitted " << r.params[0] << ", rate x"
                       << rate << ", rms " << r.rms_m << " m, " << (r.converged ? "converged" : "stalled") << ", "
                       << r.recheck_steps << " recheck steps");
        stalled += r.stalled;
        rechecked += r.recheck_steps > 0;
        CHECK((r.stalled || std::abs(rate - 1) < 0.01));
      }
  WARN(stalled << " stalled, " << rechecked << " took a step along the 10 % slope tried again");
}

TEST_CASE("calibrate separates two coefficients and gives a life spread", "[forecast][calibrate][slow]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = two_factor_problem(s);
  p.measured = scans(s, 0.7, 1.6, {1500, 3000, 4500});
  const CalibrationResult r = calibrate(p);
  INFO("fitted " << r.params[0] << ", " << r.params[1]);
  CHECK(r.params[0] == Approx(0.7).epsilon(0.02));
  CHECK(r.params[1] == Approx(1.6).epsilon(0.02));
  // the remaining life from the new liner with the fit: a spread around P50
  ForecastInput in;
  in.initial = &s;
  const LifeQuantiles q = life_quantiles(r.params, r.covariance_log, p.make_provider, in, spec());
  CHECK(q.sigma_ln > 0);
  CHECK(q.p10_h < q.p50_h);
  CHECK(q.p50_h < q.p90_h);
  TwoPartRates fitted(r.params[0], r.params[1]);
  CHECK(q.p50_h == Approx(run_forecast(in, fitted, spec()).operating_hours).epsilon(1e-9));
}

TEST_CASE("the finite differences of a calibration run at once with the results of one after the other",
          "[forecast][calibrate]") {
  // p.jobs and life_quantiles()' jobs: the forecasts of the Jacobian's
  // columns and of the life's spread are independent; running them on
  // threads must not change a bit of the fit (one iteration is enough to
  // compare, not to converge).
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = two_factor_problem(s);
  p.max_iterations = 1;
  p.measured = scans(s, 0.7, 1.6, {1000, 2000});
  p.jobs = 1;
  const CalibrationResult a = calibrate(p);
  p.jobs = 2;
  const CalibrationResult b = calibrate(p);
  REQUIRE(a.params.size() == 2);
  CHECK(b.params == a.params);
  CHECK(b.covariance_log == a.covariance_log);
  CHECK(b.rms_per_snapshot_m == a.rms_per_snapshot_m);
  CHECK(b.forecasts == a.forecasts);
  CHECK(b.iterations == a.iterations);
  CHECK(a.params[0] != a.params[1]);  // the two columns differ: a mixed-up column would show
  ForecastInput in;
  in.initial = &s;
  const LifeQuantiles qa = life_quantiles(a.params, a.covariance_log, p.make_provider, in, spec(), 1);
  const LifeQuantiles qb = life_quantiles(a.params, a.covariance_log, p.make_provider, in, spec(), 3);
  CHECK(qb.p50_h == qa.p50_h);
  CHECK(qb.sigma_ln == qa.sigma_ln);
  CHECK(qb.criterion == qa.criterion);
  CHECK(qb.forecasts == 3);
  CHECK(qa.sigma_ln > 0);
}

// J^T J of a fit with an undetermined factor is singular: its "inverse" is
// NaN or inf, and std::max(0, NaN) made the factor's sigma 0, so P10 = P50 =
// P90 with exit 0. Such a fit is refused naming the factor.
TEST_CASE("calibrate refuses a factor the measured profiles cannot determine", "[forecast][calibrate][input]") {
  const LinerSurface s = build_liner_surface(qiu(), liner());
  CalibrationProblem p = two_factor_problem(s);
  p.measured = scans(s, 0.7, 1.0, {1500, 3000});
  auto refused = [&](const std::string& words) {
    try {
      const CalibrationResult r = calibrate(p);
      FAIL("fitted " << r.params[0] << ", " << r.params[1] << " with sigma " << r.sigma_log[0] << ", "
                     << r.sigma_log[1]);
    } catch (const InputError& e) {
      CHECK(e.key() == "synthetic");
      CHECK_THAT(e.what(), Catch::Contains(words));
    }
  };
  SECTION("a factor that scales nothing (--fit impact without an impact law)") {
    p.make_provider = [](const std::vector<double>& k) { return std::make_unique<TwoPartRates>(k[0], 1.0); };
    refused("cannot determine the factor(s) impact (2 fitted: abrasion,impact): the forecast profiles at the "
            "measured hours do not change with it");
  }
  SECTION("two factors that scale the same wear") {
    p.make_provider = [](const std::vector<double>& k) {
      return std::make_unique<TwoPartRates>(k[0] * k[1], k[0] * k[1]);
    };
    refused("only as the other fitted factors do");
  }
  SECTION("a factor that moves the profiles by much less than the scans' scatter") {
    // impact wear of at most 0.004 mm by 3000 h, scans scattered by +-0.5 mm:
    // full rank, but a sigma of ln(impact factor) far above ln 10 (before: a
    // finite, meaningless spread of the life). One iteration: given more, the
    // fit raises the factor until the impact wear fits the scatter (to 13.6
    // in 12 iterations, sigma 2.2).
    p.max_iterations = 1;
    p.make_provider = [](const std::vector<double>& k) { return std::make_unique<TwoPartRates>(k[0], 1e-4 * k[1]); };
    p.measured = scans(s, 0.7, 1e-4, {1500, 3000});
    int i = 0;
    for (auto& m : p.measured.snapshots)
      for (V& q : m.points) q.y() += 5e-4 * ((i++ * 7919) % 11 - 5) / 5.0;
    refused("cannot determine the factor(s) impact (sigma of ln(factor) ");
  }
  SECTION("only the new liner's profile") {
    p.measured = scans(s, 1.0, 1.0, {0});
    refused("synthetic: the measured history has no profile after 0 h");
  }
}

TEST_CASE("parallel_for calls every index once and reports the lowest failure", "[forecast][parallel]") {
  for (const int jobs : {1, 2, 4}) {
    std::vector<std::atomic<int>> calls(50);
    parallel_for(50, jobs, [&](int i) { ++calls[static_cast<size_t>(i)]; });
    for (const auto& c : calls) CHECK(c.load() == 1);
    // failures at 7 and 8, the one at 8 first in time (on two or more
    // threads): the one at 7 is reported, and every index below it has been
    // called (a loop one after the other stops at 7)
    std::vector<std::atomic<int>> seen(50);
    try {
      parallel_for(50, jobs, [&](int i) {
        ++seen[static_cast<size_t>(i)];
        if (i == 7) std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (i == 7 || i == 8) throw std::runtime_error("case " + std::to_string(i));
      });
      FAIL("no exception");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "case 7");
    }
    for (int i = 0; i <= 7; ++i) CHECK(seen[static_cast<size_t>(i)].load() == 1);
    if (jobs == 1) CHECK(seen[8].load() == 0);  // in order: nothing after the failure
  }
  CHECK(default_jobs(3, true) == 1);
  CHECK(default_jobs(1, false) == 1);
  CHECK(default_jobs(1000, false) >= 1);
}

TEST_CASE("bad measured profile files are refused naming the line", "[forecast][calibrate][input]") {
  auto refuse = [](const std::string& text, const std::string& words) {
    try {
      parse_measured_history(text, "scans.csv");
      FAIL("accepted: " << text);
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains(words));
    }
  };
  refuse("hours,x_m,y_m\n", "no measured profile");
  refuse("1000,0,0.07\n1000,0.1,0.07\n500,0,0.07\n", "scans.csv:3");
  refuse("1000,0,0.07\n1000,0.1,0.07\n500,0,0.07\n", "increasing hours");
  refuse("1000,0,0.07\n1000,abc,0.07\n", "scans.csv:2");
  refuse("-5,0,0.07\n", "must be >= 0");
  refuse("100,0,0.07\n100,0.1,0.07\n200,0,0.07\n200,0.1,0.07\n200,0.2,0.07\n", "at least 3");
  const MeasuredHistory h = parse_measured_history("# scan\nhours,x_m,y_m\n0,0,0.075\n0,0.25,0.3\n0,0.508618,0.075\n",
                                                   "ok.csv");
  CHECK(h.snapshots.size() == 1);
  CHECK_NOTHROW(validate_measured_history(h, 5.18, 64));
  const MeasuredHistory bad = parse_measured_history("0,0,0.075\n0,0.25,-0.1\n0,0.508618,0.075\n", "out.csv");
  CHECK_THROWS_WITH(validate_measured_history(bad, 5.18, 64), Catch::Contains("inside the shell"));
  // a spreadsheet's "CSV UTF-8" starts with a byte order mark: read as the
  // same file without it (before, its header line was refused, the mark
  // invisible in the quoted line; a review, 2026-12-07)
  const MeasuredHistory bom = parse_measured_history(
      "\xEF\xBB\xBFhours,x_m,y_m\n0,0,0.075\n0,0.25,0.3\n0,0.508618,0.075\n", "bom.csv");
  REQUIRE(bom.snapshots.size() == 1);
  CHECK(bom.snapshots[0].points.size() == 3);
  CHECK(bom.snapshots[0].first_line == 2);
  // only at the start: a mark inside the file is no number
  refuse("hours,x_m,y_m\n\xEF\xBB\xBF" "0,0,0.075\n", "scans.csv:2");
}
