// mill.h - the mill shell and its operating speed.
//
// Frame (DESIGN.md §3): origin on the mill axis, x right (3 o'clock), y up,
// angles anticlockwise from +x. A clockwise mill is reported in the same
// physical frame.
#pragma once

#include <cmath>

namespace linerlife {

enum class Rotation { Ccw, Cw };

constexpr double kGravity = 9.81;  // [m/s2], as in Morrell's constants (reference/charge-models.md §1)
constexpr double kPi = 3.14159265358979323846;

struct Mill {
  double diameter_m = 0;  // [m] inside the shell (fixed as the liner wears)
  double length_m = 0;    // [m] effective grinding length; 2D results x length = full mill
  double speed_rpm = 0;   // [rev/min] fixed by the drive; the fraction of critical follows the liner
  Rotation rotation = Rotation::Ccw;

  double shell_radius_m() const { return 0.5 * diameter_m; }
  double omega_rad_s() const { return speed_rpm * 2.0 * kPi / 60.0; }  // [rad/s], magnitude
  /// +1 for an anticlockwise mill, -1 for a clockwise one.
  double sense() const { return rotation == Rotation::Ccw ? 1.0 : -1.0; }
};

/// [-] The slowest mill speed accepted, as a fraction of critical: below it
/// the charge only creeps up the shell and slides back (a tumbling mill runs
/// at 0.6-0.85; the charge models' time steps are per revolution, so a run
/// at 1e-9 rpm never ends).
constexpr double kMinSpeedFractionCritical = 0.05;

/// Critical speed [rpm] of a mill with inside diameter d_m [m]:
/// N_c = (60 / 2 pi) sqrt(2 g / D) = 42.3 / sqrt(D) (Morrell 1996; reference/charge-models.md §1).
inline double critical_speed_rpm(double d_m) {
  return 60.0 / (2.0 * kPi) * std::sqrt(2.0 * kGravity / d_m);
}

}  // namespace linerlife
