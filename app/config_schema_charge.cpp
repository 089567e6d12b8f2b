// The [charge] and [model] keys (DESIGN.md §4; issue 2 §2).
#include "app/config.h"
#include "app/config_schema_util.h"

namespace linerlife {

void add_charge_keys(Schema& s) {
  s.sections.push_back("charge");
  s.keys.push_back(real_key("charge", "filling", "-",
                            "Total charge J as a fraction of the volume inside the liners (balls, rock, voids)", 0.0,
                            0.5, true, true, std::nullopt, [](Config& c, double v) { c.charge.filling = v; },
                            [](const Config& c) { return c.charge.filling; }, true));
  s.keys.push_back(real_key("charge", "ball_filling", "-", "Ball charge J_B as a fraction of the volume inside the liners",
                            0.0, 0.5, false, true, std::nullopt, [](Config& c, double v) { c.charge.ball_filling = v; },
                            [](const Config& c) { return c.charge.ball_filling; }, true));
  s.keys.push_back(real_key("charge", "ball_diameter_m", "m", "Grinding media diameter", 0.001, 0.35, false, false,
                            std::nullopt, [](Config& c, double v) { c.charge.ball_diameter_m = v; },
                            [](const Config& c) { return c.charge.ball_diameter_m; }, true));
  s.keys.push_back(real_key("charge", "ball_density_kg_m3", "kg/m3", "Density of the grinding media", 1000.0, 20000.0,
                            false, false, 7800.0, [](Config& c, double v) { c.charge.ball_density_kg_m3 = v; },
                            [](const Config& c) { return c.charge.ball_density_kg_m3; }));
  s.keys.push_back(real_key("charge", "ore_density_kg_m3", "kg/m3", "Density of the ore", 1000.0, 8000.0, false, false,
                            2700.0, [](Config& c, double v) { c.charge.ore_density_kg_m3 = v; },
                            [](const Config& c) { return c.charge.ore_density_kg_m3; }));
  s.keys.push_back(real_key("charge", "porosity", "-", "Voids in the charge bed, E (Morrell 1996)", 0.2, 0.6, false,
                            false, 0.4, [](Config& c, double v) { c.charge.porosity = v; },
                            [](const Config& c) { return c.charge.porosity; }));
}

void add_model_keys(Schema& s) {
  s.sections.push_back("model");
  s.keys.push_back(string_key("model", "charge", "Charge-motion model", {"empirical", "layer", "dem"}, "layer",
                              [](Config& c, const std::string& v) { c.model.charge = v; },
                              [](const Config& c) { return c.model.charge; }));
  s.keys.push_back(string_key("model", "variant", "Layer model version (thesis §4.6)", {"1.0", "1.1", "1.2"}, "1.2",
                              [](Config& c, const std::string& v) { c.model.variant = v; },
                              [](const Config& c) { return c.model.variant; }));
  s.keys.push_back(real_key("model", "time_step_s", "s", "Time step of the layer model", 0.0, 0.1, true, false, 0.01,
                            [](Config& c, double v) { c.model.time_step_s = v; },
                            [](const Config& c) { return c.model.time_step_s; }));
}

}  // namespace linerlife
