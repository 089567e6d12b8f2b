// canonical_surface.h - every charge model of this module computes an
// anticlockwise mill; a clockwise mill is its mirror image (x -> -x, theta ->
// 180 deg - theta; DESIGN.md §3). This makes the mirrored liner surface and
// the maps back.
//
// The mirror of segment k of the input (centred on k D, D = 2 pi / segments)
// is centred on pi - k D. With an even number of segments that is segment
// (segments/2 - k); with an odd number it falls half a segment off, so the
// mirrored ring is also turned by -D/2, and the model starts the liner at
// that angle (initial_angle_rad), which is the same physical mill.
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
  std::vector<int> physical_segment; // canonical segment -> segment of the input surface
  int segment_of_physical_0 = 0;     // canonical segment of the input's segment 0
  double initial_angle_rad = 0;      // [rad] where the canonical liner frame is at t = 0 (mill frame)

  /// Physical-frame angle [rad] of a canonical angle: theta, or pi - theta when mirrored.
  double physical_angle(double theta_rad) const { return mirrored ? kPi - theta_rad : theta_rad; }
  Eigen::Vector2d physical_point(const Eigen::Vector2d& p) const {
    return mirrored ? Eigen::Vector2d(-p.x(), p.y()) : p;
  }
};

/// The canonical surface of `s` for a mill turning `rotation`.
CanonicalSurface make_canonical_surface(const LinerSurface& s, Rotation rotation);

}  // namespace linerlife
