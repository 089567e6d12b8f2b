#include "charge/empirical_model.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "charge/checked_range.h"
#include "charge/morrell_c_model.h"
#include "geometry/errors.h"
#include "geometry/metrics.h"

namespace linerlife {
namespace {

double to_physical_deg(double theta_rad, Rotation rot) {
  double t = rot == Rotation::Ccw ? theta_rad : kPi - theta_rad;  // mirror for a clockwise mill (DESIGN.md §3)
  double d = std::fmod(t * 180.0 / kPi, 360.0);
  return d < 0 ? d + 360.0 : d;
}

}  // namespace

ChargeResult EmpiricalModel::run(const ChargeInput& in) const {
  const auto wall0 = std::chrono::steady_clock::now();
  if (!in.surface) throw InputError("", "empirical model: no liner surface given");
  const ChargeSpec& c = in.charge;
  // A floor, not 0: the C-model's powers difference r_m^n and r_i^n, which
  // cancel as the filling vanishes (filling 1e-16 gave -1994 kW, 1e-17 NaN).
  if (!(c.filling >= 0.01 && c.filling < 1))
    throw InputError("charge.filling",
                     fmt::format("filling = {}: allowed 0.01 <= filling < 1 for Morrell's C-model (a smaller charge "
                                 "is lost in the rounding of its inner radius)",
                                 c.filling));
  const LinerMetrics lm = metrics(*in.surface, in.mill.rotation, 7800.0);
  const double D = lm.effective_diameter_m, rm = 0.5 * D;
  // Morrell's inputs in his units (t/m3, rev/s)
  MorrellInput mi;
  mi.diameter_m = D;
  mi.length_m = in.mill.length_m;
  mi.cone_length_m = c.cone_length_m;
  mi.trunnion_radius_m = c.trunnion_radius_m;
  mi.speed_rps = in.mill.speed_rpm / 60.0;
  mi.filling = c.filling;
  mi.ball_filling = c.ball_filling;
  mi.porosity = c.porosity;
  mi.slurry_void_fill = c.slurry_void_fill;
  const double w = c.slurry_solids_mass_fraction, rho_o = c.ore_density_kg_m3 / 1000.0;
  mi.pulp_density_t_m3 = 1.0 / (w / rho_o + (1.0 - w) / 1.0);
  mi.slurry_solids_volume_fraction = (w / rho_o) * mi.pulp_density_t_m3;
  mi.ore_density_t_m3 = rho_o;
  mi.ball_density_t_m3 = c.ball_density_kg_m3 / 1000.0;
  mi.overflow = c.discharge == Discharge::Overflow;
  if (mi.overflow && !(c.trunnion_radius_m > 0 && c.trunnion_radius_m < rm))
    throw InputError("mill.trunnion_diameter_m",
                     fmt::format("an overflow mill needs a trunnion diameter between 0 and the diameter inside the "
                                 "liners ({:.3f} m)",
                                 D));
  const MorrellResult r = morrell_c_model(mi);
  MorrellInput dry_pool = mi;
  dry_pool.pulp_density_t_m3 = 0;  // without the slurry pool term, to report its share
  const MorrellResult r0 = mi.overflow ? morrell_c_model(dry_pool) : r;

  ChargeResult res;
  res.model = "empirical";
  Indicators& I = res.indicators;
  I.diameter_eff_m = D;
  I.fraction_critical = r.fraction_critical;
  I.toe_deg = to_physical_deg(r.toe_rad, in.mill.rotation);
  I.shoulder_deg = to_physical_deg(r.shoulder_rad, in.mill.rotation);
  I.inner_radius_m = r.inner_radius_m;
  const double ri = r.inner_radius_m;
  // The en-masse charge of the C-model: the annular sector r_i < r < r_m,
  // theta_T < theta < theta_S + 2 pi (Morrell 1996).
  const double span = r.centrifuged ? 2.0 * kPi : 2.0 * kPi + r.shoulder_rad - r.toe_rad;
  I.charge_area_m2 = 0.5 * span * (rm * rm - ri * ri);
  const double rc = 2.0 / 3.0 * (rm * rm * rm - ri * ri * ri) / (rm * rm - ri * ri) * std::sin(0.5 * span) / (0.5 * span);
  I.com_radius_m = rc;
  I.com_angle_deg = to_physical_deg(r.toe_rad + 0.5 * span, in.mill.rotation);
  // media-diameter layers in the annulus r_i < r < r_m, rounded, and at
  // least one where there is a charge (a bed thinner than half a ball, at a
  // few per cent filling, rounded to none: the input sweep of 2026-12-07)
  I.n_layers = c.ball_diameter_m > 0 && rm > ri
                   ? std::max(1, static_cast<int>(std::lround((rm - ri) / c.ball_diameter_m)))
                   : 0;
  I.n_trajectories = -1;  // the C-model has no trajectories
  // layer speeds: Morrell's linear law at the layer centres (thesis eq. 4.16
  // with z), r_m - (j + 1/2) d; a layer whose centre would lie inside r_i
  // (only the one of a bed thinner than half a ball) at the bed's middle
  if (c.ball_diameter_m > 0 && !r.centrifuged) {
    const double vm = 2.0 * kPi * mi.speed_rps * rm, zri = r.z * ri;
    for (int j = 0; j < I.n_layers; ++j) {
      double rj = rm - (j + 0.5) * c.ball_diameter_m;
      if (rj < ri) rj = 0.5 * (ri + rm);
      I.layer_speed_rpm.push_back(vm * (rj - zri) / (rm - zri) / rj * 60.0 / (2.0 * kPi));
    }
  }
  I.net_power_kw = r.cylinder_power_kw + r.cone_power_kw;
  I.net_power_w_per_m = in.mill.length_m > 0 ? r.cylinder_power_kw * 1000.0 / in.mill.length_m : 0.0;
  I.no_load_power_kw = r.no_load_power_kw;
  I.gross_power_kw = r.gross_power_kw;
  I.slurry_pool_power_kw = (r.cylinder_power_kw + r.cone_power_kw) - (r0.cylinder_power_kw + r0.cone_power_kw);
  I.alt_net_power_kw = hogg_fuerstenau_power_kw(D, in.mill.length_m, in.mill.speed_rpm, r.charge_density_t_m3,
                                                c.filling, in.model.hf_lift_angle_deg * kPi / 180.0);
  res.loads.reset(in.surface->n_elements(), 0.0);
  res.loads.has_impacts = false;
  if (r.centrifuged)
    res.notes.push_back(fmt::format("the mill runs at {:.3f} of critical, beyond Morrell's phi_c = {:.3f}: the charge "
                                    "is taken as fully centrifuged (toe = shoulder = 90 deg)",
                                    r.fraction_critical, r.phi_c));
  for (std::string& n : checked_range_notes("Morrell's model", c.filling, r.fraction_critical))
    res.notes.push_back(std::move(n));
  // Where the formulas leave their domain (a review, 2026-12-06): the cone
  // term's 1 / (r_m - r_t) grows without bound as the trunnion nears the
  // shell (49 GW at r_t 0.4 mm inside r_m), and near the edges of the filling
  // and speed ranges the cylinder term goes negative.
  if (r.cone_power_kw > 0 && r.cylinder_power_kw > 0 && in.mill.length_m > 0 && mi.cone_length_m > 0 &&
      r.cone_power_kw / mi.cone_length_m > r.cylinder_power_kw / in.mill.length_m)
    res.notes.push_back(fmt::format(
        "Morrell's cone term gives the conical ends {:.0f} kW, more per metre of length than the cylinder's {:.0f} kW: "
        "it grows as 1 / (r_m - r_t) as the trunnion ({:.3f} m across) nears the diameter inside the liners ({:.3f} "
        "m); a cone holds less charge than the cylinder, so this figure is not physical",
        r.cone_power_kw, r.cylinder_power_kw, 2.0 * mi.trunnion_radius_m, 2.0 * rm));
  if (!(I.net_power_kw >= 0))
    res.notes.push_back(fmt::format("Morrell's model gives a negative net power ({:.1f} kW) at filling {} and {:.3f} of "
                                    "critical: outside its domain, the power is not physical here",
                                    I.net_power_kw, c.filling, r.fraction_critical));
  res.stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  res.stats.simulated_s = 0;
  res.stats.realtime_ratio = std::numeric_limits<double>::quiet_NaN();  // no simulated time
  return res;
}

std::unique_ptr<ChargeModel> make_empirical_model() { return std::make_unique<EmpiricalModel>(); }

}  // namespace linerlife
