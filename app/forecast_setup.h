// forecast_setup.h - from a configuration to everything a forecast run needs:
// the initial ring, the charge model, the wear model (checked against each
// other at setup) and the rate provider. Shared by forecast, compare and
// calibrate.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/config.h"
#include "forecast/forecast.h"
#include "geometry/liner_surface.h"

namespace linerlife {

struct ForecastSetup {
  std::shared_ptr<LinerSurface> surface;    // the initial ring
  ForecastInput input;                      // points at *surface
  std::unique_ptr<RateProvider> provider;   // charge model + wear laws
  std::vector<std::string> warnings;        // the set-up's warnings (make_forecast_setup())
};

/// A relining criterion a ring already meets: its name (as a forecast's
/// `criterion`), its [forecast] key, the gauges that meet it and the limit
/// they meet ("[forecast] min_lifter_height_m = 0.075 m"; worn_through's is
/// the remesh's 0.2 mm, not a key's).
struct MetCriterion {
  std::string name, key, gauges, limit;
};

/// The first relining criterion of c's [forecast] that `ring` already meets,
/// gauged as the forecast gauges it (forecast/forecast.cpp, Criteria:
/// segment 0's lifter, the thinnest point over one period of the pattern; a
/// liner without a lifter has no height or face criterion); none if it meets
/// none.
std::optional<MetCriterion> criterion_met(const Config& c, const LinerSurface& ring);

/// Every relining criterion `ring` already meets, in criterion_met()'s order.
std::vector<MetCriterion> criteria_met(const Config& c, const LinerSurface& ring);

/// A warning (without the prefix) for refresh = "always" with a charge model
/// that takes long to drive (layer, dem): the forecast drives it thousands of
/// times; "" otherwise.
std::string refresh_always_warning(const Config& c);

/// Throws InputError for a charge model that is not available, an
/// incompatible wear law, a liner material out of range, or a DEM coarse
/// enough that its discs would not fit under the lifter the forecast wears
/// down to (naming the key). Keeps the warnings of wear_load_warnings(), of
/// the start against the criteria and of refresh_always_warning() in `warnings` and
/// prints them unless `print_warnings` is false (compare prints its cases'
/// together: case_warning_lines()); `fitted`: the calibration factors the run
/// fits (calibrate's --fit).
ForecastSetup make_forecast_setup(const Config& c, const std::array<bool, 3>& fitted = {false, false, false},
                                  bool print_warnings = true);

/// The warnings (without the "linerlife: warning: " prefix) for a
/// configuration whose charge model gives wear loads that may be off: the DEM with coarse_grain > 1 (its wear rate
/// came out -11 to +40 % of the media-size run's on the pilot mills,
/// docs/validation/speed-accuracy.md), and the DEM with a wear calibration
/// factor (centrifugal, gravitational, impact) left at 1 that the run does
/// not fit (`fitted`): the default constants are the thesis', used with its
/// layer model, and with them the DEM wears 7.4-9.4 times as fast
/// (docs/validation/ball-mill.md). Empty for any other model.
std::vector<std::string> wear_load_warnings(const Config& c, const std::array<bool, 3>& fitted = {false, false, false});

/// Prints wear_load_warnings() to stderr, one "linerlife: warning: " line
/// each; returns whether there was any.
bool warn_wear_loads(const Config& c, const std::array<bool, 3>& fitted = {false, false, false});

/// The warnings of several cases (compare), each distinct one once, naming
/// the cases it concerns ("all N cases" when every case has it):
/// "linerlife: warning: LABELS: MESSAGE". `labels` and `warnings` run
/// parallel, one entry per case.
std::vector<std::string> case_warning_lines(const std::vector<std::string>& labels,
                                            const std::vector<std::vector<std::string>>& warnings);

/// A provider for the configuration with its wear calibration factors scaled
/// (centrifugal, gravitational, impact): the parameters `calibrate` fits.
std::unique_ptr<RateProvider> make_scaled_provider(const Config& c, double k_centrifugal, double k_gravitational,
                                                   double k_impact);

}  // namespace linerlife
