// metrics.h - what an engineer measures on a liner: lifter height, face
// angles, top width, thickness, area and mass. Definitions: docs/geometry.md.
#pragma once

#include <vector>

#include "geometry/liner_surface.h"
#include "geometry/mill.h"

namespace linerlife {

struct SegmentMetrics {
  int segment = 0;
  int design = 0;                       // 0 high, 1 low of a hi-lo pattern
  bool has_lifter = false;              // lifter_height_m above the resolution of the surface
  double plate_ref_thickness_m = 0;     // [m] thickness at the segment edges (middle of the plate)
  double min_thickness_m = 0;           // [m] thinnest point of the segment (wear-through)
  double max_thickness_m = 0;           // [m] at the crest
  double lifter_height_m = 0;           // [m] crest thickness - plate reference, >= 0
  double face_angle_leading_deg = 0;    // [deg] from the radial, fitted over 20-80 % of the height; NaN without lifter
  double face_angle_trailing_deg = 0;   // [deg] likewise
  double top_width_m = 0;               // [m] between the two fitted face lines where they meet the crest tangent; NaN without lifter
  double crest_angle_rad = 0;           // [rad] polar angle of the crest, the point closest to the axis (mill frame)
  double area_m2 = 0;                   // [m2] liner cross-section (per metre of length)
  double mass_kg_per_m = 0;             // [kg/m]
};

struct LinerMetrics {
  std::vector<SegmentMetrics> segments;
  double area_m2 = 0;                 // [m2] whole ring, per metre of length
  double mass_kg_per_m = 0;           // [kg/m] whole ring
  double free_area_m2 = 0;            // [m2] area inside the liner surface
  double effective_diameter_m = 0;    // [m] diameter of the circle with the free area
  double min_thickness_m = 0;         // [m] thinnest point of the ring
};

/// Metrics of segment k. `rotation` decides which face leads.
SegmentMetrics segment_metrics(const LinerSurface& s, int k, Rotation rotation, double density_kg_m3);

/// Metrics of every segment and of the ring.
LinerMetrics metrics(const LinerSurface& s, Rotation rotation, double density_kg_m3);

/// Cross-section area [m2] of the liner body of segment k: the region between
/// its surface polyline and the shell arc (exact sector formula).
double segment_area(const LinerSurface& s, int k);

/// Area [m2] enclosed by the surface polyline (the free area of the mill).
double free_area(const LinerSurface& s);

}  // namespace linerlife
