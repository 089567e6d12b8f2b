// Mills and runs shared by the charge-model tests.
#pragma once

#include <string>

#include "app/config.h"
#include "charge/charge_model.h"
#include "geometry/build_liner_surface.h"

namespace linerlife::test {

/// A configuration from data/mills.
inline Config mill_config(const std::string& name) {
  return load_config_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/" + name);
}

/// A ChargeInput for configuration c on surface s (which must outlive it).
inline ChargeInput charge_input(const Config& c, const LinerSurface& s, double revolutions, double settle = 2.0) {
  ChargeInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.model.settle_revolutions = settle;
  in.surface = &s;
  in.revolutions = revolutions;
  return in;
}

/// The surface of configuration c's liner meshed with elements of `element_size_m`.
inline LinerSurface surface_with_elements(const Config& c, double element_size_m) {
  LinerDesign d = c.liner;
  d.element_size_m = element_size_m;
  return build_liner_surface(c.mill, d);
}

inline ChargeResult run_model(const std::string& name, const ChargeInput& in) {
  return find_charge_model(name).make()->run(in);
}

/// Shortest distance [m] from p to the closed polyline of the surface.
inline double distance_to_liner(const LinerSurface& s, const Eigen::Vector2d& p) {
  double best = 1e300;
  for (int i = 0; i < s.n_elements(); ++i) {
    const Eigen::Vector2d a = s.nodes[i], b = s.nodes[s.next(i)];
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

/// theta -> 180 - theta, in [0, 360).
inline double mirror_deg(double a) {
  double m = std::fmod(180.0 - a, 360.0);
  return m < 0 ? m + 360.0 : m;
}

/// Smallest difference of two angles [deg].
inline double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

}  // namespace linerlife::test
