// empirical_model.h - the "empirical" charge model: Morrell's C-model
// (Morrell 1993, 1996) for the charge shape and power, with Hogg &
// Fuerstenau as a second power figure (docs/models/empirical.md). Instant;
// it resolves no liner loads. The diameter inside the liners comes from the
// (possibly worn) liner surface, so a worn liner changes the result.
#pragma once

#include <memory>

#include "charge/charge_model.h"

namespace linerlife {

class EmpiricalModel : public ChargeModel {
 public:
  ChargeResult run(const ChargeInput& in) const override;
};

std::unique_ptr<ChargeModel> make_empirical_model();

}  // namespace linerlife
