#include "geometry/resample.h"

#include <cmath>
#include <list>

namespace linerlife {

using V = Eigen::Vector2d;

std::vector<V> resample_polyline(const std::vector<V>& pts, double h) {
  std::vector<V> p;
  // drop exact duplicates first
  for (const V& q : pts)
    if (p.empty() || (q - p.back()).norm() > 1e-12 * h) p.push_back(q);
  if (p.size() >= 2 && (pts.back() - p.back()).norm() > 0) p.back() = pts.back();

  // A vertex is removed only if that takes material away or changes nothing:
  // the polyline runs anticlockwise with the charge on its left, so removing a
  // vertex that lies left of the chord joining its neighbours cuts off a
  // triangle of liner; one to the right would add liner material, which wear
  // never does.
  const double min_len = 0.3 * h, max_tri = 0.01 * h * h;
  const double collinear = std::sin(0.5 * 3.14159265358979323846 / 180.0);
  bool changed = true;
  while (changed && p.size() > 2) {
    changed = false;
    int best = -1;
    double best_tri = 1e300;
    for (size_t i = 1; i + 1 < p.size(); ++i) {
      const V a = p[i] - p[i - 1], b = p[i + 1] - p[i];
      const double la = a.norm(), lb = b.norm();
      const double merged = (p[i + 1] - p[i - 1]).norm();
      const double signed_tri = 0.5 * (a.x() * b.y() - a.y() * b.x());  // > 0: vertex right of the chord
      // a degenerate element (shorter than 1e-6 h) always goes: the area it
      // can change, below 1e-6 h^2 / 2, is round-off against the liner's
      if (std::min(la, lb) < 1e-6 * h && merged <= h) {
        best = static_cast<int>(i);
        break;
      }
      if (signed_tri > 0) continue;
      const double tri = -signed_tri;
      const bool nearly_straight = la > 0 && lb > 0 && tri / (la * lb) * 2 < collinear && a.dot(b) > 0 && merged <= h;
      const bool short_and_small = std::min(la, lb) < min_len && tri < max_tri && merged <= h;
      if ((nearly_straight || short_and_small) && tri < best_tri) {
        best_tri = tri;
        best = static_cast<int>(i);
      }
    }
    if (best > 0) {
      p.erase(p.begin() + best);
      changed = true;
    }
  }
  std::vector<V> out{p.front()};
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    // elements may stretch to 1.25 h under wear before they are split, so a
    // plate that recedes does not double its node count
    const double len = (p[i + 1] - p[i]).norm();
    const int n = len > 1.25 * h ? static_cast<int>(std::ceil(len / h - 1e-9)) : 1;
    for (int j = 1; j < n; ++j) out.push_back(p[i] + (p[i + 1] - p[i]) * (static_cast<double>(j) / n));
    out.push_back(p[i + 1]);
  }
  return out;
}

}  // namespace linerlife
