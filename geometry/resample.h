// resample.h - resampling of an open polyline to a target element size.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace linerlife {

/// Resamples the open polyline `pts` (end points kept) so that no element is
/// longer than 1.25 h (an element longer than that is split into pieces no
/// longer than h; the slack stops a receding plate, whose chords stretch a
/// little, from doubling its node count), while changing the enclosed area as little as possible:
/// a vertex is removed only when it is nearly collinear (turn < 0.5 deg and the
/// merged element no longer than h) or when it bounds an element shorter than
/// 0.3 h and the triangle it cuts off is smaller than 0.01 h^2. Long elements
/// are split into equal parts (exactly area-preserving). A vertex is removed
/// only when that removes liner material (it lies on the charge side of the
/// chord of its neighbours, for an anticlockwise liner surface): resampling
/// never adds material, except by removing degenerate elements shorter than
/// 1e-6 h (an area change below round-off).
std::vector<Eigen::Vector2d> resample_polyline(const std::vector<Eigen::Vector2d>& pts, double h);

}  // namespace linerlife
