// dem_model.h - the `dem` charge model (DESIGN.md §2; docs/models/dem.md):
// a 2D soft-disc DEM slice of the mill whose walls are the liner surface as it
// is, turning with the mill. The accuracy reference of the charge models.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "charge/charge_model.h"
#include "charge/dem/contact_law.h"
#include "charge/dem/dem_system.h"
#include "charge/dem/particle_set.h"

namespace linerlife {

/// Contact durations resolved by fewer time steps are refused (InputError).
/// From the time-step study in docs/models/dem.md §2: the Qiu slice and pilot
/// test 1 blow up at 2 steps a contact and degrade at 2.5; 5 keeps a factor 2.
constexpr double kDemMinStepsPerCollision = 5;

/// The most discs a DEM run takes: 40 times the largest charge of the DEM's
/// studies (5,000 discs, docs/benchmarks.md). 1 mm media in the Qiu mill
/// would be millions of discs; such a run filled the machine's 23 GB of memory
/// before it was refused.
constexpr double kDemMaxDiscs = 2e5;

/// [s] The shortest collision_time_s accepted. The default contacts last about
/// 1 ms (0.97 ms in the Qiu slice, 2.4 ms in pilot test 1; docs/models/dem.md
/// §2) and a real steel ball on steel about 0.1-0.3 ms; at 10 us a run already
/// takes some 100 times the default's steps, and 1e-12 s never ends.
constexpr double kDemMinCollisionTimeS = 1e-5;

/// [s] The shortest time_step_s accepted: a hundredth of the shortest
/// collision time accepted (kDemMinCollisionTimeS). The default steps are about
/// 0.1 ms; 1e-9 s never ended (a revolution of the Qiu slice in 4e9 steps).
constexpr double kDemMinTimeStepS = 1e-7;

/// [N/m per m] The softest `stiffness` accepted (linear k_n, or hertz k_h in
/// N/m^1.5 per m). The default contacts of the Qiu slice are 1e7-4e8 N/m per m
/// stiff; pilot test 1 runs at 1e5 and its discs pass through the liner at
/// 1e3 (exit 3), as the Qiu slice's do up to 1e6. Below 1e4 no mill's bed can
/// hold its discs apart, and 1e-300 made contacts last 1e150 s.
constexpr double kDemMinStiffness = 1e4;

/// What a DEM run derived and measured (the command's --json reads
/// RunStats; benchmarks and docs read this).
struct DemRunInfo {
  int particles = 0, balls = 0, rocks = 0;
  double coarse_grain = 1;            // [-]
  double collision_time_s = 0;        // [s] shortest contact duration the step is set from
  double time_step_s = 0;             // [s]
  double steps_per_collision = 0;     // [-] collision_time_s / time_step_s
  double particle_stiffness = 0;      // [N/m per m] k_n of two of the smallest discs (linear) or k_h (hertz)
  double settle_s = 0, average_s = 0;  // [s] simulated
  long long steps = 0;
  int threads = 1;
  double wall_s = 0;                  // [s] whole run, setup included
  double integrate_wall_s = 0;        // [s] time stepping only
  double particle_steps_per_s = 0;    // [1/s] particles x steps / integrate_wall_s
  double contacts_per_s = 0;          // [1/s] contact evaluations (particle + wall) per second of integration
  double mean_contacts = 0;           // [-] coordination number (particle contacts count for both discs, wall contacts once)
  long long list_builds = 0;
  double max_overlap_ratio = 0;       // [-] largest disc-disc overlap over the smaller radius
  double max_wall_overlap_ratio = 0;  // [-] largest disc-liner overlap over the radius (1: through the liner)
  long long wall_hits_dropped = 0;    // disc-liner contacts beyond DemSystem::kMaxWallHits of one disc, dropped
  long long wall_springs_dropped = 0;  // contacts beyond DemSystem::kWallSlots of one disc: tangential spring restarted
  long long impacts = 0;
  double drive_power_w_per_m = 0;     // [W/m] P = T omega from the contact forces on the liner
  double torque_arm_power_w_per_m = 0;  // [W/m] omega g <sum m x> over the samples (thesis eq. 4.3), a check
  double charge_mass_kg_per_m = 0;    // [kg/m] all discs
  std::vector<std::pair<double, double>> band_occupancy;  // (angle [deg], occupancy) of the liner band: toe and shoulder
};

/// Everything derived before the first step (exposed for tests and benchmarks).
struct DemSetup {
  ParticleSet particles;
  DemParticles initial;    // placed
  DemSettings settings;    // contact parameters, time step, rotation, threads, limits
  WallMesh walls;
  double collision_time_s = 0;   // [s] shortest contact duration
  double revolution_s = 0;       // [s] one mill revolution
  double r_eff = 0, r_crest = 0, free_area = 0;
  double mean_diameter = 0;      // [m] number-mean disc diameter
  double v_ref = 0;              // [m/s] liner speed omega r_eff
};

/// Checks the [dem] parameters against the mill and derives the setup.
/// Throws InputError ("dem.<key>", value, what is allowed) for inputs the
/// model cannot take: a time step beyond the stable range, coarse-graining the
/// scene does not allow, no liner surface, ...
DemSetup make_dem_setup(const ChargeInput& in);

/// Runs the model; info (optional) receives the run's figures.
ChargeResult run_dem(const ChargeInput& in, DemRunInfo* info = nullptr);

/// Runs the model on a setup from make_dem_setup() that the caller may have
/// changed (studies beyond the accepted range: bench/dem_bench.cpp). Nothing
/// the caller changed is checked again.
ChargeResult run_dem(const ChargeInput& in, DemSetup setup, DemRunInfo* info);

/// The table entry's factory (charge_models.cpp).
std::unique_ptr<ChargeModel> make_dem_model();

}  // namespace linerlife
