// The [charge] and [model] keys (DESIGN.md §4; issue 2 §2).
#include "app/config.h"
#include "app/config_schema_util.h"
#include "charge/layer_model.h"

namespace linerlife {

void add_charge_keys(Schema& s) {
  s.sections.push_back("charge");
  s.keys.push_back(real_key("charge", "filling", "-",
                            "Total charge J as a fraction of the volume inside the liners (balls, rock, voids)", 0.01,
                            0.5, false, true, std::nullopt, [](Config& c, double v) { c.charge.filling = v; },
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
  // Charge-motion issue: what Morrell's C-model needs of the slurry and the mill ends.
  s.keys.push_back(real_key("charge", "slurry_void_fill", "-",
                            "Fraction U of the bed voids filled with slurry (Morrell 1996; 0: dry charge)", 0.0, 1.0,
                            false, false, 0.0, [](Config& c, double v) { c.charge.slurry_void_fill = v; },
                            [](const Config& c) { return c.charge.slurry_void_fill; }));
  s.keys.push_back(real_key("charge", "slurry_solids_mass_fraction", "-", "Mass fraction of solids in the slurry", 0.0,
                            1.0, true, true, 0.7,
                            [](Config& c, double v) { c.charge.slurry_solids_mass_fraction = v; },
                            [](const Config& c) { return c.charge.slurry_solids_mass_fraction; }));
  // [mill] keys of the charge models (the Mill struct belongs to geometry;
  // these live in ChargeSpec)
  s.keys.push_back(string_key("mill", "discharge",
                              "Discharge: a grate keeps no slurry pool; an overflow mill fills up to the trunnion",
                              {"grate", "overflow"}, "grate",
                              [](Config& c, const std::string& v) {
                                c.charge.discharge = v == "overflow" ? Discharge::Overflow : Discharge::Grate;
                              },
                              [](const Config& c) {
                                return std::string(c.charge.discharge == Discharge::Overflow ? "overflow" : "grate");
                              }));
  s.keys.push_back(opt_real_key("mill", "trunnion_diameter_m", "m",
                                "Trunnion diameter: the slurry level of an overflow mill and the cone power (Morrell "
                                "1996)",
                                0.0, 15.0, true, false,
                                [](Config& c, double v) { c.charge.trunnion_radius_m = 0.5 * v; },
                                [](const Config& c) -> std::optional<double> {
                                  if (!(c.charge.trunnion_radius_m > 0)) return std::nullopt;
                                  return 2.0 * c.charge.trunnion_radius_m;
                                },
                                "required by discharge = \"overflow\" and by cone_length_m > 0"));
  s.keys.push_back(real_key("mill", "cone_length_m", "m", "Length of one conical end, L_d (0: flat ends)", 0.0, 10.0,
                            false, false, 0.0, [](Config& c, double v) { c.charge.cone_length_m = v; },
                            [](const Config& c) { return c.charge.cone_length_m; }));
}

void add_model_keys(Schema& s) {
  s.sections.push_back("model");
  s.keys.push_back(string_key("model", "charge", "Charge-motion model", {"empirical", "layer", "dem"}, "layer",
                              [](Config& c, const std::string& v) { c.model.charge = v; },
                              [](const Config& c) { return c.model.charge; }));
  s.keys.push_back(string_key("model", "variant", "Layer model version (thesis §4.6)", {"1.0", "1.1", "1.2"}, "1.2",
                              [](Config& c, const std::string& v) { c.model.variant = v; },
                              [](const Config& c) { return c.model.variant; }));
  s.keys.push_back(real_key("model", "time_step_s", "s",
                            "Time step of the layer model (a step that moves the shell more than 0.45 "
                            "media diameters per step is sub-stepped; docs/models/layer.md §9)",
                            kLayerMinTimeStepS, 0.1, false, false, 0.005,
                            [](Config& c, double v) { c.model.time_step_s = v; },
                            [](const Config& c) { return c.model.time_step_s; }));
  // Charge-motion issue: the layer model's options (docs/models/layer.md).
  s.keys.push_back(string_key("model", "slip_model",
                              "Layer speeds: Morrell's linear law (thesis eq. 4.16) or Radziszewski's friction law "
                              "(eqs. 5.5-5.7)",
                              {"morrell", "radziszewski"}, "morrell",
                              [](Config& c, const std::string& v) { c.model.slip_model = v; },
                              [](const Config& c) { return c.model.slip_model; }));
  s.keys.push_back(real_key("model", "slip_parameter", "-", "Slip parameter delta of the Radziszewski law (eq. 5.7)",
                            0.0, 1.0, false, false, 0.005, [](Config& c, double v) { c.model.slip_parameter = v; },
                            [](const Config& c) { return c.model.slip_parameter; }));
  s.keys.push_back(real_key("model", "friction_coefficient", "-",
                            "Friction coefficient mu of McIvor's flight angle (thesis eq. 4.5) and of the foot slide",
                            0.0, 2.0, false, false, 0.5,
                            [](Config& c, double v) { c.model.friction_coefficient = v; },
                            [](const Config& c) { return c.model.friction_coefficient; }));
  s.keys.push_back(real_key("model", "repose_angle_deg", "deg",
                            "Dynamic angle of repose: foot stability and the shoulder clipping of version 1.1", 10.0,
                            60.0, false, false, 35.0, [](Config& c, double v) { c.model.repose_angle_deg = v; },
                            [](const Config& c) { return c.model.repose_angle_deg; }));
  s.keys.push_back(string_key("model", "lifter_slide",
                              "Balls slide out along the lifter face before flying (Powell 1991); off: they fly "
                              "from McIvor's angle, as in the thesis",
                              {"off", "on"}, "off",
                              [](Config& c, const std::string& v) { c.model.lifter_slide = v == "on"; },
                              [](const Config& c) { return std::string(c.model.lifter_slide ? "on" : "off"); }));
  s.keys.push_back(string_key("model", "pocket_loads",
                              "Layer model: the lifter face holding a pocket carries the tangential weight of the "
                              "charge over it (normal load on the face, not shear on the plate); off: every column "
                              "loads the liner under it, as in the thesis",
                              {"off", "on"}, "off",
                              [](Config& c, const std::string& v) { c.model.pocket_loads = v == "on"; },
                              [](const Config& c) { return std::string(c.model.pocket_loads ? "on" : "off"); }));
  s.keys.push_back(string_key("model", "slurry_drag",
                              "Drag of the slurry pool on flights (thesis Appendix C); overflow mills only",
                              {"off", "on"}, "off",
                              [](Config& c, const std::string& v) { c.model.slurry_drag = v == "on"; },
                              [](const Config& c) { return std::string(c.model.slurry_drag ? "on" : "off"); }));
  s.keys.push_back(real_key("model", "settle_revolutions", "-",
                            "Mill revolutions run before the averaging starts (docs/models/layer.md)", 0.0, 100.0,
                            false, false, 1.0, [](Config& c, double v) { c.model.settle_revolutions = v; },
                            [](const Config& c) { return c.model.settle_revolutions; }));
  s.keys.push_back(real_key("model", "relaxation_interval_cells", "-",
                            "Layer model: support sweep and surface relaxation every this many outer cells of shell "
                            "travel (docs/models/layer.md §9)",
                            0.01, 4.0, false, false, 0.5, [](Config& c, double v) { c.model.relaxation_interval_cells = v; },
                            [](const Config& c) { return c.model.relaxation_interval_cells; }));
  s.keys.push_back(string_key("model", "initial_phases",
                              "Layer model at t = 0: slot 0 of every layer at angle 0 (aligned), or each layer "
                              "turned by a different fraction of its slot (staggered; docs/models/layer.md §Settling)",
                              {"aligned", "staggered"}, "staggered",
                              [](Config& c, const std::string& v) { c.model.initial_phases = v; },
                              [](const Config& c) { return c.model.initial_phases; }));
  s.keys.push_back(real_key("model", "hf_lift_angle_deg", "deg",
                            "Lift angle of the Hogg-Fuerstenau power figure of the empirical model", 10.0, 80.0, false,
                            false, 45.0, [](Config& c, double v) { c.model.hf_lift_angle_deg = v; },
                            [](const Config& c) { return c.model.hf_lift_angle_deg; }));
}

}  // namespace linerlife
