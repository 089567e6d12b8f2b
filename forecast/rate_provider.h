// rate_provider.h - what the forecast asks of the charge and wear modules: the
// recession rate of every surface element of a (worn) liner, with the mill
// indicators of that drive. The production provider runs a charge model and
// the wear laws (charge_wear_rate.h); tests use analytic fields.
#pragma once

#include <string>
#include <vector>

#include "charge/indicators.h"
#include "geometry/liner_surface.h"

namespace linerlife {

struct RateSample {
  std::vector<double> element_rate_m_s;  // [m/s] recession rate of each element of the surface passed, >= 0
  Indicators indicators;                 // of the charge drive behind the rates (zeros if none)
  bool has_indicators = false;
  double impact_fraction = 0;            // [-] share of the wear rate from impacts
  double simulated_s = 0;                // [s] charge time simulated for this sample
  double wall_s = 0;                     // [s] wall time of the sample
  std::vector<std::string> notes;        // the charge model's notes of this drive (ChargeResult::notes)
};

class RateProvider {
 public:
  virtual ~RateProvider() = default;
  /// Recession rates on surface `s`, averaged over `revolutions` mill
  /// revolutions. Throws SimulationError when the charge model fails.
  virtual RateSample sample(const LinerSurface& s, double revolutions) = 0;
  /// Drives so far, for providers whose drives depend on it (random seeds);
  /// saved in checkpoints and restored on resume.
  virtual long long drive_count() const { return 0; }
  virtual void set_drive_count(long long) {}
};

}  // namespace linerlife
