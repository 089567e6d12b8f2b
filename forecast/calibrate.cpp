#include "forecast/calibrate.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "forecast/parallel.h"
#include "geometry/errors.h"

namespace linerlife {

using V = Eigen::Vector2d;

std::vector<double> profile_residuals(const std::vector<V>& measured, const std::vector<V>& sim) {
  // the inward normal of an anticlockwise surface: the tangent turned by +90 deg
  auto normal = [&](size_t i) {
    const V ab = sim[i + 1] - sim[i];
    const double l = ab.norm();
    return l > 0 ? V(-ab.y(), ab.x()) / l : V(0, 0);
  };
  std::vector<double> out;
  out.reserve(measured.size());
  for (const V& q : measured) {
    double best = std::numeric_limits<double>::infinity();
    size_t seg = 0;
    double at = 0;
    for (size_t i = 0; i + 1 < sim.size(); ++i) {
      const V ab = sim[i + 1] - sim[i];
      const double l2 = ab.squaredNorm();
      const double s = l2 > 0 ? std::clamp((q - sim[i]).dot(ab) / l2, 0.0, 1.0) : 0.0;
      const double d = (q - (sim[i] + s * ab)).norm();
      if (d < best) best = d, seg = i, at = s;
    }
    if (!std::isfinite(best)) {
      out.push_back(best);
      continue;
    }
    // The side: by the nearest segment's normal, or where the nearest point is
    // a node by the sum of its two segments' normals (the pseudo-normal). The
    // normal of whichever segment came first flipped the sign of a point
    // beyond a corner between two nearly equal forecasts, and with it the
    // fit's Jacobian (a scan of a much worn lifter fitted in the wrong
    // direction).
    V n = normal(seg);
    const bool at_start = at <= 0.0, at_end = at >= 1.0;
    if (at_start && seg > 0) n += normal(seg - 1);
    if (at_end && seg + 2 < sim.size()) n += normal(seg + 1);
    const V c = at_end ? sim[seg + 1] : at_start ? sim[seg] : V(sim[seg] + at * (sim[seg + 1] - sim[seg]));
    out.push_back((q - c).dot(n) >= 0 ? best : -best);
  }
  return out;
}

namespace {
/// The forecast of a parameter set with snapshots at the measured hours and
/// no end-of-life criteria: the residuals of every measured point.
struct Fit {
  const CalibrationProblem& p;
  std::atomic<int> forecasts{0};  // the finite differences run at once (p.jobs)

  ForecastSpec fit_spec() const {
    ForecastSpec s = p.spec;
    s.method = ForecastMethod::Ode;
    s.min_lifter_height_m = -1;            // criteria off: the fit follows the measured history
    s.min_plate_thickness_m = 1e-6;
    s.max_face_angle_leading_deg = 1e9;
    s.extra_output_hours.clear();
    for (const auto& m : p.measured.snapshots) s.extra_output_hours.push_back(m.hours);
    s.max_operating_hours = p.measured.snapshots.back().hours * 1.0001 + 1e-3;
    s.output_interval_h = 1e9;
    return s;
  }

  /// Where a forecast ended before a measured profile: its hours, and the
  /// first measured hours it did not reach (NaN when it reached them all).
  struct Reach {
    double end_h = 0;
    double missed_h = std::numeric_limits<double>::quiet_NaN();
    bool ok() const { return std::isnan(missed_h); }
  };

  /// Residuals [m], and the RMS of each snapshot. A forecast that wears the
  /// liner through before a measured profile has no profile to compare with
  /// it; its last one stands in (a residual that hardly changes with the
  /// factors, so never one to fit: `reach` says so and the callers refuse it).
  Eigen::VectorXd residuals(const std::vector<double>& params, std::vector<double>* per_snapshot = nullptr,
                            Reach* reach = nullptr) {
    auto provider = p.make_provider(params);
    const ForecastResult f = run_forecast(p.input, *provider, fit_spec());
    ++forecasts;
    std::vector<double> all;
    if (per_snapshot) per_snapshot->clear();
    if (reach) *reach = Reach{f.profiles.back().hours};
    const double R = p.input.initial->shell_radius_m;
    for (const auto& m : p.measured.snapshots) {
      const ProfileRecord* rec = nullptr;
      for (const auto& pr : f.profiles)
        if (std::abs(pr.hours - m.hours) <= 1e-6 * std::max(1.0, m.hours)) rec = &pr;
      if (!rec) {
        rec = &f.profiles.back();
        if (reach && reach->ok()) reach->missed_h = m.hours;
      }
      const auto r = profile_residuals(unrolled_to_mill(m.points, R, p.segments), rec->nodes);
      double ss = 0;
      for (double x : r) ss += x * x;
      if (per_snapshot) per_snapshot->push_back(std::sqrt(ss / r.size()));
      all.insert(all.end(), r.begin(), r.end());
    }
    return Eigen::Map<Eigen::VectorXd>(all.data(), static_cast<Eigen::Index>(all.size()));
  }
};

/// Refuses a fit whose Jacobian J (residuals x parameters) cannot determine
/// every parameter: J^T J is then singular, its "inverse" NaN or inf, and a
/// sigma taken from it would read 0 (std::max(0, NaN)). The rank is that of
/// a column-pivoting QR of J with pivots below 1e-8 of the largest counted as
/// zero; the undetermined parameters are the columns the pivoting leaves last.
constexpr double kMaxSigmaLog = 2.302585092994046;  // ln 10: a 1-sigma factor of 10

/// A fit no step improves is at its minimum where the Gauss-Newton model
/// promises to lower the rms misfit by at most this share of it, or by at
/// most kStationaryRmsM. The forecast profiles are smooth in the factors
/// only to their remeshing's resolution: the bundled mill's 2,000 h profile
/// labelled 60,000 h ended at rms 4.07 mm with 3.98 mm promised (2.2 %, 0.09
/// mm) and no step reaching it, a fit as good as the scan allows; a 0.05 %
/// rule called it stalled. A synthetic fit ends at a few nanometres, where
/// the share means nothing.
constexpr double kStationaryShare = 0.05;
constexpr double kStationaryRmsM = 1e-4;  // [m] 0.1 mm, a tenth of what a liner scan resolves

/// Whether residuals r (rss = |r|^2, m of them) with Jacobian J are at a
/// minimum to the forecasts' resolution: the Gauss-Newton model |r + J d|^2
/// is least at d = -A^-1 g (A = J^T J, g = J^T r), rss - g^T A^-1 g there;
/// the rms it promises (`promised_rms`) lower than now by at most the
/// threshold above. A model that promises nothing finite (A singular, J with
/// NaN) promises nothing: check_determined() refuses such a Jacobian.
bool stationary(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, double rss, Eigen::Index m,
                double& promised_rms) {
  const Eigen::VectorXd g = J.transpose() * r;
  double promised = g.dot((J.transpose() * J).ldlt().solve(g));
  if (!std::isfinite(promised)) promised = 0;
  const double rms = std::sqrt(rss / static_cast<double>(m));
  promised_rms = std::sqrt(std::max(0.0, rss - promised) / static_cast<double>(m));
  return rms - promised_rms <= std::max(kStationaryShare * rms, kStationaryRmsM);
}

void check_determined(const Eigen::MatrixXd& J, const CalibrationProblem& p) {
  const Eigen::Index np = J.cols();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  qr.setThreshold(1e-8);
  const bool finite = J.allFinite();
  const Eigen::Index rank = finite ? qr.rank() : 0;
  if (finite && rank == np) return;
  std::string names, why;
  for (Eigen::Index k = finite ? rank : 0; k < np; ++k) {
    const Eigen::Index j = finite ? qr.colsPermutation().indices()(k) : k;
    names += (names.empty() ? "" : ", ") + p.names[static_cast<size_t>(j)];
    if (why.empty())
      why = !finite                   ? "the forecasts around the fit failed to give finite profiles"
            : J.col(j).norm() == 0.0 ? "the forecast profiles at the measured hours do not change with it"
                                      : "it changes the forecast profiles only as the other fitted factors do";
  }
  throw InputError(p.measured.source,
                   fmt::format("{}: the measured profiles cannot determine the factor(s) {} ({} fitted: {}): {}; fit "
                               "only factors the wear laws and the profiles can tell apart (--fit)",
                               p.measured.source, names, np, fmt::join(p.names, ","), why));
}

std::vector<double> exp_of(const Eigen::VectorXd& theta) {
  std::vector<double> v(static_cast<size_t>(theta.size()));
  for (Eigen::Index i = 0; i < theta.size(); ++i) v[static_cast<size_t>(i)] = std::exp(theta(i));
  return v;
}

}  // namespace

SerialCovariance serial_covariance(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const std::vector<int>& runs) {
  const Eigen::Index m = r.size(), np = J.cols();
  // where each run starts in r
  std::vector<Eigen::Index> start{0};
  for (int n : runs) start.push_back(start.back() + n);
  if (start.back() != m || J.rows() != m || m <= np)
    throw std::invalid_argument(fmt::format("serial_covariance: {} residuals in runs of {} points, a Jacobian of "
                                            "{} x {}",
                                            m, start.back(), J.rows(), np));
  const size_t nruns = runs.size();
  double num = 0, den = r.squaredNorm();
  for (size_t k = 0; k < nruns; ++k)
    for (Eigen::Index t = start[k] + 1; t < start[k + 1]; ++t) num += r(t) * r(t - 1);
  SerialCovariance out;
  // below 1 (Cauchy-Schwarz; a run's ends pair once); below 0 (neighbours
  // alternating) taken as 0
  out.lag1 = den > 0 ? std::clamp(num / den, 0.0, 1.0) : 0.0;
  const double rho = out.lag1;
  const double s2 = den / static_cast<double>(m - np);
  const Eigen::MatrixXd Ainv = (J.transpose() * J).inverse();
  out.covariance_independent = s2 * Ainv;
  // R J, R the run-wise matrix of rho^|i-k|: a forward and a backward
  // first-order recursion per column (f_i = x_i + rho f_i-1, b_i = x_i + rho
  // b_i+1, (R x)_i = f_i + b_i - x_i), O(m) instead of O(m^2)
  Eigen::MatrixXd RJ(m, np);
  for (Eigen::Index c = 0; c < np; ++c)
    for (size_t k = 0; k < nruns; ++k) {
      double f = 0, b = 0;
      for (Eigen::Index t = start[k]; t < start[k + 1]; ++t) {
        f = J(t, c) + rho * f;
        RJ(t, c) = f;
      }
      for (Eigen::Index t = start[k + 1] - 1; t >= start[k]; --t) {
        b = J(t, c) + rho * b;
        RJ(t, c) += b - J(t, c);
      }
    }
  out.covariance = s2 * Ainv * (J.transpose() * RJ) * Ainv;
  return out;
}

void check_history_has_wear(const MeasuredHistory& h) {
  for (const auto& m : h.snapshots)
    if (m.hours > 0) return;
  throw InputError(h.source, fmt::format("{}: the measured history has no profile after 0 h: profiles of the new liner "
                                         "alone cannot determine a wear factor; add a profile measured after some "
                                         "operating hours",
                                         h.source));
}

CalibrationResult calibrate(const CalibrationProblem& p) {
  const int np = static_cast<int>(p.initial.size());
  if (np == 0) throw std::invalid_argument("calibrate: no parameters");
  for (double v : p.initial)
    if (!(v > 0)) throw std::invalid_argument("calibrate: parameters must start > 0");
  check_history_has_wear(p.measured);
  Fit fit{p};
  CalibrationResult res;
  Eigen::VectorXd theta(np);
  for (int i = 0; i < np; ++i) theta(i) = std::log(p.initial[static_cast<size_t>(i)]);
  // Start from factors whose forecast reaches the last measured profile: all
  // of them scaled down by 0.8 times the share of its hours the liner lasted
  // (exact for wear rates that do not change with time, a factor then being
  // a scale of time), a few times over.
  const double last_h = p.measured.snapshots.back().hours;
  Fit::Reach reach;
  Eigen::VectorXd r = fit.residuals(exp_of(theta), nullptr, &reach);
  for (int tries = 0; !reach.ok() && tries < 6; ++tries) {
    theta.array() += std::log(std::clamp(0.8 * reach.end_h / last_h, 1e-3, 0.8));
    r = fit.residuals(exp_of(theta), nullptr, &reach);
  }
  auto refuse_unreached = [&](const char* which, const std::vector<double>& params) {
    std::string f;
    for (size_t i = 0; i < params.size(); ++i) f += fmt::format("{}{} {:.4g}", i ? ", " : "", p.names[i], params[i]);
    throw InputError(p.measured.source,
                     fmt::format("{}: the forecast with the {} factors ({}) wears the liner through at {:.0f} h, before "
                                 "the profile measured at {:.6g} h, so it cannot be compared with it: are the profiles' "
                                 "hours those since the liner was new?",
                                 p.measured.source, which, f, reach.end_h, reach.missed_h));
  };
  if (!reach.ok()) refuse_unreached("starting (scaled down 6 times)", exp_of(theta));
  const Eigen::Index m = r.size();
  if (m <= np)
    throw InputError(p.measured.source, fmt::format("{}: {} measured points cannot fit {} parameters",
                                                    p.measured.source, m, np));
  double rss = r.squaredNorm();
  res.rms_initial_m = std::sqrt(rss / m);
  // Two scales of finite difference, coarse then fine (implicit filtering,
  // C. T. Kelley, "Iterative Methods for Optimization", SIAM 1999, ch. 7).
  // The forecast profiles move with the factors in small steps, as the
  // charge drives and remeshes fall at other hours: a slope taken over 2 %
  // of a factor that changes the wear by under 1 % (the bundled mill's
  // impact factor) is that ruggedness, not the trend. On the bundled example
  // scans, made at every factor 1.3, the 2 % slope alone ended at abrasion
  // 1.315, impact 0.886, rms 0.87 mm, and called it a minimum; the rms at
  // abrasion 1.315, impact 1.1 is 0.53 mm, and at every factor 1.3 0.14 mm
  // (docs/measured-profiles.md, bench/misfit_at_factors.py).
  // Slopes over 10 % follow the trend to the valley first; the 2 % ones then
  // settle the fit, judge its minimum (or its stall) and give the
  // covariance, as before.
  constexpr double kCoarseStep = 0.1, kFineStep = 0.02;  // in ln(parameter)
  double h = kCoarseStep;
  double lambda = 1e-3;
  Eigen::MatrixXd J(m, np);
  // one forecast per parameter, independent: p.jobs at once, each filling
  // its own column
  // (a forward step whose forecast no longer reaches a measured profile is
  // taken backwards)
  auto jacobian = [&] {
    parallel_for(np, p.jobs, [&](int j) {
      Eigen::VectorXd t2 = theta;
      t2(j) += h;
      Fit::Reach rj;
      Eigen::VectorXd rj2 = fit.residuals(exp_of(t2), nullptr, &rj);
      if (rj.ok()) {
        J.col(j) = (rj2 - r) / h;
      } else {
        t2(j) = theta(j) - h;
        J.col(j) = (r - fit.residuals(exp_of(t2))) / h;
      }
    });
  };
  // The iterations (p.max_iterations in all) take coarse slopes until a
  // step no longer lowers the misfit, or moves the factors by less than a
  // fine step; then fine ones. Where no step along a fine slope lowers the
  // misfit though the slope promises a gain, that slope may be the
  // ruggedness: the coarse slope is tried again (`recheck`), unless it
  // already failed at this very point; a step it finds goes on from there,
  // and where it finds none, its promise judges the minimum.
  enum class Scale { coarse, fine, recheck } scale = Scale::coarse;
  double fine_promise = 0;  // [m] the rms the fine slope promised before a recheck
  // where the coarse scale found no step: the point, and its slope's verdict
  Eigen::VectorXd coarse_failed_at;
  bool coarse_failed_stationary = false;
  double coarse_failed_promise = 0;
  bool last_improved = true;
  // the verdict where neither slope finds a step: the coarse one judges;
  // a stall reports the smaller of the two slopes' promises
  auto judge_by_coarse = [&](bool coarse_stationary, double coarse_promise) {
    res.converged = coarse_stationary;
    res.stalled = !coarse_stationary;
    res.promised_rms_m = coarse_stationary ? coarse_promise : std::min(coarse_promise, fine_promise);
  };
  for (int it = 0; it < p.max_iterations; ++it) {
    res.iterations = it + 1;
    h = scale == Scale::fine ? kFineStep : kCoarseStep;
    jacobian();
    if (it == 0) check_determined(J, p);  // before a fit that cannot succeed
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false, small = false;
    Eigen::VectorXd step;
    for (int tries = 0; tries < 8 && !improved; ++tries) {
      Eigen::MatrixXd Ad = A;
      for (int j = 0; j < np; ++j) Ad(j, j) += lambda * std::max(A(j, j), 1e-30);
      step = Ad.ldlt().solve(-g);
      // keep a step within a factor e of the parameters
      const double big = step.cwiseAbs().maxCoeff();
      if (big > 1.0) step /= big;
      Fit::Reach r2reach;
      const Eigen::VectorXd r2 = fit.residuals(exp_of(theta + step), nullptr, &r2reach);
      const double rss2 = r2.squaredNorm();
      if (rss2 < rss && r2reach.ok()) {
        theta += step;
        r = r2;
        const double rel = (rss - rss2) / std::max(rss, 1e-300);
        rss = rss2;
        lambda = std::max(lambda / 3, 1e-9);
        improved = true;
        small = scale == Scale::fine ? step.cwiseAbs().maxCoeff() < 1e-4 || rel < 1e-8
                                     : step.cwiseAbs().maxCoeff() < kFineStep;  // the trend is followed
      } else {
        lambda *= 4;
      }
    }
    last_improved = improved;
    if (scale != Scale::fine) {
      if (improved) {
        if (scale == Scale::recheck) ++res.recheck_steps;
        scale = small ? Scale::fine : Scale::coarse;
        if (small) lambda = 1e-3;  // a new scale starts afresh
        continue;
      }
      double promise = 0;
      const bool at_minimum = stationary(J, r, rss, m, promise);
      if (scale == Scale::recheck) {
        judge_by_coarse(at_minimum, promise);
        break;
      }
      // the coarse scale has done what it can: on to the fine one
      coarse_failed_at = theta;
      coarse_failed_stationary = at_minimum;
      coarse_failed_promise = promise;
      scale = Scale::fine;
      lambda = 1e-3;
      continue;
    }
    if (improved) {
      if (small) {
        res.converged = true;
        break;
      }
      continue;
    }
    // No step lowers the misfit: a minimum (to the finite differences'
    // resolution) only where the linear model promised next to nothing too.
    // Where it promised more, even the shortest steps along its descent
    // failed: the misfit is not smooth there, or the Jacobian does not
    // describe it, and the fit has stalled (a review: a scan dated far past
    // the liner's life stalled at its start and was called converged),
    // unless the coarse slope finds a step or promises nothing more.
    if (stationary(J, r, rss, m, fine_promise)) {
      res.converged = true;
      res.promised_rms_m = fine_promise;
      break;
    }
    if (coarse_failed_at.size() == theta.size() && coarse_failed_at == theta) {
      judge_by_coarse(coarse_failed_stationary, coarse_failed_promise);  // a recheck would repeat it
      break;
    }
    scale = Scale::recheck;
    lambda = 1e-3;
  }
  h = kFineStep;
  // Out of iterations just after a scale found no step: nothing moves, so
  // it is a minimum or a stall, judged as a fine failure is (not "still
  // moving", a review found).
  if (!res.converged && !res.stalled && !last_improved) {
    jacobian();
    res.converged = stationary(J, r, rss, m, res.promised_rms_m);
    res.stalled = !res.converged;
  }
  res.rms_m = std::sqrt(rss / m);
  res.params = exp_of(theta);
  if (res.stalled) {  // no optimum to take a covariance at (require_converged() says so)
    res.forecasts = fit.forecasts;
    return res;
  }
  // covariance of ln(parameters) at the optimum (serial_covariance()), with J re-evaluated there
  jacobian();
  // Out of iterations and still moving: a minimum after all where the model
  // at the last point promises as little as a stall's test allows (a misfit
  // creeping by the forecasts' own noise), otherwise not converged.
  if (!res.converged) res.converged = stationary(J, r, rss, m, res.promised_rms_m);
  check_determined(J, p);
  // residuals correlated along a scan (a misfit of the model's, smooth along
  // the profile) are fewer independent measurements than points
  std::vector<int> runs;
  for (const auto& snap : p.measured.snapshots) runs.push_back(static_cast<int>(snap.points.size()));
  const SerialCovariance sc = serial_covariance(J, r, runs);
  res.covariance_log = sc.covariance;
  res.residual_lag1 = sc.lag1;
  for (int j = 0; j < np; ++j)
    res.sigma_log_independent.push_back(std::sqrt(std::max(0.0, sc.covariance_independent(j, j))));
  for (int j = 0; j < np; ++j) {
    const double v = res.covariance_log(j, j);
    if (!(std::isfinite(v) && v >= 0))  // check_determined() should have caught it; never a sigma of 0 for it
      throw SimulationError(fmt::format("calibrate: the variance of ln({}) came out {}: (J^T J) could not be inverted "
                                        "at the fitted factors",
                                        p.names[static_cast<size_t>(j)], v));
    res.sigma_log.push_back(std::sqrt(v));
  }
  // Full rank is not enough: a factor that moves the profiles by little more
  // than the forecasts' own resolution gets a finite but meaningless sigma
  // (the bundled mill's default fit against three points at 1000 h: the
  // impact factor's 1-sigma came out "x/ inf", its P90 1e79 h). A factor
  // known only to within a factor of 10 at one sigma is not determined, and
  // the spread of the life, linearised in ln(factor) over +-0.02, would mean
  // nothing that far out.
  std::string loose;
  for (int j = 0; j < np; ++j)
    if (res.sigma_log[static_cast<size_t>(j)] > kMaxSigmaLog)
      loose += fmt::format("{}{} (sigma of ln(factor) {:.3g})", loose.empty() ? "" : ", ", p.names[static_cast<size_t>(j)],
                           res.sigma_log[static_cast<size_t>(j)]);
  if (!loose.empty())
    throw InputError(p.measured.source,
                     fmt::format("{}: the measured profiles cannot determine the factor(s) {}: known only to within "
                                 "more than a factor of 10 at one sigma ({} fitted: {}); fit fewer factors (--fit), "
                                 "or measure profiles where and when the wear they scale shows",
                                 p.measured.source, loose, np, fmt::join(p.names, ",")));
  fit.residuals(res.params, &res.rms_per_snapshot_m, &reach);
  if (!reach.ok()) refuse_unreached("fitted", res.params);  // cannot happen: every accepted step reached them
  res.forecasts = fit.forecasts;
  return res;
}

void require_converged(const CalibrationProblem& p, const CalibrationResult& r) {
  if (r.converged) return;
  std::string f;
  for (size_t i = 0; i < r.params.size(); ++i) f += fmt::format("{}{} {:.4g}", i ? ", " : "", p.names[i], r.params[i]);
  throw SimulationError(
      r.stalled
          ? fmt::format("{}: the fit stalled at the factors {} after {} iteration(s): no step lowers the misfit (rms "
                        "{:.2f} mm, {:.2f} mm at the start), though its slope promises an rms of {:.2f} mm; the forecast "
                        "profiles do not change smoothly with the factors there. Check the profiles' hours (those "
                        "since the liner was new: a scan dated far past the liner's life is one cause), or fit fewer "
                        "factors (--fit)",
                        p.measured.source, f, r.iterations, 1000 * r.rms_m, 1000 * r.rms_initial_m,
                        1000 * r.promised_rms_m)
          : fmt::format("{}: the fit did not converge in {} iteration(s): the factors {} still move (rms {:.2f} mm, "
                        "{:.2f} mm at the start); check the profiles' hours, or fit fewer factors (--fit)",
                        p.measured.source, r.iterations, f, 1000 * r.rms_m, 1000 * r.rms_initial_m));
}

std::vector<ProfileRecord> fitted_profiles(const CalibrationProblem& p, const std::vector<double>& params) {
  Fit fit{p};
  auto provider = p.make_provider(params);
  const ForecastResult f = run_forecast(p.input, *provider, fit.fit_spec());
  std::vector<ProfileRecord> out;
  for (const auto& m : p.measured.snapshots) {
    const ProfileRecord* rec = &f.profiles.back();
    for (const auto& pr : f.profiles)
      if (std::abs(pr.hours - m.hours) <= 1e-6 * std::max(1.0, m.hours)) rec = &pr;
    out.push_back(*rec);
  }
  return out;
}

LifeQuantiles life_quantiles(const std::vector<double>& params, const Eigen::MatrixXd& cov,
                             const ProviderFactory& make_provider, const ForecastInput& input, const ForecastSpec& spec,
                             int jobs) {
  LifeQuantiles q;
  const int np = static_cast<int>(params.size());
  const double h = 0.02;
  // the life at the fitted parameters (k = 0) and with each one raised by h
  // in ln (k = j + 1): independent forecasts, `jobs` at once
  std::vector<double> lives(static_cast<size_t>(np) + 1);
  std::vector<std::string> criteria(lives.size());
  parallel_for(np + 1, jobs, [&](int k) {
    std::vector<double> pr = params;
    if (k > 0) pr[static_cast<size_t>(k - 1)] *= std::exp(h);
    auto provider = make_provider(pr);
    const ForecastResult f = run_forecast(input, *provider, spec);
    lives[static_cast<size_t>(k)] = f.operating_hours;
    criteria[static_cast<size_t>(k)] = f.criterion;
  });
  q.forecasts = np + 1;
  q.criterion = criteria[0];
  const double t50 = lives[0];
  Eigen::VectorXd g(np);
  for (int j = 0; j < np; ++j) g(j) = (std::log(lives[static_cast<size_t>(j) + 1]) - std::log(t50)) / h;
  q.sigma_ln = std::sqrt(std::max(0.0, (g.transpose() * cov * g)(0, 0)));
  const double z = 1.2815515655446004;  // the 90 % quantile of the standard normal
  q.p50_h = t50;
  q.p10_h = t50 * std::exp(-z * q.sigma_ln);
  q.p90_h = t50 * std::exp(z * q.sigma_ln);
  return q;
}

}  // namespace linerlife
