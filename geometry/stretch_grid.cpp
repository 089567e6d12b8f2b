#include "geometry/stretch_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace linerlife {

StretchGrid::StretchGrid(const std::vector<Eigen::Vector2d>& pts, double pad) {
  const int n = static_cast<int>(pts.size());
  const int ns = std::max(0, n - 1);
  double total = 0, max_abs = 0, x_min = 0, y_min = 0;
  bool finite = true;
  for (int i = 0; i < n; ++i) {
    finite = finite && std::isfinite(pts[i].x()) && std::isfinite(pts[i].y());
    max_abs = std::max({max_abs, std::abs(pts[i].x()), std::abs(pts[i].y())});
    x_min = i == 0 ? pts[i].x() : std::min(x_min, pts[i].x());
    y_min = i == 0 ? pts[i].y() : std::min(y_min, pts[i].y());
    if (i > 0) total += (pts[i] - pts[i - 1]).norm();
  }
  double c = ns > 0 ? std::max(total / ns, 2 * pad) : 1.0;
  // the thickening: pad plus the round-off of the checks that use the grid
  // (their touch tolerances are below 1e-13 of the coordinates) and of the
  // pieces a long stretch is cut into
  const double grow = pad + 1e-9 * c + 1e-12 * max_abs + 1e-14;
  const double x0 = x_min - grow - c, y0 = y_min - grow - c;
  // a polyline spans at most its length, so a cell index stays below about n;
  // non-finite input (or a length beyond a double) puts everything in one cell,
  // where every pair is looked at as without a grid
  const bool one_cell = !finite || !(c > 0) || !std::isfinite(c) || !std::isfinite(grow) ||
                        !(total / c < 4.0 * ns + 16) || !std::isfinite(x0) || !std::isfinite(y0);
  if (one_cell) c = 1.0;
  auto ix = [&](double x) { return one_cell ? int64_t{0} : static_cast<int64_t>(std::floor((x - x0) / c)); };
  auto iy = [&](double y) { return one_cell ? int64_t{0} : static_cast<int64_t>(std::floor((y - y0) / c)); };
  int64_t nx = 1, ny = 1;
  if (!one_cell)
    for (int i = 0; i < n; ++i) {
      nx = std::max(nx, ix(pts[i].x() + grow) + 2);
      ny = std::max(ny, iy(pts[i].y() + grow) + 2);
    }
  one_cell_ = one_cell;
  x0_ = x0;
  y0_ = y0;
  c_ = c;
  nx_ = nx;
  ny_ = ny;
  auto key = [&](int64_t a, int64_t b) { return a * ny + b; };

  // the cells of each stretch: its pieces no longer than a cell, each thickened
  std::vector<int64_t> keys_of_stretches;  // per stretch, sorted and unique
  stretch_cells_begin_.assign(static_cast<size_t>(ns) + 1, 0);
  std::vector<int64_t> mine;
  for (int s = 0; s < ns; ++s) {
    mine.clear();
    const Eigen::Vector2d a = pts[s], b = pts[s + 1];
    const double len = (b - a).norm();
    const int64_t pieces = one_cell ? 1 : std::max<int64_t>(1, static_cast<int64_t>(std::ceil(len / c)));
    Eigen::Vector2d p = a;
    for (int64_t m = 1; m <= pieces; ++m) {
      const Eigen::Vector2d q = m == pieces ? b : Eigen::Vector2d(a + (b - a) * (static_cast<double>(m) / pieces));
      const int64_t i0 = ix(std::min(p.x(), q.x()) - grow), i1 = ix(std::max(p.x(), q.x()) + grow);
      const int64_t j0 = iy(std::min(p.y(), q.y()) - grow), j1 = iy(std::max(p.y(), q.y()) + grow);
      for (int64_t i = i0; i <= i1; ++i)
        for (int64_t j = j0; j <= j1; ++j) mine.push_back(key(i, j));
      p = q;
    }
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    keys_of_stretches.insert(keys_of_stretches.end(), mine.begin(), mine.end());
    stretch_cells_begin_[static_cast<size_t>(s) + 1] = static_cast<int64_t>(keys_of_stretches.size());
  }
  std::vector<int64_t> point_keys(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) point_keys[static_cast<size_t>(i)] = key(ix(pts[i].x()), iy(pts[i].y()));

  // number the cells that hold a stretch (a point elsewhere is near none)
  std::vector<int64_t> cells = keys_of_stretches;
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  auto cell_of = [&](int64_t k) {
    const auto it = std::lower_bound(cells.begin(), cells.end(), k);
    return it != cells.end() && *it == k ? static_cast<int>(it - cells.begin()) : -1;
  };
  keys_ = cells;
  const size_t nc = cells.size();
  stretch_cells_.resize(keys_of_stretches.size());
  cell_stretch_begin_.assign(nc + 1, 0);
  for (size_t k = 0; k < keys_of_stretches.size(); ++k) {
    stretch_cells_[k] = cell_of(keys_of_stretches[k]);
    ++cell_stretch_begin_[static_cast<size_t>(stretch_cells_[k]) + 1];
  }
  for (size_t c2 = 0; c2 < nc; ++c2) cell_stretch_begin_[c2 + 1] += cell_stretch_begin_[c2];
  stretch_ids_.resize(keys_of_stretches.size());
  std::vector<int64_t> fill(cell_stretch_begin_.begin(), cell_stretch_begin_.end() - 1);
  for (int s = 0; s < ns; ++s)  // in increasing s: every cell's list comes out sorted
    for (int64_t k = stretch_cells_begin_[s]; k < stretch_cells_begin_[s + 1]; ++k)
      stretch_ids_[static_cast<size_t>(fill[static_cast<size_t>(stretch_cells_[k])]++)] = s;

  std::vector<int> point_cell(static_cast<size_t>(n));
  cell_point_begin_.assign(nc + 1, 0);
  for (int i = 0; i < n; ++i) {
    point_cell[static_cast<size_t>(i)] = cell_of(point_keys[static_cast<size_t>(i)]);
    if (point_cell[static_cast<size_t>(i)] >= 0) ++cell_point_begin_[static_cast<size_t>(point_cell[i]) + 1];
  }
  for (size_t c2 = 0; c2 < nc; ++c2) cell_point_begin_[c2 + 1] += cell_point_begin_[c2];
  point_ids_.resize(static_cast<size_t>(cell_point_begin_[nc]));
  fill.assign(cell_point_begin_.begin(), cell_point_begin_.end() - 1);
  for (int i = 0; i < n; ++i)
    if (point_cell[static_cast<size_t>(i)] >= 0)
      point_ids_[static_cast<size_t>(fill[static_cast<size_t>(point_cell[i])]++)] = i;
}

}  // namespace linerlife
