// stretch_grid.h - a uniform grid that buckets the stretches and points of an
// open polyline by cell, so that the checks of every point against every
// stretch (measured_profile.cpp: crossings, detail finer than 0.01 mm) look
// only at neighbours instead of at all n^2 pairs.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace linerlife {

/// The stretches (points i to i + 1) and the points of an open polyline,
/// bucketed in square cells.
///
/// Inputs: `pts` (n >= 2 points, all finite) [m, any frame] and `pad` >= 0 [m].
/// A stretch is listed in every cell that meets the stretch thickened by
/// `pad` plus a round-off slack (1e-9 of the cell size plus 1e-12 of the largest
/// coordinate): every point nearer than `pad` to a stretch, and every stretch
/// that touches it, share a cell with it. A point is listed in the one cell
/// that holds it. Cell lists are in increasing index order.
///
/// Cell size: the mean stretch length, at least 2 pad (at most about 9 cells
/// per mean-length piece of a stretch; a stretch k times the mean meets about
/// 3 k cells). Memory and building time are O(n + total length / cell); a
/// query visits the stretches and points near its own, which for a profile
/// whose stretches are not packed much closer than their length (any scan or
/// drawing: points a few mm apart, or densely resampled) is a handful.
class StretchGrid {
 public:
  StretchGrid(const std::vector<Eigen::Vector2d>& pts, double pad);

  /// Calls f(cell) for each cell stretch `s` is listed in (once per cell, in
  /// increasing cell order). A cell is a range of stretch indices
  /// (stretches_in) or point indices (points_in).
  template <class F>
  void for_each_cell_of_stretch(int s, F&& f) const {
    for (int64_t k = stretch_cells_begin_[s]; k < stretch_cells_begin_[s + 1]; ++k) f(stretch_cells_[k]);
  }

  /// The stretches listed in cell `c` (an index from for_each_cell_of_stretch),
  /// in increasing order: [first, last).
  std::pair<const int*, const int*> stretches_in(int c) const {
    return {stretch_ids_.data() + cell_stretch_begin_[c], stretch_ids_.data() + cell_stretch_begin_[c + 1]};
  }
  /// The points that lie in cell `c`, in increasing order: [first, last).
  std::pair<const int*, const int*> points_in(int c) const {
    return {point_ids_.data() + cell_point_begin_[c], point_ids_.data() + cell_point_begin_[c + 1]};
  }

  /// [m] The side of a cell.
  double cell_size() const { return c_; }

  /// Calls f(s) for every stretch s listed in a cell that meets the box
  /// [x_lo, x_hi] x [y_lo, y_hi] (a stretch may come more than once): every
  /// stretch that passes through the box is among them. Returns whether the
  /// box covered every cell (then every stretch came).
  template <class F>
  bool for_each_stretch_in_box(double x_lo, double x_hi, double y_lo, double y_hi, F&& f) const {
    const int64_t i0 = std::max<int64_t>(0, cell_x(x_lo)), i1 = std::min(nx_ - 1, cell_x(x_hi));
    const int64_t j0 = std::max<int64_t>(0, cell_y(y_lo)), j1 = std::min(ny_ - 1, cell_y(y_hi));
    for (int64_t i = i0; i <= i1; ++i)
      for (int64_t j = j0; j <= j1; ++j) {
        const auto it = std::lower_bound(keys_.begin(), keys_.end(), i * ny_ + j);
        if (it == keys_.end() || *it != i * ny_ + j) continue;
        const int c = static_cast<int>(it - keys_.begin());
        for (int64_t k = cell_stretch_begin_[c]; k < cell_stretch_begin_[c + 1]; ++k) f(stretch_ids_[k]);
      }
    return i0 == 0 && j0 == 0 && i1 == nx_ - 1 && j1 == ny_ - 1;
  }

 private:
  // the cell column and row of a coordinate; clamped so that any double, even
  // far outside the grid, gives a number in [-1, nx_] or [-1, ny_]
  int64_t cell_x(double x) const {
    if (one_cell_) return 0;
    const double f = std::floor((x - x0_) / c_);
    return !(f >= 0) ? -1 : f >= static_cast<double>(nx_) ? nx_ : static_cast<int64_t>(f);
  }
  int64_t cell_y(double y) const {
    if (one_cell_) return 0;
    const double f = std::floor((y - y0_) / c_);
    return !(f >= 0) ? -1 : f >= static_cast<double>(ny_) ? ny_ : static_cast<int64_t>(f);
  }

  bool one_cell_ = false;
  double x0_ = 0, y0_ = 0, c_ = 1;  // [m] the corner of cell (0, 0) and the cell size
  int64_t nx_ = 1, ny_ = 1;         // columns and rows
  std::vector<int64_t> keys_;       // column * ny_ + row of each cell, increasing
  std::vector<int64_t> stretch_cells_begin_;  // stretch s: cells stretch_cells_[begin[s] .. begin[s + 1])
  std::vector<int> stretch_cells_;            // compact cell numbers
  std::vector<int64_t> cell_stretch_begin_;   // cell c: stretch_ids_[begin[c] .. begin[c + 1])
  std::vector<int> stretch_ids_;
  std::vector<int64_t> cell_point_begin_;     // cell c: point_ids_[begin[c] .. begin[c + 1])
  std::vector<int> point_ids_;
};

}  // namespace linerlife
