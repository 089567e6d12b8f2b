// build_liner_surface.h - LinerDesign -> LinerSurface (DESIGN.md §2).
#pragma once

#include "geometry/lifter_design.h"
#include "geometry/liner_surface.h"
#include "geometry/mill.h"

namespace linerlife {

/// The fewest lifter rows: with one, the segment is the whole ring, whose
/// chord at the lifter top is zero (no lifter fits) and whose one cell the
/// forecast's remesh cannot wear (a plain plate of one row fails there).
constexpr int kMinSegments = 2;

/// [m] The finest surface element: below the finest run of both element-size
/// studies (docs/geometry.md: 2.5 mm, which differs from 5 mm by under 0.2 %;
/// docs/validation/forecast.md: 1.5 mm). A 15 m mill has 47,000 nodes at
/// 1 mm; 1e-9 m asked for 3e10 and ended in bad_alloc.
constexpr double kMinElementSizeM = 0.001;

/// Builds the whole ring of liners for `mill` from `design`, with surface
/// elements no longer than design.element_size_m. The leading face of a
/// parametric lifter faces the mill's direction of rotation; a measured
/// profile is placed as given (its x runs anticlockwise).
///
/// Throws InputError (naming the liner.* key, the value and what is allowed)
/// for designs that cannot be built: a lifter taller than a quarter of the
/// shell radius, a top or base wider than its segment, face angles outside
/// [0, 80) deg, a fillet that does not fit, elements too coarse to resolve the
/// lifter.
LinerSurface build_liner_surface(const Mill& mill, const LinerDesign& design);

/// The profile of one segment centred on angle 0 (the +x axis), nodes in
/// anticlockwise order from the radial line at -pi/segments to the one at
/// +pi/segments, both ends included. Used by build_liner_surface.
std::vector<Eigen::Vector2d> segment_profile(const Mill& mill, const LinerDesign& design, int which_design);

/// A ring of `segments` rows from segment profiles centred on angle 0 (both
/// edge nodes included, as segment_profile gives them): segment k uses
/// profiles[segment_design[k]] rotated by k * 2 pi / segments.
LinerSurface assemble_ring(double shell_radius_m, int segments, const std::vector<std::vector<Eigen::Vector2d>>& profiles,
                           const std::vector<int>& segment_design);

/// Rotates points about the mill axis by `angle_rad` (anticlockwise).
std::vector<Eigen::Vector2d> rotate_points(const std::vector<Eigen::Vector2d>& p, double angle_rad);

/// Checks a parametric design against the shell and the segment (the checks
/// listed for build_liner_surface). `prefix` names the keys ("liner." or
/// "liner.low_").
void validate_lifter_design(const Mill& mill, int segments, const LifterDesign& d, double element_size_m,
                            const char* prefix);

}  // namespace linerlife
