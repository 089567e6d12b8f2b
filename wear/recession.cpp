#include "wear/recession.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "geometry/errors.h"
#include "geometry/mill.h"
#include "wear/wear_laws.h"

namespace linerlife {
namespace {

void require_positive(const char* key, double v, double hi) {
  if (!(std::isfinite(v) && v > 0 && v <= hi))
    throw InputError(key, fmt::format("{} = {}: out of range; allowed 0 < value <= {}", key, v, hi));
}

const LawParameter& param(const WearLawEntry& e, const char* key) {
  for (const auto& p : e.parameters)
    if (p.key == key) return p;
  throw std::logic_error(fmt::format("wear law {} has no parameter {}", e.name, key));
}

}  // namespace

void validate_wear_spec(const WearSpec& spec) {
  require_positive("wear.calibration_centrifugal", spec.calibration_centrifugal, 1e5);
  require_positive("wear.calibration_gravitational", spec.calibration_gravitational, 1e5);
  require_positive("wear.calibration_impact", spec.calibration_impact, 1e5);
  require_positive("wear.amplification_abrasion", spec.amplification_abrasion, 1e9);
  require_positive("wear.amplification_impact", spec.amplification_impact, 1e9);
  require_positive("wear.revolutions", spec.revolutions, 1e4);
  require_positive("wear.drive_revolutions", spec.drive_revolutions, 1e3);
  if (spec.remesh_every_steps < 1)
    throw InputError("wear.remesh_every_steps",
                     fmt::format("remesh_every_steps = {}: allowed an integer >= 1", spec.remesh_every_steps));
  if (spec.feedback_every_steps < 0)
    throw InputError("wear.feedback_every_steps",
                     fmt::format("feedback_every_steps = {}: allowed an integer >= 0", spec.feedback_every_steps));
  if (spec.snapshots < 0)
    throw InputError("wear.snapshots", fmt::format("snapshots = {}: allowed an integer >= 0", spec.snapshots));
  if (spec.liner_computation != "one" && spec.liner_computation != "all")
    throw InputError(
        "wear.liner_computation",
        fmt::format("liner_computation = \"{}\": allowed one of \"one\", \"all\"", spec.liner_computation));
  if (!(spec.smoothing.csaps_p > 0 && spec.smoothing.csaps_p <= 1))
    throw InputError("wear.smoothing_p",
                     fmt::format("smoothing_p = {}: out of range; allowed 0 < value <= 1", spec.smoothing.csaps_p));
  if (spec.smoothing.window < 1)
    throw InputError("wear.smoothing_window",
                     fmt::format("smoothing_window = {}: allowed an integer >= 1", spec.smoothing.window));
  tukey_smooth({0.0, 1.0, 0.0}, spec.smoothing.tukey, false);  // throws for a malformed sequence
  std::set<std::string> seen;
  for (const std::string& name : spec.laws) {
    find_wear_law(name);
    if (!seen.insert(name).second)
      throw InputError("wear.laws", fmt::format("wear law \"{}\" is listed twice in laws", name));
  }
  // A parameter given for a law that is not chosen is not an error (switching
  // laws keeps a file valid), but its value must still be in range.
  for (const auto& e : wear_laws())
    for (const auto& p : e.parameters) {
      if (p.choices.empty())
        law_parameter(spec, p);
      else
        law_choice(spec, p);
    }
}

WearModel make_wear_model(const WearSpec& spec, const ChargeModelEntry& charge_model) {
  validate_wear_spec(spec);
  WearModel m;
  m.spec = spec;
  m.charge_model = charge_model.name;
  // the charge models that give what a law needs, for the message
  auto models_with = [](bool ChargeModelEntry::*what) {
    std::string list;
    for (const ChargeModelEntry& cm : charge_models())
      if (cm.*what) list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", cm.name);
    return list;
  };
  // what the charge model allows: its laws by name, or only none (a review,
  // 2026-12-08: "laws without an abrasion/ law" sent the empirical model's
  // user to an impact law, refused in turn)
  std::string allowed;
  for (const WearLawEntry& w : wear_laws())
    if (w.kind == WearKind::Impact ? charge_model.resolves_impacts : charge_model.resolves_abrasion)
      allowed += fmt::format("{}\"{}\"", allowed.empty() ? "" : ", ", w.name);
  allowed = allowed.empty() ? "only laws = \"none\" (no wear: it gives no loads on the liner)"
                            : "laws among " + allowed;
  for (const std::string& name : spec.laws) {
    const WearLawEntry& e = find_wear_law(name);
    if (e.kind == WearKind::Impact && !charge_model.resolves_impacts)
      throw InputError("wear.laws",
                       fmt::format("[wear] laws: wear law \"{}\" needs impact spectra, but [model] charge = \"{}\" "
                                   "gives none; allowed with it: {}; or a charge model that resolves impacts ({})",
                                   name, charge_model.name, allowed, models_with(&ChargeModelEntry::resolves_impacts)));
    if (e.kind == WearKind::Abrasion && !charge_model.resolves_abrasion)
      throw InputError("wear.laws",
                       fmt::format("[wear] laws: wear law \"{}\" needs the sliding loads on the liner, but [model] "
                                   "charge = \"{}\" gives none; allowed with it: {}; or a charge model that gives "
                                   "them ({})",
                                   name, charge_model.name, allowed,
                                   models_with(&ChargeModelEntry::resolves_abrasion)));
    if (name == "abrasion/radziszewski") {
      m.radziszewski = true;
      m.radziszewski_tan_theta = law_parameter(spec, param(e, "radziszewski_tan_theta"));
      const std::string slip = law_choice(spec, param(e, "radziszewski_slip"));
      m.slip = slip == "morrell"        ? SlipModel::Morrell
               : slip == "radziszewski" ? SlipModel::Radziszewski
                                        : SlipModel::ChargeModel;
      m.static_friction = law_parameter(spec, param(e, "radziszewski_static_friction"));
      m.slippage_s_per_m = law_parameter(spec, param(e, "radziszewski_slippage_s_per_m"));
    } else if (name == "abrasion/archard") {
      m.archard = true;
      m.archard_k = law_parameter(spec, param(e, "archard_k"));
    } else if (name == "impact/finnie") {
      m.finnie = true;
      m.finnie_params.cutting_fraction = law_parameter(spec, param(e, "finnie_cutting_fraction"));
      m.finnie_params.force_ratio = law_parameter(spec, param(e, "finnie_force_ratio"));
      m.finnie_params.depth_ratio = law_parameter(spec, param(e, "finnie_depth_ratio"));
      m.finnie_params.inertia_ratio = law_parameter(spec, param(e, "finnie_inertia_ratio"));
    } else if (name == "impact/bitter") {
      m.bitter = true;
      m.bitter_params.deformation_j_m3 = law_parameter(spec, param(e, "bitter_deformation_j_m3"));
      m.bitter_params.cutting_j_m3 = law_parameter(spec, param(e, "bitter_cutting_j_m3"));
    } else if (name == "impact/rabinowicz") {
      m.rabinowicz = true;
      m.rabinowicz_params.tan_theta = law_parameter(spec, param(e, "rabinowicz_tan_theta"));
    } else if (name == "impact/sheldon_kanhere") {
      m.sheldon_kanhere = true;
      m.sheldon_kanhere_params.k = law_parameter(spec, param(e, "sheldon_kanhere_k"));
      m.sheldon_kanhere_params.exponent = law_parameter(spec, param(e, "sheldon_kanhere_exponent"));
      m.sheldon_kanhere_params.normal_speed = law_choice(spec, param(e, "sheldon_kanhere_speed")) == "normal";
    }
  }
  return m;
}

void set_operating_point(WearModel& model, const OperatingPoint& op) { model.operating = op; }

double impact_volume(const WearModel& m, const ImpactEvent& e, const LinerMaterial& mat) {
  double v = 0;
  if (m.finnie) v += finnie_volume(e.mass_kg, e.normal_speed_m_s, e.tangential_speed_m_s, m.finnie_params, mat);
  if (m.bitter) v += bitter_volume(e.mass_kg, e.normal_speed_m_s, e.tangential_speed_m_s, m.bitter_params, mat).total();
  if (m.rabinowicz)
    v += rabinowicz_volume(e.mass_kg, e.normal_speed_m_s, e.tangential_speed_m_s, e.diameter_m, m.rabinowicz_params,
                           mat);
  if (m.sheldon_kanhere)
    v += sheldon_kanhere_volume(e.mass_kg, e.normal_speed_m_s, e.tangential_speed_m_s, m.sheldon_kanhere_params, mat);
  return v;
}

void recession_rates(const WearModel& m, const LinerLoads& loads, const LinerSurface& s, const LinerMaterial& mat,
                     RecessionRates& out) {
  const int n = s.n_elements();
  if (loads.n_elements != n)
    throw std::invalid_argument(
        fmt::format("recession_rates: loads for {} elements on a surface of {}", loads.n_elements, n));
  const size_t un = static_cast<size_t>(n);
  for (auto* v : {&out.total, &out.centrifugal, &out.gravitational, &out.impact}) v->assign(un, 0.0);
  out.slip_speed_m_s = 0;
  const double H = mat.hardness_pa();  // [Pa]

  // Abrasion volume rates [m2/s] (per metre of mill length); held in `centrifugal` for now.
  if (m.needs_abrasion()) {
    if (loads.normal_force_n_per_m.size() != un || loads.normal_slip_power_w_per_m.size() != un ||
        loads.shear_work_rate_w_per_m.size() != un)
      throw std::invalid_argument("recession_rates: per-element loads of the wrong size");
    double vslip = 0;
    if (m.radziszewski && m.slip != SlipModel::ChargeModel) {
      if (!m.operating.valid)
        throw std::logic_error("recession_rates: the slip model needs an operating point (set_operating_point)");
      vslip = m.slip == SlipModel::Morrell
                  ? morrell_slip_speed(m.operating)
                  : radziszewski_slip_speed(m.operating, m.static_friction, m.slippage_s_per_m);
      out.slip_speed_m_s = vslip;
    }
    const double kr = m.radziszewski ? m.radziszewski_tan_theta / (kPi * H) : 0.0;  // [1/Pa] eq. 5.4
    const double ka = m.archard ? m.archard_k / H : 0.0;                            // [1/Pa] Archard
    for (size_t i = 0; i < un; ++i) {
      if (loads.normal_force_n_per_m[i] == 0 && loads.normal_slip_power_w_per_m[i] == 0 &&
          loads.shear_work_rate_w_per_m[i] == 0)
        continue;  // unloaded
      double v = 0;
      if (m.radziszewski) {
        // thesis eq. 5.4: m_lin = rho tan(theta) / (pi H) N_t V_surf, here as a volume rate
        const double power = m.slip == SlipModel::ChargeModel ? loads.normal_slip_power_w_per_m[i]
                                                              : loads.normal_force_n_per_m[i] * vslip;
        v += kr * power;
      }
      if (m.archard) v += ka * loads.shear_work_rate_w_per_m[i];  // Qiu 2001: V = K S P / H per unit time
      out.centrifugal[i] = std::max(0.0, v);
    }
  }
  // Impact volume rates [m2/s].
  if (m.needs_impacts()) {
    if (!loads.has_impacts)
      throw std::logic_error("recession_rates: impact laws need loads with impacts (refused by make_wear_model)");
    for (const ImpactEvent& e : loads.impacts) {
      if (e.element < 0 || e.element >= n) throw std::invalid_argument("recession_rates: impact on no element");
      if (!(e.rate_per_s > 0) || !(e.mass_kg > 0) || !(e.normal_speed_m_s > 0)) continue;
      out.impact[static_cast<size_t>(e.element)] += e.rate_per_s * impact_volume(m, e, mat);
    }
  }
  // Split, calibrate, divide by the element length; sum the mass rates.
  const double rho = mat.density_kg_m3;
  const auto& spec = m.spec;
  double vc = 0, vg = 0, vi = 0;
  const bool split = loads.centrifugal_force_n_per_m.size() == un && loads.gravitational_force_n_per_m.size() == un;
  for (size_t i = 0; i < un; ++i) {
    const double va = out.centrifugal[i];
    if (va == 0 && out.impact[i] == 0) continue;  // an unloaded element (its rates are already 0)
    double share = 0;                             // centrifugal share of the normal force
    if (split) {
      const double fc = std::max(0.0, loads.centrifugal_force_n_per_m[i]);
      const double fg = std::max(0.0, loads.gravitational_force_n_per_m[i]);
      if (fc + fg > 0) share = fc / (fc + fg);
    }
    const double c = spec.calibration_centrifugal * va * share;
    const double g = spec.calibration_gravitational * va * (1.0 - share);
    const double im = spec.calibration_impact * out.impact[i];
    const double len = s.length[i];
    if (len > 0) {
      out.centrifugal[i] = c / len;
      out.gravitational[i] = g / len;
      out.impact[i] = im / len;
      vc += c;
      vg += g;
      vi += im;
    } else {  // a degenerate element cannot recede; its load is dropped from the mass rates too
      out.centrifugal[i] = out.gravitational[i] = out.impact[i] = 0;
    }
    out.total[i] = out.centrifugal[i] + out.gravitational[i] + out.impact[i];
  }
  out.centrifugal_mass_rate_kg_s_per_m = rho * vc;
  out.gravitational_mass_rate_kg_s_per_m = rho * vg;
  out.impact_mass_rate_kg_s_per_m = rho * vi;
  out.mass_rate_kg_s_per_m = rho * (vc + vg + vi);
}

RecessionRates recession_rates(const WearModel& m, const LinerLoads& loads, const LinerSurface& s,
                               const LinerMaterial& mat) {
  RecessionRates r;
  recession_rates(m, loads, s, mat, r);
  return r;
}

}  // namespace linerlife
