// charge_wear_rate.h - the production RateProvider: a charge-model run on the
// current (worn) ring, its LinerLoads turned into recession rates by the wear
// laws (wear/recession.h), without the wear run's amplification.
#pragma once

#include <memory>

#include "charge/charge_model.h"
#include "forecast/rate_provider.h"
#include "wear/liner_material.h"
#include "wear/recession.h"

namespace linerlife {

class ChargeWearRate : public RateProvider {
 public:
  /// `wear` must have been made for `entry` (make_wear_model). Drive k
  /// passes seed + k to the charge model (ChargeInput::seed), so a resumed
  /// forecast repeats its drives: the layer model seeds its shuffle of
  /// element ids with it. The DEM does not read it: every DEM drive takes
  /// its disc sizes and placement from `[dem] seed` (ModelSpec), the same
  /// for every drive.
  ChargeWearRate(const Mill& mill, const ChargeSpec& charge, const ModelSpec& model, const ChargeModelEntry& entry,
                 WearModel wear, const LinerMaterial& material, unsigned long long seed = 1);

  RateSample sample(const LinerSurface& s, double revolutions) override;

  /// The number of drives so far (the next drive's seed offset).
  long long drive_count() const override { return drives_; }
  void set_drive_count(long long n) override { drives_ = n; }

 private:
  Mill mill_;
  ChargeSpec charge_;
  ModelSpec spec_;
  std::unique_ptr<ChargeModel> model_;
  WearModel wear_;
  LinerMaterial material_;
  unsigned long long seed_;
  long long drives_ = 0;
  RecessionRates rates_;
};

}  // namespace linerlife
