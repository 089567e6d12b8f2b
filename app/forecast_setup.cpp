#include "app/forecast_setup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/commands.h"
#include "charge/dem/particle_set.h"
#include "forecast/charge_wear_rate.h"
#include "geometry/errors.h"
#include "geometry/build_liner_surface.h"
#include "geometry/metrics.h"
#include "wear/recession.h"

namespace linerlife {

std::unique_ptr<RateProvider> make_scaled_provider(const Config& c, double kc, double kg, double ki) {
  const ChargeModelEntry& entry = find_charge_model(c.model.charge);
  WearSpec spec = c.wear;
  spec.calibration_centrifugal *= kc;
  spec.calibration_gravitational *= kg;
  spec.calibration_impact *= ki;
  WearModel wear;
  try {
    wear = make_wear_model(spec, entry);
  } catch (const InputError& e) {
    rethrow_located(c, e);  // the [wear] laws line of the file
  }
  validate_liner_material(c.material);
  return std::make_unique<ChargeWearRate>(c.mill, c.charge, c.model, entry, std::move(wear), c.material, 1);
}

std::vector<std::string> wear_load_warnings(const Config& c, const std::array<bool, 3>& fitted) {
  std::vector<std::string> out;
  if (c.model.charge != "dem") return out;
  if (c.model.dem.coarse_grain > 1)
    out.push_back(fmt::format(
        "[dem] coarse_grain = {} changes the DEM's wear rate (by -11 to +40 % at s = 1.3 on the pilot mills, "
        "within 5 % on the Qiu mill up to s = 1.8: docs/validation/speed-accuracy.md); check it against "
        "coarse_grain = 1 before trusting the wear",
        c.model.dem.coarse_grain));
  // The default wear constants are the thesis', used with its layer model;
  // the DEM's loads wear the new liner 7.4 (Qiu) and 9.4 (the example ball
  // mill) times as fast with them (docs/validation/speed-accuracy.md,
  // "Relining time"; docs/validation/ball-mill.md). A factor left at 1 that
  // the run does not fit (calibrate fits its --fit factors) is uncalibrated.
  const WearSpec& w = c.wear;
  const std::array<std::pair<const char*, double>, 3> factors = {{{"calibration_centrifugal", w.calibration_centrifugal},
                                                                  {"calibration_gravitational", w.calibration_gravitational},
                                                                  {"calibration_impact", w.calibration_impact}}};
  std::string at_one;
  for (size_t i = 0; i < factors.size(); ++i)
    if (!fitted[i] && factors[i].second == 1) at_one += (at_one.empty() ? "" : ", ") + std::string(factors[i].first);
  if (!at_one.empty())
    out.push_back(fmt::format(
        "the DEM drives the wear with [wear] {} = 1, and the default wear constants are the thesis', used with its "
        "layer model: with them the DEM's new-liner mass-loss rate is 7.4 times the layer model's on the bundled Qiu "
        "mill and 9.4 times on the example ball mill (docs/validation/speed-accuracy.md, "
        "docs/validation/ball-mill.md), and its life several times shorter; calibrate the DEM's wear to measured "
        "profiles (linerlife calibrate) or scale the calibration factors",
        at_one));
  return out;
}

bool warn_wear_loads(const Config& c, const std::array<bool, 3>& fitted) {
  const std::vector<std::string> w = wear_load_warnings(c, fitted);
  for (const std::string& m : w) std::cerr << "linerlife: warning: " << m << "\n";
  return !w.empty();
}

std::vector<std::string> case_warning_lines(const std::vector<std::string>& labels,
                                            const std::vector<std::vector<std::string>>& warnings) {
  // each distinct warning once, in the order of first appearance, with the
  // cases it concerns
  std::vector<std::pair<std::string, std::vector<size_t>>> groups;
  for (size_t i = 0; i < warnings.size() && i < labels.size(); ++i)
    for (const std::string& m : warnings[i]) {
      auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == m; });
      if (g == groups.end()) {
        groups.push_back({m, {}});
        g = groups.end() - 1;
      }
      if (g->second.empty() || g->second.back() != i) g->second.push_back(i);
    }
  std::vector<std::string> lines;
  for (const auto& [m, cases] : groups) {
    std::string who;
    if (cases.size() == labels.size() && labels.size() > 1) {
      who = fmt::format("all {} cases", labels.size());
    } else {
      for (const size_t i : cases) who += (who.empty() ? "" : ", ") + labels[i];
    }
    lines.push_back(fmt::format("linerlife: warning: {}: {}", who, m));
  }
  return lines;
}

namespace {

/// The new liner against the relining criteria, as the forecast gauges it
/// (forecast/forecast.cpp, Criteria: segment 0's lifter, the thinnest point
/// over one period of the pattern; a liner without a lifter has no height or
/// face criterion). The forecast refuses a start that meets one too, but only
/// when it runs: compare set every case up first and still ran the cases
/// before a refused one (a review: --vary forecast.min_lifter_height_m=0.1,0.3
/// forecast the first case for 14 s before refusing the second).
/// Returns the warning for criteria given that cannot apply ("" if none).
std::string check_start_criteria(const Config& c, const LinerSurface& ring) {
  // Every criterion met is named, and a limit the file does not set is said
  // to be the default: the bundled pilot mills' 25 mm bars and 5 mm plates
  // meet both default limits, and the refusal named one, as if the file had
  // set it, and then the next (a review, 2026-12-07).
  const std::vector<MetCriterion> all = criteria_met(c, ring);
  if (!all.empty()) {
    const MetCriterion& met = all.front();
    std::vector<std::string> also, defaults;
    for (const MetCriterion& m : all) {
      if (m.name == "worn_through") continue;  // said by min_plate_thickness, whose key it shares
      if (m.name != met.name) also.push_back(fmt::format("{} ({})", m.name, m.limit));
      if (!key_given(c, m.key)) defaults.push_back(m.key.substr(m.key.find('.') + 1));
    }
    auto join = [](const std::vector<std::string>& v) {
      std::string t;
      for (size_t i = 0; i < v.size(); ++i) t += (i == 0 ? "" : i + 1 == v.size() ? " and " : ", ") + v[i];
      return t;
    };
    std::string more;
    if (!also.empty()) more += fmt::format("; it also meets {}", join(also));
    if (!defaults.empty())
      more += fmt::format("; {} {} the default{}, not set in the file: set {} in [forecast] below what the new liner "
                          "has",
                          join(defaults), defaults.size() == 1 ? "is" : "are", defaults.size() == 1 ? "" : "s",
                          defaults.size() == 1 ? "it" : "them");
    throw located(c, InputError(met.key, fmt::format("the liner already meets the relining criterion {} at the start "
                                                     "({}): nothing to forecast{}; check the [forecast] criteria "
                                                     "against the liner",
                                                     met.name, met.gauges, more)));
  }
  const ForecastSpec& f = c.forecast;
  const SegmentMetrics lifter = segment_metrics(ring, 0, c.mill.rotation, c.liner.density_kg_m3);
  const bool has = lifter.has_lifter;
  // A liner without a lifter (a plain plate, or a measured profile with none)
  // has no lifter to wear down: a height or face criterion given for it is
  // ignored, which is said, as a warning, for the keys the file or --vary set.
  if (has) return "";
  std::string ignored;
  if (key_given(c, "forecast.min_lifter_height_m") && f.min_lifter_height_m > 0)
    ignored = fmt::format("min_lifter_height_m = {} m", f.min_lifter_height_m);
  if (key_given(c, "forecast.max_face_angle_leading_deg"))
    ignored += (ignored.empty() ? "" : " and ") + fmt::format("max_face_angle_leading_deg = {} deg",
                                                              f.max_face_angle_leading_deg);
  if (ignored.empty()) return "";
  const bool both = ignored.find(" and ") != std::string::npos;
  return fmt::format("the liner has no lifter ({}lifter height {:.4f} m at the start): [forecast] {} {} not apply; its "
                     "life ends on min_plate_thickness_m = {} m or the horizon (leave {} out of [forecast] for a liner "
                     "without lifters)",
                     c.liner.measured ? "" : "a plain plate, ", lifter.lifter_height_m, ignored, both ? "do" : "does",
                     f.min_plate_thickness_m, both ? "them" : "it");
}

}  // namespace

std::optional<MetCriterion> criterion_met(const Config& c, const LinerSurface& ring) {
  const std::vector<MetCriterion> all = criteria_met(c, ring);
  if (all.empty()) return std::nullopt;
  return all.front();
}

std::vector<MetCriterion> criteria_met(const Config& c, const LinerSurface& ring) {
  const ForecastSpec& f = c.forecast;
  const int period = pattern_period(ring);
  const SegmentMetrics lifter = segment_metrics(ring, 0, c.mill.rotation, c.liner.density_kg_m3);
  double thinnest = lifter.min_thickness_m;
  for (int k = 1; k < period; ++k)
    thinnest = std::min(thinnest, segment_metrics(ring, k, c.mill.rotation, c.liner.density_kg_m3).min_thickness_m);
  const bool has = lifter.has_lifter;
  const double face = lifter.face_angle_leading_deg;
  constexpr double kWornThroughM = 2e-4;  // forecast.cpp's: the remesh holds nodes 1e-4 m off the shell
  const std::array<std::pair<const char*, bool>, 4> met = {{
      {"min_lifter_height", has && lifter.lifter_height_m <= f.min_lifter_height_m},
      {"min_plate_thickness", thinnest <= f.min_plate_thickness_m},
      {"max_face_angle_leading", has && !std::isnan(face) && face >= f.max_face_angle_leading_deg},
      {"worn_through", thinnest <= kWornThroughM},
  }};
  const std::array<const char*, 4> keys = {"forecast.min_lifter_height_m", "forecast.min_plate_thickness_m",
                                           "forecast.max_face_angle_leading_deg", "forecast.min_plate_thickness_m"};
  // the limit met, as said in a message: worn_through has no key of its own
  // (it shares min_plate_thickness_m's line), its limit is the remesh's
  const std::array<std::string, 4> limits = {
      fmt::format("[forecast] min_lifter_height_m = {} m", f.min_lifter_height_m),
      fmt::format("[forecast] min_plate_thickness_m = {} m", f.min_plate_thickness_m),
      fmt::format("[forecast] max_face_angle_leading_deg = {} deg", f.max_face_angle_leading_deg),
      fmt::format("a plate at most {} mm thick", 1000 * kWornThroughM)};
  std::vector<MetCriterion> out;
  for (size_t i = 0; i < met.size(); ++i)
    if (met[i].second)
      out.push_back(MetCriterion{met[i].first, keys[i],
                                 fmt::format("lifter height {:.4f} m, thinnest point {:.4f} m, leading face {:.2f} deg",
                                             lifter.lifter_height_m, thinnest, face),
                                 limits[i]});
  return out;
}

std::string refresh_always_warning(const Config& c) {
  const ForecastSpec& f = c.forecast;
  if (!f.refresh_always || f.method != ForecastMethod::Ode || (c.model.charge != "layer" && c.model.charge != "dem"))
    return "";
  // The figures: `linerlife forecast --json` on the bundled mill with refresh
  // = "always" (2026-12-07, the build of 4e858b5: 527 s of CPU, 7,483 drives,
  // 6,674 h) against the default "auto" (97 drives, 6,696 h, about 6 s); the
  // DEM's drives: docs/validation/speed-accuracy.md (35 in 1,115 s).
  return fmt::format(
      "{}refresh = \"always\" drives the {} charge model on every right-hand side the ODE solver evaluates: on the "
      "bundled Qiu mill with the layer model that is 7,483 drives and 528 s, against 97 drives and about 6 s with "
      "\"auto\", for a life 0.3 % shorter (6,674 against 6,696 h){}. It is meant for a fast model; \"auto\" with a "
      "smaller refresh_tol_m converges the life at less cost (docs/models/forecast.md)",
      config_location(c, "forecast.refresh"), c.model.charge,
      c.model.charge == "dem" ? "; the DEM's drives take about 30 s each, so expect days" : "");
}

ForecastSetup make_forecast_setup(const Config& c, const std::array<bool, 3>& fitted, bool print_warnings) {
  // A coarse-grained DEM needs its largest disc under the lifter
  // (docs/models/dem.md §3); the forecast wears the lifter down to
  // min_lifter_height_m, and the DEM would refuse a drive part-way through.
  // Refuse it here, before any work.
  if (c.model.charge == "dem" && c.model.dem.coarse_grain > 1 && c.forecast.min_lifter_height_m > 0) {
    const double s = c.model.dem.coarse_grain;
    const double dmax = largest_real_diameter_m(c.charge, c.model.dem);
    const double h_end = c.forecast.min_lifter_height_m;
    if (s * dmax > h_end * (1 + 1e-9))
      throw InputError("dem.coarse_grain",
                       fmt::format("{}coarse_grain = {}: the largest coarse disc ({:.4g} m) is taller than the lifter "
                                   "the forecast wears down to ([forecast] min_lifter_height_m = {} m), so the DEM "
                                   "would refuse a charge drive part-way through the life; for this forecast "
                                   "coarse_grain <= {:.3g} (1: none)",
                                   config_location(c, "dem.coarse_grain"), s, s * dmax, h_end,
                                   std::max(1.0, std::floor(h_end / dmax * 1000) / 1000)));
  }
  ForecastSetup s;
  s.surface = std::make_shared<LinerSurface>(build_liner_surface(c.mill, c.liner));
  s.warnings = wear_load_warnings(c, fitted);
  if (const std::string w = check_start_criteria(c, *s.surface); !w.empty()) s.warnings.push_back(w);
  if (const std::string w = refresh_always_warning(c); !w.empty()) s.warnings.push_back(w);
  if (print_warnings)
    for (const std::string& m : s.warnings) std::cerr << "linerlife: warning: " << m << "\n";
  s.input.initial = s.surface.get();
  s.input.rotation = c.mill.rotation;
  s.input.density_kg_m3 = c.liner.density_kg_m3;
  s.input.element_size_m = c.liner.element_size_m;
  s.input.speed_rpm = c.mill.speed_rpm;
  s.provider = make_scaled_provider(c, 1, 1, 1);
  return s;
}

}  // namespace linerlife
