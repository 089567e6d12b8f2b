// The table of wear laws (docs/models/wear.md §4 gives the equations and the
// reasoning behind every default). A new law is one more row here and one
// more case in recession.cpp.
#include "wear/wear_laws.h"

#include <fmt/format.h>

#include <cmath>

#include "geometry/errors.h"

namespace linerlife {
namespace {

LawParameter real(const char* key, const char* unit, const char* help, double lo, double hi, double def,
                  bool lo_open = true, bool hi_open = false) {
  LawParameter p;
  p.key = key;
  p.unit = unit;
  p.help = help;
  p.lo = lo;
  p.hi = hi;
  p.lo_open = lo_open;
  p.hi_open = hi_open;
  p.default_value = def;
  return p;
}

LawParameter choice(const char* key, const char* help, std::vector<std::string> choices, const char* def) {
  LawParameter p;
  p.key = key;
  p.unit = "-";
  p.help = help;
  p.choices = std::move(choices);
  p.default_choice = def;
  return p;
}

}  // namespace

const std::vector<WearLawEntry>& wear_laws() {
  static const std::vector<WearLawEntry> table = {
      {"abrasion/radziszewski",
       WearKind::Abrasion,
       "thesis eq. 5.4 (Radziszewski & Tarasiewicz 1993, after Rabinowicz's abrasive wear equation)",
       "volume rate tan(theta) / (pi H) x normal force x slip speed",
       {real("radziszewski_tan_theta", "-",
             "Abrasion factor tan(theta) of eq. 5.4 (Rabinowicz: mean slope of the abrading asperities)", 0, 1, 0.02),
        choice("radziszewski_slip",
               "Slip speed: the charge model's <N v_slip>, or thesis eqs. 5.8-5.10 (Morrell) or 5.5-5.7 (Radziszewski)",
               {"charge_model", "morrell", "radziszewski"}, "charge_model"),
        real("radziszewski_static_friction", "-", "Static friction mu_s of eq. 5.5 (slip = \"radziszewski\")", 0, 2,
             0.3),
        real("radziszewski_slippage_s_per_m", "s/m",
             "Slippage parameter delta of eqs. 5.5-5.7 (slip = \"radziszewski\")", 0, 1000, 5.0)}},
      {"abrasion/archard",
       WearKind::Abrasion,
       "Archard (1953), as used by Qiu et al. (2001): V = K S P / H",
       "volume rate K x shear force x sliding speed / H (the shear work rate of LinerLoads)",
       {real("archard_k", "-", "Dimensionless Archard wear coefficient K", 0, 1, 0.02)}},
      {"impact/finnie",
       WearKind::Impact,
       "thesis eq. 5.11 (Finnie 1960, with particle rotation as revised 1967/72)",
       "ductile cutting: peaks at a low angle, vanishes at normal incidence",
       {real("finnie_cutting_fraction", "-", "Share c of impacts that cut in the idealised way (Finnie: about 0.5)", 0,
             1, 0.5),
        real("finnie_force_ratio", "-", "K, vertical over horizontal force on the cutting tip (Finnie: 2)", 0, 20, 2.0),
        real("finnie_depth_ratio", "-", "psi, contact length over cut depth (Finnie: 2)", 0, 20, 2.0),
        real("finnie_inertia_ratio", "-", "m r^2 / I of the impacting body (solid sphere 2.5)", 0, 20, 2.5, false)}},
      {"impact/bitter",
       WearKind::Impact,
       "thesis eqs. 5.12-5.18 (Bitter 1963, parts I and II)",
       "deformation plus cutting wear above the elastic limit velocity",
       {real("bitter_deformation_j_m3", "J/m3", "Deformation wear factor epsilon (energy per unit volume removed)", 0,
             1e15, 7.0e10),
        real("bitter_cutting_j_m3", "J/m3", "Cutting wear factor Q (the thesis' F_c, energy per unit volume removed)",
             0, 1e15, 5.0e10)}},
      {"impact/rabinowicz",
       WearKind::Impact,
       "thesis eqs. 5.19-5.27 (Rabinowicz; friction Yabuki 1999; contact time Hertz; restitution Tabor/Thornton 1997)",
       "energy dissipated in the impact turned into abrasive wear",
       {real("rabinowicz_tan_theta", "-", "tan(theta) of the impacting surface's asperities (Rabinowicz)", 0, 1, 0.1)}},
      {"impact/sheldon_kanhere",
       WearKind::Impact,
       "thesis eq. 5.28 (Sheldon & Kanhere 1972), exponent as thesis §5.4.2",
       "indentation energy balance, V = k D^3 (rho U^2 / H_v)^(n/2)",
       {real("sheldon_kanhere_k", "-", "Dimensionless constant k", 0, 1e3, 0.07),
        real("sheldon_kanhere_exponent", "-", "Velocity exponent n (original 3; thesis 2.35)", 1, 4, 2.35, false),
        choice("sheldon_kanhere_speed",
               "Impact speed U: the normal component (indentation physics) or the total speed (as in the thesis)",
               {"normal", "total"}, "normal")}},
  };
  return table;
}

const WearLawEntry& find_wear_law(const std::string& name) {
  std::string names;
  for (const auto& e : wear_laws()) {
    if (e.name == name) return e;
    names += (names.empty() ? "" : ", ") + e.name;
  }
  throw InputError("wear.laws", fmt::format("unknown wear law \"{}\"; the laws are: {}", name, names));
}

double law_parameter(const WearSpec& spec, const LawParameter& p) {
  auto it = spec.parameters.find(p.key);
  const double v = it == spec.parameters.end() ? p.default_value : it->second;
  const bool ok = std::isfinite(v) && (p.lo_open ? v > p.lo : v >= p.lo) && (p.hi_open ? v < p.hi : v <= p.hi);
  if (!ok)
    throw InputError("wear." + p.key, fmt::format("{} = {}: out of range; allowed {} {} value {} {}{}", p.key, v, p.lo,
                                                  p.lo_open ? "<" : "<=", p.hi_open ? "<" : "<=", p.hi,
                                                  p.unit == "-" ? "" : " " + p.unit));
  return v;
}

std::string law_choice(const WearSpec& spec, const LawParameter& p) {
  auto it = spec.choices.find(p.key);
  const std::string v = it == spec.choices.end() ? p.default_choice : it->second;
  std::string list;
  for (const auto& c : p.choices) {
    if (c == v) return v;
    list += (list.empty() ? "\"" : ", \"") + c + "\"";
  }
  throw InputError("wear." + p.key, fmt::format("{} = \"{}\": allowed one of {}", p.key, v, list));
}

std::vector<std::string> parse_law_list(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty() && cur != "none") out.push_back(cur);
    cur.clear();
  };
  for (char c : text) {
    if (c == ',' || c == ' ' || c == '\t' || c == '+')
      flush();
    else
      cur += c;
  }
  flush();
  return out;
}

std::string law_list_text(const std::vector<std::string>& laws) {
  if (laws.empty()) return "none";
  std::string s;
  for (const auto& l : laws) s += (s.empty() ? "" : ", ") + l;
  return s;
}

}  // namespace linerlife
