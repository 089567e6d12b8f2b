// liner_surface.h - the liner as the charge sees it: a closed polyline round
// the whole ring, split into straight surface elements.
//
// Nodes run anticlockwise round the mill axis (mill frame, DESIGN.md §3);
// element i joins nodes[i] to nodes[(i + 1) % n]. The liner body lies outside
// the polyline (towards the shell), the charge inside. Segment k (one lifter
// row) owns the elements segment_begin[k] .. segment_begin[k + 1] - 1 and spans
// the angles [segment_start_rad(k), segment_start_rad(k + 1)]; its first node
// lies on the radial line at its start angle, in the middle of the plate
// between two lifters. Lifter k is centred on angle k * 2 pi / segments.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace linerlife {

struct LinerSurface {
  double shell_radius_m = 0;            // [m] inside radius of the shell
  int segments = 0;                     // lifter rows
  std::vector<Eigen::Vector2d> nodes;   // [m] mill frame, anticlockwise
  std::vector<int> segment_begin;       // size segments + 1; segment_begin[segments] == nodes.size()
  std::vector<int> segment_design;      // design index of each segment (0 high, 1 low of a hi-lo)

  // Derived per element by finalize(); do not edit by hand.
  std::vector<double> length;           // [m]
  std::vector<Eigen::Vector2d> normal;  // unit, from the liner into the mill interior
  std::vector<Eigen::Vector2d> midpoint;  // [m]
  std::vector<int> element_segment;     // segment of each element

  int n_elements() const { return static_cast<int>(nodes.size()); }
  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int next(int i) const { return i + 1 == n_nodes() ? 0 : i + 1; }
  int prev(int i) const { return i == 0 ? n_nodes() - 1 : i - 1; }
  double segment_angle_rad() const;              // 2 pi / segments
  double segment_start_rad(int k) const;         // (k - 1/2) * segment angle
  double segment_centre_rad(int k) const;        // k * segment angle
  int segment_of_angle(double theta_rad) const;  // the segment whose span holds theta
  /// Element count of segment k.
  int segment_size(int k) const { return segment_begin[k + 1] - segment_begin[k]; }

  /// Recomputes length, normal, midpoint and element_segment from nodes and
  /// segment_begin. Call after any change of the nodes.
  void finalize();
};

/// Recession direction of every node: into the liner body, against the
/// inward normals of its two elements (their normalised mean), scaled by the
/// miter factor 1 / cos(half the turn) (capped at max_miter) so that a node
/// moved by depth * direction offsets both adjacent elements by exactly depth.
/// Nodes on a segment edge recede radially so segments keep their angular span.
std::vector<Eigen::Vector2d> node_offset_directions(const LinerSurface& s, double max_miter = 2.0);

}  // namespace linerlife
