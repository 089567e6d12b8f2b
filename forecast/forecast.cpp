#include "forecast/forecast.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <stdexcept>

#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"
#include "geometry/stretch_grid.h"

namespace linerlife {

const char* method_name(ForecastMethod m) {
  switch (m) {
    case ForecastMethod::Ode: return "ode";
    case ForecastMethod::Amplify: return "amplify";
    case ForecastMethod::Euler: return "euler";
  }
  return "?";
}

double explicit_step_s(const ForecastSpec& spec, double speed_rpm) {
  switch (spec.method) {
    case ForecastMethod::Ode: return 0.0;
    case ForecastMethod::Euler: return spec.euler_step_h * 3600.0;
    case ForecastMethod::Amplify: return spec.amplify_revolutions * (60.0 / speed_rpm) * spec.amplification;
  }
  return 0.0;
}

int pattern_period(const LinerSurface& s) {
  for (int p = 1; p <= s.segments; ++p) {
    if (s.segments % p != 0) continue;
    bool ok = true;
    for (int k = 0; k < s.segments && ok; ++k)
      ok = s.segment_design[static_cast<size_t>(k)] == s.segment_design[static_cast<size_t>(k % p)] &&
           s.segment_size(k) == s.segment_size(k % p);
    if (ok) return p;
  }
  return s.segments;
}

std::vector<double> smooth_along_surface(const LinerSurface& s, std::vector<double> v, int passes) {
  // Flux form: v_i += (F_{i+1/2} - F_{i-1/2}) / L_i with F_{i+1/2} =
  // min(L_i, L_{i+1}) (v_{i+1} - v_i) / 4. The fluxes telescope, so
  // sum(L v) is kept exactly; a uniform field is kept whatever the element
  // lengths; the weights (<= 1/4 each side) are non-negative, so no new extrema.
  const int n = s.n_elements();
  std::vector<double> flux(static_cast<size_t>(n));
  for (int p = 0; p < passes; ++p) {
    for (int i = 0; i < n; ++i) {
      const int j = s.next(i);
      flux[i] = 0.25 * std::min(s.length[i], s.length[j]) * (v[j] - v[i]);
    }
    for (int i = 0; i < n; ++i)
      if (s.length[i] > 0) v[i] += (flux[i] - flux[s.prev(i)]) / s.length[i];
  }
  return v;
}

int smoothing_passes(double element_size_m, int min_passes, double length_m) {
  // The 1-2-1 pass spreads a value over its neighbours with weights 1/4,
  // 1/2, 1/4: a variance of h^2 / 2 per pass on elements of length h. Two
  // passes on the default 10 mm elements smooth over 10 mm (the default's
  // rate_smoothing_m, so the default is two passes as before); on 2 mm
  // elements two passes smoothed over 2 mm only, and the lifter left at
  // the end of the bundled forecast rose 7 mm from 10 to 1.5 mm elements
  // (docs/validation/forecast.md, "Surface element size").
  int p = std::max(0, min_passes);
  if (length_m > 0 && element_size_m > 0) {
    const double r = length_m / element_size_m, want = std::round(2.0 * r * r);
    p = std::max(p, static_cast<int>(std::min<double>(want, kMaxSmoothingPasses)));
  }
  return p;
}

// The smallest projection, over the cell's elements (and the one before
// it), of an element of the displaced ring on the same element of the ring
// it was displaced from, relative to that element's squared length: 1 right
// after a remesh, 0 where an element has turned by 90 deg. Between remeshes
// the nodes move along their offset directions; at a convex corner, where
// they converge, an element shorter than the depth between remeshes shrinks
// and turns over without crossing anything (cell_folds() does not see it).
// The bundled Qiu forecast had elements of about 1 mm turned by up to 136
// deg; a DEM disc pressed on such a corner lay "behind" the turned element
// (docs/models/forecast.md).
double min_element_projection(const LinerSurface& base, const LinerSurface& ring, int n_cell) {
  double mn = std::numeric_limits<double>::infinity();
  for (int i = -1; i < n_cell; ++i) {
    const int a = i < 0 ? base.prev(0) : i;
    const Eigen::Vector2d d0 = base.nodes[static_cast<size_t>(base.next(a))] - base.nodes[static_cast<size_t>(a)];
    const Eigen::Vector2d d1 = ring.nodes[static_cast<size_t>(ring.next(a))] - ring.nodes[static_cast<size_t>(a)];
    const double l2 = d0.squaredNorm();
    if (l2 > 0) mn = std::min(mn, d1.dot(d0) / l2);
  }
  return mn;
}

namespace {

using V = Eigen::Vector2d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

/// True if the cell's part of a displaced ring (its elements and one on each
/// side) crosses itself. Between remeshes the nodes move along their offset
/// directions; where a worn lifter has become a needle with notches smaller
/// than the depth between remeshes, a notch node can pass through the needle
/// and the ring folds. The folded part is material the wear removed (a remesh
/// takes it away), but a gauge read on the folded ring sees its points: the
/// soak (docs/reliability.md) found a crest that "rose" 3.8 mm that way.
///
/// Only proper crossings count. geometry's polyline_self_intersects() also
/// counts a point lying on another element; with it the 100-mill soak failed
/// on run 5 (the crest rose 0.1 mm per record, as if the root never fired -
/// likely a touching point right after a remesh, which starts the root at -1
/// so that no crossing is ever seen). Not investigated further.
bool cell_folds(const LinerSurface& s, int n_cell) {
  using V = Eigen::Vector2d;
  const int n = s.n_nodes();
  auto at = [&](int i) -> const V& { return s.nodes[static_cast<size_t>(((i % n) + n) % n)]; };
  auto orient = [](const V& a, const V& b, const V& c) {
    const double o = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    return (o > 0) - (o < 0);
  };
  const int lo = -1, hi = std::min(n_cell + 1, n - 1);  // elements lo .. hi-1
  if (hi - lo < 3) return false;
  // Every pair i < j - 1 of these elements was compared directly before
  // 2026-12-04: O(n^2) at every root evaluation, 2e8 pairs for a cell meshed
  // from a measured profile of 20,000 points. Only elements that share a cell
  // of the grid can cross; the answer is the same.
  std::vector<V> chain;
  chain.reserve(static_cast<size_t>(hi - lo + 1));
  for (int i = lo; i <= hi; ++i) chain.push_back(at(i));
  const StretchGrid grid(chain, 0.0);
  for (int i = lo; i < hi; ++i) {
    bool folds = false;
    grid.for_each_cell_of_stretch(i - lo, [&](int cell) {
      const auto [first, last] = grid.stretches_in(cell);
      for (const int* k = std::upper_bound(first, last, i + 1 - lo); k != last && !folds; ++k) {
        const int j = *k + lo;
        if (((j + 1 - i) % n) == 0) continue;  // adjacent through the wrap
        const V &a = at(i), &b = at(i + 1), &c = at(j), &d = at(j + 1);
        folds = orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
      }
    });
    if (folds) return true;
  }
  return false;
}

namespace {

/// The representative cell of the ring: segments 0 .. p-1, repeated by rotation.
class Cell {
 public:
  Cell(const LinerSurface& ring, int period) : base_(ring), p_(period) {
    n_cell_ = ring.segment_begin[static_cast<size_t>(p_)];
    copies_ = ring.segments / p_;
    if (copies_ * n_cell_ != ring.n_nodes())
      throw std::invalid_argument("forecast: the ring is not a repetition of its first segments");
  }
  const LinerSurface& base() const { return base_; }
  int size() const { return n_cell_; }
  int period() const { return p_; }

  std::vector<double> ring_depth(const double* y) const {
    std::vector<double> d(static_cast<size_t>(base_.n_nodes()));
    for (int c = 0; c < copies_; ++c)
      for (int i = 0; i < n_cell_; ++i) d[static_cast<size_t>(c * n_cell_ + i)] = y[i];
    return d;
  }
  LinerSurface displaced(const double* y) const { return displace_nodes(base_, ring_depth(y)); }

  /// Element rates of the ring -> smoothed -> node rates -> mean over the copies of the cell.
  std::vector<double> cell_rates(const LinerSurface& ring, const std::vector<double>& element_rate, int passes) const {
    const std::vector<double> r = smooth_along_surface(ring, element_rate, passes);
    std::vector<double> out(static_cast<size_t>(n_cell_), 0.0);
    for (int c = 0; c < copies_; ++c)
      for (int i = 0; i < n_cell_; ++i) {
        const int g = c * n_cell_ + i, a = ring.prev(g);
        const double w = ring.length[a] + ring.length[g];
        out[i] += w > 0 ? (ring.length[a] * r[a] + ring.length[g] * r[g]) / w : 0.5 * (r[a] + r[g]);
      }
    for (double& x : out) x = std::max(0.0, x / copies_);
    return out;
  }

  /// Carries cell-node fields across a remesh: each node of the new cell takes
  /// the value at its closest point on `old_ring` (the old surface as it was
  /// displaced when remeshed), interpolated along that element. The remesh
  /// leaves the new nodes on the old surface (up to removed loops), so this is
  /// an interpolation, not an extrapolation.
  std::vector<double> transfer(const LinerSurface& old_ring, int old_cell, const std::vector<double>& f_old) const {
    std::vector<double> out(static_cast<size_t>(n_cell_));
    const int n_old = old_ring.n_nodes();
    // old elements of the cell and one on each side
    const int lo = -1, hi = old_ring.segment_begin[static_cast<size_t>(p_)] + 1;
    auto node = [&](int e) { return ((e % n_old) + n_old) % n_old; };
    // The closest element (the first of equals in the order lo .. hi-1), as a
    // scan of every element finds it; before 2026-12-04 that scan ran for
    // every node, O(n^2) at every remesh. Now only the elements in a box
    // round q that holds one at most the box's half side away are looked at.
    std::vector<V> chain;
    chain.reserve(static_cast<size_t>(hi - lo + 1));
    for (int e = lo; e <= hi; ++e) chain.push_back(old_ring.nodes[static_cast<size_t>(node(e))]);
    const StretchGrid grid(chain, 0.0);
    for (int i = 0; i < n_cell_; ++i) {
      const V& q = base_.nodes[i];
      double best = 1e300;
      int best_e = hi;
      auto look = [&](int e) {
        const int a = node(e), b = (a + 1) % n_old;
        const V ab = old_ring.nodes[b] - old_ring.nodes[a];
        const double l2 = ab.squaredNorm();
        const double s = l2 > 0 ? std::clamp((q - old_ring.nodes[a]).dot(ab) / l2, 0.0, 1.0) : 0.0;
        const double d2 = (old_ring.nodes[a] + s * ab - q).squaredNorm();
        if (d2 < best || (d2 == best && best_e < hi && e < best_e)) {
          best = d2;
          best_e = e;
        }
      };
      for (double r = grid.cell_size();; r *= 2) {
        if (!std::isfinite(r) || !q.allFinite()) {  // everything, as the scan
          for (int e = lo; e < hi; ++e) look(e);
          break;
        }
        const bool all = grid.for_each_stretch_in_box(q.x() - r, q.x() + r, q.y() - r, q.y() + r,
                                                      [&](int s) { look(s + lo); });
        if (all || (best_e < hi && best <= r * r * (1 - 1e-9))) break;
      }
      double val = 0;
      if (best_e < hi) {
        const int a = node(best_e), b = (a + 1) % n_old;
        const V ab = old_ring.nodes[b] - old_ring.nodes[a];
        const double l2 = ab.squaredNorm();
        const double s = l2 > 0 ? std::clamp((q - old_ring.nodes[a]).dot(ab) / l2, 0.0, 1.0) : 0.0;
        val = (1 - s) * f_old[static_cast<size_t>(a % old_cell)] + s * f_old[static_cast<size_t>(b % old_cell)];
      }
      out[static_cast<size_t>(i)] = val;
    }
    return out;
  }

  /// Applies the depths y with the CGAL remesh of the cell's segments and
  /// rebuilds the ring; returns the status of the cell.
  SegmentRemesh remesh(const double* y, const RemeshOptions& opt) {
    const std::vector<double> d = ring_depth(y);
    SegmentRemesh status;
    std::vector<std::vector<V>> profiles;
    for (int k = 0; k < p_; ++k) {
      SegmentRemesh r = remesh_segment(base_, d, k, opt);
      if (r.status != RemeshStatus::Ok && status.status == RemeshStatus::Ok) status = r;
      profiles.push_back(rotate_points(r.nodes, -base_.segment_centre_rad(k)));
    }
    std::vector<int> design(static_cast<size_t>(base_.segments));
    for (int k = 0; k < base_.segments; ++k) design[static_cast<size_t>(k)] = k % p_;
    base_ = assemble_ring(base_.shell_radius_m, base_.segments, profiles, design);
    n_cell_ = base_.segment_begin[static_cast<size_t>(p_)];
    return status;
  }

 private:
  LinerSurface base_;
  int p_ = 1, n_cell_ = 0, copies_ = 1;
};

/// What the criteria look at.
struct Gauge {
  SegmentMetrics lifter;      // segment 0
  SegmentMetrics low;         // segment 1 where it is a hi-lo ring's low lifter (low.design == 1)
  double min_thickness = 0;   // [m] over the cell
  double mass_kg_per_m = 0;   // [kg/m] ring
};

Gauge gauge(const LinerSurface& ring, int period, Rotation rot, double density) {
  Gauge g;
  g.lifter = segment_metrics(ring, 0, rot, density);
  g.min_thickness = g.lifter.min_thickness_m;
  double cell_mass = g.lifter.mass_kg_per_m;
  for (int k = 1; k < period; ++k) {
    const SegmentMetrics m = segment_metrics(ring, k, rot, density);
    if (k == 1 && m.design == 1) g.low = m;
    g.min_thickness = std::min(g.min_thickness, m.min_thickness_m);
    cell_mass += m.mass_kg_per_m;
  }
  g.mass_kg_per_m = cell_mass * ring.segments / period;
  return g;
}

constexpr double kWornThroughM = 2e-4;  // [m] the remesh holds nodes 1e-4 m off the shell

/// Criterion functions, positive while the liner is serviceable.
struct Criteria {
  const ForecastSpec* spec;
  bool lifter = true;  // the liner starts with a lifter: the height and face criteria apply
  double g_height(const Gauge& g) const {
    return lifter ? g.lifter.lifter_height_m - spec->min_lifter_height_m : spec->min_lifter_height_m + 1.0;
  }
  double g_plate(const Gauge& g) const { return g.min_thickness - spec->min_plate_thickness_m; }
  double g_face(const Gauge& g) const {
    const double a = g.lifter.face_angle_leading_deg;
    return !lifter || std::isnan(a) ? spec->max_face_angle_leading_deg : spec->max_face_angle_leading_deg - a;
  }
  double g_worn(const Gauge& g) const { return g.min_thickness - kWornThroughM; }
  static const char* name(int i) {
    static const char* names[] = {"min_lifter_height", "min_plate_thickness", "max_face_angle_leading",
                                  "worn_through"};
    return names[i];
  }
  void eval(const Gauge& g, double* out) const {
    out[0] = g_height(g);
    out[1] = g_plate(g);
    out[2] = g_face(g);
    out[3] = g_worn(g);
  }
  /// Fraction of the life used, for progress display: the largest of the criteria's.
  double progress(const Gauge& g0, const Gauge& g) const {
    double f = 0;
    double a[4], b[4];
    eval(g0, a);
    eval(g, b);
    for (int i = 0; i < 4; ++i)
      if (a[i] > 0) f = std::max(f, 1.0 - b[i] / a[i]);
    return std::clamp(f, 0.0, 1.0);
  }
};

/// The forecast's moving parts, shared by the three methods.
class Life {
 public:
  Life(const ForecastInput& in, RateProvider& rates, const ForecastSpec& spec, const ForecastHooks& hooks)
      : in_(in), rates_(rates), spec_(spec), hooks_(hooks), progress_(hooks.progress),
        cell_(*in.initial, pattern_period(*in.initial)), crit_{&spec} {
    opt_.element_size_m = in.element_size_m;
    remesh_depth_ = spec.remesh_depth_m > 0 ? spec.remesh_depth_m : 0.5 * in.element_size_m;
    smoothing_passes_ = smoothing_passes(in.element_size_m, spec.rate_smoothing_passes, spec.rate_smoothing_m);
    y_.assign(static_cast<size_t>(cell_.size()), 0.0);
    g0_ = gauge(*in.initial, cell_.period(), in.rotation, in.density_kg_m3);
    crit_.lifter = g0_.lifter.has_lifter;  // a plain plate has no lifter to wear down
    double g[4];
    crit_.eval(g0_, g);
    for (int i = 0; i < 4; ++i)
      if (g[i] <= 0)
        throw InputError(std::string("forecast.") + (i == 0   ? "min_lifter_height_m"
                                                     : i == 1 ? "min_plate_thickness_m"
                                                     : i == 2 ? "max_face_angle_leading_deg"
                                                              : "min_plate_thickness_m"),
                         fmt::format("the liner already meets the relining criterion {} at the start (lifter "
                                     "height {:.4f} m, thinnest point {:.4f} m, leading face {:.2f} deg): nothing "
                                     "to forecast; check the [forecast] criteria against the liner",
                                     Criteria::name(i), g0_.lifter.lifter_height_m, g0_.min_thickness,
                                     g0_.lifter.face_angle_leading_deg));
  }

  ForecastResult run() {
    const auto t0 = std::chrono::steady_clock::now();
    wall0_ = t0;
    for (double h : spec_.extra_output_hours)
      if (h > 0) extra_.push_back(h * 3600.0);
    std::sort(extra_.begin(), extra_.end());
    next_regular_ = spec_.output_interval_h * 3600.0;
    next_explicit_out_ = next_regular_;
    double wall_before = 0;
    if (hooks_.resume) {
      restore(*hooks_.resume);
      wall_before = res_.stats.wall_s;
    } else {
      drive(spec_.revolutions_per_drive);
      record(0.0);
    }
    try {
      switch (spec_.method) {
        case ForecastMethod::Ode: run_ode(); break;
        case ForecastMethod::Euler:
          run_explicit(explicit_step_s(spec_, in_.speed_rpm), spec_.revolutions_per_drive, false);
          break;
        case ForecastMethod::Amplify:
          run_explicit(explicit_step_s(spec_, in_.speed_rpm), spec_.amplify_revolutions, true);
          break;
      }
    } catch (const SimulationError&) {
      if (hooks_.partial) {
        res_.stats.wall_s = wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        res_.operating_hours = t_ / 3600.0;
        res_.criterion = "failed";
        res_.reached = false;
        // where it stopped, on the calendar as a finished run's end (a review,
        // 2026-12-06: the partial file said end_date 2000-01-01, 0 days, 0 t)
        res_.calendar_days = spec_.calendar.calendar_days_for(res_.operating_hours);
        res_.relining_date = spec_.calendar.date_after(res_.operating_hours);
        res_.tonnes = res_.operating_hours * spec_.throughput_t_per_h;
        res_.final_surface = cell_.displaced(y_.data());
        *hooks_.partial = res_;
      }
      throw;
    }
    res_.stats.wall_s = wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    res_.calendar_days = spec_.calendar.calendar_days_for(res_.operating_hours);
    res_.relining_date = spec_.calendar.date_after(res_.operating_hours);
    res_.tonnes = res_.operating_hours * spec_.throughput_t_per_h;
    res_.final_surface = cell_.displaced(y_.data());
    return res_;
  }

  // --- the right-hand side of the ODE, called through CVODE ---
  void rhs(const double* y, double* ydot) {
    const std::vector<double>* r = &r_now_;
    if (spec_.refresh_always) {
      sample_at(y, spec_.revolutions_per_drive);
      r = &r_now_;
      for (int i = 0; i < cell_.size(); ++i) ydot[i] = (*r)[i];
      return;
    }
    if (spec_.rate_model == "secant" && have_prev_) {
      // linear in the path from the previous drive to the last one
      double num = 0, den = 0;
      for (int i = 0; i < cell_.size(); ++i) {
        const double dy = y_drive_[i] - y_prev_[i];
        num += (y[i] - y_drive_[i]) * dy;
        den += dy * dy;
      }
      const double s = den > 0 ? std::clamp(num / den, 0.0, 3.0) : 0.0;
      for (int i = 0; i < cell_.size(); ++i) ydot[i] = std::max(0.0, r_now_[i] + s * (r_now_[i] - r_prev_[i]));
      return;
    }
    for (int i = 0; i < cell_.size(); ++i) ydot[i] = (*r)[i];
  }

  // --- the root functions: criteria, remesh and refresh ---
  static constexpr int kRoots = 8;
  void roots(const double* y, double* g) {
    const LinerSurface ring = cell_.displaced(y);
    const Gauge gg = gauge(ring, cell_.period(), in_.rotation, in_.density_kg_m3);
    crit_.eval(gg, g);
    double ymax = 0, moved = 0;
    for (int i = 0; i < cell_.size(); ++i) {
      ymax = std::max(ymax, y[i]);
      moved = std::max(moved, std::abs(y[i] - y_drive_[i]));
    }
    g[4] = remesh_depth_ - ymax;
    g[5] = spec_.refresh_always ? 1.0 : spec_.refresh_tol_m - moved;
    // a fold of the displaced ring: remesh where it starts (a step function;
    // CVODE's root finding brackets its switch like any sign change)
    g[6] = cell_folds(ring, cell_.size()) ? -1.0 : 1.0;
    // an element turning over: remesh when one has turned by 90 deg from its
    // direction at the last remesh (continuous in y)
    g[7] = min_element_projection(cell_.base(), ring, cell_.size());
  }

  std::exception_ptr error;  // set by a callback that failed

 private:
  double moved_since_drive() const {
    double moved = 0;
    for (int i = 0; i < cell_.size(); ++i) moved = std::max(moved, std::abs(y_[i] - y_drive_[i]));
    return moved;
  }

  /// A charge drive at the current state: new rates, shifted history.
  void drive(double revolutions) {
    r_prev_ = r_now_;
    y_prev_ = y_drive_;
    have_prev_ = !r_prev_.empty();
    sample_at(y_.data(), revolutions);
    y_drive_ = y_;
  }

  void sample_at(const double* y, double revolutions) {
    const LinerSurface ring = cell_.displaced(y);
    try {
      last_ = rates_.sample(ring, revolutions);
    } catch (const SimulationError& e) {
      // when along the life the charge model failed (a review, 2026-12-06:
      // "no room left for a landing element" alone, from 1,900 h of wear)
      throw SimulationError(fmt::format("at {:.0f} operating hours, on the liner worn so far: {}", t_ / 3600.0, e.what()));
    }
    if (static_cast<int>(last_.element_rate_m_s.size()) != ring.n_elements())
      throw std::logic_error("rate provider: one rate per element expected");
    for (double r : last_.element_rate_m_s)
      if (!std::isfinite(r) || r < 0)
        throw SimulationError(fmt::format("the charge/wear model returned a recession rate of {} m/s at {:.0f} "
                                          "operating hours; rates must be finite and >= 0",
                                          r, t_ / 3600.0));
    r_now_ = cell_.cell_rates(ring, last_.element_rate_m_s, smoothing_passes_);
    ++res_.stats.charge_redrives;
    add_drive_notes(res_.notes, last_.notes, res_.stats.charge_redrives);
    res_.stats.charge_wall_s += last_.wall_s;
    res_.stats.charge_simulated_s += last_.simulated_s;
  }

  Gauge gauge_now() const { return gauge(cell_.displaced(y_.data()), cell_.period(), in_.rotation, in_.density_kg_m3); }

  void record(double t_s) { record_ring(t_s, cell_.displaced(y_.data())); }

  /// A history and profile record of `ring` (a ring of the current cell's
  /// period) at operating time t_s, with the last drive's indicators.
  void record_ring(double t_s, const LinerSurface& ring) {
    const Gauge g = gauge(ring, cell_.period(), in_.rotation, in_.density_kg_m3);
    LifeRecord r;
    r.hours = t_s / 3600.0;
    r.lifter_height_m = g.lifter.lifter_height_m;
    r.crest_thickness_m = g.lifter.max_thickness_m;
    r.face_angle_leading_deg = g.lifter.face_angle_leading_deg;
    r.face_angle_trailing_deg = g.lifter.face_angle_trailing_deg;
    r.top_width_m = g.lifter.top_width_m;
    r.min_thickness_m = g.min_thickness;
    r.liner_mass_kg_per_m = g.mass_kg_per_m;
    if (g.low.design == 1) {
      r.low_lifter_height_m = g.low.lifter_height_m;
      r.low_face_angle_leading_deg = g.low.face_angle_leading_deg;
    }
    const Indicators& ind = last_.indicators;
    r.net_power_kw = last_.has_indicators ? ind.net_power_kw : kNaN;
    r.toe_deg = last_.has_indicators ? ind.toe_deg : kNaN;
    r.shoulder_deg = last_.has_indicators ? ind.shoulder_deg : kNaN;
    r.direct_impact_fraction = last_.has_indicators ? ind.direct_impact_fraction : kNaN;
    r.impact_fraction = last_.impact_fraction;
    res_.history.push_back(r);
    ProfileRecord p;
    p.hours = r.hours;
    for (int i = ring.segment_begin[0]; i <= ring.segment_begin[1]; ++i) p.nodes.push_back(ring.nodes[i % ring.n_nodes()]);
    res_.profiles.push_back(std::move(p));
    if (progress_) progress_(r.hours, crit_.progress(g0_, g));
  }

  /// The first criterion (in Criteria order) the current state meets, or -1.
  int criterion_met() const {
    double g[4];
    crit_.eval(gauge_now(), g);
    for (int i = 0; i < 4; ++i)
      if (g[i] <= 0) return i;
    return -1;
  }

  /// Whether an explicit step that ends at depths y on `cell` remeshes: every
  /// step (amplify), or as the ODE method's roots, at the remesh depth or
  /// where an element has turned by 90 deg.
  bool explicit_remesh_due(const Cell& cell, const std::vector<double>& y, bool every_step) const {
    if (every_step) return true;
    double ymax = 0;
    for (double v : y) ymax = std::max(ymax, v);
    return ymax > remesh_depth_ || min_element_projection(cell.base(), cell.displaced(y.data()), cell.size()) <= 0;
  }

  /// The ring an explicit step from the current cell would leave if it ended
  /// at depths y: remeshed where a step ending there would remesh
  /// (explicit_remesh_due), else the displaced ring. The current cell is
  /// unchanged. The output rows inside a step and the step's criteria are
  /// read on it, so a criterion is found on the state that is reported.
  LinerSurface explicit_ring(const std::vector<double>& y, bool remesh_every_step) const {
    if (!explicit_remesh_due(cell_, y, remesh_every_step)) return cell_.displaced(y.data());
    Cell c = cell_;
    c.remesh(y.data(), opt_);
    const std::vector<double> zero(static_cast<size_t>(c.size()), 0.0);
    return c.displaced(zero.data());
  }

  /// The record of an output time inside an explicit step, at the depths y
  /// of that time: the ring as the step would leave it there.
  void record_explicit(double t_s, const std::vector<double>& y, bool remesh_every_step) {
    record_ring(t_s, explicit_ring(y, remesh_every_step));
  }

  /// Remeshes at the current depths and carries the drive history onto the
  /// new nodes, so the rate model continues across the remesh without a new
  /// charge drive: the rates by closest point, the drive states as depths
  /// relative to the new profile (y_drive - y, <= 0: the profile at the drive
  /// lay that far outside the current one).
  void do_remesh() {
    const LinerSurface old_ring = cell_.displaced(y_.data());
    const int old_cell = cell_.size();
    std::vector<double> rel_drive(y_drive_), rel_prev(y_prev_);
    for (int i = 0; i < old_cell; ++i) {
      rel_drive[i] -= y_[i];
      if (!rel_prev.empty()) rel_prev[i] -= y_[i];
    }
    const SegmentRemesh st = cell_.remesh(y_.data(), opt_);
    (void)st;  // worn-through is a criterion (root), caught before a remesh reaches the shell
    r_now_ = cell_.transfer(old_ring, old_cell, r_now_);
    y_drive_ = cell_.transfer(old_ring, old_cell, rel_drive);
    if (have_prev_) {
      r_prev_ = cell_.transfer(old_ring, old_cell, r_prev_);
      y_prev_ = cell_.transfer(old_ring, old_cell, rel_prev);
    }
    y_.assign(static_cast<size_t>(cell_.size()), 0.0);
    ++res_.stats.remeshes;
  }

  void finish(double t_s, const std::string& criterion, bool reached) {
    t_ = t_s;
    res_.reached = reached;
    res_.criterion = criterion;
    res_.operating_hours = t_s / 3600.0;
    record(t_s);
  }

  // --- output times: every output_interval_h, and exactly at the extra times ---
  double next_output() const {
    return next_extra_ < extra_.size() ? std::min(next_regular_, extra_[next_extra_]) : next_regular_;
  }
  void advance_output() {  // past every output time already reached
    while (next_extra_ < extra_.size() && extra_[next_extra_] <= t_ * (1 + 1e-12)) ++next_extra_;
    while (next_regular_ <= t_ * (1 + 1e-12)) next_regular_ += spec_.output_interval_h * 3600.0;
  }

  // --- checkpoints: right after a drive or remesh, where the integrator restarts ---
  void maybe_checkpoint() {
    if (!hooks_.checkpoint) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_checkpoint_).count() < hooks_.checkpoint_interval_s) return;
    last_checkpoint_ = now;
    ForecastCheckpoint c;
    c.method = method_name(spec_.method);
    c.t_s = t_;
    c.y = y_;
    c.y_drive = y_drive_;
    c.y_prev = y_prev_;
    c.r_now = r_now_;
    c.r_prev = r_prev_;
    c.have_prev = have_prev_;
    c.next_regular_s = next_regular_;
    c.next_extra = static_cast<long long>(next_extra_);
    c.next_explicit_out_s = next_explicit_out_;
    c.base = cell_.base();
    c.has_indicators = last_.has_indicators;
    c.net_power_kw = last_.indicators.net_power_kw;
    c.toe_deg = last_.indicators.toe_deg;
    c.shoulder_deg = last_.indicators.shoulder_deg;
    c.direct_impact_fraction = last_.indicators.direct_impact_fraction;
    c.impact_fraction = last_.impact_fraction;
    c.provider_drives = rates_.drive_count();
    c.history = res_.history;
    c.profiles = res_.profiles;
    c.stats = res_.stats;
    c.notes = res_.notes;
    c.stats.wall_s += std::chrono::duration<double>(now - wall0_).count();
    hooks_.checkpoint(c);
  }

  void restore(const ForecastCheckpoint& c) {
    if (c.method != method_name(spec_.method))
      throw InputError("--resume", fmt::format("the checkpoint is of a {} forecast, this run asks for {}", c.method,
                                               method_name(spec_.method)));
    const CheckpointProblem bad = checkpoint_problem(c, in_, spec_);
    if (!bad.ok())
      throw InputError("--resume", fmt::format("the checkpoint's {}: {} (a damaged checkpoint?)", bad.field, bad.what));
    cell_ = Cell(c.base, cell_.period());
    t_ = c.t_s;
    y_ = c.y;
    y_drive_ = c.y_drive;
    y_prev_ = c.y_prev;
    r_now_ = c.r_now;
    r_prev_ = c.r_prev;
    have_prev_ = c.have_prev;
    next_regular_ = c.next_regular_s;
    next_extra_ = static_cast<size_t>(c.next_extra);
    next_explicit_out_ = c.next_explicit_out_s;
    last_ = RateSample{};
    last_.has_indicators = c.has_indicators;
    last_.indicators.net_power_kw = c.net_power_kw;
    last_.indicators.toe_deg = c.toe_deg;
    last_.indicators.shoulder_deg = c.shoulder_deg;
    last_.indicators.direct_impact_fraction = c.direct_impact_fraction;
    last_.impact_fraction = c.impact_fraction;
    rates_.set_drive_count(c.provider_drives);
    res_.history = c.history;
    res_.profiles = c.profiles;
    res_.stats = c.stats;
    res_.notes = c.notes;
  }

  void run_ode();
  void run_explicit(double dt_s, double revolutions, bool remesh_every_step);

  const ForecastInput& in_;
  RateProvider& rates_;
  const ForecastSpec& spec_;
  const ForecastHooks& hooks_;
  ProgressFn progress_;
  std::vector<double> extra_;  // [s] extra output times, sorted
  size_t next_extra_ = 0;
  double next_regular_ = 0, next_explicit_out_ = 0;
  std::chrono::steady_clock::time_point wall0_, last_checkpoint_{};
  Cell cell_;
  Criteria crit_;
  RemeshOptions opt_;
  int smoothing_passes_ = 2;  // over each drive's rate field (smoothing_passes())
  double remesh_depth_ = 0;
  double t_ = 0;
  Gauge g0_;
  std::vector<double> y_, y_drive_, y_prev_, r_now_, r_prev_;
  bool have_prev_ = false;
  RateSample last_;
  ForecastResult res_;
};

// ---------------------------------------------------------------------------
// CVODE plumbing: every SUNDIALS return code goes through check(); callbacks
// never throw through C (they stash the exception and return -1).

thread_local std::string g_cvode_message;  // the last message of CVODE's error handler

void cvode_error_handler(int, const char* module, const char* function, char* msg, void*) {
  g_cvode_message = fmt::format("{} {}: {}", module ? module : "", function ? function : "", msg ? msg : "");
}

void check(int flag, const char* call, double t_s) {
  if (flag >= 0) return;
  // CVodeGetReturnFlagName returns a malloc'ed string the caller frees (ASan: leak)
  char* raw = CVodeGetReturnFlagName(flag);
  const std::string name = raw ? raw : "?";
  std::free(raw);
  std::string hint;
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      hint = "the wear-rate field changes too fast for the step budget: raise rtol or refresh_tol_m, or average more "
             "revolutions per drive so the rates are less noisy";
      break;
    case CV_ERR_FAILURE:
    case CV_CONV_FAILURE:
      hint = "repeated error-test or convergence failures: the rate field is probably noisy or discontinuous; average "
             "more revolutions per drive, raise rate_smoothing_m, or use rate_model = \"frozen\"";
      break;
    case CV_RHSFUNC_FAIL:
    case CV_RTFUNC_FAIL:
      hint = "the charge/wear model failed inside the integration (see above)";
      break;
    default:
      hint = "an integrator error";
  }
  std::string detail = g_cvode_message.empty() ? "" : " (" + g_cvode_message + ")";
  g_cvode_message.clear();
  throw SimulationError(fmt::format("CVODE {} failed with {} at {:.1f} operating hours{}: {}", call,
                                    name, t_s / 3600.0, detail, hint));
}

template <class T>
T* check_ptr(T* p, const char* what) {
  if (!p) throw std::runtime_error(fmt::format("SUNDIALS could not create {}", what));
  return p;
}

struct Sundials {
  SUNContext ctx = nullptr;
  void* mem = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  Sundials() { check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create", 0); }
  void release() {
    if (mem) CVodeFree(&mem);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    mem = nullptr;
    NLS = nullptr;
    LS = nullptr;
    A = nullptr;
    y = nullptr;
  }
  ~Sundials() {
    release();
    if (ctx) SUNContext_Free(&ctx);
  }
};

int rhs_callback(realtype, N_Vector y, N_Vector ydot, void* user) {
  Life* life = static_cast<Life*>(user);
  try {
    life->rhs(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
  } catch (...) {
    life->error = std::current_exception();
    return -1;
  }
}

int root_callback(realtype, N_Vector y, realtype* g, void* user) {
  Life* life = static_cast<Life*>(user);
  try {
    life->roots(N_VGetArrayPointer(y), g);
    return 0;
  } catch (...) {
    life->error = std::current_exception();
    return -1;
  }
}

void Life::run_ode() {
  Sundials s;
  const double horizon = spec_.max_operating_hours * 3600.0;
  ForecastStats& st = res_.stats;
  // CVODE's counters restart at every CVodeInit and CVodeReInit: add them up first
  auto collect = [&] {
    if (!s.mem) return;
    long int v = 0;
    check(CVodeGetNumSteps(s.mem, &v), "CVodeGetNumSteps", t_);
    st.cvode_steps += v;
    check(CVodeGetNumRhsEvals(s.mem, &v), "CVodeGetNumRhsEvals", t_);
    st.rhs_evals += v;
    check(CVodeGetNumErrTestFails(s.mem, &v), "CVodeGetNumErrTestFails", t_);
    st.error_test_failures += v;
    check(CVodeGetNumNonlinSolvConvFails(s.mem, &v), "CVodeGetNumNonlinSolvConvFails", t_);
    st.nonlinear_failures += v;
  };
  // (Re)creates the integrator for the current state size: after a remesh the
  // node count changes, so a CVodeReInit is not enough.
  auto start = [&] {
    collect();
    s.release();
    const sunindextype n = cell_.size();
    s.y = check_ptr(N_VNew_Serial(n, s.ctx), "an N_Vector");
    std::copy(y_.begin(), y_.end(), N_VGetArrayPointer(s.y));
    const bool bdf = spec_.integrator == "bdf";
    s.mem = check_ptr(CVodeCreate(bdf ? CV_BDF : CV_ADAMS, s.ctx), "CVODE");
    check(CVodeSetErrHandlerFn(s.mem, cvode_error_handler, nullptr), "CVodeSetErrHandlerFn", t_);
    check(CVodeInit(s.mem, rhs_callback, t_, s.y), "CVodeInit", t_);
    check(CVodeSetUserData(s.mem, this), "CVodeSetUserData", t_);
    check(CVodeSStolerances(s.mem, spec_.rtol, spec_.atol), "CVodeSStolerances", t_);
    check(CVodeSetMaxNumSteps(s.mem, 20000), "CVodeSetMaxNumSteps", t_);
    if (bdf) {
      s.A = check_ptr(SUNDenseMatrix(n, n, s.ctx), "a dense matrix");
      s.LS = check_ptr(SUNLinSol_Dense(s.y, s.A, s.ctx), "a dense linear solver");
      check(CVodeSetLinearSolver(s.mem, s.LS, s.A), "CVodeSetLinearSolver", t_);
    } else {
      s.NLS = check_ptr(SUNNonlinSol_FixedPoint(s.y, 0, s.ctx), "a fixed-point solver");
      check(CVodeSetNonlinearSolver(s.mem, s.NLS), "CVodeSetNonlinearSolver", t_);
    }
    check(CVodeRootInit(s.mem, kRoots, root_callback), "CVodeRootInit", t_);
    int dir[kRoots] = {-1, -1, -1, -1, -1, -1, -1, -1};
    check(CVodeSetRootDirection(s.mem, dir), "CVodeSetRootDirection", t_);
  };
  auto reinit = [&] {
    collect();
    std::copy(y_.begin(), y_.end(), N_VGetArrayPointer(s.y));
    check(CVodeReInit(s.mem, t_, s.y), "CVodeReInit", t_);
  };
  auto stop = [&](double t_end, const std::string& criterion, bool reached) {
    collect();
    s.release();
    finish(t_end, criterion, reached);
  };

  start();
  while (true) {
    const double next_out = next_output();
    // an event can land on an output time: record it before asking CVODE for
    // an interval it would call too short
    if (t_ >= next_out * (1 - 1e-12) && next_out < horizon) {
      record(t_);
      advance_output();
      continue;
    }
    const double tout = std::min(next_out, horizon);
    realtype t = t_;
    const int flag = CVode(s.mem, tout, s.y, &t, CV_NORMAL);
    if (error) std::rethrow_exception(error);
    check(flag, "CVode", t_);
    t_ = t;
    std::copy(N_VGetArrayPointer(s.y), N_VGetArrayPointer(s.y) + cell_.size(), y_.begin());
    if (flag == CV_ROOT_RETURN) {
      int found[kRoots] = {0};
      check(CVodeGetRootInfo(s.mem, found), "CVodeGetRootInfo", t_);
      int criterion = -1;
      for (int i = 0; i < 4 && criterion < 0; ++i)
        if (found[i]) criterion = i;
      if (criterion >= 0) {
        stop(t_, Criteria::name(criterion), true);
        return;
      }
      // A remesh and a refresh can fall on the same step, and after a restart
      // a refresh condition sitting exactly at zero is not seen as a crossing:
      // decide the refresh from the state, not from the root flag alone.
      const bool remeshed = found[4] != 0 || found[6] != 0 || found[7] != 0;
      if (remeshed) {
        do_remesh();
        // The remesh can itself meet a criterion (it removes loops and
        // resamples the crest). CVODE restarts below with root directions -1,
        // and a criterion function that starts at or below 0 never crosses
        // again: check the criteria on the remeshed state and end here.
        const int met = criterion_met();
        if (met >= 0) {
          stop(t_, Criteria::name(met), true);
          return;
        }
      }
      if (spec_.refresh_always ? remeshed : (found[5] || moved_since_drive() >= (1 - 1e-6) * spec_.refresh_tol_m))
        drive(spec_.revolutions_per_drive);
      if (remeshed)
        start();
      else
        reinit();
      maybe_checkpoint();
      continue;
    }
    // an output time or the horizon
    if (t_ >= horizon * (1 - 1e-12)) {
      stop(horizon, "horizon", false);
      return;
    }
    record(t_);
    advance_output();
  }
}

// ---------------------------------------------------------------------------
// Explicit methods: Euler with feedback, and the thesis' amplification.

void Life::run_explicit(double dt_s, double revolutions, bool remesh_every_step) {
  const double horizon = spec_.max_operating_hours * 3600.0;
  const double out_dt = spec_.output_interval_h * 3600.0;
  if (spec_.method == ForecastMethod::Amplify && !hooks_.resume) {
    // the first drive already happened with revolutions_per_drive; the thesis
    // method drives over its own short window
    drive(revolutions);
  }
  // Within a step the wear is linear in time (rate x time, the rates fixed
  // at the step's start): the state at a fraction f of the step is
  // y + f r h exactly. The outputs inside a step and the criterion crossing
  // are placed on that line.
  auto state_at = [&](double f, double h) {
    std::vector<double> yf(y_);
    for (int i = 0; i < cell_.size(); ++i) yf[i] += f * r_now_[i] * h;
    return yf;
  };
  // the output times before t_end (exclusive), each at the state of its own
  // time within the step from t_ (length h), remeshed as the step's end would
  // be: one row per output time, hours increasing
  auto record_outputs_before = [&](double t_end, double h) {
    while (next_explicit_out_ < t_end * (1 - 1e-12)) {
      if (next_explicit_out_ > t_) record_explicit(next_explicit_out_, state_at((next_explicit_out_ - t_) / h, h),
                                                   remesh_every_step);
      next_explicit_out_ += out_dt;
    }
  };
  // The criteria at a fraction f of the step from t_ (length h), on the ring
  // the step would leave if it ended there (explicit_ring()); the index of
  // the criterion met (the one furthest past its limit), or -1.
  auto crossed_at = [&](double f, double h, double* g) {
    crit_.eval(gauge(explicit_ring(state_at(f, h), remesh_every_step), cell_.period(), in_.rotation,
                     in_.density_kg_m3),
               g);
    int which = -1;
    for (int i = 0; i < 4; ++i)
      if (g[i] <= 0 && (which < 0 || g[i] < g[which])) which = i;
    return which;
  };
  while (t_ < horizon) {
    // the last step ends on the horizon: a life beyond it is not reached,
    // and the state at the horizon is the one reported for it
    const bool last = horizon - t_ <= dt_s * (1 + 1e-9);
    const double h = last ? horizon - t_ : dt_s;
    const std::vector<double> y_new = state_at(1.0, h);
    ++res_.stats.explicit_steps;
    // The criteria are not monotone in the step fraction on a long step
    // (amplify, a coarse Euler step): the remeshed profile can lay its face
    // back past the limit and then lose the lifter, so that the step's end
    // reads serviceable again. The step is therefore read at fractions at
    // most one remesh depth of wear apart (the ODE method's remesh interval;
    // one sample, the step's end, when the whole step wears less), and the
    // first sample where a criterion is met brackets the crossing with the
    // sample before it.
    double move = 0;
    for (int i = 0; i < cell_.size(); ++i) move = std::max(move, r_now_[i] * h);
    const int samples = static_cast<int>(std::clamp(std::ceil(move / remesh_depth_ * (1 - 1e-9)), 1.0, 1e4));
    int first = -1;
    double lo = 0, hi = 1, g_lo[4], g_hi[4];
    crit_.eval(gauge(explicit_ring(y_, remesh_every_step), cell_.period(), in_.rotation, in_.density_kg_m3), g_lo);
    for (int k = 1; k <= samples; ++k) {
      hi = static_cast<double>(k) / samples;
      first = crossed_at(hi, h, g_hi);
      if (first >= 0) break;
      lo = hi;
      std::copy(g_hi, g_hi + 4, g_lo);
    }
    if (first >= 0) {
      // The crossing inside the bracket [lo, hi]: a first guess by linear
      // interpolation of the criterion, then bisection of the step fraction
      // to 1e-6 of the step on the same readings, so that the end state (the
      // ring at hi, remeshed as the step would leave it) meets the criterion
      // it is reported for.
      int w = -1;
      double g[4];
      const double guess =
          g_lo[first] > g_hi[first] ? lo + (hi - lo) * g_lo[first] / (g_lo[first] - g_hi[first]) : hi;
      if (guess > lo && guess < hi) {
        if ((w = crossed_at(guess, h, g)) >= 0) hi = guess, first = w;
        else lo = guess;
      }
      while (hi - lo > 1e-6) {
        const double mid = 0.5 * (lo + hi);
        if ((w = crossed_at(mid, h, g)) >= 0) hi = mid, first = w;
        else lo = mid;
      }
      const double t_end = last && hi == 1.0 ? horizon : t_ + hi * h;
      record_outputs_before(t_end, h);
      y_ = state_at(hi, h);
      // the end profile is the ring the criterion was read on: remeshed where
      // the step would remesh (on a long step the displaced ring folds, and
      // the loops are material that the step wore away)
      if (explicit_remesh_due(cell_, y_, remesh_every_step)) do_remesh();
      finish(t_end, Criteria::name(first), true);
      return;
    }
    const double t_end = last ? horizon : t_ + h;
    record_outputs_before(t_end, h);
    y_ = y_new;
    t_ = t_end;
    // as the ODE method's roots: the depth, and an element turned by 90 deg
    // (checked after the step, so a turned element never reaches a drive)
    if (explicit_remesh_due(cell_, y_, remesh_every_step)) {
      do_remesh();
      // a criterion the remesh itself meets ends the life here, as in run_ode
      // (the step's last sample already read this remeshed ring: a guard)
      const int met = criterion_met();
      if (met >= 0) {
        finish(t_, Criteria::name(met), true);
        return;
      }
    }
    if (last) break;  // the horizon: finish() records it
    // the output time at the step's end, after its remesh
    if (next_explicit_out_ <= t_ * (1 + 1e-12)) {
      record(t_);
      while (next_explicit_out_ <= t_ * (1 + 1e-12)) next_explicit_out_ += out_dt;
    }
    drive(revolutions);
    maybe_checkpoint();
  }
  finish(horizon, "horizon", false);
}

}  // namespace

CheckpointProblem checkpoint_problem(const ForecastCheckpoint& c, const ForecastInput& in, const ForecastSpec& spec) {
  auto bad = [](const char* field, std::string what) { return CheckpointProblem{field, std::move(what)}; };
  const LinerSurface& b = c.base;
  const LinerSurface& s0 = *in.initial;
  if (!(std::isfinite(b.shell_radius_m) && b.shell_radius_m == s0.shell_radius_m))
    return bad("shell_radius_m", fmt::format("{} m; the liner's shell radius is {} m", b.shell_radius_m,
                                             s0.shell_radius_m));
  if (b.segments != s0.segments)
    return bad("segments", fmt::format("{}; the liner has {} segments", b.segments, s0.segments));
  const size_t nseg = static_cast<size_t>(s0.segments);
  if (b.segment_begin.size() != nseg + 1)
    return bad("base_segment_begin", fmt::format("{} entries; {} expected (segments + 1)", b.segment_begin.size(),
                                                 nseg + 1));
  if (b.segment_begin[0] != 0) return bad("base_segment_begin", fmt::format("starts at {}; must start at 0", b.segment_begin[0]));
  for (size_t k = 0; k < nseg; ++k)
    if (b.segment_begin[k + 1] <= b.segment_begin[k])
      return bad("base_segment_begin", fmt::format("entry {} is {} after {}; the entries must increase", k + 1,
                                                   b.segment_begin[k + 1], b.segment_begin[k]));
  if (static_cast<size_t>(b.segment_begin[nseg]) != b.nodes.size())
    return bad("base_segment_begin", fmt::format("ends at {}; the ring has {} nodes (base_nodes)", b.segment_begin[nseg],
                                                 b.nodes.size()));
  for (const Eigen::Vector2d& q : b.nodes)
    if (!q.allFinite()) return bad("base_nodes", "a coordinate that is not a finite number");
  if (b.segment_design.size() != nseg)
    return bad("base_segment_design", fmt::format("{} entries; the liner has {} segments", b.segment_design.size(), nseg));
  for (size_t k = 0; k < nseg; ++k)
    if (b.segment_design[k] != s0.segment_design[k])
      return bad("base_segment_design", fmt::format("entry {} is {}; the liner's segment {} has design {}", k,
                                                    b.segment_design[k], k, s0.segment_design[k]));
  const int p = pattern_period(s0);
  const int n = b.segment_begin[static_cast<size_t>(p)];
  if (static_cast<size_t>(n) * (nseg / static_cast<size_t>(p)) != b.nodes.size())
    return bad("base_segment_begin", fmt::format("the ring of {} nodes is not its first {} segment(s) ({} nodes) "
                                                 "repeated",
                                                 b.nodes.size(), p, n));
  struct Vec {
    const char* name;
    const std::vector<double>* v;
    bool required, rate;
  };
  for (const Vec& v : {Vec{"y", &c.y, true, false}, Vec{"y_drive", &c.y_drive, true, false},
                       Vec{"r_now", &c.r_now, true, true}, Vec{"y_prev", &c.y_prev, c.have_prev, false},
                       Vec{"r_prev", &c.r_prev, c.have_prev, true}}) {
    if (v.v->size() != static_cast<size_t>(n) && (v.required || !v.v->empty()))
      return bad(v.name, fmt::format("{} values; the stored ring's cell has {} nodes{}", v.v->size(), n,
                                     v.required ? "" : " (or none, without have_prev)"));
    for (double x : *v.v)
      if (!std::isfinite(x) || (v.rate && x < 0))
        return bad(v.name, fmt::format("a value {}; must be finite{}", x, v.rate ? " and >= 0" : ""));
    // depths (against the stored ring; y_prev can be below 0 after a remesh)
    // never reach across the shell
    if (!v.rate)
      for (double x : *v.v)
        if (!(std::abs(x) <= b.shell_radius_m))
          return bad(v.name, fmt::format("a depth of {} m; allowed at most the shell radius ({} m) either way", x,
                                         b.shell_radius_m));
  }
  const double horizon = spec.max_operating_hours * 3600.0;
  if (!(c.t_s >= 0 && c.t_s <= horizon))
    return bad("t_s", fmt::format("{} s; allowed 0 <= t_s <= max_operating_hours ({} s)", c.t_s, horizon));
  if (!(std::isfinite(c.next_regular_s) && c.next_regular_s > 0))
    return bad("next_regular_s", fmt::format("{} s; must be finite and > 0", c.next_regular_s));
  if (!(std::isfinite(c.next_explicit_out_s) && c.next_explicit_out_s > 0))
    return bad("next_explicit_out_s", fmt::format("{} s; must be finite and > 0", c.next_explicit_out_s));
  long long extra = 0;
  for (double h : spec.extra_output_hours)
    if (h > 0) ++extra;
  if (c.next_extra < 0 || c.next_extra > extra)
    return bad("next_extra", fmt::format("{}; allowed 0 to {} (the extra output times)", c.next_extra, extra));
  if (c.history.size() != c.profiles.size())
    return bad("profile_hours", fmt::format("{} profiles for {} history records; one each expected",
                                            c.profiles.size(), c.history.size()));
  // The history so far (a NaN hour once crashed the resumed run's calendar):
  // hours from 0 up to the checkpoint's time, in order; the gauges finite and
  // inside the shell; the indicators finite or NaN (a drive without them).
  const double R = b.shell_radius_m, t_h = c.t_s / 3600.0;
  for (size_t i = 0; i < c.history.size(); ++i) {
    const double h = c.history[i].hours, prev = i == 0 ? 0.0 : c.history[i - 1].hours;
    if (!(h >= prev && h <= t_h * (1 + 1e-12) + 1e-9))
      return bad("history_hours", fmt::format("record {} at {} h after {} h; allowed in order from 0 to the "
                                              "checkpoint's {} h",
                                              i, h, prev, t_h));
  }
  for (size_t i = 0; i < c.history.size(); ++i) {
    const LifeRecord& r = c.history[i];
    if (!(c.profiles[i].hours == r.hours))
      return bad("profile_hours", fmt::format("profile {} at {} h; its history record is at {} h", i,
                                              c.profiles[i].hours, r.hours));
    for (const Eigen::Vector2d& q : c.profiles[i].nodes)
      if (!q.allFinite()) return bad("profile_nodes", fmt::format("profile {}: a coordinate that is not a finite number", i));
    struct Gauge {
      const char* name;
      double v;
    };
    for (const Gauge& g : {Gauge{"history_lifter_height_m", r.lifter_height_m},
                           Gauge{"history_crest_thickness_m", r.crest_thickness_m},
                           Gauge{"history_min_thickness_m", r.min_thickness_m}})
      if (!(std::abs(g.v) <= R))
        return bad(g.name, fmt::format("record {}: {} m; allowed a finite length within the shell radius ({} m)", i,
                                       g.v, R));
    // the low lifter of a hi-lo ring as the high one's; NaN on a uniform ring
    if (!(std::isnan(r.low_lifter_height_m) || std::abs(r.low_lifter_height_m) <= R))
      return bad("history_low_lifter_height_m",
                 fmt::format("record {}: {} m; allowed a finite length within the shell radius ({} m), or NaN", i,
                             r.low_lifter_height_m, R));
    if (!(r.liner_mass_kg_per_m >= 0 && std::isfinite(r.liner_mass_kg_per_m)))
      return bad("history_liner_mass_kg_per_m", fmt::format("record {}: {} kg/m; allowed finite and >= 0", i,
                                                            r.liner_mass_kg_per_m));
    for (const Gauge& g : {Gauge{"history_face_angle_leading_deg", r.face_angle_leading_deg},
                           Gauge{"history_face_angle_trailing_deg", r.face_angle_trailing_deg},
                           Gauge{"history_top_width_m", r.top_width_m}, Gauge{"history_net_power_kw", r.net_power_kw},
                           Gauge{"history_toe_deg", r.toe_deg}, Gauge{"history_shoulder_deg", r.shoulder_deg},
                           Gauge{"history_direct_impact_fraction", r.direct_impact_fraction},
                           Gauge{"history_impact_fraction", r.impact_fraction},
                           Gauge{"history_low_face_angle_leading_deg", r.low_face_angle_leading_deg}})
      if (std::isinf(g.v) || std::abs(g.v) > 1e9)
        return bad(g.name, fmt::format("record {}: {}; allowed a finite value of at most 1e9 (or NaN: not known)", i, g.v));
  }
  struct Attr {
    const char* name;
    double v;
  };
  for (const Attr& a : {Attr{"net_power_kw", c.net_power_kw}, Attr{"toe_deg", c.toe_deg},
                        Attr{"shoulder_deg", c.shoulder_deg}, Attr{"direct_impact_fraction", c.direct_impact_fraction},
                        Attr{"impact_fraction", c.impact_fraction}})
    if (std::isinf(a.v) || std::abs(a.v) > 1e9)
      return bad(a.name, fmt::format("the last drive's {}; allowed a finite value of at most 1e9 (or NaN: not known)",
                                     a.v));
  if (c.has_indicators && !std::isfinite(c.net_power_kw))
    return bad("net_power_kw", fmt::format("{} with has_indicators; must be a finite number", c.net_power_kw));
  for (double x : {c.stats.wall_s, c.stats.charge_wall_s, c.stats.charge_simulated_s})
    if (!(x >= 0 && std::isfinite(x)))
      return bad("stats_double", fmt::format("a value {}; allowed finite and >= 0", x));
  for (long long x : {static_cast<long long>(c.stats.charge_redrives), static_cast<long long>(c.stats.remeshes),
                      c.stats.cvode_steps, c.stats.rhs_evals, c.stats.error_test_failures, c.stats.nonlinear_failures,
                      static_cast<long long>(c.stats.explicit_steps)})
    if (x < 0) return bad("stats_int", fmt::format("a count of {}; allowed >= 0", x));
  if (!(c.provider_drives >= 0 && c.provider_drives <= (1LL << 40)))
    return bad("provider_drives", fmt::format("{}; allowed 0 to 2^40", c.provider_drives));
  return {};
}

ForecastResult run_forecast(const ForecastInput& in, RateProvider& rates, const ForecastSpec& spec,
                            const ForecastHooks& hooks) {
  if (!in.initial) throw std::invalid_argument("run_forecast: no initial surface");
  Life life(in, rates, spec, hooks);
  return life.run();
}

ForecastResult run_forecast(const ForecastInput& in, RateProvider& rates, const ForecastSpec& spec,
                            const ProgressFn& progress) {
  ForecastHooks hooks;
  hooks.progress = progress;
  return run_forecast(in, rates, spec, hooks);
}

}  // namespace linerlife
