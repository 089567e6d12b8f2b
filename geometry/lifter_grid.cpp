#include "geometry/lifter_grid.h"

#include <algorithm>
#include <cmath>

#include "geometry/metrics.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;

/// The liner body of segment k in the local lifter frame, as a closed polygon
/// (surface, then the shell arc back), with the shell sampled finely.
std::vector<V> local_body(const LinerSurface& s, int k, double h) {
  const double R = s.shell_radius_m, c = s.segment_centre_rad(k);
  const double cs = std::cos(c), sn = std::sin(c);
  auto local = [&](const V& p) {
    // rotate by -c: the lifter centreline becomes +x; local y = R - x_rot, local x = y_rot
    const double xr = cs * p.x() + sn * p.y(), yr = -sn * p.x() + cs * p.y();
    return V(yr, R - xr);
  };
  std::vector<V> out;
  const int n = s.n_nodes();
  for (int i = s.segment_begin[k]; i <= s.segment_begin[k + 1]; ++i) out.push_back(local(s.nodes[i % n]));
  const double th0 = s.segment_start_rad(k), th1 = s.segment_start_rad(k + 1);
  const int narc = std::max(8, static_cast<int>(std::ceil((th1 - th0) * R / h)));
  for (int j = narc; j >= 0; --j) {
    const double th = th0 + (th1 - th0) * j / narc;
    out.push_back(local(V(R * std::cos(th), R * std::sin(th))));
  }
  return out;
}

double polygon_area(const std::vector<V>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const V& u = p[i];
    const V& w = p[(i + 1) % p.size()];
    a += u.x() * w.y() - u.y() * w.x();
  }
  return 0.5 * a;
}

/// Sutherland-Hodgman clipping of a (possibly non-convex) polygon by the
/// axis-aligned rectangle [x0, x1] x [y0, y1]; the area of the result is exact.
double clipped_area(const std::vector<V>& poly, double x0, double x1, double y0, double y1) {
  std::vector<V> in = poly, out;
  auto clip = [&](auto inside, auto cut) {
    out.clear();
    for (size_t i = 0; i < in.size(); ++i) {
      const V& a = in[i];
      const V& b = in[(i + 1) % in.size()];
      const bool ia = inside(a), ib = inside(b);
      if (ia) out.push_back(a);
      if (ia != ib) out.push_back(cut(a, b));
    }
    in.swap(out);
  };
  auto cut_x = [](double x) { return [x](const V& a, const V& b) { return V(x, a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x())); }; };
  auto cut_y = [](double y) { return [y](const V& a, const V& b) { return V(a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()), y); }; };
  clip([&](const V& p) { return p.x() >= x0; }, cut_x(x0));
  if (in.empty()) return 0;
  clip([&](const V& p) { return p.x() <= x1; }, cut_x(x1));
  if (in.empty()) return 0;
  clip([&](const V& p) { return p.y() >= y0; }, cut_y(y0));
  if (in.empty()) return 0;
  clip([&](const V& p) { return p.y() <= y1; }, cut_y(y1));
  if (in.size() < 3) return 0;
  return std::abs(polygon_area(in));
}

}  // namespace

LifterGridSpec lifter_grid_spec(const LinerSurface& s, int k, int n) {
  const double R = s.shell_radius_m;
  std::vector<V> body = local_body(s, k, s.segment_angle_rad() * R / 200.0);
  const int m = s.segment_size(k) + 1;  // the surface part of the body polygon
  // the lifter base: where the radial thickness exceeds the plate (the
  // thickness at the segment edges) by more than 1 % of the lifter height
  std::vector<double> t(m);
  for (int i = 0; i < m; ++i) t[i] = R - s.nodes[(s.segment_begin[k] + i) % s.n_nodes()].norm();
  const double ref = 0.5 * (t.front() + t.back());
  const double tmax = *std::max_element(t.begin(), t.end());
  const double thresh = ref + 0.01 * (tmax - ref);
  double xl = 0, xr = 0, top = 0;
  for (int i = 0; i < m; ++i)
    if (t[i] > thresh) {
      xl = std::min(xl, body[i].x());
      xr = std::max(xr, body[i].x());
      top = std::max(top, body[i].y());
    }
  LifterGridSpec g;
  g.segment = k;
  g.nx = g.ny = n;
  const double w = xr - xl;
  g.y0 = 0;
  if (w > 0) {
    g.dx = w / (n - 1);  // one extra cell's width so the base is fully inside
    g.x0 = xl - 0.5 * g.dx;
    g.dy = top / n;
  } else {  // no lifter: a grid over the middle half of the plate
    const double half = 0.25 * s.segment_angle_rad() * R;
    g.dx = 2 * half / n;
    g.x0 = -half;
    g.dy = std::max(tmax, 1e-9) / n;
  }
  return g;
}

LifterGrid fill_lifter_grid(const LifterGridSpec& spec, const LinerSurface& s) {
  LifterGrid g;
  g.spec = spec;
  g.fraction.assign(static_cast<size_t>(spec.nx) * spec.ny, 0.0);
  const double h = s.segment_angle_rad() * s.shell_radius_m / 400.0;
  const std::vector<V> body = local_body(s, spec.segment, h);
  const double cell = spec.dx * spec.dy;
  for (int j = 0; j < spec.ny; ++j)
    for (int i = 0; i < spec.nx; ++i) {
      const double x0 = spec.x0 + i * spec.dx, y0 = spec.y0 + j * spec.dy;
      const double a = clipped_area(body, x0, x0 + spec.dx, y0, y0 + spec.dy);
      g.fraction[static_cast<size_t>(j) * spec.nx + i] = std::clamp(a / cell, 0.0, 1.0);
      g.grid_area_m2 += a;
    }
  // material of the segment outside the grid: the whole body area (exact, by
  // the sector formula) minus what the grid holds; the fine polygonal shell
  // used for clipping only enters through cells that reach the shell.
  g.plate_area_m2 = segment_area(s, spec.segment) - g.grid_area_m2;
  return g;
}

}  // namespace linerlife
