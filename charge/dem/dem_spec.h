// dem_spec.h - what the user sets for the 2D soft-disc DEM charge model
// (the [dem] section of the configuration, docs/models/dem.md).
//
// Every field has a working default; zero in an "optional" field means "not
// given, derive it" as its comment says. SI units.
#pragma once

#include <string>

namespace linerlife {

struct DemSpec {
  // --- contact (docs/models/dem.md §2) ---
  std::string contact_law = "linear";  // "linear" spring-dashpot | "hertz" (Tsuji et al. 1992 damping)
  double restitution = 0.725;          // [-] particle-particle e (mill DEM inputs: ball-ball 0.725)
  double wall_restitution = 0.8;       // [-] particle-liner e (ball-wall 0.80)
  double friction = 0.3;               // [-] particle-particle Coulomb mu (0.25-0.30 in mill DEM inputs)
  double wall_friction = 0.3;          // [-] particle-liner Coulomb mu
  double rolling_resistance = 0.02;    // [-] mu_r of the constant directional torque, both contact kinds
  double collision_time_s = 0;         // [s] optional: contact duration of every pair (linear) or at the
                                       //     liner speed (hertz); 0: from overlap_fraction
  double stiffness = 0;                // optional instead of collision_time_s: linear k_n [N/m per m of
                                       //     length], hertz k_h [N/m^1.5 per m]; 0: not given
  double overlap_fraction = 0.05;      // [-] default rule for the collision time: the smallest particle
                                       //     meeting the liner at the liner speed overlaps this share of its diameter
  double steps_per_collision = 8;      // [-] time step = shortest collision time / this
  double time_step_s = 0;              // [s] optional: the time step itself (refused above the stable limit)
  // --- charge (docs/models/dem.md §3) ---
  double coarse_grain = 1;             // [-] s >= 1: every disc s times the media/rock diameter (Bierwisch et al. 2009)
  double ball_size_spread = 0.1;       // [-] ball diameters uniform in [d (1 - spread), d] (stops 2D crystallisation)
  double rock_diameter_max_m = 0;      // [m] largest rock; 0: the ball diameter
  double rock_diameter_min_m = 0;      // [m] smallest rock simulated; 0: a quarter of the ball diameter
  double rock_size_exponent = 0.5;     // [-] Gates-Gaudin-Schuhmann modulus m: mass passing (d / d_max)^m
  double packing_fraction_2d = 0.82;   // [-] solid area fraction of the disc bed (random close packing, Berryman 1983)
  // --- run ---
  double revolutions = 3;              // [-] mill revolutions averaged (when ChargeInput::revolutions is 0)
  double settle_revolutions = 1.5;     // [-] revolutions run before averaging starts
  double impact_min_speed_m_s = 0.1;   // [m/s] contact onsets slower than this (normal) are not impacts
  long long seed = 1;                  // random placement and sizes; runs repeat exactly for a seed
  int threads = 0;                     // OpenMP threads; 0: all cores, adapting to the load (the results do not depend on it)
};

}  // namespace linerlife
