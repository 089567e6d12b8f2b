// forecast_spec.h - the [forecast] settings (docs/configuration.md).
#pragma once

#include <string>
#include <vector>

#include "forecast/calendar.h"

namespace linerlife {

enum class ForecastMethod {
  Ode,      // CVODE on the wear-rate ODE with geometry feedback (the default)
  Amplify,  // the thesis / Qiu method: N revolutions, wear x A, no time integration
  Euler,    // fixed-step explicit with feedback
};

struct ForecastSpec {
  ForecastMethod method = ForecastMethod::Ode;
  std::string integrator = "adams";  // CVODE linear multistep family: "adams" | "bdf"
  double rtol = 1e-4;                // [-] CVODE relative tolerance
  double atol = 1e-6;                // [m] CVODE absolute tolerance on recession depth
  double refresh_tol_m = 0.002;      // [m] re-drive the charge once the profile moved this far since the last drive
  bool refresh_always = false;       // re-drive on every right-hand side (refresh = "always")
  std::string rate_model = "frozen";  // between drives: "frozen" (rates of the last drive) | "secant" (linear in the path);
                                      // frozen by default: docs/validation/forecast.md (the secant amplifies drive noise)
  int rate_smoothing_passes = 2;     // conservative 1-2-1 passes over element rates along the surface, at least
  double rate_smoothing_m = 0.01;    // [m] and at least this smoothing length on elements of the remesh's size
                                     //     (the passes' standard deviation): smoothing_passes(), docs/models/forecast.md
  double revolutions_per_drive = 10;  // [rev] averaged per charge drive (docs/validation/forecast.md: the mean life over realisations at 10 is within 0.2 % of 40)
  double remesh_depth_m = 0;         // [m] remesh once any node receded this far; 0: half the element size
  // end-of-life criteria: the first reached ends the life
  double min_lifter_height_m = 0.075;      // [m] above the plate
  double min_plate_thickness_m = 0.025;    // [m] thinnest point of the liner
  double max_face_angle_leading_deg = 60;  // [deg] from the radial
  double max_operating_hours = 50000;      // [h] horizon: a life longer than this is reported as not reached
  // time and money
  Calendar calendar;
  double throughput_t_per_h = 0;  // [t/h] while running
  // reference methods
  double amplification = 1e7;        // [-] amplify: wear multiplier A
  double amplify_revolutions = 1.5;  // [rev] amplify: revolutions simulated per step (Qiu 2001: about 1.5)
  double euler_step_h = 100;         // [h] euler: fixed step
  double output_interval_h = 100;    // [h] history and profile snapshots at least this often
  double checkpoint_interval_s = 60;  // [s] wall time between checkpoints of a run with --out (0: every drive)
  std::vector<double> extra_output_hours;  // [h] snapshots also exactly at these times (calibration; ode method)
};

const char* method_name(ForecastMethod m);
/// The fixed step [s] of an explicit method (euler: euler_step_h; amplify:
/// amplify_revolutions mill periods times the amplification); 0 for the ode
/// method, which has none.
double explicit_step_s(const ForecastSpec& spec, double speed_rpm);

}  // namespace linerlife
