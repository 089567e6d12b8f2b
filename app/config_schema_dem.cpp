// The [dem] keys: parameters of the 2D soft-disc DEM charge model
// (docs/models/dem.md; issue 6 §1). Every key has a working default, so a file
// without [dem] runs the DEM with the documented defaults.
#include <fmt/format.h>

#include "app/config.h"
#include "app/config_schema_util.h"
#include "charge/dem/dem_model.h"
#include "geometry/errors.h"

namespace linerlife {

namespace {

/// A [dem] number stored in DemSpec with a default.
KeySpec dem_real(const char* name, const char* unit, const char* help, double lo, double hi, bool lo_open,
                 bool hi_open, double def, double DemSpec::*field) {
  return real_key(
      "dem", name, unit, help, lo, hi, lo_open, hi_open, def, [field](Config& c, double v) { c.model.dem.*field = v; },
      [field](const Config& c) { return c.model.dem.*field; });
}

/// A [dem] number that may be absent (stored as 0 = derive it).
KeySpec dem_opt_real(const char* name, const char* unit, const char* help, double lo, double hi, bool hi_open,
                     double DemSpec::*field, const char* note, bool lo_open = true) {
  return opt_real_key(
      "dem", name, unit, help, lo, hi, lo_open, hi_open, [field](Config& c, double v) { c.model.dem.*field = v; },
      [field](const Config& c) -> std::optional<double> {
        const double v = c.model.dem.*field;
        if (v > 0) return v;
        return std::nullopt;
      },
      note);
}

}  // namespace

void add_dem_keys(Schema& s) {
  s.sections.push_back("dem");
  auto& k = s.keys;
  k.push_back(string_key("dem", "contact_law",
                         "Normal contact: linear spring-dashpot, or Hertzian with Tsuji damping (docs/models/dem.md)",
                         {"linear", "hertz"}, "linear", [](Config& c, const std::string& v) { c.model.dem.contact_law = v; },
                         [](const Config& c) { return c.model.dem.contact_law; }));
  k.push_back(dem_real("restitution", "-", "Coefficient of restitution between discs (mill DEM: ball-ball 0.725)", 0.0,
                       1.0, true, false, 0.725, &DemSpec::restitution));
  k.push_back(dem_real("wall_restitution", "-", "Coefficient of restitution disc-liner (mill DEM: ball-wall 0.80)", 0.0,
                       1.0, true, false, 0.8, &DemSpec::wall_restitution));
  k.push_back(dem_real("friction", "-", "Coulomb friction between discs", 0.0, 2.0, false, false, 0.3,
                       &DemSpec::friction));
  k.push_back(dem_real("wall_friction", "-", "Coulomb friction disc-liner", 0.0, 2.0, false, false, 0.3,
                       &DemSpec::wall_friction));
  k.push_back(dem_real("rolling_resistance", "-",
                       "Rolling resistance mu_r (constant directional torque mu_r F_n R*), both contact kinds", 0.0,
                       0.5, false, false, 0.02, &DemSpec::rolling_resistance));
  k.push_back(dem_opt_real("collision_time_s", "s",
                           "Contact duration of the real (not coarse-grained) discs; hertz: at the liner speed (the "
                           "default is about 1 ms; from 10 us: shorter takes over 100 times its steps)",
                           kDemMinCollisionTimeS, 1.0, false, &DemSpec::collision_time_s,
                           "default: from overlap_fraction; or give stiffness", false));
  k.push_back(dem_opt_real("stiffness", "N/m per m",
                           "Normal stiffness instead of collision_time_s: linear k_n [N/m per m], hertz k_h "
                           "[N/m^1.5 per m] (softer than 1e4 no bed holds its discs apart)",
                           kDemMinStiffness, 1e15, false, &DemSpec::stiffness, "alternative to collision_time_s", false));
  k.push_back(dem_real("overlap_fraction", "-",
                       "Default collision time: the smallest disc meeting the liner at the liner speed overlaps this "
                       "share of its diameter",
                       0.0, 0.2, true, false, 0.05, &DemSpec::overlap_fraction));
  k.push_back(dem_real("steps_per_collision", "-",
                       "Time step = shortest collision time / this (refused below 5: unstable)", 5.0, 10000.0, false,
                       false, 8.0, &DemSpec::steps_per_collision));
  k.push_back(dem_opt_real("time_step_s", "s", "The time step itself (refused beyond collision time / 5)",
                           kDemMinTimeStepS, 0.1, false, &DemSpec::time_step_s,
                           "default: collision time / steps_per_collision", false));
  k.push_back(dem_real("coarse_grain", "-",
                       "Coarse-graining factor s: discs s times the media size, s^2 fewer (refused where the mill "
                       "does not allow it)",
                       1.0, 20.0, false, false, 1.0, &DemSpec::coarse_grain));
  k.push_back(dem_real("ball_size_spread", "-", "Ball diameters uniform in [d (1 - spread), d]", 0.0, 0.5, false,
                       false, 0.1, &DemSpec::ball_size_spread));
  k.push_back(dem_opt_real("rock_diameter_max_m", "m", "Largest rock (SAG charge: filling - ball_filling is rock)",
                           0.0, 1.0, false, &DemSpec::rock_diameter_max_m, "default: the ball diameter"));
  k.push_back(dem_opt_real("rock_diameter_min_m", "m", "Smallest rock simulated (finer ore is not modelled)", 0.0,
                           1.0, false, &DemSpec::rock_diameter_min_m, "default: a quarter of the ball diameter"));
  k.push_back(dem_real("rock_size_exponent", "-",
                       "Gates-Gaudin-Schuhmann modulus m of the rocks: mass passing (d / d_max)^m", 0.0, 3.0, true,
                       false, 0.5, &DemSpec::rock_size_exponent));
  k.push_back(dem_real("packing_fraction_2d", "-",
                       "Solid area fraction of the disc bed; sets the disc count and the mass scaling", 0.5, 0.9069,
                       false, false, 0.82, &DemSpec::packing_fraction_2d));
  k.push_back(dem_real("revolutions", "-", "Mill revolutions averaged (after settling)", 0.0, 1000.0, true, false, 3.0,
                       &DemSpec::revolutions));
  k.push_back(dem_real("settle_revolutions", "-", "Revolutions run before averaging starts", 0.0, 100.0, false, false,
                       1.5, &DemSpec::settle_revolutions));
  k.push_back(dem_real("impact_min_speed_m_s", "m/s", "Wall-contact onsets slower than this (normal) are not impacts",
                       0.0, 10.0, false, false, 0.1, &DemSpec::impact_min_speed_m_s));
  k.push_back(int_key("dem", "seed", "Random seed of the sizes and the placement", 0, (1LL << 62), false,
                      [](Config& c, long long v) { c.model.dem.seed = v; }, [](const Config& c) { return c.model.dem.seed; },
                      1));
  k.push_back(int_key("dem", "threads", "OpenMP threads (0: all cores, 1 while a second does not pay); results repeat for a seed whatever the count",
                      0, 256, false, [](Config& c, long long v) { c.model.dem.threads = static_cast<int>(v); },
                      [](const Config& c) { return static_cast<long long>(c.model.dem.threads); }, 0));
}

void check_dem_keys(const Config& c) {
  const DemSpec& d = c.model.dem;
  if (d.collision_time_s > 0 && d.stiffness > 0)
    throw InputError("dem.stiffness", config_location(c, "dem.stiffness") +
                                          "give [dem] collision_time_s or stiffness, not both");
  const double dmax = d.rock_diameter_max_m > 0 ? d.rock_diameter_max_m : c.charge.ball_diameter_m;
  const double dmin = d.rock_diameter_min_m > 0 ? d.rock_diameter_min_m : 0.25 * c.charge.ball_diameter_m;
  if (dmin > dmax)
    throw InputError("dem.rock_diameter_min_m",
                     config_location(c, "dem.rock_diameter_min_m") +
                         fmt::format("rock_diameter_min_m = {} m is larger than the largest rock ({} m); allowed "
                                     "rock_diameter_min_m <= rock_diameter_max_m",
                                     dmin, dmax));
}

}  // namespace linerlife
