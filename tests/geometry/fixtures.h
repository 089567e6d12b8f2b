// Shared mills and designs for the geometry tests.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "geometry/build_liner_surface.h"
#include "geometry/liner_surface.h"

namespace linerlife::test {

/// The bundled Qiu SAG mill (data/mills/qiu2001_sag.toml).
inline Mill qiu_mill(Rotation r = Rotation::Ccw) {
  Mill m;
  m.diameter_m = 10.36;
  m.length_m = 5.0;
  m.speed_rpm = 10.36;
  m.rotation = r;
  return m;
}

inline LinerDesign qiu_liner(double h = 0.01) {
  LinerDesign d;
  d.segments = 64;
  d.design.plate_thickness_m = 0.075;
  d.design.lifter_height_m = 0.25;
  d.design.top_width_m = 0.15;
  d.design.face_angle_leading_deg = 20;
  d.design.face_angle_trailing_deg = 20;
  d.element_size_m = h;
  d.density_kg_m3 = 7800;
  d.hardness_bhn = 350;
  return d;
}

/// The pilot mill of thesis §4.3 (clockwise, 8 square-ish lifters).
inline Mill pilot_mill() {
  Mill m;
  m.diameter_m = 0.762;
  m.length_m = 0.381;
  m.speed_rpm = 29;
  m.rotation = Rotation::Cw;
  return m;
}

inline LinerDesign pilot_liner(double h = 0.002) {
  LinerDesign d;
  d.segments = 8;
  d.design.plate_thickness_m = 0.005;
  d.design.lifter_height_m = 0.025;
  d.design.top_width_m = 0.025;
  d.design.face_angle_leading_deg = 5;
  d.design.face_angle_trailing_deg = 5;
  d.element_size_m = h;
  d.density_kg_m3 = 7800;
  return d;
}

inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Area of a closed polygon (anticlockwise positive).
inline double polygon_area(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

/// Winding number of the closed polyline `poly` round point q.
inline int winding(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& q) {
  int w = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    if (a.y() <= q.y()) {
      if (b.y() > q.y() && cross(b - a, q - a) > 0) ++w;
    } else if (b.y() <= q.y() && cross(b - a, q - a) < 0) {
      --w;
    }
  }
  return w;
}

/// Nodes of segment k with both edge nodes.
inline std::vector<Eigen::Vector2d> segment_chain(const LinerSurface& s, int k) {
  std::vector<Eigen::Vector2d> out;
  for (int i = s.segment_begin[k]; i <= s.segment_begin[k + 1]; ++i) out.push_back(s.nodes[i % s.n_nodes()]);
  return out;
}

}  // namespace linerlife::test
