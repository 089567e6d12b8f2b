#include "forecast/charge_wear_rate.h"

#include "wear/slip_models.h"

namespace linerlife {

ChargeWearRate::ChargeWearRate(const Mill& mill, const ChargeSpec& charge, const ModelSpec& model,
                               const ChargeModelEntry& entry, WearModel wear, const LinerMaterial& material,
                               unsigned long long seed)
    : mill_(mill), charge_(charge), spec_(model), model_(entry.make()), wear_(std::move(wear)), material_(material),
      seed_(seed) {}

RateSample ChargeWearRate::sample(const LinerSurface& s, double revolutions) {
  ChargeInput in;
  in.mill = mill_;
  in.charge = charge_;
  in.model = spec_;
  in.surface = &s;
  in.revolutions = revolutions;
  in.seed = seed_ + static_cast<unsigned long long>(drives_);
  const ChargeResult cr = model_->run(in);
  ++drives_;
  if (wear_.needs_operating_point()) set_operating_point(wear_, operating_point(mill_, charge_, &cr.indicators, s));
  recession_rates(wear_, cr.loads, s, material_, rates_);
  RateSample r;
  r.element_rate_m_s = rates_.total;
  r.indicators = cr.indicators;
  r.has_indicators = true;
  r.impact_fraction = rates_.mass_rate_kg_s_per_m > 0 ? rates_.impact_mass_rate_kg_s_per_m / rates_.mass_rate_kg_s_per_m : 0;
  r.simulated_s = cr.stats.simulated_s;
  r.wall_s = cr.stats.wall_s;
  r.notes = cr.notes;
  return r;
}

}  // namespace linerlife
