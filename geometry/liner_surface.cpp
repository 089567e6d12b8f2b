#include "geometry/liner_surface.h"

#include <algorithm>
#include <cmath>

#include "geometry/mill.h"

namespace linerlife {

double LinerSurface::segment_angle_rad() const { return 2.0 * kPi / segments; }

double LinerSurface::segment_start_rad(int k) const { return (k - 0.5) * segment_angle_rad(); }

double LinerSurface::segment_centre_rad(int k) const { return k * segment_angle_rad(); }

int LinerSurface::segment_of_angle(double theta_rad) const {
  const double d = segment_angle_rad();
  double t = std::fmod(theta_rad + 0.5 * d, 2.0 * kPi);
  if (t < 0) t += 2.0 * kPi;
  int k = static_cast<int>(std::floor(t / d));
  return std::clamp(k, 0, segments - 1);
}

void LinerSurface::finalize() {
  const int n = n_nodes();
  length.resize(n);
  normal.resize(n);
  midpoint.resize(n);
  element_segment.resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d t = nodes[next(i)] - nodes[i];
    const double len = t.norm();
    length[i] = len;
    // Anticlockwise traversal: the mill interior is on the left, so the
    // inward normal is the tangent turned by +90 deg.
    normal[i] = len > 0 ? Eigen::Vector2d(-t.y() / len, t.x() / len) : Eigen::Vector2d(0, 0);
    midpoint[i] = 0.5 * (nodes[i] + nodes[next(i)]);
  }
  for (int k = 0; k < segments; ++k)
    for (int i = segment_begin[k]; i < segment_begin[k + 1]; ++i) element_segment[i] = k;
}

std::vector<Eigen::Vector2d> node_offset_directions(const LinerSurface& s, double max_miter) {
  const int n = s.n_nodes();
  std::vector<Eigen::Vector2d> dir(n);
  std::vector<char> edge(n, 0);
  for (int k = 0; k < s.segments; ++k) edge[s.segment_begin[k]] = 1;
  for (int i = 0; i < n; ++i) {
    if (edge[i]) {  // radial, towards the shell
      dir[i] = s.nodes[i].normalized();
      continue;
    }
    // recession runs against the inward normals
    const Eigen::Vector2d a = -s.normal[s.prev(i)];
    const Eigen::Vector2d b = -s.normal[i];
    Eigen::Vector2d m = a + b;
    const double mn = m.norm();
    if (mn < 1e-12) {  // a hairpin: fall back to one side
      dir[i] = b;
      continue;
    }
    m /= mn;
    const double c = std::max(m.dot(b), 1.0 / max_miter);  // cos(half turn)
    dir[i] = m / c;
  }
  return dir;
}

}  // namespace linerlife
