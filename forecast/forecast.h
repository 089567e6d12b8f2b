// forecast.h - the wear life of a liner: integrates d(depth)/dt = rate(profile)
// over operating time with the charge re-driven on the worn geometry, to the
// first end-of-life criterion (DESIGN.md §2; docs/models/forecast.md).
//
// State: the recession depth [m] of every surface node of one representative
// cell of the ring (one segment, or a high and a low segment of a hi-lo
// pattern), measured from the profile of the last remesh. The ring is the cell
// rotated round the mill; rates are averaged over all copies of the cell.
#pragma once

#include <functional>
#include <string>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "charge/drive_notes.h"
#include "forecast/calendar.h"
#include "forecast/forecast_spec.h"
#include "forecast/rate_provider.h"
#include "geometry/liner_surface.h"
#include "geometry/mill.h"

namespace linerlife {

struct ForecastInput {
  const LinerSurface* initial = nullptr;  // the ring at the start (new or measured)
  Rotation rotation = Rotation::Ccw;      // decides the leading face
  double density_kg_m3 = 7800;            // [kg/m3] liner material
  double element_size_m = 0.01;           // [m] remesh element size
  double speed_rpm = 0;                   // [rpm] for the amplify method's revolutions
};

/// The liner and the charge at one moment of the life.
struct LifeRecord {
  double hours = 0;                    // [h] operating time
  double lifter_height_m = 0;          // design-0 lifter (the high one of a hi-lo), above the worn plate
  double crest_thickness_m = 0;        // its crest above the shell (never rises; the height can, when the plate wears faster)
  double face_angle_leading_deg = 0;
  double face_angle_trailing_deg = 0;
  double top_width_m = 0;
  double min_thickness_m = 0;          // thinnest point of the cell
  double liner_mass_kg_per_m = 0;      // whole ring
  double net_power_kw = 0;             // from the last charge drive (NaN without indicators)
  double toe_deg = 0, shoulder_deg = 0;
  double direct_impact_fraction = 0;   // share of impacting mass thrown straight onto the liner
  double impact_fraction = 0;          // share of the wear rate from impacts
  // The low lifter of a hi-lo ring (segment 1), as the high one above; NaN on
  // a uniform ring. (A review, 2026-12-08: a hi-lo forecast reported only the
  // high lifter, while the low one's crest lost more and the plate beside it
  // ended the life.)
  double low_lifter_height_m = std::numeric_limits<double>::quiet_NaN();
  double low_face_angle_leading_deg = std::numeric_limits<double>::quiet_NaN();
};

/// Profile of segment 0 (centred on angle 0), both edge nodes, mill frame.
struct ProfileRecord {
  double hours = 0;
  std::vector<Eigen::Vector2d> nodes;
};

struct ForecastStats {
  int charge_redrives = 0;
  int remeshes = 0;
  long long cvode_steps = 0, rhs_evals = 0, error_test_failures = 0, nonlinear_failures = 0;
  int explicit_steps = 0;
  double wall_s = 0;
  double charge_wall_s = 0;       // [s] spent in the rate provider
  double charge_simulated_s = 0;  // [s] charge time simulated in all drives
};

struct ForecastResult {
  bool reached = false;          // a criterion ended the life within the horizon
  std::string criterion;         // "min_lifter_height", "min_plate_thickness", "max_face_angle_leading", "worn_through", or "horizon"
  double operating_hours = 0;    // [h] to the end of life
  double calendar_days = 0;      // [d]
  CivilDate relining_date;       // the end of the run: the relining date, or the horizon's date when !reached
  double tonnes = 0;             // [t] processed
  std::vector<LifeRecord> history;
  std::vector<ProfileRecord> profiles;
  ForecastStats stats;
  LinerSurface final_surface;
  std::vector<DriveNote> notes;  // the charge model's notes over all drives (drive_notes.h)
};

/// progress(hours, fraction of the horizon or of the life so far)
using ProgressFn = std::function<void(double hours, double fraction)>;

/// Everything a forecast needs to continue exactly as it would have: taken
/// right after a charge drive or a remesh, where the integrator restarts from
/// (t, y) anyway, so a run resumed from it repeats the uninterrupted one.
struct ForecastCheckpoint {
  std::string method;                  // method_name() of the run
  double t_s = 0;                      // [s] operating time
  std::vector<double> y, y_drive, y_prev, r_now, r_prev;  // cell-node depths [m] and rates [m/s]
  bool have_prev = false;
  double next_regular_s = 0;           // [s] next regular output time
  long long next_extra = 0;            // index of the next extra output time
  double next_explicit_out_s = 0;      // [s] explicit methods' next output time
  LinerSurface base;                   // the ring at the last remesh
  // what the records need from the last drive
  bool has_indicators = false;
  double net_power_kw = 0, toe_deg = 0, shoulder_deg = 0, direct_impact_fraction = 0, impact_fraction = 0;
  long long provider_drives = 0;       // the provider's drive counter (seeds)
  std::vector<LifeRecord> history;
  std::vector<ProfileRecord> profiles;
  ForecastStats stats;
  std::vector<DriveNote> notes;
};

/// What makes a checkpoint unusable: `field` names the ForecastCheckpoint
/// member (the dataset or attribute of app/checkpoint_file.cpp: "y", "r_now",
/// "base_segment_begin", ...), `what` says what is wrong with it; both empty
/// when the checkpoint is usable.
struct CheckpointProblem {
  std::string field, what;
  bool ok() const { return field.empty(); }
};

/// Checks a checkpoint read back from a file before a run continues from it,
/// against itself and the run it is to continue (`in`, `spec`): the stored
/// ring (shell radius and segments as the initial liner's, segment_begin from
/// 0 increasing to the node count, the initial liner's segment_design, the
/// cell repeated round the ring), the cell-node vectors (y, y_drive, r_now;
/// y_prev and r_prev when have_prev, else empty or of the cell's size), finite
/// values and rates >= 0, the times (0 <= t_s <= the horizon) and the output
/// schedule (next_extra within spec.extra_output_hours), and one profile per
/// history record.
CheckpointProblem checkpoint_problem(const ForecastCheckpoint& c, const ForecastInput& in, const ForecastSpec& spec);

struct ForecastHooks {
  ProgressFn progress;
  /// Called with a checkpoint at most every checkpoint_interval_s of wall time
  /// (0: at every drive); the caller stores it atomically.
  std::function<void(const ForecastCheckpoint&)> checkpoint;
  double checkpoint_interval_s = 60;
  /// Continue from this checkpoint instead of the initial liner.
  const ForecastCheckpoint* resume = nullptr;
  /// When the run fails, the results so far (history, profiles, stats) go
  /// here before the SimulationError is rethrown, to be written marked partial.
  ForecastResult* partial = nullptr;
};

/// Runs the forecast with spec.method. Throws InputError when a criterion is
/// already met at the start, SimulationError when the integration fails (with
/// what failed, when, and what to change).
ForecastResult run_forecast(const ForecastInput& in, RateProvider& rates, const ForecastSpec& spec,
                            const ProgressFn& progress = {});
ForecastResult run_forecast(const ForecastInput& in, RateProvider& rates, const ForecastSpec& spec,
                            const ForecastHooks& hooks);

/// The number of consecutive segments that repeat round the ring (1 for a
/// uniform liner, 2 for hi-lo).
int pattern_period(const LinerSurface& s);

/// The smallest projection of an element of `ring` on the same element of
/// `base` (same node count; `ring` displaced from `base`), relative to that
/// element's squared length, over elements -1 .. n_cell - 1: 1 for equal
/// rings, 0 where an element has turned by 90 deg, negative where it has
/// turned over. The forecast remeshes where it reaches 0.
double min_element_projection(const LinerSurface& base, const LinerSurface& ring, int n_cell);

/// True if the cell's part of a displaced ring (elements -1 .. n_cell, the
/// cell's and one on each side) crosses itself properly (a point lying on
/// another element does not count). The forecast remeshes where it turns true.
bool cell_folds(const LinerSurface& s, int n_cell);

/// How many passes of smooth_along_surface() a drive's rate field gets: at
/// least `min_passes`, and enough for a smoothing length (the standard
/// deviation of the passes, h sqrt(p / 2) on elements of length h) of at
/// least `length_m` on elements of the remesh's size h = `element_size_m`:
/// round(2 (length_m / h)^2), at most kMaxSmoothingPasses.
constexpr int kMaxSmoothingPasses = 2000;
int smoothing_passes(double element_size_m, int min_passes, double length_m);

/// Smoothing of element values along the closed surface, `passes` times: a
/// flux-form 1-2-1 filter that keeps sum(length x value) exactly, keeps a
/// uniform field uniform for any element lengths, and creates no new extrema.
std::vector<double> smooth_along_surface(const LinerSurface& s, std::vector<double> v, int passes);

}  // namespace linerlife
