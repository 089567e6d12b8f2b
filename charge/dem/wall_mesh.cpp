#include "charge/dem/wall_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linerlife {

int WallMesh::chain_distance(int a, int b) const {
  const int d = std::abs(a - b);
  return closed ? std::min(d, n_elements() - d) : d;
}

WallMesh make_wall_mesh(const std::vector<Eigen::Vector2d>& nodes, bool closed, double merge_angle_deg) {
  WallMesh w;
  w.closed = closed;
  const int nn = static_cast<int>(nodes.size());
  const int ne = closed ? nn : nn - 1;
  w.ax.resize(ne), w.ay.resize(ne), w.ux.resize(ne), w.uy.resize(ne), w.nx.resize(ne), w.ny.resize(ne);
  w.len.resize(ne), w.prev.resize(ne), w.next.resize(ne);
  w.convex_start.assign(ne, 0), w.convex_end.assign(ne, 0), w.merge_next.assign(ne, 0);
  for (int e = 0; e < ne; ++e) {
    const Eigen::Vector2d a = nodes[e], b = nodes[(e + 1) % nn];
    const Eigen::Vector2d d = b - a;
    const double l = d.norm();
    w.ax[e] = a.x(), w.ay[e] = a.y();
    w.len[e] = l;
    const Eigen::Vector2d u = l > 0 ? Eigen::Vector2d(d / l) : Eigen::Vector2d(1, 0);
    w.ux[e] = u.x(), w.uy[e] = u.y();
    w.nx[e] = -u.y(), w.ny[e] = u.x();  // tangent turned +90 deg: the left side
    w.prev[e] = e > 0 ? e - 1 : (closed ? ne - 1 : -1);
    w.next[e] = e + 1 < ne ? e + 1 : (closed ? 0 : -1);
  }
  // Zero-length elements carry the neighbours' direction for the vertex tests.
  for (int e = 0; e < ne; ++e) {
    if (w.len[e] > 0) continue;
    int k = w.next[e];
    while (k >= 0 && k != e && w.len[k] == 0) k = w.next[k];
    if (k >= 0 && k != e) w.ux[e] = w.ux[k], w.uy[e] = w.uy[k], w.nx[e] = w.nx[k], w.ny[e] = w.ny[k];
  }
  const double cos_merge = std::cos(merge_angle_deg * 3.14159265358979323846 / 180.0);
  for (int e = 0; e < ne; ++e) {
    const int p = w.prev[e];
    if (p < 0) {
      w.convex_start[e] = 1;  // free end
    } else {
      const double turn = w.ux[p] * w.uy[e] - w.uy[p] * w.ux[e];  // cross(u_prev, u): < 0 turns right
      w.convex_start[e] = turn < -1e-12;
    }
    if (w.next[e] < 0) w.convex_end[e] = 1;
    const int q = w.next[e];
    if (q >= 0) {
      const double turn = w.ux[e] * w.uy[q] - w.uy[e] * w.ux[q];
      const double dot = w.nx[e] * w.nx[q] + w.ny[e] * w.ny[q];
      w.merge_next[e] = turn >= -1e-12 && dot > cos_merge;
    }
  }
  w.min_radius = std::numeric_limits<double>::max();
  for (int e = 0; e < ne; ++e) {
    const double t = std::clamp(-(w.ax[e] * w.ux[e] + w.ay[e] * w.uy[e]), 0.0, w.len[e]);
    w.min_radius = std::min(w.min_radius, std::hypot(w.ax[e] + t * w.ux[e], w.ay[e] + t * w.uy[e]));
  }
  for (const auto& p : nodes) w.max_radius = std::max(w.max_radius, p.norm());
  if (ne == 0) w.min_radius = 0;
  return w;
}

WallMesh make_wall_mesh(const LinerSurface& surface, double merge_angle_deg) {
  return make_wall_mesh(surface.nodes, true, merge_angle_deg);
}

void build_wall_grid(WallMesh& w, double reach, double cell) {
  const int ne = w.n_elements();
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (int e = 0; e < ne; ++e) {
    const double bx = w.ax[e] + w.ux[e] * w.len[e], by = w.ay[e] + w.uy[e] * w.len[e];
    x0 = std::min({x0, w.ax[e], bx}), x1 = std::max({x1, w.ax[e], bx});
    y0 = std::min({y0, w.ay[e], by}), y1 = std::max({y1, w.ay[e], by});
  }
  w.reach = reach;
  w.cell = cell;
  w.grid_x0 = x0 - reach - cell;
  w.grid_y0 = y0 - reach - cell;
  w.grid_nx = static_cast<int>(std::ceil((x1 - x0 + 2 * reach + 2 * cell) / cell));
  w.grid_ny = static_cast<int>(std::ceil((y1 - y0 + 2 * reach + 2 * cell) / cell));
  const int nc = w.grid_nx * w.grid_ny;
  // Element e goes into every cell whose square comes within `reach` of it:
  // tested conservatively as segment-to-centre distance <= reach + half diagonal.
  const double r_test = reach + 0.5 * std::sqrt(2.0) * cell;
  std::vector<std::vector<int>> lists(nc);
  for (int e = 0; e < ne; ++e) {
    if (w.len[e] <= 0) continue;
    const double ax = w.ax[e], ay = w.ay[e], bx = ax + w.ux[e] * w.len[e], by = ay + w.uy[e] * w.len[e];
    const int cx0 = std::max(0, static_cast<int>(std::floor((std::min(ax, bx) - r_test - w.grid_x0) / cell)));
    const int cx1 = std::min(w.grid_nx - 1, static_cast<int>(std::floor((std::max(ax, bx) + r_test - w.grid_x0) / cell)));
    const int cy0 = std::max(0, static_cast<int>(std::floor((std::min(ay, by) - r_test - w.grid_y0) / cell)));
    const int cy1 = std::min(w.grid_ny - 1, static_cast<int>(std::floor((std::max(ay, by) + r_test - w.grid_y0) / cell)));
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) {
        const double px = w.grid_x0 + (cx + 0.5) * cell, py = w.grid_y0 + (cy + 0.5) * cell;
        double t = (px - ax) * w.ux[e] + (py - ay) * w.uy[e];
        t = std::clamp(t, 0.0, w.len[e]);
        const double dx = px - (ax + t * w.ux[e]), dy = py - (ay + t * w.uy[e]);
        if (dx * dx + dy * dy <= r_test * r_test) lists[cy * w.grid_nx + cx].push_back(e);
      }
  }
  w.cell_start.assign(nc + 1, 0);
  for (int c = 0; c < nc; ++c) w.cell_start[c + 1] = w.cell_start[c] + static_cast<int>(lists[c].size());
  w.cell_elems.resize(w.cell_start[nc]);
  for (int c = 0; c < nc; ++c) std::copy(lists[c].begin(), lists[c].end(), w.cell_elems.begin() + w.cell_start[c]);
}

}  // namespace linerlife
