// The [wear] keys (issue 4; docs/models/wear.md). The law parameters are
// generated from the law table in wear/wear_laws.cpp, so every law's
// parameters appear here with the unit, range and default the law declares.
#include <algorithm>

#include <fmt/format.h>

#include "app/config.h"
#include "app/config_schema_util.h"
#include "geometry/errors.h"
#include "wear/recession.h"
#include "wear/wear_laws.h"

namespace linerlife {
namespace {

KeySpec int_range_key(const char* name, const char* help, long long lo, long long hi, long long def,
                      std::function<void(Config&, long long)> set, std::function<long long(const Config&)> get) {
  return int_key("wear", name, help, lo, hi, false, std::move(set), std::move(get), def);
}

}  // namespace

void add_wear_keys(Schema& s) {
  s.sections.push_back("wear");
  auto& k = s.keys;
  {
    std::string names;
    for (const auto& e : wear_laws()) names += (names.empty() ? "" : ", ") + e.name;
    KeySpec laws = string_key(
        "wear", "laws", "", {}, "abrasion/radziszewski, impact/sheldon_kanhere",
        [](Config& c, const std::string& v) { c.wear_laws_text = v; },
        [](const Config& c) { return c.wear_laws_text; });
    laws.help = "Wear laws whose wear adds up, separated by commas (\"none\": no wear); the laws are " + names;
    k.push_back(laws);
  }
  // parameters of the laws, from the table
  for (const auto& law : wear_laws())
    for (const auto& p : law.parameters) {
      const std::string help = p.help + " [" + law.name + "]";
      if (p.choices.empty()) {
        KeySpec key = real_key(
            "wear", p.key.c_str(), p.unit.c_str(), "", p.lo, p.hi, p.lo_open, p.hi_open, p.default_value,
            [key = p.key](Config& c, double v) { c.wear.parameters[key] = v; },
            [key = p.key, def = p.default_value](const Config& c) {
              auto it = c.wear.parameters.find(key);
              return it == c.wear.parameters.end() ? def : it->second;
            });
        key.help = help;
        k.push_back(key);
      } else {
        KeySpec key = string_key(
            "wear", p.key.c_str(), "", p.choices, p.default_choice.c_str(),
            [key = p.key](Config& c, const std::string& v) { c.wear.choices[key] = v; },
            [key = p.key, def = p.default_choice](const Config& c) {
              auto it = c.wear.choices.find(key);
              return it == c.wear.choices.end() ? def : it->second;
            });
        key.help = help;
        k.push_back(key);
      }
    }
  // thesis Table B.1: calibration and amplification
  auto factor = [&](const char* name, const char* help, double hi, double WearSpec::*field) {
    k.push_back(real_key(
        "wear", name, "-", help, 0.0, hi, true, false, 1.0, [field](Config& c, double v) { c.wear.*field = v; },
        [field](const Config& c) { return c.wear.*field; }));
  };
  factor("calibration_centrifugal", "Calibration factor of the wear from the centrifugal force (Table B.1 CalifCF)",
         1e5, &WearSpec::calibration_centrifugal);
  factor("calibration_gravitational", "Calibration factor of the wear from the gravitational force (Table B.1 CalifGF)",
         1e5, &WearSpec::calibration_gravitational);
  factor("calibration_impact", "Calibration factor of the impact wear (Table B.1 CalifImp)", 1e5,
         &WearSpec::calibration_impact);
  factor("amplification_abrasion",
         "Amplification of the abrasive wear in the coupled wear run (Table B.1; Qiu 2001: 1e7); not used by forecasts",
         1e9, &WearSpec::amplification_abrasion);
  factor("amplification_impact", "Amplification of the impact wear in the coupled wear run (Table B.1)", 1e9,
         &WearSpec::amplification_impact);
  // the coupled wear run
  k.push_back(string_key(
      "wear", "liner_computation", "Wear one liner of each design and copy it to its like, or every liner (Table B.1)",
      {"one", "all"}, "one", [](Config& c, const std::string& v) { c.wear.liner_computation = v; },
      [](const Config& c) { return c.wear.liner_computation; }));
  k.push_back(int_range_key(
      "feedback", "1: re-drive the charge model on the worn profile (Table B.1 FeedBack)", 0, 1, 0,
      [](Config& c, long long v) { c.wear.feedback = v != 0; },
      [](const Config& c) { return static_cast<long long>(c.wear.feedback ? 1 : 0); }));
  k.push_back(real_key(
      "wear", "revolutions", "-", "Mill revolutions the wear run simulates", kMinRevolutions, 1e4, false, false, 1.5,
      [](Config& c, double v) { c.wear.revolutions = v; }, [](const Config& c) { return c.wear.revolutions; }));
  k.push_back(int_range_key(
      "remesh_every_steps", "Charge time steps between two remeshes of the worn profile (docs/models/wear.md §6.2)", 1,
      1000000, 10, [](Config& c, long long v) { c.wear.remesh_every_steps = static_cast<int>(v); },
      [](const Config& c) { return static_cast<long long>(c.wear.remesh_every_steps); }));
  k.push_back(int_range_key(
      "feedback_every_steps", "With feedback: time steps between two charge drives (0: at every remesh)", 0, 1000000, 0,
      [](Config& c, long long v) { c.wear.feedback_every_steps = static_cast<int>(v); },
      [](const Config& c) { return static_cast<long long>(c.wear.feedback_every_steps); }));
  k.push_back(real_key(
      "wear", "drive_revolutions", "-", "Revolutions each charge drive averages its loads over", kMinRevolutions,
      1000.0, false, false, 1.0, [](Config& c, double v) { c.wear.drive_revolutions = v; },
      [](const Config& c) { return c.wear.drive_revolutions; }));
  k.push_back(int_range_key(
      "snapshots", "Worn profiles stored between the initial and the final one", 0, 100, 5,
      [](Config& c, long long v) { c.wear.snapshots = static_cast<int>(v); },
      [](const Config& c) { return static_cast<long long>(c.wear.snapshots); }));
  // smoothing (thesis §5.8)
  k.push_back(string_key(
      "wear", "smoothing", "Smoother of the recession depth before each remesh (thesis §5.8)",
      {"csaps", "moving_average", "tukey", "tukey_csaps", "none"}, "csaps",
      [](Config& c, const std::string& v) { c.wear.smoothing.method = smoothing_method_from_name(v); },
      [](const Config& c) { return std::string(smoothing_method_name(c.wear.smoothing.method)); }));
  k.push_back(real_key(
      "wear", "smoothing_p", "-", "csaps smoothing parameter p, x in metres of arc length (thesis: 0.9999)", 0.0, 1.0,
      true, false, 0.9999, [](Config& c, double v) { c.wear.smoothing.csaps_p = v; },
      [](const Config& c) { return c.wear.smoothing.csaps_p; }));
  k.push_back(int_range_key(
      "smoothing_window", "Moving-average filter length in nodes (thesis: 10)", 1, 1000, 10,
      [](Config& c, long long v) { c.wear.smoothing.window = static_cast<int>(v); },
      [](const Config& c) { return static_cast<long long>(c.wear.smoothing.window); }));
  {
    KeySpec t = string_key(
        "wear", "smoothing_tukey", "Tukey compound smoother (e.g. \"3RSSH,twice\", \"3RRSHRRSRR\")", {}, "3RSSH,twice",
        [](Config& c, const std::string& v) { c.wear.smoothing.tukey = v; },
        [](const Config& c) { return c.wear.smoothing.tukey; });
    k.push_back(t);
  }
  // materials (docs/models/wear.md §2)
  auto material = [&](const char* name, const char* unit, const char* help, double lo, double hi, bool lo_open,
                      bool hi_open, double def, double scale, double LinerMaterial::*field) {
    k.push_back(real_key(
        "wear", name, unit, help, lo, hi, lo_open, hi_open, def,
        [field, scale](Config& c, double v) { c.material.*field = v * scale; },
        [field, scale](const Config& c) { return c.material.*field / scale; }));
  };
  material("liner_elastic_modulus_gpa", "GPa", "Elastic modulus of the liner", 0, 2000, true, false, 210, 1e9,
           &LinerMaterial::elastic_modulus_pa);
  material("liner_poisson_ratio", "-", "Poisson ratio of the liner", 0, 0.5, false, true, 0.29, 1.0,
           &LinerMaterial::poisson_ratio);
  material("liner_yield_stress_mpa", "MPa", "Yield stress (elastic load limit) of the liner", 0, 20000, true, false,
           1000, 1e6, &LinerMaterial::yield_stress_pa);
  material("liner_shear_strength_mpa", "MPa", "Shear strength of the liner (impact friction, eq. 5.20)", 0, 20000, true,
           false, 700, 1e6, &LinerMaterial::shear_strength_pa);
  auto ball = [&](const char* name, const char* unit, const char* help, double lo, double hi, bool lo_open,
                  bool hi_open, double def, double scale, double BallMaterial::*field) {
    k.push_back(real_key(
        "wear", name, unit, help, lo, hi, lo_open, hi_open, def,
        [field, scale](Config& c, double v) { c.material.ball.*field = v * scale; },
        [field, scale](const Config& c) { return c.material.ball.*field / scale; }));
  };
  ball("ball_elastic_modulus_gpa", "GPa", "Elastic modulus of the grinding media", 0, 2000, true, false, 210, 1e9,
       &BallMaterial::elastic_modulus_pa);
  ball("ball_poisson_ratio", "-", "Poisson ratio of the grinding media", 0, 0.5, false, true, 0.29, 1.0,
       &BallMaterial::poisson_ratio);
  ball("ball_hardness_bhn", "BHN", "Brinell hardness of the grinding media", 0, 1000, true, false, 600, 1.0,
       &BallMaterial::hardness_bhn);
}

void resolve_wear_config(Config& c) {
  c.material.density_kg_m3 = c.liner.density_kg_m3;
  c.material.hardness_bhn = c.liner.hardness_bhn;
  c.material.ball.density_kg_m3 = c.charge.ball_density_kg_m3;
  c.wear.laws = parse_law_list(c.wear_laws_text);
  // "none" is the whole list or absent: beside laws it was dropped, and an
  // empty list meant no wear without saying so.
  std::vector<std::string> tokens;  // as parse_law_list() splits them, "none" kept
  std::string cur;
  for (char ch : c.wear_laws_text + ",") {
    if (ch == ',' || ch == ' ' || ch == '\t' || ch == '+') {
      if (!cur.empty()) tokens.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (tokens.empty())
    throw InputError("wear.laws", fmt::format("laws = \"{}\": no wear law named; give the laws separated by commas, or "
                                              "\"none\" for no wear",
                                              c.wear_laws_text));
  if (tokens.size() > 1 && std::find(tokens.begin(), tokens.end(), "none") != tokens.end())
    throw InputError("wear.laws", fmt::format("laws = \"{}\": \"none\" (no wear) must stand alone; give \"none\" or "
                                              "the laws, not both",
                                              c.wear_laws_text));
  validate_wear_spec(c.wear);
  validate_liner_material(c.material);
}

}  // namespace linerlife
