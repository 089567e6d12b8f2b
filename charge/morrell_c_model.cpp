#include "charge/morrell_c_model.h"

#include <cmath>

#include <fmt/format.h>

#include "geometry/errors.h"
#include "geometry/mill.h"

namespace linerlife {

double morrell_toe_rad(double J, double phi) {
  // Morrell (1996) eq. for theta_T; thesis eq. 4.15; reference/charge-models.md §1.
  const double phi_c = 0.35 * (3.364 - J);
  return 2.5307 * (1.2796 - J) * (1.0 - std::exp(-19.42 * (phi_c - phi))) + 0.5 * kPi;
}

double morrell_shoulder_rad(double J, double phi, double toe) {
  // Morrell (1996); thesis eq. 4.6.
  return 0.5 * kPi - (toe - 0.5 * kPi) * ((0.3386 + 0.1041 * phi) + (1.54 - 2.5673 * phi) * J);
}

MorrellInnerRadius morrell_inner_radius(double rm, double Nm, double J, double thT, double thS) {
  MorrellInnerRadius o{};
  const double span = 2.0 * kPi + thS - thT;  // [rad] angular extent of the en-masse charge
  // mean radius of the charge (Morrell 1996)
  const double q = 1.0 - 2.0 * kPi * J / span;
  o.mean_radius_m = 0.5 * rm * (1.0 + std::sqrt(std::max(0.0, q)));
  // time in the charge at the mean speed N_bar = N_m / 2, and in free fall
  o.time_in_charge_s = span / (2.0 * kPi * 0.5 * Nm);
  o.time_in_flight_s = std::sqrt(std::max(0.0, 2.0 * o.mean_radius_m * (std::sin(thS) - std::sin(thT)) / kGravity));
  o.beta = o.time_in_charge_s / (o.time_in_flight_s + o.time_in_charge_s);
  o.inner_radius_m = inner_radius_for_beta(rm, J, thT, thS, o.beta);
  return o;
}

double inner_radius_for_beta(double rm, double J, double thT, double thS, double beta) {
  // inner surface radius (Morrell 1996; thesis eq. 4.14): the share beta of
  // the charge J fills the annulus r_i..r_m over the angle from toe to shoulder
  const double span = 2.0 * kPi + thS - thT;
  return rm * std::sqrt(std::max(0.0, 1.0 - 2.0 * kPi * beta * J / span));
}

double morrell_charge_density(double J, double JB, double E, double U, double S, double rho_o, double rho_b,
                              double rho_w) {
  // Morrell (1996): rock with slurry in its voids, the extra mass of the balls,
  // and the water of the slurry.
  return (J * rho_o * (1.0 - E + E * U * S) + JB * (rho_b - rho_o) * (1.0 - E) + J * E * U * (1.0 - S) * rho_w) / J;
}

double morrell_no_load_power_kw(double D, double phi, double L, double Ld) {
  // Morrell (1996); thesis eq. 4.2 (the 0.667 of the cone term as in
  // reference/charge-models.md §1).
  return 1.68 * std::pow(D, 2.05) * std::pow(phi * (0.667 * Ld + L), 0.82);
}

double hogg_fuerstenau_power_kw(double D, double L, double rpm, double rho_app, double J, double alpha) {
  // Hogg & Fuerstenau (1972), Moly-Cop form (reference/charge-models.md §2).
  constexpr double kFtPerM = 1.0 / 0.3048;
  const double D_ft = D * kFtPerM, L_ft = L * kFtPerM;
  const double Nc = rpm / (76.6 / std::sqrt(D_ft));
  return 0.238 * std::pow(D_ft, 3.5) * (L_ft / D_ft) * Nc * rho_app * (J - 1.065 * J * J) * std::sin(alpha);
}

MorrellResult morrell_c_model(const MorrellInput& in) {
  if (!(in.diameter_m > 0)) throw InputError("mill.diameter_m", fmt::format("Morrell's C-model needs D > 0, got {}", in.diameter_m));
  if (!(in.filling > 0 && in.filling < 1))
    throw InputError("charge.filling", fmt::format("Morrell's C-model needs 0 < J < 1, got J = {}", in.filling));
  if (!(in.speed_rps > 0)) throw InputError("mill.speed_rpm", fmt::format("Morrell's C-model needs a speed > 0, got {} rev/s", in.speed_rps));
  MorrellResult r;
  const double D = in.diameter_m, rm = 0.5 * D, J = in.filling, Nm = in.speed_rps;
  const double rpm = 60.0 * Nm;
  r.fraction_critical = rpm / (42.3 / std::sqrt(D));  // N_c = 42.3 / sqrt(D) rpm (Morrell 1996)
  const double phi = r.fraction_critical;
  r.phi_c = 0.35 * (3.364 - J);
  if (phi > r.phi_c) {
    // Guard (reference/charge-models.md §1): beyond phi_c the toe formula
    // passes pi/2; treat the charge as fully centrifuged.
    r.centrifuged = true;
    r.toe_rad = r.shoulder_rad = 0.5 * kPi;
  } else {
    r.toe_rad = morrell_toe_rad(J, phi);
    r.shoulder_rad = morrell_shoulder_rad(J, phi, r.toe_rad);
  }
  const double thT = r.toe_rad, thS = r.shoulder_rad;
  // theta_TO, the toe of the slurry pool (Morrell 1996; reference/charge-models.md
  // §1): where the slurry surface at the trunnion, y = -r_t, meets the shell.
  // The pool lies between it and the charge toe; a slurry surface below the
  // toe (theta_TO past theta_T: a high filling or a wide trunnion) leaves no
  // pool, and its term rho_p (sin theta_T - sin theta_TO) would turn positive,
  // power from a pool that is not there: theta_TO = theta_T then, as a grate's.
  r.slurry_toe_rad = in.overflow ? std::min(kPi + std::asin(std::min(1.0, in.trunnion_radius_m / rm)), thT) : thT;
  r.z = std::pow(1.0 - J, 0.4532);
  r.charge_density_t_m3 = morrell_charge_density(J, in.ball_filling, in.porosity, in.slurry_void_fill,
                                                 in.slurry_solids_volume_fraction, in.ore_density_t_m3,
                                                 in.ball_density_t_m3, 1.0);
  if (r.centrifuged) {
    // A centrifuged charge is a ring on the shell: no lift, no power beyond no-load.
    r.inner_radius_m = rm * std::sqrt(1.0 - J);
    r.mean_radius_m = 0.5 * (rm + r.inner_radius_m);
    r.beta = 1.0;
  } else {
    const MorrellInnerRadius ir = morrell_inner_radius(rm, Nm, J, thT, thS);
    r.mean_radius_m = ir.mean_radius_m;
    r.time_in_charge_s = ir.time_in_charge_s;
    r.time_in_flight_s = ir.time_in_flight_s;
    r.beta = ir.beta;
    r.inner_radius_m = ir.inner_radius_m;
    const double ri = r.inner_radius_m, z = r.z, rho_c = r.charge_density_t_m3, L = in.length_m;
    const double A = rho_c * (std::sin(thS) - std::sin(thT)) + in.pulp_density_t_m3 * (std::sin(thT) - std::sin(r.slurry_toe_rad));
    // Cylinder power P_t [kW] (Morrell 1996; reference/charge-models.md §1).
    const double a = rm - z * ri;
    r.cylinder_power_kw =
        kPi * kGravity * L * Nm * rm / (3.0 * a) * (2.0 * rm * rm * rm - 3.0 * z * ri * rm * rm + ri * ri * ri * (3.0 * z - 2.0)) * A +
        L * rho_c * std::pow(kPi * Nm * rm / a, 3) * (std::pow(a, 4) - std::pow(ri, 4) * std::pow(z - 1.0, 4));
    // Cone power P_c [kW] (Morrell 1996).
    if (in.cone_length_m > 0) {
      const double Ld = in.cone_length_m, rt = in.trunnion_radius_m;
      if (!(rt > 0 && rt < rm))
        throw InputError("mill.trunnion_diameter_m",
                         fmt::format("conical ends (cone_length_m = {}) need a trunnion radius 0 < r_t < D/2 = {}, got {}", Ld, rm, rt));
      r.cone_power_kw = kPi * Ld * Nm * kGravity / (3.0 * (rm - rt)) *
                            (std::pow(rm, 4) - 4.0 * rm * std::pow(ri, 3) + 3.0 * std::pow(ri, 4)) * A +
                        2.0 * std::pow(kPi, 3) * Ld * std::pow(Nm, 3) * rho_c / (5.0 * (rm - rt)) *
                            (std::pow(rm, 5) - 5.0 * rm * std::pow(ri, 4) + 4.0 * std::pow(ri, 5));
    }
  }
  r.no_load_power_kw = morrell_no_load_power_kw(D, phi, in.length_m, in.cone_length_m);
  r.gross_power_kw = r.no_load_power_kw + in.k_calibration * (r.cylinder_power_kw + r.cone_power_kw);
  return r;
}

}  // namespace linerlife
