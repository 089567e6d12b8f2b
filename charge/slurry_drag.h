// slurry_drag.h - the drag of the slurry pool of an overflow mill on a flying
// ball (thesis Appendix C, lines 146-186; docs/models/layer.md §Slurry).
#pragma once

#include <Eigen/Core>

namespace linerlife {

struct SlurryDrag {
  double fluid_density_kg_m3 = 0;     // rho_f, the pulp
  double particle_density_kg_m3 = 0;  // rho_p
  double diameter_m = 0;              // d
  double viscosity_pa_s = 0.00278;    // mu of the slurry, as in the thesis code
};

/// Sphere drag coefficient of the thesis code: C_d = 0.2021 exp(4.7297 Re^-0.2101)
/// for Re >= 1, and Stokes' 24 / Re below, where that correlation overshoots.
double slurry_drag_coefficient(double reynolds);

/// One step h [s] of the velocity v [m/s] of a ball in the pool: gravity less
/// buoyancy, g (1 - rho_f / rho_p), and drag 3/4 C_d rho_f |v| v / (rho_p d),
/// implicit in the drag so that it never reverses the velocity (the thesis
/// code applies it per component and explicitly).
Eigen::Vector2d slurry_drag_step(const SlurryDrag& s, const Eigen::Vector2d& v, double h);

}  // namespace linerlife
