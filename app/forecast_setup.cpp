#include "app/forecast_setup.h"

#include <iostream>

#include <fmt/format.h>

#include "forecast/charge_wear_rate.h"
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

bool warn_wear_loads(const Config& c) {
  if (c.model.charge != "dem" || !(c.model.dem.coarse_grain > 1)) return false;
  std::cerr << fmt::format(
      "linerlife: warning: [dem] coarse_grain = {} biases the DEM's wear loads upwards (by 13 to 82 % at the "
      "largest coarse-graining in docs/validation/speed-accuracy.md); the indicators are fine, the wear and the "
      "relining date are not: use coarse_grain = 1 for wear\n",
      c.model.dem.coarse_grain);
  return true;
}

ForecastSetup make_forecast_setup(const Config& c) {
  warn_wear_loads(c);
  ForecastSetup s;
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
