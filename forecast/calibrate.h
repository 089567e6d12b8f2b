// calibrate.h - fits wear coefficients to lifter profiles measured at stated
// operating hours, by least squares on the distance of the measured points to
// the forecast profiles (Levenberg-Marquardt on ln(parameter), Eigen), with
// the parameter covariance and the spread it gives the remaining life
// (docs/models/forecast.md, "Calibration").
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "forecast/forecast.h"
#include "forecast/measured_history.h"

namespace linerlife {

/// Makes the rate provider for a parameter vector (each parameter > 0, e.g.
/// the Archard K or a Table B.1 calibration factor).
using ProviderFactory = std::function<std::unique_ptr<RateProvider>(const std::vector<double>& params)>;

struct CalibrationProblem {
  std::vector<std::string> names;  // parameter names, for reports
  std::vector<double> initial;     // initial values, > 0
  ProviderFactory make_provider;
  ForecastInput input;             // the liner as new, when the hours started
  ForecastSpec spec;               // forecast settings; the fit runs the ode method without end-of-life criteria
  MeasuredHistory measured;        // profiles at hours since new, in the unrolled frame of segment 0
  int segments = 0;                // lifter rows (for the unrolled -> mill mapping)
  int max_iterations = 12;
  int jobs = 1;                    // forecasts at once for the finite differences (forecast/parallel.h)
};

struct CalibrationResult {
  std::vector<double> params;         // fitted values
  std::vector<double> sigma_log;      // 1-sigma of ln(parameter), from covariance_log
  Eigen::MatrixXd covariance_log;     // of ln(parameters), for residuals correlated along a scan (serial_covariance)
  std::vector<double> sigma_log_independent;  // 1-sigma of ln(parameter) were every measured point independent
  double residual_lag1 = 0;           // lag-1 autocorrelation of the residuals along the scans, in [0, 1)
  double rms_m = 0;                   // [m] RMS distance of the measured points to the fitted profiles
  double rms_initial_m = 0;           // [m] with the initial parameters
  std::vector<double> rms_per_snapshot_m;
  int forecasts = 0;
  int iterations = 0;
  bool converged = false;
  bool stalled = false;        // no step lowered the misfit, though the linear models promised a gain
  double promised_rms_m = 0;   // [m] the rms the linear models promised where the fit stalled (the smaller)
  int recheck_steps = 0;       // steps a 10 % slope found where the 2 % one before it found none
};

/// The covariance of least-squares parameters whose residuals are correlated
/// along each scan (docs/measured-profiles.md, "How far the factors can be
/// trusted"). The residuals r (Jacobian J: residuals x parameters) come in
/// runs, one per scan, each in the order of its points. A misfit the model
/// makes along a profile is smooth, so neighbouring points miss together and
/// the points are not independent measurements; s^2 (J^T J)^-1 then reads
/// sigmas too small, by up to about sqrt((1 + rho) / (1 - rho)) for slopes
/// smooth along long scans. The errors are taken as first-order
/// autoregressive along each run (a point's correlation with the one k
/// places on is rho^k; independent between runs) and the covariance of the
/// least-squares estimate is the sandwich
///   (J^T J)^-1 J^T Sigma J (J^T J)^-1,  Sigma_ik = s^2 rho^|i-k| within a run
/// (J. M. Wooldridge, Introductory Econometrics, 4th ed., ch. 12.1, the
/// variance of OLS under AR(1) errors), with rho the residuals' lag-1
/// autocorrelation sum r_t r_t-1 / sum r_t^2 over the runs (not centred: an
/// offset common to a scan is a correlation too; below 1), taken as 0 when
/// negative, and s^2 = |r|^2 / (m - parameters). With rho = 0 it is
/// s^2 (J^T J)^-1; for slopes smooth along the scans (the wear's) rho > 0
/// widens the sigmas (slopes that alternate along a scan could narrow them).
struct SerialCovariance {
  Eigen::MatrixXd covariance;              // the sandwich
  Eigen::MatrixXd covariance_independent;  // s^2 (J^T J)^-1
  double lag1 = 0;                         // rho as used, in [0, 1)
};
SerialCovariance serial_covariance(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const std::vector<int>& runs);

/// Fits p.names to p.measured. Throws InputError naming p.measured.source
/// when the data cannot determine a factor: no profile after 0 h
/// (check_history_has_wear), or a Jacobian of the residuals without full
/// column rank (a factor that does not change the forecast profiles, or
/// changes them only as the others do), naming the factor(s); never a sigma
/// of 0 for an undetermined factor. The slopes are finite differences over
/// 10 % of each factor first, then over 2 % (docs/measured-profiles.md, "Two
/// scales of slope"). A fit that stalls (no step along either slope lowers
/// the misfit, though the Gauss-Newton model of the 10 % slope promises to
/// lower its rms by more than 5 % and 0.1 mm; `promised_rms_m` the smaller
/// of the two slopes' promises), or that runs out of iterations where the
/// 2 % model at its last point still promises that much, is returned with
/// `converged` false (`stalled` for the first, and for the second where
/// its last iteration found no step); require_converged() refuses it. The
/// covariance is serial_covariance()'s at the fitted factors, over the 2 %
/// slope.
CalibrationResult calibrate(const CalibrationProblem& p);

/// Throws SimulationError (exit 3) naming p.measured.source, the factors, the
/// misfit and what went wrong where `r` did not converge: its factors are not
/// a fit and are never to be reported as one.
void require_converged(const CalibrationProblem& p, const CalibrationResult& r);

/// Throws InputError naming the file when the history has no profile after
/// 0 h: profiles of the new liner alone cannot determine a wear factor.
void check_history_has_wear(const MeasuredHistory& h);

/// The forecast profiles of segment 0 at the measured hours for `params`
/// (mill frame), as the fit compares them.
std::vector<ProfileRecord> fitted_profiles(const CalibrationProblem& p, const std::vector<double>& params);

/// Signed distances [m] of measured points (mill frame) to a simulated
/// profile chain: positive where the measured surface stands on the charge
/// side of the simulated one (less worn than simulated).
std::vector<double> profile_residuals(const std::vector<Eigen::Vector2d>& measured,
                                      const std::vector<Eigen::Vector2d>& simulated);

/// The spread of a life from the parameter uncertainty: ln T is linearised in
/// ln(parameters) by finite differences (one forecast per parameter) and
/// taken as normal. P10 is the short life (the early relining date).
struct LifeQuantiles {
  double p10_h = 0, p50_h = 0, p90_h = 0;  // [h] operating hours
  double sigma_ln = 0;                      // of ln T
  std::string criterion;                    // of the P50 forecast
  int forecasts = 0;
};
LifeQuantiles life_quantiles(const std::vector<double>& params, const Eigen::MatrixXd& covariance_log,
                             const ProviderFactory& make_provider, const ForecastInput& input, const ForecastSpec& spec,
                             int jobs = 1);

}  // namespace linerlife
