#include "charge/canonical_surface.h"

#include <cmath>
#include <numeric>

namespace linerlife {

CanonicalSurface make_canonical_surface(const LinerSurface& s, Rotation rotation) {
  CanonicalSurface c;
  const int n = s.n_nodes(), S = s.segments;
  c.physical_segment.resize(S);
  if (rotation == Rotation::Ccw) {
    c.surface = s;
    c.physical_element.resize(n);
    std::iota(c.physical_element.begin(), c.physical_element.end(), 0);
    std::iota(c.physical_segment.begin(), c.physical_segment.end(), 0);
    return c;
  }
  c.mirrored = true;
  const double D = 2.0 * kPi / S;
  const double rho = (S % 2) ? -0.5 * D : 0.0;  // turn of the mirrored ring that puts its lifters on k D
  const double cr = std::cos(rho), sr = std::sin(rho);
  c.initial_angle_rad = -rho;
  LinerSurface& m = c.surface;
  m.shell_radius_m = s.shell_radius_m;
  m.segments = S;
  m.nodes.reserve(n);
  m.segment_begin.assign(S + 1, 0);
  m.segment_design.assign(S, 0);
  c.physical_element.reserve(n);
  auto mirror = [&](const Eigen::Vector2d& p) {  // x -> -x, then turned by rho
    return Eigen::Vector2d(-cr * p.x() - sr * p.y(), -sr * p.x() + cr * p.y());
  };
  for (int kc = 0; kc < S; ++kc) {
    const int kp = ((S / 2 - kc) % S + S) % S;  // physical segment mirrored onto canonical kc
    c.physical_segment[kc] = kp;
    if (kp == 0) c.segment_of_physical_0 = kc;
    m.segment_begin[kc] = static_cast<int>(m.nodes.size());
    m.segment_design[kc] = s.segment_design.empty() ? 0 : s.segment_design[kp];
    // physical nodes begin[kp] .. begin[kp+1] (the last is the next segment's
    // first node, on the radial line at the physical end angle, which mirrors
    // to the canonical start angle); walk them backwards, dropping begin[kp].
    const int b = s.segment_begin[kp], e = s.segment_begin[kp + 1];
    for (int i = e; i > b; --i) {
      m.nodes.push_back(mirror(s.nodes[i % n]));
      // canonical element from mirror(p_i) to mirror(p_{i-1}) is physical element i-1
      c.physical_element.push_back(i - 1);
    }
  }
  m.segment_begin[S] = static_cast<int>(m.nodes.size());
  m.finalize();
  return c;
}

}  // namespace linerlife
