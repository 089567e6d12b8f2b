// lifter_grid.h - the thesis' 2D lifter discretisation (Arekar 2004, §5.6,
// Fig. 5-10, eqs. 5.29-5.30) as material bookkeeping behind the surface.
//
// An nx x ny grid of rectangular cells covers one lifter in a local Cartesian
// frame: origin on the shell at the lifter centreline, x tangential (pointing
// anticlockwise), y radial towards the mill axis (height above the shell).
// Each cell holds the share of its area that is still liner material; its
// mass is rho dx dy L times that share (eq. 5.29). The plate outside the grid
// is bookkept per surface element (the thesis' 1D plate elements) as the rest
// of the segment's area. The surface stays the boundary of what is left.
#pragma once

#include <vector>

#include "geometry/liner_surface.h"

namespace linerlife {

struct LifterGridSpec {
  int segment = 0;
  int nx = 0, ny = 0;
  double x0 = 0, y0 = 0;  // [m] lower-left corner of the grid (local frame)
  double dx = 0, dy = 0;  // [m] cell size (eq. 5.30: width / nx, height / ny)
};

struct LifterGrid {
  LifterGridSpec spec;
  std::vector<double> fraction;   // ny rows of nx cells, row j = heights [y0 + j dy, y0 + (j+1) dy]
  double grid_area_m2 = 0;        // [m2] material inside the grid
  double plate_area_m2 = 0;       // [m2] material of the segment outside the grid
  double fraction_at(int i, int j) const { return fraction[static_cast<size_t>(j) * spec.nx + i]; }
  /// eq. 5.29: m = rho dx dy L times the share of the cell left [kg]
  double cell_mass_kg(int i, int j, double density_kg_m3, double length_m) const {
    return density_kg_m3 * spec.dx * spec.dy * length_m * fraction_at(i, j);
  }
};

/// A grid of n x n cells over the lifter of segment k of a new surface: from
/// the shell (y = 0) to the crest, across the lifter base (where the liner is
/// thicker than the plate by more than 1 % of the lifter height) plus one cell.
LifterGridSpec lifter_grid_spec(const LinerSurface& s, int k, int n);

/// The shares of material left in each cell of `spec` for the (possibly worn)
/// surface s, by clipping the segment's liner body against each cell.
LifterGrid fill_lifter_grid(const LifterGridSpec& spec, const LinerSurface& s);

}  // namespace linerlife
