// measured_profile.h - a lifter profile given as points instead of a
// parametric design (a plant scan, a digitised drawing). Format: docs/profile-csv.md.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "geometry/lifter_design.h"

namespace linerlife {

/// Reads a profile CSV: optional '#' comment lines, an optional header line
/// "x_m,y_m", then one "x,y" pair per line in metres (x along the shell,
/// anticlockwise; y thickness above the shell). Throws InputError naming the
/// file and line for a missing or unreadable file, a directory, non-numeric
/// or missing fields, fewer than 3 points, or non-finite values.
MeasuredProfile load_profile_csv(const std::string& path);

/// Parses profile CSV text (the same rules); `source` names it in messages.
MeasuredProfile parse_profile_csv(const std::string& text, const std::string& source);

/// [m] The finest detail a profile may have: 0.01 mm, a hundredth of the
/// finest surface element ([liner] element_size_m >= 1 mm) and far below what
/// a scan of a liner resolves (about a millimetre). Consecutive points closer
/// than this, or a point closer than this to a stretch of the profile it does
/// not end (a needle or a fold thinner than this), are not a measurement:
/// before, a needle 0.2 um wide was meshed as it was and moved the bundled
/// mill's relining date by 20 days.
constexpr double kMinProfileDetailM = 1e-5;

/// Checks that the profile fits the mill: x runs from 0 to the segment width
/// pi D / segments (within 1 mm), stays in [0, width], every y is inside the
/// shell (0 < y < R / 2), both ends have the same thickness (within 1 mm, the
/// profile repeats round the ring), consecutive points are at least
/// kMinProfileDetailM apart, the polyline does not cross itself, and no point
/// comes closer than kMinProfileDetailM to a stretch it does not end.
/// Throws InputError naming the file.
void validate_measured_profile(const MeasuredProfile& p, double shell_radius_m, int segments);

/// Maps the profile onto the segment centred at angle 0 (theta = x / R - half
/// segment, r = R - y), subdividing in the (x, y) frame so plate stretches
/// follow the shell curvature; elements no longer than h. Both end nodes lie
/// on the segment's radial edges.
std::vector<Eigen::Vector2d> measured_profile_to_segment(const MeasuredProfile& p, double shell_radius_m,
                                                         int segments, double h);

/// The inverse: a segment's nodes (segment centred at `centre_rad`) in the
/// unrolled (x, y) frame of the CSV format.
std::vector<Eigen::Vector2d> segment_to_profile_xy(const std::vector<Eigen::Vector2d>& nodes, double shell_radius_m,
                                                   double centre_rad, double segment_angle_rad);

/// Whether an open polyline crosses itself (segments that are not neighbours
/// touch or cross). Near-linear: only stretches that share a cell of a
/// StretchGrid (geometry/stretch_grid.h) are compared.
bool polyline_self_intersects(const std::vector<Eigen::Vector2d>& pts);

/// The first pair (i, j), i < j, of non-neighbouring stretches (points i to
/// i + 1 and j to j + 1) that touch or cross, first in the order of a scan of
/// every i, then every j (least i, then least j); (-1, -1) if none.
std::pair<int, int> first_self_crossing(const std::vector<Eigen::Vector2d>& pts);

/// The first stretch j (points j to j + 1) with a point i it does not end
/// (i != j, j + 1) nearer to it than `d` [m], and the first such point, in the
/// order of a scan of every j, then every i; (-1, -1) if none. Near-linear
/// (a StretchGrid, geometry/stretch_grid.h): a needle or fold finer than
/// kMinProfileDetailM in validate_measured_profile.
std::pair<int, int> first_point_near_stretch(const std::vector<Eigen::Vector2d>& pts, double d);

}  // namespace linerlife
