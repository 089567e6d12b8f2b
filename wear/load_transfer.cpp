#include "wear/load_transfer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace linerlife {
namespace {

using V = Eigen::Vector2d;

/// The per-element fields that add up (forces, powers).
std::vector<std::vector<double> LinerLoads::*> extensive_fields() {
  return {&LinerLoads::normal_force_n_per_m,        &LinerLoads::centrifugal_force_n_per_m,
          &LinerLoads::gravitational_force_n_per_m, &LinerLoads::shear_force_n_per_m,
          &LinerLoads::normal_slip_power_w_per_m,   &LinerLoads::shear_work_rate_w_per_m};
}

/// A polyline prepared for closest-element queries.
struct Polyline {
  std::vector<V> a, ab;
  std::vector<double> inv_l2;  // 1 / |ab|^2, 0 for a degenerate element
  explicit Polyline(const std::vector<V>& pts) {
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      a.push_back(pts[i]);
      ab.push_back(pts[i + 1] - pts[i]);
      const double l2 = ab.back().squaredNorm();
      inv_l2.push_back(l2 > 0 ? 1.0 / l2 : 0.0);
    }
  }
  double distance2(const V& p, size_t i) const {
    const V ap = p - a[i];
    const double t = std::clamp(ap.dot(ab[i]) * inv_l2[i], 0.0, 1.0);
    return (ap - t * ab[i]).squaredNorm();
  }
  /// closest(p), searching first a window round `guess` (the answer for the
  /// previous point along a similar chain) and everywhere when the best found
  /// lies on the window's edge.
  int closest_near(const V& p, int guess) const {
    const int m = static_cast<int>(a.size()), w = 6;
    const int lo = std::max(0, guess - w), hi = std::min(m - 1, guess + w);
    int best = lo;
    double bd = std::numeric_limits<double>::max();
    for (int i = lo; i <= hi; ++i) {
      const double d = distance2(p, static_cast<size_t>(i));
      if (d < bd) {
        bd = d;
        best = i;
      }
    }
    if ((best == lo && lo > 0) || (best == hi && hi < m - 1)) return closest(p);
    return best;
  }
  /// The element whose segment is closest to p.
  int closest(const V& p) const {
    double best = std::numeric_limits<double>::max();
    int where = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      const V ap = p - a[i];
      const double t = std::clamp(ap.dot(ab[i]) * inv_l2[i], 0.0, 1.0);
      const double d = (ap - t * ab[i]).squaredNorm();
      if (d < best) {
        best = d;
        where = static_cast<int>(i);
      }
    }
    return where;
  }
};

int closest_element(const V& p, const std::vector<V>& pts) { return Polyline(pts).closest(p); }

/// The chain of segment k (both edge nodes), rotated by rot.
std::vector<V> chain(const LinerSurface& s, int k, double rot) {
  const Eigen::Rotation2Dd r(rot);
  std::vector<V> pts;
  for (int i = s.segment_begin[k]; i <= s.segment_begin[k + 1]; ++i) pts.push_back(r * s.nodes[i % s.n_nodes()]);
  return pts;
}

/// True when segment k carries no load at all (nothing to carry).
bool segment_empty(const LinerLoads& in, const LinerSurface& s, int k) {
  for (auto f : extensive_fields()) {
    const auto& v = in.*f;
    if (v.size() != static_cast<size_t>(s.n_elements())) continue;
    for (int i = s.segment_begin[k]; i < s.segment_begin[k + 1]; ++i)
      if (v[i] != 0) return false;
  }
  return true;
}

/// Where each target element of segment kt of `to` takes its loads from: the
/// element q of segment ks of `from` (rotated by rot) closest to the target's
/// midpoint, and the factor length_target / length_q that turns q's loads into
/// the target's at the same load per unit length.
std::vector<std::pair<int, double>> source_of(const LinerSurface& from, int ks, const LinerSurface& to, int kt,
                                              double rot) {
  const int fb = from.segment_begin[ks];
  const Polyline sp(chain(from, ks, rot));
  std::vector<std::pair<int, double>> src;
  int guess = 0;
  for (int j = to.segment_begin[kt]; j < to.segment_begin[kt + 1]; ++j) {
    guess = sp.closest_near(to.midpoint[j], guess);
    const int q = fb + guess;
    const double lq = from.length[q];
    src.emplace_back(q, lq > 0 ? to.length[j] / lq : 0.0);
  }
  return src;
}

/// Adds `weight` x the loads of segment ks of `in` (on `from`) carried onto
/// segment kt of `to` into `out`: each target element takes the load per unit
/// length of its source element (source_of) times its length, and every field
/// (and the impact rates together) is scaled so the segment's totals are kept.
void carry_segment(const LinerLoads& in, const LinerSurface& from, int ks, const LinerSurface& to, int kt, double rot,
                   double weight, const std::vector<std::vector<const ImpactEvent*>>& impacts_on, LinerLoads& out) {
  const auto src = source_of(from, ks, to, kt, rot);
  const int tb = to.segment_begin[kt];
  const int nt = static_cast<int>(src.size());
  for (auto f : extensive_fields()) {
    const auto& s = in.*f;
    auto& d = out.*f;
    if (s.size() != static_cast<size_t>(from.n_elements())) continue;
    double total = 0, carried = 0;
    for (int i = from.segment_begin[ks]; i < from.segment_begin[ks + 1]; ++i) total += s[i];
    for (int j = 0; j < nt; ++j) carried += s[src[j].first] * src[j].second;
    if (total == 0) continue;
    if (carried != 0) {
      const double scale = weight * total / carried;
      for (int j = 0; j < nt; ++j) d[tb + j] += scale * s[src[j].first] * src[j].second;
    } else {  // no target fell on a loaded element: spread the total by length
      double len = 0;
      for (int j = 0; j < nt; ++j) len += to.length[tb + j];
      for (int j = 0; j < nt; ++j) d[tb + j] += weight * total * to.length[tb + j] / len;
    }
  }
  // speeds are intensive: slip speed = <N v> / <N> of what was carried in
  if (in.slip_speed_m_s.size() == static_cast<size_t>(from.n_elements()))
    for (int j = 0; j < nt; ++j) {
      const double n = out.normal_force_n_per_m[tb + j];
      out.slip_speed_m_s[tb + j] = n > 0 ? out.normal_slip_power_w_per_m[tb + j] / n : in.slip_speed_m_s[src[j].first];
    }
  // impacts: copies on every target of the element they hit, rates as load per length, total kept
  double total = 0, carried = 0;
  const int fb = from.segment_begin[ks];
  for (int q = fb; q < from.segment_begin[ks + 1]; ++q)
    for (const ImpactEvent* e : impacts_on[q - fb]) total += e->rate_per_s;
  if (total == 0) return;
  const size_t first = out.impacts.size();
  for (int j = 0; j < nt; ++j)
    for (const ImpactEvent* e : impacts_on[src[j].first - fb]) {
      ImpactEvent c = *e;
      c.element = tb + j;
      c.rate_per_s = e->rate_per_s * src[j].second;
      carried += c.rate_per_s;
      out.impacts.push_back(c);
    }
  if (carried > 0) {
    for (size_t i = first; i < out.impacts.size(); ++i) out.impacts[i].rate_per_s *= weight * total / carried;
  } else {  // no target fell on a hit element: put the impacts on the target nearest to each
    const std::vector<V> tpts = chain(to, kt, 0.0);
    for (int q = fb; q < from.segment_begin[ks + 1]; ++q)
      for (const ImpactEvent* e : impacts_on[q - fb]) {
        ImpactEvent c = *e;
        c.element = tb + closest_element(Eigen::Rotation2Dd(rot) * from.midpoint[q], tpts);
        c.rate_per_s = weight * e->rate_per_s;
        out.impacts.push_back(c);
      }
  }
}

/// Impacts identical but for their rate, on the same element, become one.
void merge_impacts(std::vector<ImpactEvent>& ev) {
  auto key = [](const ImpactEvent& e) {
    return std::make_tuple(e.element, e.normal_speed_m_s, e.tangential_speed_m_s, e.mass_kg, e.diameter_m, e.direct);
  };
  std::sort(ev.begin(), ev.end(), [&](const ImpactEvent& a, const ImpactEvent& b) { return key(a) < key(b); });
  std::vector<ImpactEvent> out;
  for (const ImpactEvent& e : ev) {
    if (!out.empty() && key(out.back()) == key(e))
      out.back().rate_per_s += e.rate_per_s;
    else
      out.push_back(e);
  }
  ev.swap(out);
}

/// The impacts on each element of segment k of s.
std::vector<std::vector<const ImpactEvent*>> impacts_by_element(const LinerLoads& l, const LinerSurface& s, int k) {
  std::vector<std::vector<const ImpactEvent*>> by(static_cast<size_t>(s.segment_size(k)));
  for (const ImpactEvent& e : l.impacts)
    if (e.element >= s.segment_begin[k] && e.element < s.segment_begin[k + 1])
      by[static_cast<size_t>(e.element - s.segment_begin[k])].push_back(&e);
  return by;
}

void check_same_segments(const LinerSurface& a, const LinerSurface& b) {
  if (a.segments != b.segments) throw std::invalid_argument("load transfer: surfaces with different segments");
}

}  // namespace

LinerLoads transfer_loads(const LinerLoads& loads, const LinerSurface& from, const LinerSurface& to,
                          const std::vector<int>* only) {
  check_same_segments(from, to);
  if (loads.n_elements != from.n_elements()) throw std::invalid_argument("transfer_loads: loads do not fit `from`");
  LinerLoads out;
  out.reset(to.n_elements(), loads.duration_s);
  out.has_impacts = loads.has_impacts;
  std::vector<char> has_impact(static_cast<size_t>(from.segments), 0);
  for (const ImpactEvent& e : loads.impacts) has_impact[static_cast<size_t>(from.element_segment[e.element])] = 1;
  if (only) {
    for (int k : *only) carry_segment(loads, from, k, to, k, 0.0, 1.0, impacts_by_element(loads, from, k), out);
  } else {
    for (int k = 0; k < from.segments; ++k) {
      if (!has_impact[k] && segment_empty(loads, from, k)) continue;  // nothing to carry
      carry_segment(loads, from, k, to, k, 0.0, 1.0, impacts_by_element(loads, from, k), out);
    }
  }
  merge_impacts(out.impacts);
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
    const Eigen::Rotation2Dd rot((k - r) * da);
    for (int i = s.segment_begin[r]; i < s.segment_begin[r + 1]; ++i) out.nodes.push_back(rot * s.nodes[i]);
  }
  out.segment_begin.push_back(out.n_nodes());
  out.finalize();
  return out;
}

LinerSurface replicate_chains(const LinerSurface& s, const std::vector<std::vector<Eigen::Vector2d>>& chains) {
  const std::vector<int> rep = representative_segments(s);
  LinerSurface out;
  out.shell_radius_m = s.shell_radius_m;
  out.segments = s.segments;
  out.segment_design = s.segment_design;
  const double da = s.segment_angle_rad();
  size_t total = 0;
  for (const auto& c : chains) total += c.size();
  out.nodes.reserve(total * static_cast<size_t>(s.segments));
  for (int k = 0; k < s.segments; ++k) {
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    out.segment_begin.push_back(out.n_nodes());
    const Eigen::Rotation2Dd rot((k - rep[d]) * da);
    for (size_t i = 0; i + 1 < chains[d].size(); ++i) out.nodes.push_back(rot * chains[d][i]);
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
  for (int k = 0; k < s.segments; ++k) {
    const int d = s.segment_design.empty() ? 0 : s.segment_design[k];
    carry_segment(loads, s, k, s, rep[d], (rep[d] - k) * da, 1.0 / count[d], impacts_by_element(loads, s, k), out);
  }
  // slip speeds of the representatives from the averaged powers and forces
  for (int i = 0; i < s.n_elements(); ++i) {
    const double n = out.normal_force_n_per_m[i];
    out.slip_speed_m_s[i] = n > 0 ? out.normal_slip_power_w_per_m[i] / n : 0.0;
  }
  merge_impacts(out.impacts);
  return out;
}

}  // namespace linerlife
