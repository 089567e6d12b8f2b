// The table of charge-motion models (DESIGN.md §2). One row per model; a new
// model is one more row here.
#include "charge/charge_model.h"

#include <fmt/format.h>

#include "charge/empirical_model.h"
#include "charge/layer_model.h"
#include "charge/dem/dem_model.h"
#include "geometry/errors.h"

namespace linerlife {

const std::vector<ChargeModelEntry>& charge_models() {
  static const std::vector<ChargeModelEntry> table = {
      // {name, description, resolves_impacts, resolves_abrasion, make, runs_in_time (default true)}
      {"empirical", "Morrell's C-model and Hogg-Fuerstenau: charge shape and power, instant (docs/models/empirical.md)",
       false, false, &make_empirical_model, false},
      {"layer", "the thesis' real-time layer simulator, versions 1.0/1.1/1.2 (docs/models/layer.md)", true, true,
       &make_layer_model},
      {"dem", "2D soft-disc DEM slice on the liner surface (the accuracy reference; docs/models/dem.md)", true,
       true, make_dem_model},
  };
  return table;
}

const ChargeModelEntry& find_charge_model(const std::string& name) {
  std::string names;
  for (const auto& e : charge_models()) {
    if (name == e.name) return e;
    names += (names.empty() ? "" : ", ") + std::string(e.name);
  }
  throw InputError("model.charge", fmt::format("charge model \"{}\" is not available; the models are: {}", name,
                                               names.empty() ? "(none built)" : names));
}

}  // namespace linerlife
