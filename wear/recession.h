// recession.h - from the loads the charge puts on the liner to the speed at
// which each surface element recedes into the liner body (DESIGN.md §2; thesis
// §5.4, eqs. 5.4, 5.11-5.28 and 5.31-5.32). The forecast calls
// recession_rates() on every right-hand side; the wear run once per remesh.
//
// Per element i of the surface the loads were computed on (LinerLoads are per
// metre of mill length):
//   abrasion volume rate   Va_i [m2/s] = sum of the abrasion laws (Radziszewski, Archard)
//   impact volume rate     Vi_i [m2/s] = sum over impacts on i of rate x volume per impact (sum of the impact laws)
// split and calibrated (thesis Table B.1 CalifCF, CalifGF, CalifImp):
//   centrifugal_i   = k_cf  Va_i s_i       / length_i   [m/s]
//   gravitational_i = k_gf  Va_i (1 - s_i) / length_i   [m/s]
//   impact_i        = k_imp Vi_i           / length_i   [m/s]
// with s_i = F_c / (F_c + F_g) the centrifugal share of the element's normal
// force (thesis eqs. 5.1-5.2); a model that does not split its normal force
// has all its abrasion counted as gravitational. Amplification (Table B.1)
// is NOT included: recession rates are physical; the coupled wear run
// multiplies by the amplification factors (amplified_rate()).
#pragma once

#include <cstddef>  // before charge/liner_loads.h, which uses size_t without including it
#include <string>
#include <vector>

#include "charge/charge_model.h"
#include "charge/liner_loads.h"
#include "geometry/liner_surface.h"
#include "wear/impact_laws.h"
#include "wear/liner_material.h"
#include "wear/slip_models.h"
#include "wear/wear_spec.h"

namespace linerlife {

/// A wear specification checked against the law table and resolved into
/// typed parameters. Build it with make_wear_model().
struct WearModel {
  WearSpec spec;
  std::string charge_model;  // the charge model it was checked against
  // the chosen laws
  bool radziszewski = false, archard = false;
  bool finnie = false, bitter = false, rabinowicz = false, sheldon_kanhere = false;
  // their parameters
  double radziszewski_tan_theta = 0;
  SlipModel slip = SlipModel::ChargeModel;
  double static_friction = 0, slippage_s_per_m = 0;
  double archard_k = 0;
  FinnieParams finnie_params;
  BitterParams bitter_params;
  RabinowiczParams rabinowicz_params;
  SheldonKanhereParams sheldon_kanhere_params;
  /// For the closed-form slip models (slip != ChargeModel): set by
  /// set_operating_point() after every charge drive.
  OperatingPoint operating;

  bool needs_abrasion() const { return radziszewski || archard; }
  bool needs_impacts() const { return finnie || bitter || rabinowicz || sheldon_kanhere; }
  bool needs_operating_point() const { return radziszewski && slip != SlipModel::ChargeModel; }
};

/// Checks `spec` on its own: law names (known, not repeated), every law
/// parameter in its declared range, calibration and amplification factors
/// > 0, smoothing and run settings. Throws InputError naming the [wear] key,
/// the value and the allowed range.
void validate_wear_spec(const WearSpec& spec);

/// validate_wear_spec() plus the combination with the charge model: an impact
/// law with a model that resolves no impacts, or an abrasion law with one
/// that resolves no sliding, is refused (InputError, key "wear.laws").
WearModel make_wear_model(const WearSpec& spec, const ChargeModelEntry& charge_model);

/// Updates the operating point the closed-form slip models read (after each
/// charge drive; the lifter face angle and the diameter follow the wear).
void set_operating_point(WearModel& model, const OperatingPoint& op);

struct RecessionRates {
  // Per element [m/s], calibrated, not amplified; >= 0.
  std::vector<double> total;
  std::vector<double> centrifugal;    // abrasion from the centrifugal part of the normal force
  std::vector<double> gravitational;  // abrasion from the gravitational part
  std::vector<double> impact;
  // Mass loss rates per metre of mill length [kg/(s m)], calibrated, not amplified.
  double mass_rate_kg_s_per_m = 0;
  double centrifugal_mass_rate_kg_s_per_m = 0;
  double gravitational_mass_rate_kg_s_per_m = 0;
  double impact_mass_rate_kg_s_per_m = 0;
  double slip_speed_m_s = 0;  // [m/s] the closed-form slip speed used (0 with slip from the charge model)
};

/// Recession rate of every element of `surface` under `loads`. `loads` must
/// have one entry per element of `surface` (the surface the loads were
/// computed on, or a displaced copy of it with the same elements:
/// displace_nodes()). Impacts on element i count against its current length.
/// Cost: O(elements + impacts), no allocation when `out` is reused.
/// Throws std::invalid_argument for mismatched sizes and std::logic_error when
/// an impact law meets loads without impacts or a closed-form slip model has
/// no operating point (both are refused at setup by make_wear_model()).
void recession_rates(const WearModel& model, const LinerLoads& loads, const LinerSurface& surface,
                     const LinerMaterial& material, RecessionRates& out);
RecessionRates recession_rates(const WearModel& model, const LinerLoads& loads, const LinerSurface& surface,
                               const LinerMaterial& material);

/// Amplified recession rate of element i [m/s]: A_abr (centrifugal + gravitational) + A_imp impact.
inline double amplified_rate(const WearModel& m, const RecessionRates& r, int i) {
  return m.spec.amplification_abrasion * (r.centrifugal[i] + r.gravitational[i]) +
         m.spec.amplification_impact * r.impact[i];
}

/// Volume [m3 per m of mill length] one impact removes under the model's impact laws (uncalibrated).
double impact_volume(const WearModel& model, const ImpactEvent& e, const LinerMaterial& material);

}  // namespace linerlife
