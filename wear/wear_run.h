// wear_run.h - the per-step coupled wear run of thesis chapter 5 (§5.5-5.7,
// Fig. 5-11; Table B.1): the charge model is driven on the liner, its loads
// are turned into amplified recession rates, the wear of every time step is
// added to the discretised liner profile, the profile is remeshed, and with
// feedback the charge is driven again on the worn profile.
//
// The loop (docs/models/wear.md §6):
//   drive: ChargeModel::run on the current surface, averaging its loads over
//          WearSpec::drive_revolutions -> LinerLoads
//   rates: recession_rates() (LinerComputation "one": loads averaged over the
//          liners of a design onto one representative; copied back after the remesh)
//   every charge time step dt (ModelSpec::time_step_s), until revolutions x 60 / rpm:
//          node depth += dt x (A_abr abrasion + A_imp impact) rate
//   every remesh_every_steps steps (earlier if a node would recede more than
//   half an element): smooth the depth (WearSpec::smoothing), move the
//   profile (recede(): remesh() or its fast path), book the area the profile
//   lost; with feedback drive again on the worn surface, without it carry the
//   loads onto the new elements (transfer_loads); new rates.
// The rates between two remeshes are those of the last remeshed profile, so
// the depth of k steps is k dt x rate exactly, added at the remesh; the
// remesh interval sets how often the profile the rates see is updated
// (convergence study: docs/models/wear.md §6.2).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "charge/charge_model.h"
#include "charge/drive_notes.h"
#include "geometry/remesh.h"
#include "wear/liner_material.h"
#include "wear/recession.h"
#include "wear/wear_spec.h"

namespace linerlife {

struct WearRunInput {
  Mill mill;  // speed resolved; `rotation` is the direction the mill turns in this run
  ChargeSpec charge;
  ModelSpec model;       // time_step_s is the wear step
  LinerSurface surface;  // the liner at the start
  LinerMaterial material;
  WearSpec wear;
  RemeshOptions remesh;  // element_size_m of the liner
  unsigned long long seed = 1;
  std::function<void(double)> progress;  // called with the fraction done (0..1); may be empty
};

struct ProfileSnapshot {
  double time_s = 0;  // [s] simulated (not amplified)
  LinerSurface surface;
};

/// Cumulative wear asked for by the laws (amplified), per metre of mill length.
struct WearHistory {
  std::vector<double> time_s;          // [s] simulated
  std::vector<double> total_kg_per_m;  // [kg/m]
  std::vector<double> centrifugal_kg_per_m, gravitational_kg_per_m, impact_kg_per_m;
  int segments = 0;
  std::vector<double> per_segment_kg_per_m;  // [kg/m] rows = entries of time_s, columns = segments (row-major)
};

struct WearRunResult {
  LinerSurface initial, final;
  std::vector<ProfileSnapshot> snapshots;  // the initial profile, WearSpec::snapshots between, the final one
  WearHistory history;
  RecessionRates rates;  // the last rates (calibrated, not amplified), on `rates_surface`
  LinerSurface rates_surface;
  ChargeResult charge;  // the last charge drive
  // Mass per metre of mill length [kg/m]
  double liner_mass_initial_kg_per_m = 0;
  double liner_mass_final_kg_per_m = 0;
  double mass_loss_kg_per_m = 0;              // density x area the profile lost (= initial - final mass)
  double mass_loss_centrifugal_kg_per_m = 0;  // mass_loss split in proportion to the laws' contributions
  double mass_loss_gravitational_kg_per_m = 0;
  double mass_loss_impact_kg_per_m = 0;
  double commanded_mass_kg_per_m = 0;   // what the laws asked for (amplified)
  double mass_balance_rel_error = 0;    // mass_loss / commanded - 1 (remesh discretisation)
  double max_recession_m = 0;           // [m] deepest point of the final profile below the initial one
  double smoothing_max_rel_change = 0;  // largest |mass change| a smoother needed corrected (before rescaling)
  int steps = 0, charge_drives = 0;
  int remeshes = 0;                                                          // through geometry's remesh() (CGAL)
  int fast_remeshes = 0;                                                     // by recede()'s fast path
  double step_s = 0;                                                         // [s] the wear step
  double simulated_s = 0, wall_s = 0, charge_wall_s = 0, remesh_wall_s = 0;  // [s]
  double realtime_ratio = 0;                                                 // simulated_s / wall_s
  bool worn_through = false;
  std::string message;
  std::vector<DriveNote> notes;  // the charge model's notes over all drives (charge/drive_notes.h)
};

/// Runs the coupled wear loop with the charge model of `entry`. Throws
/// InputError for a specification refused at setup (make_wear_model,
/// validate_liner_material) and SimulationError when a step would remove more
/// than half an element (amplification too large for the step) or the
/// charge model fails. A liner worn through ends the run early with
/// worn_through set.
WearRunResult run_wear(const WearRunInput& in, const ChargeModelEntry& entry);

/// Largest distance [m] of a node of `worn` below the surface `initial`
/// (same segments): the deepest recession; over the segments `only` if given.
double max_recession(const LinerSurface& initial, const LinerSurface& worn, const std::vector<int>* only = nullptr);

/// Liner cross-section of the ring [m2] (sum of segment_area).
double ring_area(const LinerSurface& s);

}  // namespace linerlife
