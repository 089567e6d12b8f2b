#include "app/forecast_setup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "charge/dem/particle_set.h"
#include "forecast/charge_wear_rate.h"
#include "geometry/errors.h"
#include "geometry/build_liner_surface.h"
#include "wear/recession.h"

namespace linerlife {

std::unique_ptr<RateProvider> make_scaled_provider(const Config& c, double kc, double kg, double ki) {
  const ChargeModelEntry& entry = find_charge_model(c.model.charge);
  WearSpec spec = c.wear;
  spec.calibration_centrifugal *= kc;
  spec.calibration_gravitational *= kg;
  spec.calibration_impact *= ki;
  WearModel wear = make_wear_model(spec, entry);
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
  s.warnings = wear_load_warnings(c, fitted);
  if (print_warnings)
    for (const std::string& m : s.warnings) std::cerr << "linerlife: warning: " << m << "\n";
  s.surface = std::make_shared<LinerSurface>(build_liner_surface(c.mill, c.liner));
  s.input.initial = s.surface.get();
  s.input.rotation = c.mill.rotation;
  s.input.density_kg_m3 = c.liner.density_kg_m3;
  s.input.element_size_m = c.liner.element_size_m;
  s.input.speed_rpm = c.mill.speed_rpm;
  s.provider = make_scaled_provider(c, 1, 1, 1);
  return s;
}

}  // namespace linerlife
