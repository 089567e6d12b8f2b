// canonical_surface.h - every charge model of this module computes an
// anticlockwise mill; a clockwise mill is its mirror image (x -> -x,
// DESIGN.md §3). This makes the mirrored liner surface and the maps back.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/liner_surface.h"
#include "geometry/mill.h"

namespace linerlife {

struct CanonicalSurface {
  LinerSurface surface;              // anticlockwise-mill frame (a copy of the input for an anticlockwise mill)
  bool mirrored = false;             // the input mill turns clockwise
  std::vector<int> physical_element; // canonical element -> element of the input surface

  /// Physical-frame angle [rad] of a canonical angle: theta, or pi - theta when mirrored.
  double physical_angle(double theta_rad) const { return mirrored ? kPi - theta_rad : theta_rad; }
  Eigen::Vector2d physical_point(const Eigen::Vector2d& p) const {
    return mirrored ? Eigen::Vector2d(-p.x(), p.y()) : p;
  }
};

/// The canonical surface of `s` for a mill turning `rotation`. For a clockwise
/// mill, segment k of the input becomes segment (segments - k) mod segments
/// (so segment 0 stays segment 0) and nodes are reordered to run anticlockwise.
CanonicalSurface make_canonical_surface(const LinerSurface& s, Rotation rotation);

}  // namespace linerlife
