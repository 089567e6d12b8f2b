#include "geometry/resample.h"

#include <cmath>
#include <set>
#include <utility>

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
  // The vertices are removed one at a time, as a scan of them all would pick
  // each: the first degenerate one if there is one, else the one cutting off
  // the least triangle (the first of equals). Removing a vertex changes only
  // its two neighbours, so the candidates are kept in ordered sets and only
  // the neighbours looked at again: O(n log n). Before (2026-12-04) every
  // removal scanned the whole polyline again, O(n^2): a measured profile of
  // 50,000 points took seconds for each of its segments at every wear step.
  const int m = static_cast<int>(p.size());
  std::vector<int> prev(static_cast<size_t>(m)), next(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    prev[static_cast<size_t>(i)] = i - 1;
    next[static_cast<size_t>(i)] = i + 1;
  }
  std::set<int> degenerate;                   // vertices whose removal changes nothing
  std::set<std::pair<double, int>> removable;  // (triangle cut off, vertex)
  std::vector<double> key(static_cast<size_t>(m), -1);  // vertex's triangle in `removable`, -1: not in it
  auto classify = [&](int i) {
    degenerate.erase(i);
    if (key[static_cast<size_t>(i)] >= 0) removable.erase({key[static_cast<size_t>(i)], i});
    key[static_cast<size_t>(i)] = -1;
    const int ip = prev[static_cast<size_t>(i)], in = next[static_cast<size_t>(i)];
    if (ip < 0 || in >= m) return;  // an end is kept
    const V a = p[i] - p[ip], b = p[in] - p[i];
    const double la = a.norm(), lb = b.norm();
    const double merged = (p[in] - p[ip]).norm();
    const double signed_tri = 0.5 * (a.x() * b.y() - a.y() * b.x());  // > 0: vertex right of the chord
    // a degenerate element (shorter than 1e-6 h) always goes: the area it
    // can change, below 1e-6 h^2 / 2, is round-off against the liner's; so
    // does the 1e-6 h it adds to its neighbour (before, only where that kept
    // the neighbour within h: a pair of vertices 2e-15 m apart between two
    // elements of about h stayed, ran back on itself, and the next remesh
    // refused the ring as crossing itself, element_size_m = 0.002)
    if (std::min(la, lb) < 1e-6 * h) {
      degenerate.insert(i);
      return;
    }
    if (signed_tri > 0) return;
    const double tri = -signed_tri;
    const bool nearly_straight = la > 0 && lb > 0 && tri / (la * lb) * 2 < collinear && a.dot(b) > 0 && merged <= h;
    const bool short_and_small = std::min(la, lb) < min_len && tri < max_tri && merged <= h;
    if ((nearly_straight || short_and_small) && tri < 1e300) {
      removable.insert({tri, i});
      key[static_cast<size_t>(i)] = tri;
    }
  };
  for (int i = 1; i + 1 < m; ++i) classify(i);
  int left = m;
  while (left > 2 && (!degenerate.empty() || !removable.empty())) {
    const int i = !degenerate.empty() ? *degenerate.begin() : removable.begin()->second;
    degenerate.erase(i);
    if (key[static_cast<size_t>(i)] >= 0) removable.erase({key[static_cast<size_t>(i)], i});
    const int ip = prev[static_cast<size_t>(i)], in = next[static_cast<size_t>(i)];
    next[static_cast<size_t>(ip)] = in;
    prev[static_cast<size_t>(in)] = ip;
    --left;
    classify(ip);
    classify(in);
  }
  {
    std::vector<V> kept;
    kept.reserve(static_cast<size_t>(left));
    for (int i = 0; i < m; i = next[static_cast<size_t>(i)]) kept.push_back(p[i]);
    p.swap(kept);
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
