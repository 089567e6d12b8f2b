// charge_model.h - the one interface of the charge-motion models (DESIGN.md
// §2): a run takes the mill, the charge and the (possibly worn) liner surface
// and returns the indicators, the liner loads and run statistics. Models are
// chosen by name from a plain table (charge_models.cpp), LAMMPS-style: no
// macros, no self-registering statics.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "charge/charge_spec.h"
#include "charge/indicators.h"
#include "charge/liner_loads.h"
#include "geometry/liner_surface.h"
#include "geometry/mill.h"

namespace linerlife {

/// Everything a run needs, explicit (Chrono's contact interface style).
struct ChargeInput {
  Mill mill;                 // speed_rpm resolved; rotation
  ChargeSpec charge;
  ModelSpec model;
  const LinerSurface* surface = nullptr;  // the liner as it is now
  double revolutions = 0;    // mill revolutions to average over (after settling); 0: the model's default
  unsigned long long seed = 1;  // for models with random elements
  bool record_snapshot = false;  // keep element/particle positions of the last revolution for charts
  // The share of the run done (0 < f <= 1, rising, 1 last), reported by the slow models as they go
  // (the DEM: after each of its sampling chunks, settling included); may be empty. The layer and
  // empirical models, done in milliseconds, do not call it.
  std::function<void(double)> progress;
};

/// Positions of the charge at one instant, for charts and HDF5.
struct ChargeSnapshot {
  double time_s = 0;
  std::vector<Eigen::Vector2d> position;  // [m] mill frame
  std::vector<double> radius_m;           // [m] drawn size of each element
  std::vector<int> state;                 // model-specific: 0 en masse, 1 in flight, ...
  double liner_angle_rad = 0;             // [rad] how far the liner has turned since t = 0, physical frame
                                          //       (anticlockwise positive; negative for a clockwise mill)
};

struct ChargeResult {
  std::string model;        // name from the table
  Indicators indicators;
  LinerLoads loads;
  RunStats stats;
  std::vector<ChargeSnapshot> snapshots;  // when record_snapshot
  std::vector<std::string> notes;         // things the user should know (sub-stepping, centrifuging...)
};

class ChargeModel {
 public:
  virtual ~ChargeModel() = default;
  /// Runs the model. Throws InputError for inputs the model cannot take and
  /// SimulationError when the run cannot give a trustworthy result.
  virtual ChargeResult run(const ChargeInput& in) const = 0;
};

/// One row of the model table.
struct ChargeModelEntry {
  const char* name;          // "empirical", "layer", "dem"
  const char* description;
  bool resolves_impacts;     // fills LinerLoads::impacts
  bool resolves_abrasion;    // fills the per-element forces and slip
  std::unique_ptr<ChargeModel> (*make)();
  bool runs_in_time = true;  // moves the charge over ChargeInput::revolutions (false: closed-form, no run length)
};

/// The table of charge models.
const std::vector<ChargeModelEntry>& charge_models();

/// The entry named `name`; throws InputError (key "model.charge") listing the names otherwise.
const ChargeModelEntry& find_charge_model(const std::string& name);

}  // namespace linerlife
