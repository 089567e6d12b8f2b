// wall_mesh.h - rigid walls for the 2D DEM: a polyline of straight elements
// fixed in a body frame that turns about the origin (the liner surface turning
// with the mill, or a resting test box), with a uniform grid that lists, per
// grid cell, the elements a disc centred in that cell can touch.
//
// Orientation (as LinerSurface): travelling from node i to node i + 1 the
// particles are on the left; the unit normal of an element points into the
// particle side. A node where the wall turns right is convex (a lifter crest
// corner): a disc can touch the node itself. A node where it turns left is
// concave (a lifter foot, the curved shell): the two faces meet the disc, the
// node never does.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/liner_surface.h"

namespace linerlife {

struct WallMesh {
  bool closed = true;
  // Per element, body frame (SoA for the contact loop):
  std::vector<double> ax, ay;    // [m] start node
  std::vector<double> ux, uy;    // [-] unit tangent, start -> end
  std::vector<double> nx, ny;    // [-] unit normal into the particle side
  std::vector<double> len;       // [m]
  std::vector<int> prev, next;   // neighbour elements; -1 at the ends of an open chain
  std::vector<char> convex_start;  // a disc can touch the start node (convex, or the free end of an open chain)
  std::vector<char> convex_end;    // the end node of the last element of an open chain
  std::vector<char> merge_next;  // the node shared with `next` is concave by less than merge_angle_deg:
                                 // contacts with both faces are one contact (the deeper is kept)
  double min_radius = 0;         // [m] distance from the origin to the nearest wall point: a disc
                                 //     centred closer than min_radius - radius touches no wall
  double max_radius = 0;         // [m] farthest node from the origin

  // Candidate grid (body frame): cell (cx, cy) lists elements within `reach` of the cell.
  double grid_x0 = 0, grid_y0 = 0, cell = 0;
  int grid_nx = 0, grid_ny = 0;
  double reach = 0;              // [m] largest disc radius the grid serves
  std::vector<int> cell_start;   // size nx * ny + 1
  std::vector<int> cell_elems;

  int n_elements() const { return static_cast<int>(ax.size()); }
  /// The grid cell holding body-frame point (qx, qy), -1 outside the grid.
  int cell_of(double qx, double qy) const {
    const double fx = (qx - grid_x0) / cell, fy = (qy - grid_y0) / cell;
    if (!(fx >= 0 && fy >= 0 && fx < grid_nx && fy < grid_ny)) return -1;
    return static_cast<int>(fy) * grid_nx + static_cast<int>(fx);
  }
  /// Number of elements between a and b along the chain (cyclic for closed meshes).
  int chain_distance(int a, int b) const;
};

/// A wall from the nodes of a polyline (closed: the last node joins the first).
/// Zero-length elements are kept (so indices match) but never touched.
WallMesh make_wall_mesh(const std::vector<Eigen::Vector2d>& nodes, bool closed, double merge_angle_deg = 20.0);

/// The liner surface as a wall; element i is LinerSurface element i.
WallMesh make_wall_mesh(const LinerSurface& surface, double merge_angle_deg = 20.0);

/// Builds the candidate grid for discs of radius up to `reach` [m] with cells
/// of size `cell` [m], covering the nodes' bounding box plus reach.
void build_wall_grid(WallMesh& w, double reach, double cell);

}  // namespace linerlife
