#include "wear/load_transfer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

namespace linerlife {
namespace {

using V = Eigen::Vector2d;

/// The per-element fields that add up (forces, powers).
std::vector<std::vector<double> LinerLoads::*> extensive_fields() {
  return {&LinerLoads::normal_force_n_per_m,      &LinerLoads::centrifugal_force_n_per_m,
          &LinerLoads::gravitational_force_n_per_m, &LinerLoads::shear_force_n_per_m,
          &LinerLoads::normal_slip_power_w_per_m, &LinerLoads::shear_work_rate_w_per_m};
}

V rotate(const V& p, double a) { return Eigen::Rotation2Dd(a) * p; }

int nearest(const V& p, const LinerSurface& s, int b, int e, double rot) {
  int best = b;
  double bd = std::numeric_limits<double>::max();
  for (int j = b; j < e; ++j) {
    const double d = (rotate(s.midpoint[j], rot) - p).squaredNorm();
    if (d < bd) {
      bd = d;
      best = j;
    }
  }
  return best;
}

/// Carries segment ks of `from` (rotated by `rot`) onto segment kt of `to`,
/// adding `weight` x the loads into `out` (sized for `to`). Returns the map
/// from source element to target element for the impacts.
std::vector<int> carry_segment(const LinerLoads& in, const LinerSurface& from, int ks, const LinerSurface& to, int kt,
                               double rot, double weight, LinerLoads& out) {
  const int fb = from.segment_begin[ks], fe = from.segment_begin[ks + 1];
  const int tb = to.segment_begin[kt], te = to.segment_begin[kt + 1];
  std::vector<int> src_of(static_cast<size_t>(te - tb)), dst_of(static_cast<size_t>(fe - fb));
  std::vector<double> mapped_len(static_cast<size_t>(fe - fb), 0.0);
  for (int j = tb; j < te; ++j) {
    // target midpoint rotated back into the source frame
    const int i = nearest(rotate(to.midpoint[j], -rot), from, fb, fe, 0.0);
    src_of[j - tb] = i;
    mapped_len[i - fb] += to.length[j];
  }
  for (int i = fb; i < fe; ++i) dst_of[i - fb] = nearest(rotate(from.midpoint[i], rot), to, tb, te, 0.0);
  const auto fields = extensive_fields();
  for (auto f : fields) {
    const auto& src = in.*f;
    auto& dst = out.*f;
    if (src.size() != static_cast<size_t>(from.n_elements())) continue;
    for (int j = tb; j < te; ++j) {
      const int i = src_of[j - tb];
      const double ml = mapped_len[i - fb];
      if (ml > 0) dst[j] += weight * src[i] * to.length[j] / ml;
    }
    for (int i = fb; i < fe; ++i)
      if (!(mapped_len[i - fb] > 0)) dst[dst_of[i - fb]] += weight * src[i];
  }
  // speeds are intensive: the load-weighted mean of what maps in (slip_speed = <N v>/<N>)
  if (in.slip_speed_m_s.size() == static_cast<size_t>(from.n_elements()))
    for (int j = tb; j < te; ++j) {
      const int i = src_of[j - tb];
      if (out.normal_force_n_per_m.empty()) {
        out.slip_speed_m_s[j] = in.slip_speed_m_s[i];
      } else {
        const double n = out.normal_force_n_per_m[j];
        out.slip_speed_m_s[j] = n > 0 ? out.normal_slip_power_w_per_m[j] / n : in.slip_speed_m_s[i];
      }
    }
  return dst_of;
}

void check_same_segments(const LinerSurface& a, const LinerSurface& b) {
  if (a.segments != b.segments) throw std::invalid_argument("load transfer: surfaces with different segments");
}

}  // namespace

LinerLoads transfer_loads(const LinerLoads& loads, const LinerSurface& from, const LinerSurface& to) {
  check_same_segments(from, to);
  if (loads.n_elements != from.n_elements()) throw std::invalid_argument("transfer_loads: loads do not fit `from`");
  LinerLoads out;
  out.reset(to.n_elements(), loads.duration_s);
  out.has_impacts = loads.has_impacts;
  std::vector<int> dst(static_cast<size_t>(from.n_elements()));
  for (int k = 0; k < from.segments; ++k) {
    const std::vector<int> d = carry_segment(loads, from, k, to, k, 0.0, 1.0, out);
    for (size_t q = 0; q < d.size(); ++q) dst[static_cast<size_t>(from.segment_begin[k]) + q] = d[q];
  }
  out.impacts = loads.impacts;
  for (ImpactEvent& e : out.impacts) e.element = dst[static_cast<size_t>(e.element)];
  return out;
}

std::vector<int> representative_segments(const LinerSurface& s) {
  std::vector<int> rep;
  for (int k = 0; k < s.segments; ++k) {
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    if (d >= static_cast<int>(rep.size())) rep.resize(static_cast<size_t>(d + 1), -1);
    if (rep[d] < 0) rep[d] = k;
  }
  return rep;
}

std::vector<int> design_counts(const LinerSurface& s) {
  std::vector<int> c;
  for (int k = 0; k < s.segments; ++k) {
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    if (d >= static_cast<int>(c.size())) c.resize(static_cast<size_t>(d + 1), 0);
    ++c[d];
  }
  return c;
}

LinerSurface replicate_representatives(const LinerSurface& s) {
  const std::vector<int> rep = representative_segments(s);
  LinerSurface out;
  out.shell_radius_m = s.shell_radius_m;
  out.segments = s.segments;
  out.segment_design = s.segment_design;
  const double da = s.segment_angle_rad();
  for (int k = 0; k < s.segments; ++k) {
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    const int r = rep[d];
    out.segment_begin.push_back(out.n_nodes());
    for (int i = s.segment_begin[r]; i < s.segment_begin[r + 1]; ++i) out.nodes.push_back(rotate(s.nodes[i], (k - r) * da));
  }
  out.segment_begin.push_back(out.n_nodes());
  out.finalize();
  return out;
}

LinerLoads average_onto_representatives(const LinerLoads& loads, const LinerSurface& s) {
  if (loads.n_elements != s.n_elements()) throw std::invalid_argument("average_onto_representatives: size mismatch");
  const std::vector<int> rep = representative_segments(s);
  const std::vector<int> count = design_counts(s);
  LinerLoads out;
  out.reset(s.n_elements(), loads.duration_s);
  out.has_impacts = loads.has_impacts;
  const double da = s.segment_angle_rad();
  std::vector<int> dst(static_cast<size_t>(s.n_elements()));
  for (int k = 0; k < s.segments; ++k) {
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    const std::vector<int> m = carry_segment(loads, s, k, s, rep[d], (rep[d] - k) * da, 1.0 / count[d], out);
    for (size_t q = 0; q < m.size(); ++q) dst[static_cast<size_t>(s.segment_begin[k]) + q] = m[q];
  }
  // slip speeds of the representatives from the averaged powers and forces
  for (int i = 0; i < s.n_elements(); ++i) {
    const double n = out.normal_force_n_per_m[i];
    out.slip_speed_m_s[i] = n > 0 ? out.normal_slip_power_w_per_m[i] / n : 0.0;
  }
  for (const ImpactEvent& e : loads.impacts) {
    ImpactEvent c = e;
    const int k = s.element_segment[e.element];
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    c.element = dst[static_cast<size_t>(e.element)];
    c.rate_per_s = e.rate_per_s / count[d];
    out.impacts.push_back(c);
  }
  return out;
}

}  // namespace linerlife
