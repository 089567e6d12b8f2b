// worn_profiles.h - worn liner profiles for the charge-model studies on worn
// geometry (docs/models/layer-worn.md): the profiles a forecast stored in its
// results file, rings built from one segment profile, and a continuous blend
// between two profiles (for continuity sweeps).
//
// A segment profile here is the node list of segment 0 of a ring, centred on
// angle 0 (the +x axis), anticlockwise, both radial edges included: what
// `/forecast/profiles` stores (docs/output.md) and what assemble_ring() takes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "app/config.h"
#include "app/h5_reader.h"
#include "geometry/build_liner_surface.h"
#include "geometry/liner_surface.h"

namespace linerlife::bench {

/// The worn profiles of a forecast results file (`linerlife forecast --out`).
struct WornHistory {
  Config config;                                     // the resolved configuration of the run
  std::vector<double> hours;                         // [h] operating hours of each profile
  std::vector<std::vector<Eigen::Vector2d>> profiles;  // [m] segment 0, centred on angle 0
};

inline WornHistory read_worn_history(const std::string& h5_path) {
  H5Reader h5(h5_path);
  WornHistory w;
  w.config = load_config_text(h5.text("/config"), h5_path, ".");
  w.hours = h5.doubles("/forecast/profiles/hours");
  const std::vector<double> xy = h5.doubles("/forecast/profiles/nodes");
  const std::vector<long long> off = h5.ints("/forecast/profiles/offset");
  for (size_t k = 0; k + 1 < off.size(); ++k) {
    std::vector<Eigen::Vector2d> p;
    for (long long i = off[k]; i < off[k + 1]; ++i) p.emplace_back(xy[2 * i], xy[2 * i + 1]);
    w.profiles.push_back(std::move(p));
  }
  return w;
}

/// A uniform ring of `segments` rows of one segment profile.
inline LinerSurface ring_of(double shell_radius_m, int segments, const std::vector<Eigen::Vector2d>& profile) {
  return assemble_ring(shell_radius_m, segments, {profile}, std::vector<int>(static_cast<size_t>(segments), 0));
}

/// The profile's radius [m] along the ray at polar angle theta: the
/// crossing nearest the axis (the surface the charge sees).
inline double radius_on_ray(const std::vector<Eigen::Vector2d>& p, double theta) {
  const Eigen::Vector2d u(std::cos(theta), std::sin(theta));
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    const Eigen::Vector2d a = p[i], e = p[i + 1] - p[i];
    // a + s e = r u  ->  solve [e, -u] (s, r) = -a
    const double det = -e.x() * u.y() + e.y() * u.x();
    if (std::abs(det) < 1e-15) continue;
    const double s = (a.x() * u.y() - a.y() * u.x()) / det;
    const double r = (a.x() * e.y() - a.y() * e.x()) / det;
    if (s >= -1e-9 && s <= 1 + 1e-9 && r > 0) best = std::min(best, r);
  }
  if (!std::isfinite(best)) {  // a ray along a segment edge that rounding made miss: the nearest end node
    const Eigen::Vector2d& e = std::abs(std::remainder(std::atan2(p.front().y(), p.front().x()) - theta, 2 * M_PI)) <
                                       std::abs(std::remainder(std::atan2(p.back().y(), p.back().x()) - theta, 2 * M_PI))
                                   ? p.front()
                                   : p.back();
    best = e.norm();
  }
  return best;
}

/// A profile between `a` (t = 0) and `b` (t = 1): on n + 1 rays evenly over
/// the segment, the radius is interpolated linearly. Continuous in t: a small
/// step of t moves every point of the surface a little. (Both profiles must be
/// star-shaped about the axis over the segment, as new and worn lifters are.)
inline std::vector<Eigen::Vector2d> blend_profiles(const std::vector<Eigen::Vector2d>& a,
                                                   const std::vector<Eigen::Vector2d>& b, double t, int segments,
                                                   int n = 400) {
  const double half = M_PI / segments;
  std::vector<Eigen::Vector2d> out;
  out.reserve(static_cast<size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double th = -half + 2.0 * half * i / n;
    // the edge rays are the segment edges exactly (assemble_ring joins there)
    const double ra = radius_on_ray(a, th), rb = radius_on_ray(b, th);
    const double r = (1 - t) * ra + t * rb;
    out.emplace_back(r * std::cos(th), r * std::sin(th));
  }
  return out;
}

/// A whole ring stored in a results file (`/surface`, `/final_surface`:
/// nodes, segment_begin, segment_design; docs/output.md), rebuilt from its
/// first segment of each design (a forecast's ring repeats them), so that a
/// hi-lo ring keeps its low lifters, which `/forecast/profiles` (segment 0,
/// the high lifter) does not hold.
inline LinerSurface read_ring(const std::string& h5_path, const std::string& group, double shell_radius_m,
                              std::vector<std::vector<Eigen::Vector2d>>* design_profiles = nullptr) {
  H5Reader h5(h5_path);
  const std::vector<double> xy = h5.doubles(group + "/nodes");
  const std::vector<long long> begin = h5.ints(group + "/segment_begin");
  const std::vector<long long> design_ll = h5.ints(group + "/segment_design");
  const int S = static_cast<int>(design_ll.size());
  const size_t n = xy.size() / 2;
  std::vector<int> design(design_ll.begin(), design_ll.end());
  const int n_designs = *std::max_element(design.begin(), design.end()) + 1;
  std::vector<std::vector<Eigen::Vector2d>> profiles(static_cast<size_t>(n_designs));
  for (int d = 0; d < n_designs; ++d) {
    const int k = static_cast<int>(std::find(design.begin(), design.end(), d) - design.begin());
    const double a = -k * 2.0 * M_PI / S, c = std::cos(a), sn = std::sin(a);
    for (long long i = begin[k]; i <= begin[k + 1]; ++i) {
      const size_t q = static_cast<size_t>(i) % n;
      profiles[d].emplace_back(c * xy[2 * q] - sn * xy[2 * q + 1], sn * xy[2 * q] + c * xy[2 * q + 1]);
    }
  }
  if (design_profiles) *design_profiles = profiles;
  return assemble_ring(shell_radius_m, S, profiles, design);
}

/// Segment 0 of a ring, as a segment profile.
inline std::vector<Eigen::Vector2d> segment0_profile(const LinerSurface& s) {
  std::vector<Eigen::Vector2d> p;
  for (int i = s.segment_begin[0]; i <= s.segment_begin[1]; ++i) p.push_back(s.nodes[static_cast<size_t>(i % s.n_nodes())]);
  return p;
}

}  // namespace linerlife::bench
