// lifter_design.h - what the user describes: one or two lifter designs on
// curved shell plates, or a measured profile.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace linerlife {

/// One parametric lifter on its shell plate (thesis Fig. 5-12; Qiu 2001).
/// The plate is an arc of constant thickness; the lifter is a trapezoid
/// standing on it with a flat (chordal) top and straight faces.
///
/// Face angles are measured from the radial through the face's point at
/// mid-height of the lifter,
/// positive when the face leans away from the lifter as it goes down to the
/// plate (a relieved face). The leading face is the one facing the direction
/// of rotation.
struct LifterDesign {
  double plate_thickness_m = 0;        // [m] shell plate, radial
  double lifter_height_m = 0;          // [m] above the plate; 0 gives a plain plate
  double top_width_m = 0;              // [m] chord of the flat top
  double face_angle_leading_deg = 0;   // [deg] from the radial, 0 <= a < 80
  double face_angle_trailing_deg = 0;  // [deg] from the radial, 0 <= a < 80
  double corner_radius_m = 0;          // [m] fillet of the two top corners (0: sharp)
};

/// A measured (or otherwise given) profile of one segment in the unrolled
/// liner frame of thesis Fig. 5-12: x [m] is arc length along the shell,
/// increasing anticlockwise, from 0 at one segment edge to the segment width
/// pi D / segments at the other; y [m] is the liner thickness (radial height
/// above the shell). Points run from x = 0 to x = width.
struct MeasuredProfile {
  std::string source;                  // file it came from (for messages)
  std::vector<Eigen::Vector2d> points;  // (x, y) [m]
  std::vector<int> lines;               // line of the file of each point (for messages); empty if not from a file
};

/// How a full ring of liners is built.
struct LinerDesign {
  int segments = 0;                // lifter rows round the ring
  LifterDesign design;             // the (high) lifter
  bool hi_lo = false;              // alternate `design` and `low` (even segments high)
  LifterDesign low;                // the low lifter of a hi-lo pattern
  bool measured = false;           // use `profile` for every segment instead of `design`
  MeasuredProfile profile;
  double element_size_m = 0;       // [m] longest surface element
  double density_kg_m3 = 0;        // [kg/m3] liner material
  double hardness_bhn = 0;         // [BHN] liner material
  int lifter_grid_cells = 60;      // n for the thesis' n x n lifter grid (§5.6, Table B.1)
};

}  // namespace linerlife
