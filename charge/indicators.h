// indicators.h - the nine mill indicators of thesis §4.4 (Arekar 2004), with
// one definition for every charge model (docs/models/indicators.md).
//
// Angles are in degrees in the physical mill frame (DESIGN.md §3): anticlockwise
// from 3 o'clock; a clockwise mill is reported in the same frame, so its toe is
// near 310 deg and its shoulder near 135 deg. NaN where a model does not give
// the indicator.
#pragma once

#include <vector>

namespace linerlife {

struct Indicators {
  // 1. Power (thesis eq. 4.1): no-load + charge + slurry pool.
  double net_power_w_per_m = 0;   // [W/m] charge + slurry, per metre of the 2D slice
  double net_power_kw = 0;        // [kW] net, for the full mill length
  double no_load_power_kw = 0;    // [kW] Morrell eq. 4.2
  double gross_power_kw = 0;      // [kW] no-load + net (empirical: + k (P_t + P_c), Morrell)
  double alt_net_power_kw = 0;    // [kW] a second figure where a model has one (Hogg-Fuerstenau)
  // 2-3. Toe and shoulder [deg, physical frame].
  double toe_deg = 0;
  double shoulder_deg = 0;
  // 4. Centre of mass of the en-masse charge.
  double com_angle_deg = 0;       // [deg] physical frame
  double com_radius_m = 0;        // [m] from the mill axis
  // 5-6.
  int n_layers = 0;               // layers below the centre of circulation
  int n_trajectories = 0;         // layers in flight
  // 7. Forces on one lifter over a revolution (thesis Figs. 4-21/4-22).
  std::vector<double> lifter_force_angle_deg;      // [deg] angular position of the lifter (physical frame)
  std::vector<double> lifter_normal_force_n_per_m;   // [N/m]
  std::vector<double> lifter_tangential_force_n_per_m;  // [N/m]
  // 8. Charge area: the en-masse region [m2].
  double charge_area_m2 = 0;
  // 9. Layer speeds, outermost layer first [rpm].
  std::vector<double> layer_speed_rpm;
  // Context every model reports.
  double diameter_eff_m = 0;      // [m] diameter inside the (possibly worn) liners
  double fraction_critical = 0;   // [-] speed / critical speed for diameter_eff_m
  double direct_impact_fraction = 0;  // [-] share of the landing mass thrown straight onto the liner (indicators.md)
  // Added by the charge-motion issue:
  double slurry_pool_power_kw = 0;    // [kW] part of net_power_kw due to the slurry pool of an overflow mill
  double inner_radius_m = 0;          // [m] inner surface radius r_i of the circulating charge (Morrell eq. 4.14)
};

/// Statistics every run reports.
struct RunStats {
  double simulated_s = 0;   // [s] simulated time
  double wall_s = 0;        // [s] wall-clock time of the run
  double realtime_ratio = 0;  // simulated_s / wall_s
  long long steps = 0;      // time steps taken
  // Added by the charge-motion issue:
  double time_step_s = 0;   // [s] time step actually used (after sub-stepping)
  int substeps = 1;         // sub-steps per requested step (1: the requested step was stable)
  long long elements = 0;   // discrete elements / particles simulated
  long long flights = 0;    // flights launched during the run
  double charge_mass_kg_per_m = 0;  // [kg/m] mass of all elements (conserved), per metre of length
  double relaxation_interval_s = 0;  // [s] layer model: time between two surface relaxations (0: other models)
  double airborne_fraction = 0;      // [-] layer model: time-averaged share of the elements in flight over the
                                     //     averaged revolutions (Morrell's 1 - beta, eq. 4.14; 0: other models)
  double inner_radius_beta = 0;      // [-] layer model: the en-masse share beta its eq. 4.14 used (version 1.2)
  // Particle models (dem) only; 0 otherwise. For `linerlife charge --json`.
  double particle_steps_per_s = 0;  // [1/s] particles x steps per second of wall time while stepping
  double contacts_per_s = 0;        // [1/s] contact evaluations per second of wall time while stepping
};

}  // namespace linerlife
