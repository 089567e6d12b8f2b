// remesh.h - moves the liner surface into the liner body by a recession depth
// and repairs it (DESIGN.md §2).
//
// The worn body is the old body minus the region swept by every surface
// element as it recedes (one quadrilateral per element: its old and new
// position). The difference is taken with CGAL's exact 2D Boolean set
// operations, so loops and self-intersections of the moved polyline never
// reach the result and material is never added. The new surface is the
// boundary of what is left, resampled to the element size.
#pragma once

#include <string>
#include <vector>

#include "geometry/liner_surface.h"

namespace linerlife {

enum class RemeshStatus {
  Ok,
  WornThrough,  // some node reached the shell; the surface was held min_thickness_m short of it
};

struct RemeshOptions {
  double element_size_m = 0.01;   // [m] target element size; remeshed elements stay under 1.25 x this
  double min_thickness_m = 1e-4;  // [m] a node never comes closer than this to the shell
  double max_miter = 2.0;         // cap on the corner displacement factor 1 / cos(half turn)
};

struct RemeshResult {
  LinerSurface surface;
  RemeshStatus status = RemeshStatus::Ok;
  int worn_through_segment = -1;        // first segment reaching the shell
  double worn_through_angle_rad = 0;    // [rad] polar angle of the first node that reached it
  double removed_area_m2 = 0;           // [m2] old liner area - new liner area (per metre)
  double detached_area_m2 = 0;          // [m2] pieces cut loose from the liner (counted as removed)
  std::string message;                  // for WornThrough: where, in words
};

/// Recedes every node i by node_depth_m[i] >= 0 [m] along its offset direction
/// (node_offset_directions) and returns the repaired, resampled surface.
/// Segments whose nodes (and their neighbours') do not move are copied as they
/// are. Throws std::invalid_argument for a depth vector of the wrong size or
/// negative or non-finite depths (a programming error of the caller).
RemeshResult remesh(const LinerSurface& s, const std::vector<double>& node_depth_m, const RemeshOptions& opt);

/// The new profile of segment k alone, both edge nodes included, in the mill
/// frame. For callers that rebuild the ring from representative segments
/// (assemble_ring): it costs one segment's Boolean operations, not the ring's.
struct SegmentRemesh {
  std::vector<Eigen::Vector2d> nodes;
  RemeshStatus status = RemeshStatus::Ok;  // WornThrough if any node of the ring reached the shell
  int worn_through_segment = -1;
  double worn_through_angle_rad = 0;
  double removed_area_m2 = 0;   // [m2] old - new area of segment k
  double detached_area_m2 = 0;  // [m2]
  std::string message;
};
SegmentRemesh remesh_segment(const LinerSurface& s, const std::vector<double>& node_depth_m, int k,
                             const RemeshOptions& opt);

/// Element depths -> node depths: each node takes the length-weighted mean of
/// its two elements.
std::vector<double> element_to_node_depth(const LinerSurface& s, const std::vector<double>& element_depth_m);

/// remesh() with a recession depth per element.
RemeshResult remesh_elements(const LinerSurface& s, const std::vector<double>& element_depth_m,
                             const RemeshOptions& opt);

/// The surface with every node moved by node_depth_m along its offset
/// direction, no repair and no resampling: the cheap view of a slightly worn
/// surface between two remeshes (the forecast's right-hand side uses it).
LinerSurface displace_nodes(const LinerSurface& s, const std::vector<double>& node_depth_m, double max_miter = 2.0);

}  // namespace linerlife
