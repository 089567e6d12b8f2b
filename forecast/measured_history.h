// measured_history.h - lifter profiles measured at stated operating hours
// (plant scans), the input of `linerlife calibrate`. Format:
// docs/measured-profiles.md.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace linerlife {

struct MeasuredSnapshot {
  double hours = 0;                     // [h] operating hours since the liner was new
  std::vector<Eigen::Vector2d> points;  // (x, y) [m] in the unrolled frame of profile_csv (x along the shell, y thickness)
  int first_line = 0;                   // line of the file where it starts (for messages)
  std::vector<int> lines;               // line of the file of each point (for messages)
};

struct MeasuredHistory {
  std::string source;
  std::vector<MeasuredSnapshot> snapshots;  // in order of hours
};

/// Parses "hours,x_m,y_m" rows (optional '#' comments and that header line).
/// Consecutive rows with the same hours form one profile, its points in order
/// along the surface. Throws InputError naming the file and line for
/// non-numeric fields, hours that decrease or repeat a finished profile,
/// negative hours, a profile with fewer than 3 points, or no profile at all.
MeasuredHistory parse_measured_history(const std::string& text, const std::string& source);
MeasuredHistory load_measured_history(const std::string& path);

/// Checks every snapshot against the segment (the checks of
/// validate_measured_profile: inside the shell, x within the segment, not
/// self-crossing); throws InputError naming the file, the hours and the line.
void validate_measured_history(const MeasuredHistory& h, double shell_radius_m, int segments);

/// (x, y) of the unrolled frame -> the mill frame of segment 0 (centred on angle 0).
std::vector<Eigen::Vector2d> unrolled_to_mill(const std::vector<Eigen::Vector2d>& xy, double shell_radius_m,
                                              int segments);

}  // namespace linerlife
