// `linerlife calibrate [CONFIG] --measured FILE.csv [--fit abrasion,impact]
// [--json] [--out DIR]`: fits the wear calibration factors (thesis Table B.1:
// centrifugal, gravitational, impact) to lifter profiles measured at stated
// operating hours, reports the misfit and the parameter uncertainty, writes
// the calibrated configuration, and forecasts the rest of the life from the
// last measurement with a P10/P50/P90 relining date
// (docs/measured-profiles.md, docs/models/forecast.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/config_edit.h"
#include "app/forecast_setup.h"
#include "app/json.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "app/results.h"
#include "forecast/calibrate.h"
#include "forecast/measured_history.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"

namespace linerlife {
namespace {

struct CalibrateOptions {
  std::string config;
  std::string measured;
  std::string fit = "abrasion,impact";
  bool json = false;
  std::string out;
  int jobs = 0;  // forecasts at once (the finite differences); 0: forecast_jobs()
};

/// Which calibration factors each fitted parameter scales.
struct Param {
  std::string name;
  bool centrifugal, gravitational, impact;
};

std::vector<Param> parse_fit(const std::string& fit) {
  if (fit == "abrasion,impact" || fit == "impact,abrasion")
    return {{"abrasion", true, true, false}, {"impact", false, false, true}};
  if (fit == "abrasion") return {{"abrasion", true, true, false}};
  if (fit == "impact") return {{"impact", false, false, true}};
  if (fit == "all") return {{"all", true, true, true}};
  if (fit == "centrifugal,gravitational,impact")
    return {{"centrifugal", true, false, false}, {"gravitational", false, true, false}, {"impact", false, false, true}};
  throw InputError("--fit", fmt::format("--fit {}: allowed abrasion,impact (default), abrasion, impact, all, or "
                                        "centrifugal,gravitational,impact",
                                        fit));
}

/// Refuses a fitted factor that scales no wear: the abrasion factors without
/// an abrasion law, the impact factor without an impact law. The fit could
/// not determine it (calibrate() would refuse it after the first forecasts).
void check_fit_against_laws(const std::vector<Param>& ps, const std::string& fit, const Config& c) {
  bool abrasion = false, impact = false;
  for (const std::string& law : c.wear.laws) {
    abrasion = abrasion || law.rfind("abrasion/", 0) == 0;
    impact = impact || law.rfind("impact/", 0) == 0;
  }
  for (const Param& q : ps) {
    const bool scales_wear = ((q.centrifugal || q.gravitational) && abrasion) || (q.impact && impact);
    if (scales_wear) continue;
    throw InputError("--fit", fmt::format("--fit {}: the {} factor scales {} wear, and the wear laws (\"{}\") have no "
                                          "{} law: the profiles cannot determine it; fit {} or add such a law to "
                                          "[wear] laws",
                                          fit, q.name, q.impact && !q.centrifugal ? "impact" : "abrasive",
                                          c.wear_laws_text, q.impact && !q.centrifugal ? "impact" : "abrasion",
                                          abrasion ? "--fit abrasion" : impact ? "--fit impact" : "nothing (no wear law)"));
  }
}

/// The scale of each calibration factor for a parameter vector.
std::array<double, 3> scales(const std::vector<Param>& ps, const std::vector<double>& v) {
  std::array<double, 3> s{1, 1, 1};
  for (size_t i = 0; i < ps.size(); ++i) {
    if (ps[i].centrifugal) s[0] *= v[i];
    if (ps[i].gravitational) s[1] *= v[i];
    if (ps[i].impact) s[2] *= v[i];
  }
  return s;
}

// A factor beyond its key's range is the fit's doing, not the file's (a
// review, 2026-12-06: scans labelled 0.01 h instead of 2,000 h ended with
// "FILE:185: wear.calibration_centrifugal = 162754.79...: out of range", a
// value the file never held): say so, naming the scans. A trial point of the
// fit beyond the range fails as before (the same InputError the wear model's
// range check throws), now with this message.
void check_fitted_factors(const Config& c, const std::array<double, 3>& s, const std::string& measured,
                          const MeasuredHistory& h) {
  const std::array<std::pair<const char*, double>, 3> fitted{{
      {"calibration_centrifugal", c.wear.calibration_centrifugal * s[0]},
      {"calibration_gravitational", c.wear.calibration_gravitational * s[1]},
      {"calibration_impact", c.wear.calibration_impact * s[2]},
  }};
  for (const auto& [key, v] : fitted) {
    const KeySpec* spec = config_schema().find("wear", key);
    if (!spec || spec->accepts(v)) continue;
    const bool high = v >= spec->lo;  // out of range above
    throw InputError(measured, fmt::format(
          "{}: the fit to these profiles asks for [wear] {} = {:.4g}, outside what the key allows ({}): the "
          "profiles wear the liner {} than the model does at any allowed calibration. Check the hours of the "
          "profiles ({} to {} h) and that they are of this mill",
          measured, key, v, spec->allowed(), high ? "far faster" : "far slower", h.snapshots.front().hours,
          h.snapshots.back().hours));
  }
}

/// Where the configuration sets a key: "FILE:LINE", or "the default" where
/// the file does not set it (messages that name a limit the user never wrote).
std::string key_origin_text(const Config& c, const std::string& key) {
  if (!key_given(c, key)) return "the default";
  std::string at = config_location(c, key);  // "FILE:LINE: "
  return at.substr(0, at.size() - 2);
}

/// The rest of the life is forecast from the last measured profile up to the
/// forecast's horizon, [forecast] max_operating_hours counted from the new
/// liner as in `linerlife forecast`: a profile measured at or beyond it
/// leaves nothing to forecast. (A review, 2026-12-07: the rest ran for the
/// whole horizon again from the scan, so a 4,500 h horizon gave a relining
/// at 5,431 h, exit 0; scans labelled 1e12 h gave dates past the year 9999,
/// and 1e30 h made the fit's forecast ask for some 1e21 records.)
void check_history_within_horizon(const Config& c, const MeasuredHistory& h, const std::string& measured) {
  const MeasuredSnapshot& last = h.snapshots.back();
  const double horizon = c.forecast.max_operating_hours;
  if (last.hours < horizon) return;
  throw InputError(measured, fmt::format(
      "{}:{}: hours = {}: the profile is measured at or beyond the forecast's horizon, [forecast] "
      "max_operating_hours = {} h ({}), counted from the new liner; allowed hours below {} h: check the hours of "
      "the profiles, or raise max_operating_hours",
      measured, last.first_line, last.hours, horizon, key_origin_text(c, "forecast.max_operating_hours"), horizon));
}

/// The misfit's correlation along the scans, and the ratio of the sigmas to
/// independent points' (serial_covariance(), docs/measured-profiles.md, "How
/// far the factors can be trusted").
std::string correlation_text(const CalibrationResult& r) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (size_t i = 0; i < r.sigma_log.size(); ++i) {
    const double w = r.sigma_log_independent[i] > 0 ? r.sigma_log[i] / r.sigma_log_independent[i] : 1.0;
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  const std::string widen = hi - lo < 0.005 ? fmt::format("{:.2f}", hi) : fmt::format("{:.2f}-{:.2f}", lo, hi);
  return fmt::format("misfit correlated along the scans with lag-1 {:.2f}: sigmas x{} those of independent points",
                     r.residual_lag1, widen);
}

/// Where the fit misses the scans by more than a scan resolves (about 1 mm)
/// and neighbouring points miss together (lag-1 at least 0.8), the misfit is
/// the model's, not a scanner's noise: the factors absorb it, by more than
/// their sigmas say (the stale example scans of docs/measured-profiles.md:
/// rms 1.38 mm, lag-1 0.95, the impact factor 0.32 for 1.3). The text of a
/// note saying so, or "" for a fit within the scans' resolution or with
/// uncorrelated residuals.
std::string model_misfit_text(const CalibrationResult& r) {
  constexpr double kScanResolutionM = 1e-3, kSharedLag1 = 0.8;
  if (!(r.rms_m >= kScanResolutionM && r.residual_lag1 >= kSharedLag1)) return "";
  return fmt::format("the fit misses the scans by {:.2f} mm rms, and neighbouring points miss together (lag-1 {:.2f}): "
                     "the misfit is the model's, not a scanner's noise, and the factors absorb it by more than their "
                     "sigmas say; check the scans' hours and the configuration against the mill "
                     "(docs/measured-profiles.md, \"How far the factors can be trusted\")",
                     1000 * r.rms_m, r.residual_lag1);
}

int run_calibrate(const CalibrateOptions& o) {
  const Config c = load_config_or_default(o.config);
  if (o.measured.empty()) throw InputError("--measured", "calibrate needs --measured FILE.csv (docs/measured-profiles.md)");
  // The measured profiles are of one lifter row, and the rest of the life is
  // forecast on a ring built from the last of them: a hi-lo liner would go on
  // as a ring of identical worn high lifters, its low rows' wear unmeasured.
  if (c.liner.hi_lo)
    rethrow_located(c, InputError("liner.pattern",
                                  "pattern = \"hi-lo\": calibrate does not support a hi-lo liner: the measured "
                                  "profiles are of one lifter row, and the rest of the life would be forecast on a "
                                  "ring of identical worn high lifters (the low rows' wear is not measured); "
                                  "calibrate a uniform liner (docs/measured-profiles.md)"));
  const MeasuredHistory h = load_measured_history(o.measured);
  validate_measured_history(h, c.mill.shell_radius_m(), c.liner.segments);
  check_history_within_horizon(c, h, o.measured);
  check_history_has_wear(h);
  const std::vector<Param> ps = parse_fit(o.fit);
  check_fit_against_laws(ps, o.fit, c);
  // the finite differences: one forecast per parameter, and one more for the life's spread
  const int jobs = forecast_jobs(o.jobs, static_cast<int>(ps.size()) + 1, c.model.charge == "dem");
  if (!o.out.empty()) check_output_dir_writable(o.out, {"calibrated.toml", "calibrate.h5"});

  std::array<bool, 3> fit_factors{false, false, false};  // centrifugal, gravitational, impact
  for (const Param& q : ps)
    fit_factors = {fit_factors[0] || q.centrifugal, fit_factors[1] || q.gravitational, fit_factors[2] || q.impact};
  ForecastSetup setup = make_forecast_setup(c, fit_factors);  // checks the models at setup
  CalibrationProblem p;
  for (const Param& q : ps) p.names.push_back(q.name);
  p.initial.assign(ps.size(), 1.0);
  p.make_provider = [&c, &ps, &o, &h](const std::vector<double>& v) {
    const auto s = scales(ps, v);
    check_fitted_factors(c, s, o.measured, h);
    return make_scaled_provider(c, s[0], s[1], s[2]);
  };
  p.input = setup.input;
  p.spec = c.forecast;
  p.measured = h;
  p.segments = c.liner.segments;
  p.jobs = jobs;
  // The rest of the life is forecast from the last measured profile. Where
  // it already meets a relining criterion, the liner is due now: said before
  // the fit (which still gives the factors), and the remaining life is 0 h
  // (before, the forecast from it refused the run after the fit, "at the
  // start", naming neither the scan nor the criterion's line).
  const MeasuredSnapshot& last = h.snapshots.back();
  LinerDesign worn = c.liner;
  worn.measured = true;
  worn.hi_lo = false;  // refused above: a hi-lo ring cannot be rebuilt from one measured row
  worn.profile.source = fmt::format("{} at {} h", o.measured, last.hours);
  worn.profile.points = last.points;
  auto worn_ring = std::make_shared<LinerSurface>(build_liner_surface(c.mill, worn));
  const std::optional<MetCriterion> due = criterion_met(c, *worn_ring);
  if (due) {
    std::string at = config_location(c, due->key);  // "FILE:LINE: "
    at = at.substr(0, at.size() - 2);
    const std::string rule = due->name == "worn_through" ? due->limit : fmt::format("{} at {}", due->limit, at);
    note(fmt::format("linerlife: note: the last measured profile ({} at {} h) already meets the relining criterion {} "
                     "({}; {}): the liner is due for relining now, its remaining life 0 h; the fit goes on for the "
                     "factors",
                     o.measured, last.hours, due->name, due->gauges, rule));
  }
  if (!o.json) std::cerr << fmt::format("  fitting {} parameter(s) to {} profiles...\n", ps.size(), h.snapshots.size());
  const CalibrationResult r = calibrate(p);
  require_converged(p, r);  // a stalled fit's factors are not a fit (exit 3)
  const std::string misfit = model_misfit_text(r);
  if (!misfit.empty()) note("linerlife: note: " + misfit);

  // the calibrated configuration
  Config cal = c;
  const auto s = scales(ps, r.params);
  check_fitted_factors(c, s, o.measured, h);
  cal = config_with(cal, "wear.calibration_centrifugal", fmt::format("{}", c.wear.calibration_centrifugal * s[0]), "calibrate");
  cal = config_with(cal, "wear.calibration_gravitational", fmt::format("{}", c.wear.calibration_gravitational * s[1]), "calibrate");
  cal = config_with(cal, "wear.calibration_impact", fmt::format("{}", c.wear.calibration_impact * s[2]), "calibrate");

  // the rest of the life from the last measured profile
  ForecastInput rest = setup.input;
  rest.initial = worn_ring.get();
  // up to the horizon, counted from the new liner (check_history_within_horizon())
  ForecastSpec rest_spec = c.forecast;
  const double horizon_h = c.forecast.max_operating_hours - last.hours;  // > 0
  rest_spec.max_operating_hours = horizon_h;
  const LifeQuantiles q = due ? LifeQuantiles{0, 0, 0, 0, due->name, 0}
                              : life_quantiles(r.params, r.covariance_log, p.make_provider, rest, rest_spec, jobs);
  const Calendar& cal_days = c.forecast.calendar;
  // A quantile at the horizon or beyond is a life the forecast did not reach
  // (the fitted run ended on the horizon, or the spread carries it past):
  // as `linerlife forecast` does, no relining date for it: null in --json,
  // "" in calibrate.h5, "beyond the horizon" in the text.
  auto beyond = [&](double remaining_h) { return q.criterion == "horizon" || remaining_h >= horizon_h; };
  auto date = [&](double remaining_h) {
    return beyond(remaining_h) ? std::string() : iso_date(cal_days.date_after(last.hours + remaining_h));
  };
  const std::string horizon_date = iso_date(cal_days.date_after(c.forecast.max_operating_hours));
  auto life_text = [&](const char* name, double remaining_h) {
    if (beyond(remaining_h))
      return fmt::format("{} beyond the horizon ({:.0f} h, {})", name, horizon_h, horizon_date);
    return fmt::format("{} {:.0f} h ({})", name, remaining_h, date(remaining_h));
  };
  const std::string lives =
      q.criterion == "horizon"
          ? fmt::format("not reached within the horizon: more than {:.0f} h (the horizon, {}); horizon", horizon_h,
                        horizon_date)
          : fmt::format("{}, {}, {}; {}", life_text("P10", q.p10_h), life_text("P50", q.p50_h),
                        life_text("P90", q.p90_h), q.criterion);

  if (o.json) {
    Json params = Json::array();
    for (size_t i = 0; i < ps.size(); ++i)
      params.push(Json::object()
                      .set("name", ps[i].name)
                      .set("factor", r.params[i])
                      .set("sigma_ln", r.sigma_log[i])
                      .set("sigma_ln_independent", r.sigma_log_independent[i]));
    Json j = Json::object();
    j.set("config", c.source)
        .set("measured", o.measured)
        .set("profiles", static_cast<int>(h.snapshots.size()))
        .set("parameters", params)
        .set("calibration_centrifugal", cal.wear.calibration_centrifugal)
        .set("calibration_gravitational", cal.wear.calibration_gravitational)
        .set("calibration_impact", cal.wear.calibration_impact)
        .set("rms_initial_m", r.rms_initial_m)
        .set("rms_m", r.rms_m)
        .set("rms_per_profile_m", r.rms_per_snapshot_m)
        .set("residual_lag1", r.residual_lag1)
        .set("converged", r.converged)
        .set("forecasts", r.forecasts + q.forecasts)
        .set("fit_forecasts", r.forecasts)
        .set("last_measured_hours", last.hours)
        .set("remaining_hours_p10", q.p10_h)
        .set("remaining_hours_p50", q.p50_h)
        .set("remaining_hours_p90", q.p90_h)
        .set_or_null("relining_date_p10", date(q.p10_h))
        .set_or_null("relining_date_p50", date(q.p50_h))
        .set_or_null("relining_date_p90", date(q.p90_h))
        .set("criterion", q.criterion)
        .set("horizon_date", horizon_date);
    std::cout << j.dump() << "\n";
  } else {
    std::cout << fmt::format("Calibration of {} against {} ({} profiles, {} to {} h)\n", c.source, o.measured,
                             h.snapshots.size(), h.snapshots.front().hours, last.hours);
    for (size_t i = 0; i < ps.size(); ++i)
      std::cout << fmt::format("  {:<14} factor {:.4g}  (1-sigma x/ {:.3f})\n", ps[i].name, r.params[i],
                               std::exp(r.sigma_log[i]));
    std::cout << "  " << correlation_text(r) << "\n";
    std::cout << fmt::format("  calibration_centrifugal = {:.6g}, calibration_gravitational = {:.6g}, "
                             "calibration_impact = {:.6g}\n",
                             cal.wear.calibration_centrifugal, cal.wear.calibration_gravitational,
                             cal.wear.calibration_impact);
    // every forecast the command ran, as --json's "forecasts" (a review,
    // 2026-12-07: the text gave the fit's only, 19 where --json said 21)
    std::cout << fmt::format("  RMS misfit {:.2f} mm (was {:.2f} mm with the given factors); {} forecasts ({} for the "
                             "fit, {} for the remaining life)\n",
                             1000 * r.rms_m, 1000 * r.rms_initial_m, r.forecasts + q.forecasts, r.forecasts,
                             q.forecasts);
    if (due)
      std::cout << fmt::format("  remaining life from {} h: 0 h, due now ({}): the last measured profile meets {}\n",
                               last.hours, date(0), q.criterion);
    else
      std::cout << fmt::format("  remaining life from {} h: {}\n", last.hours, lives);
  }

  if (!o.out.empty()) {
    OutputDir dir(o.out);
    dir.prepare();
    // the fit's result as comments: a file passed on alone still says how
    // far its factors can be trusted (the same figures as --json and calibrate.h5)
    std::string head = fmt::format("# Calibrated by `linerlife calibrate` against {} ({} profiles, {} to {} h)\n",
                                   o.measured, h.snapshots.size(), h.snapshots.front().hours, last.hours);
    for (size_t i = 0; i < ps.size(); ++i)
      head += fmt::format("#   {}: factor {:.4g}, 1-sigma x/ {:.3f} (sigma_ln {:.4g})\n", ps[i].name, r.params[i],
                          std::exp(r.sigma_log[i]), r.sigma_log[i]);
    head += "#   " + correlation_text(r) + "\n";
    if (!misfit.empty()) head += "#   " + misfit + "\n";
    head += fmt::format("#   RMS misfit {:.2f} mm (was {:.2f} mm with the given factors){}\n", 1000 * r.rms_m,
                        1000 * r.rms_initial_m, r.converged ? "" : "; the fit did not converge");
    head += due ? fmt::format("#   remaining life from {} h: 0 h, due now ({})\n", last.hours, q.criterion)
                : fmt::format("#   remaining life from {} h: {}\n", last.hours, lives);
    dir.write_text("calibrated.toml", head + config_to_toml(cal, true));
    const std::vector<ProfileRecord> fitted = fitted_profiles(p, r.params);
    const std::string tmp = dir.temp_path("calibrate.h5");
    {
      H5Writer h5(tmp);
      write_run_header(h5, cal, "calibrate");
      write_surface(h5, "/surface", *setup.surface);
      h5.group("/calibrate");
      h5.attr("/calibrate", "rms_m", r.rms_m);
      h5.attr("/calibrate", "rms_initial_m", r.rms_initial_m);
      h5.attr("/calibrate", "residual_lag1", r.residual_lag1);
      h5.attr("/calibrate", "remaining_hours_p10", q.p10_h);
      h5.attr("/calibrate", "remaining_hours_p50", q.p50_h);
      h5.attr("/calibrate", "remaining_hours_p90", q.p90_h);
      // the fit's result, as --json gives it (a review: the file had the
      // misfit and the remaining hours but not the factors or the dates)
      h5.attr("/calibrate", "measured_file", o.measured);
      h5.attr("/calibrate", "converged", static_cast<long long>(r.converged));
      h5.attr("/calibrate", "last_measured_hours", last.hours);
      h5.attr("/calibrate", "criterion", q.criterion);
      h5.attr("/calibrate", "relining_date_p10", date(q.p10_h));
      h5.attr("/calibrate", "relining_date_p50", date(q.p50_h));
      h5.attr("/calibrate", "relining_date_p90", date(q.p90_h));
      h5.attr("/calibrate", "horizon_date", horizon_date);
      h5.attr("/calibrate", "calibration_centrifugal", cal.wear.calibration_centrifugal);
      h5.attr("/calibrate", "calibration_gravitational", cal.wear.calibration_gravitational);
      h5.attr("/calibrate", "calibration_impact", cal.wear.calibration_impact);
      {
        std::string names;
        std::vector<double> factor, sigma, sigma_independent;
        for (size_t i = 0; i < ps.size(); ++i) {
          names += (i ? "\n" : "") + ps[i].name;
          factor.push_back(r.params[i]);
          sigma.push_back(r.sigma_log[i]);
          sigma_independent.push_back(r.sigma_log_independent[i]);
        }
        h5.attr("/calibrate", "parameters", names);  // one name per line, in the order of factor and sigma_ln
        h5.dataset("/calibrate/factor", factor, {factor.size()}, "-");
        h5.dataset("/calibrate/sigma_ln", sigma, {sigma.size()}, "-");
        h5.dataset("/calibrate/sigma_ln_independent", sigma_independent, {sigma_independent.size()}, "-");
        h5.dataset("/calibrate/rms_per_profile_m", r.rms_per_snapshot_m, {r.rms_per_snapshot_m.size()}, "m");
      }
      for (size_t i = 0; i < h.snapshots.size(); ++i) {
        const std::string g = fmt::format("/calibrate/profile_{}", i);
        h5.group(g);
        h5.attr(g, "hours", h.snapshots[i].hours);
        std::vector<double> m, f;
        for (const auto& pt : unrolled_to_mill(h.snapshots[i].points, c.mill.shell_radius_m(), c.liner.segments))
          m.push_back(pt.x()), m.push_back(pt.y());
        for (const auto& pt : fitted[i].nodes) f.push_back(pt.x()), f.push_back(pt.y());
        h5.dataset(g + "/measured", m, {m.size() / 2, 2}, "m");
        h5.dataset(g + "/fitted", f, {f.size() / 2, 2}, "m");
      }
      h5.close();
    }
    dir.commit(tmp, "calibrate.h5");
    draw_charts("calibrate", dir.path("calibrate.h5"), dir.dir());
    if (!o.json) std::cout << fmt::format("Wrote {}, {} and charts\n", dir.path("calibrated.toml"), dir.path("calibrate.h5"));
  }
  return 0;
}

}  // namespace

void register_calibrate(CLI::App& app, std::function<int()>& run) {
  auto o = std::make_shared<CalibrateOptions>();
  auto* cmd = app.add_subcommand("calibrate", "Fit the wear calibration factors to measured profiles and forecast the rest of the life");
  cmd->add_option("CONFIG", o->config, "Mill configuration (TOML); default: the bundled Qiu SAG mill")
      ->check(config_path_check());
  cmd->add_option("--measured", o->measured, "Measured profiles: CSV hours,x_m,y_m (docs/measured-profiles.md)");
  cmd->add_option("--fit", o->fit,
                  "Factors to fit: abrasion,impact (default), abrasion, impact, all, or centrifugal,gravitational,impact");
  cmd->add_flag("--json", o->json, "Print one JSON object");
  cmd->add_option("--out", o->out, "Write calibrated.toml, calibrate.h5 and charts into this folder")
      ->check(out_folder_check("without --out nothing is written"));
  cmd->add_option("--jobs", o->jobs, "Forecasts run at once for the finite differences (default: one per core; one "
                                     "at a time with the DEM)")
      ->transform(decimal_check(true));
  cmd->callback([&run, o] { run = [o] { return run_calibrate(*o); }; });
}

}  // namespace linerlife
