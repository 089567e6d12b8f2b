// synthetic_charge.h - a stand-in ChargeModel with loads of plausible size
// and place but NO charge physics, for the wear benchmarks and demo charts
// made before the real charge models are merged. Every figure made with it
// says so.
//
// Per liner, time-averaged over a revolution (every liner alike):
//   charge mass per metre M_c = J A_free rho_c, rho_c = (J_B rho_b + (J - J_B) rho_o)(1 - E) / J;
//   normal force on the shell 0.8 M_c (g + omega^2 r_bar) shared by the rows,
//   0.8 M_c g gravitational and 0.8 M_c omega^2 r_bar centrifugal (thesis eqs. 5.1-5.2);
//   along a liner the load per unit length is 0.1 (1 - h)^2 + 1.5 h s(a) with h
//   the height above the plate as a fraction of the lifter's and s(a) a smooth
//   step (over about 5 cm) from the trailing to the leading side of the crest:
//   the plate carries some, the leading face and top most, the trailing face
//   little; slip speed from Morrell's layer speeds (thesis eq. 5.9); shear
//   force 0.3 N; 2 % of the cataracting charge (a tenth of M_c a second) hits
//   the liner directly at 6 m/s and 45 deg, evenly on the plate.
// Heights and sides are found on the current (possibly worn) surface, so with
// feedback the loads follow the wear.
#pragma once

#include <cmath>
#include <memory>

#include "charge/charge_model.h"
#include "geometry/metrics.h"
#include "wear/impact_submodels.h"
#include "wear/slip_models.h"

namespace linerlife::bench {

class SyntheticCharge : public ChargeModel {
 public:
  ChargeResult run(const ChargeInput& in) const override {
    const LinerSurface& s = *in.surface;
    const Mill& mill = in.mill;
    const ChargeSpec& c = in.charge;
    ChargeResult r;
    r.model = "synthetic";
    const double period = 60.0 / mill.speed_rpm;
    r.loads.reset(s.n_elements(), period * (in.revolutions > 0 ? in.revolutions : 1.0));
    r.loads.has_impacts = true;
    const double R = s.shell_radius_m;
    const double free_area = linerlife::free_area(s);
    const double rho_c = (c.ball_filling * c.ball_density_kg_m3 + (c.filling - c.ball_filling) * c.ore_density_kg_m3) *
                         (1 - c.porosity) / c.filling;
    const double mc = c.filling * free_area * rho_c;  // [kg/m]
    const double w = mill.omega_rad_s();
    const double rbar = 0.8 * std::sqrt(free_area / kPi);
    const double ng = 0.8 * mc * kGravity / s.segments, nc = 0.8 * mc * w * w * rbar / s.segments;  // [N/m] per liner
    const OperatingPoint op = operating_point(mill, c, nullptr, s);
    const double slip = morrell_slip_speed(op);
    const double sense = mill.sense();
    for (int k = 0; k < s.segments; ++k) {
      const int b = s.segment_begin[k], e = s.segment_begin[k + 1];
      // plate level: the thinnest point of the segment; crest: the thickest
      double tmin = 1e9, tmax = 0;
      for (int i = b; i < e; ++i) {
        const double t = R - s.midpoint[i].norm();
        tmin = std::min(tmin, t);
        tmax = std::max(tmax, t);
      }
      const double centre = s.segment_centre_rad(k);
      auto offset = [&](int i) {  // angle ahead of the lifter centre in the direction of rotation
        double a = std::atan2(s.midpoint[i].y(), s.midpoint[i].x()) - centre;
        a = std::remainder(a, 2 * kPi);
        return sense * a;
      };
      // load density along the liner, continuous: the plate (falling with the height fraction
      // h above it) plus the lift on the leading side (growing with h, switched on smoothly
      // across the crest within about 5 cm)
      std::vector<double> wgt(static_cast<size_t>(e - b));
      double wsum = 0;
      for (int i = b; i < e; ++i) {
        const double h = std::clamp((R - s.midpoint[i].norm() - tmin) / std::max(tmax - tmin, 1e-9), 0.0, 1.0);
        const double lead = 1.0 / (1.0 + std::exp(-offset(i) / 0.01));
        wgt[i - b] = (0.1 * (1 - h) * (1 - h) + 1.5 * h * lead) * s.length[i];
        wsum += wgt[i - b];
      }
      for (int i = b; i < e; ++i) {
        const double f = wgt[i - b] / wsum;
        r.loads.centrifugal_force_n_per_m[i] = nc * f;
        r.loads.gravitational_force_n_per_m[i] = ng * f;
        r.loads.normal_force_n_per_m[i] = (nc + ng) * f;
        r.loads.shear_force_n_per_m[i] = 0.3 * (nc + ng) * f;
        r.loads.slip_speed_m_s[i] = slip;
        r.loads.normal_slip_power_w_per_m[i] = (nc + ng) * f * slip;
        r.loads.shear_work_rate_w_per_m[i] = 0.3 * (nc + ng) * f * slip;
      }
      // direct impacts: spread evenly over the plate (within 2 cm of its level) by length
      const double ball = ball_mass_kg(c.ball_diameter_m, c.ball_density_kg_m3);
      const double flow = 0.02 * 0.1 * mc / s.segments;  // [kg/s per m] onto this liner
      std::vector<int> hit;
      double hit_len = 0;
      for (int i = b; i < e; ++i)
        if (R - s.midpoint[i].norm() < tmin + 0.02) {
          hit.push_back(i);
          hit_len += s.length[i];
        }
      for (int i : hit) {
        ImpactEvent ev;
        ev.element = i;
        ev.normal_speed_m_s = 6 * std::sin(kPi / 4);
        ev.tangential_speed_m_s = 6 * std::cos(kPi / 4);
        ev.mass_kg = ball;
        ev.diameter_m = c.ball_diameter_m;
        ev.rate_per_s = flow / ball * s.length[i] / hit_len;
        ev.direct = true;
        r.loads.impacts.push_back(ev);
      }
    }
    r.stats.simulated_s = r.loads.duration_s;
    return r;
  }
};

inline std::unique_ptr<ChargeModel> make_synthetic_charge() { return std::make_unique<SyntheticCharge>(); }

/// A table row for the synthetic model.
inline const ChargeModelEntry& synthetic_entry() {
  static const ChargeModelEntry e{"synthetic", "test double: loads of plausible size, no charge physics", true, true,
                                  &make_synthetic_charge};
  return e;
}

}  // namespace linerlife::bench
