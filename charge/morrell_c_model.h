// morrell_c_model.h - Morrell's C-model of charge shape and power (Morrell
// 1993, 1996; Morrell et al. 1994), and the Hogg & Fuerstenau torque-arm power
// (Hogg & Fuerstenau 1972, in the Moly-Cop form), as pure functions.
//
// Equations as checked in reference/charge-models.md §1-2. Angles in radians in
// Morrell's frame, which is the mill frame of an anticlockwise mill (DESIGN.md
// §3): anticlockwise from 3 o'clock, toe near 4 rad, shoulder near 0.8 rad.
// Lengths in m, densities in t/m3 (so that the powers come out in kW, as in
// Morrell's papers), speed in rev/s.
#pragma once

namespace linerlife {

struct MorrellInput {
  double diameter_m = 0;        // [m] D, inside the liners
  double length_m = 0;          // [m] L, belly length
  double cone_length_m = 0;     // [m] L_d, one cone end
  double trunnion_radius_m = 0; // [m] r_t (cones, overflow pool)
  double speed_rps = 0;         // [rev/s] N_m
  double filling = 0;           // [-] J, total charge
  double ball_filling = 0;      // [-] J_B
  double porosity = 0.4;        // [-] E
  double slurry_void_fill = 0;  // [-] U
  double slurry_solids_volume_fraction = 0;  // [-] S
  double ore_density_t_m3 = 0;   // [t/m3] rho_o
  double ball_density_t_m3 = 0;  // [t/m3] rho_b
  double pulp_density_t_m3 = 1;  // [t/m3] rho_p
  bool overflow = false;         // slurry pool up to the trunnion (theta_TO = pi + asin(r_t / r_m))
  double k_calibration = 1.26;   // [-] k, Morrell's lumped factor for industrial mills
};

struct MorrellResult {
  double fraction_critical = 0;  // [-] phi = N_m / N_c, N_c = 42.3 / sqrt(D) rpm
  double phi_c = 0;              // [-] 0.35 (3.364 - J): speed at which centrifuging is complete
  bool centrifuged = false;      // phi > phi_c: the charge is treated as fully centrifuged
  double toe_rad = 0;            // [rad] theta_T
  double shoulder_rad = 0;       // [rad] theta_S
  double slurry_toe_rad = 0;     // [rad] theta_TO
  double mean_radius_m = 0;      // [m] r_bar
  double time_in_charge_s = 0;   // [s] t_c
  double time_in_flight_s = 0;   // [s] t_f
  double beta = 0;               // [-] t_c / (t_c + t_f)
  double inner_radius_m = 0;     // [m] r_i, inner surface of the circulating charge
  double z = 0;                  // [-] (1 - J)^0.4532
  double charge_density_t_m3 = 0;  // [t/m3] rho_c
  double cylinder_power_kw = 0;  // [kW] P_t
  double cone_power_kw = 0;      // [kW] P_c
  double no_load_power_kw = 0;   // [kW] P_noload
  double gross_power_kw = 0;     // [kW] P_noload + k (P_t + P_c)
};

/// Morrell's toe angle theta_T [rad] (Morrell 1996; thesis eq. 4.15), without
/// the centrifuging guard.
double morrell_toe_rad(double filling, double fraction_critical);

/// Morrell's shoulder angle theta_S [rad] for a given toe (Morrell 1996; thesis eq. 4.6).
double morrell_shoulder_rad(double filling, double fraction_critical, double toe_rad);

/// Morrell's inner surface radius r_i [m] of the circulating charge for given
/// toe and shoulder (Morrell 1996; thesis eq. 4.14), with the intermediate
/// mean radius, times in the charge and in flight.
struct MorrellInnerRadius {
  double mean_radius_m, time_in_charge_s, time_in_flight_s, beta, inner_radius_m;
};
MorrellInnerRadius morrell_inner_radius(double mill_radius_m, double speed_rps, double filling, double toe_rad,
                                        double shoulder_rad);
/// Inner surface radius [m] of thesis eq. 4.14 for a given en-masse share beta
/// (the share of the charge between the toe and the shoulder).
double inner_radius_for_beta(double mill_radius_m, double filling, double toe_rad, double shoulder_rad, double beta);

/// Charge density rho_c (Morrell 1996), any consistent density unit.
double morrell_charge_density(double filling, double ball_filling, double porosity, double void_fill,
                              double solids_volume_fraction, double ore_density, double ball_density,
                              double water_density);

/// The whole C-model. Throws InputError for inputs outside its domain
/// (J <= 0, D <= 0, ...).
MorrellResult morrell_c_model(const MorrellInput& in);

/// No-load power [kW] (Morrell 1996; thesis eq. 4.2): 1.68 D^2.05 [phi (0.667 L_d + L)]^0.82.
double morrell_no_load_power_kw(double diameter_m, double fraction_critical, double length_m, double cone_length_m);

/// Hogg & Fuerstenau net power [kW] in the Moly-Cop form (reference/charge-models.md §2):
/// 0.238 D_ft^3.5 (L_ft / D_ft) N_c rho_app (J - 1.065 J^2) sin(alpha), with
/// N_c = rpm / (76.6 / sqrt(D_ft)). rho_app in t/m3.
double hogg_fuerstenau_power_kw(double diameter_m, double length_m, double speed_rpm, double apparent_density_t_m3,
                                double filling, double lift_angle_rad);

}  // namespace linerlife
