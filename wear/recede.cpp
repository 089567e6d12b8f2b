#include "wear/recede.h"

#include <cmath>
#include <stdexcept>

#include "geometry/measured_profile.h"
#include "geometry/metrics.h"
#include "geometry/resample.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;

/// Angle of p relative to `start`, in [0, 2 pi).
double angle_from(const V& p, double start) {
  double a = std::atan2(p.y(), p.x()) - start;
  a = std::fmod(a, 2 * M_PI);
  return a < 0 ? a + 2 * M_PI : a;
}

}  // namespace

/// Offset direction of node i (geometry's node_offset_directions, for one node).
V offset_direction(const LinerSurface& s, int i, const std::vector<char>& edge, double max_miter) {
  if (edge[i]) return s.nodes[i].normalized();  // segment edges recede radially
  const V a = -s.normal[s.prev(i)], b = -s.normal[i];
  V m = a + b;
  const double mn = m.norm();
  if (mn < 1e-12) return b;
  m /= mn;
  return m / std::max(m.dot(b), 1.0 / max_miter);
}

bool recede_segments(const LinerSurface& s, const std::vector<double>& depth, const RemeshOptions& opt,
                     const std::vector<int>& segments, std::vector<std::vector<Eigen::Vector2d>>& chains) {
  const int n = s.n_nodes();
  const double rmax = s.shell_radius_m - opt.min_thickness_m;
  const double h = opt.element_size_m;
  std::vector<char> edge(static_cast<size_t>(n), 0);
  for (int k = 0; k < s.segments; ++k) edge[s.segment_begin[k]] = 1;
  chains.assign(segments.size(), {});
  int repairs = 0;
  for (size_t si = 0; si < segments.size(); ++si) {
    const int k = segments[si];
    const int b = s.segment_begin[k], e = s.segment_begin[k + 1];  // e may equal n
    std::vector<V>& c = chains[si];
    std::vector<V> old;
    for (int i = b; i <= e; ++i) {
      const int j = i % n;
      old.push_back(s.nodes[j]);
      c.push_back(depth[j] > 0 ? V(s.nodes[j] + depth[j] * offset_direction(s, j, edge, opt.max_miter)) : s.nodes[j]);
    }
    const double th0 = s.segment_start_rad(k), span = s.segment_angle_rad();
    for (int q = 0; q < static_cast<int>(c.size()); ++q) {
      const V& p = c[q];
      if (p.norm() > rmax) return false;  // wear through: remesh() reports it
      if (q > 0 && q + 1 < static_cast<int>(c.size())) {
        const double a = angle_from(p, th0);
        if (!(a > 0 && a < span)) return false;  // left its segment
      }
      if (q + 1 < static_cast<int>(c.size()) && !((old[q + 1] - old[q]).dot(c[q + 1] - p) > 0)) {
        // An element turned over: a short element at a worn convex corner whose offset makes a
        // small swallowtail. The envelope remesh() keeps runs along the neighbouring elements to
        // the point where they cross; put the corner there and drop the flipped element.
        if (q == 0 || q + 2 >= static_cast<int>(c.size())) return false;
        const V d1 = c[q] - c[q - 1], d2 = c[q + 2] - c[q + 1];
        const double den = d1.x() * d2.y() - d1.y() * d2.x();
        if (std::abs(den) < 1e-12 * d1.norm() * d2.norm()) return false;
        const V w = c[q + 1] - c[q - 1];
        const double t1 = (w.x() * d2.y() - w.y() * d2.x()) / den;   // along d1 from c[q - 1]
        const double t2 = (w.x() * d1.y() - w.y() * d1.x()) / den;   // along d2 from c[q + 1]
        if (!(t1 > 0 && t1 < 2 && t2 > -1 && t2 < 1)) return false;  // not a small swallowtail
        c[q] = c[q - 1] + t1 * d1;
        c.erase(c.begin() + q + 1);
        old.erase(old.begin() + q + 1);
        if (++repairs > 8) return false;
        q = std::max(-1, q - 2);  // check the neighbourhood again
      }
    }
    if (polyline_self_intersects(c)) return false;  // a loop: remesh() cuts it away
    c = resample_polyline(c, h);
  }
  return true;
}

RemeshResult recede(const LinerSurface& s, const std::vector<double>& depth, const RemeshOptions& opt, bool* fast) {
  const int n = s.n_nodes();
  if (static_cast<int>(depth.size()) != n) throw std::invalid_argument("recede: one depth per node expected");
  for (double d : depth)
    if (!(d >= 0) || !std::isfinite(d)) throw std::invalid_argument("recede: depths must be finite and >= 0");
  if (fast) *fast = false;
  std::vector<int> moving;
  for (int k = 0; k < s.segments; ++k) {
    bool moves = false;
    for (int i = s.segment_begin[k]; i <= s.segment_begin[k + 1] && !moves; ++i) moves = depth[i % n] > 0;
    if (moves) moving.push_back(k);
  }
  std::vector<std::vector<V>> chains;
  if (!recede_segments(s, depth, opt, moving, chains)) return remesh(s, depth, opt);
  RemeshResult res;
  LinerSurface& out = res.surface;
  out.shell_radius_m = s.shell_radius_m;
  out.segments = s.segments;
  out.segment_design = s.segment_design;
  out.nodes.reserve(s.nodes.size() + 16);
  size_t next = 0;
  for (int k = 0; k < s.segments; ++k) {
    out.segment_begin.push_back(out.n_nodes());
    if (next < moving.size() && moving[next] == k) {
      out.nodes.insert(out.nodes.end(), chains[next].begin(), chains[next].end() - 1);
      ++next;
    } else {
      out.nodes.insert(out.nodes.end(), s.nodes.begin() + s.segment_begin[k], s.nodes.begin() + s.segment_begin[k + 1]);
    }
  }
  out.segment_begin.push_back(out.n_nodes());
  out.finalize();
  for (int k : moving) res.removed_area_m2 += segment_area(s, k) - segment_area(out, k);
  if (fast) *fast = true;
  return res;
}

}  // namespace linerlife
