#include "charge/slurry_drag.h"

#include <algorithm>
#include <cmath>

#include "geometry/mill.h"

namespace linerlife {

double slurry_drag_coefficient(double Re) {
  Re = std::max(Re, 1e-9);
  return Re >= 1.0 ? 0.2021 * std::exp(4.7297 * std::pow(Re, -0.2101)) : 24.0 / Re;
}

Eigen::Vector2d slurry_drag_step(const SlurryDrag& s, const Eigen::Vector2d& v, double h) {
  const double rf = s.fluid_density_kg_m3, rp = s.particle_density_kg_m3;
  const double sp = v.norm();
  const double Re = rf * sp * s.diameter_m / s.viscosity_pa_s;
  const double k = 0.75 * slurry_drag_coefficient(Re) * rf * sp / (rp * s.diameter_m);  // [1/s]
  const Eigen::Vector2d g(0, -kGravity * (1.0 - rf / rp));
  return (v + h * g) / (1.0 + k * h);
}

}  // namespace linerlife
