#include "wear/wear_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "geometry/errors.h"
#include "geometry/metrics.h"
#include "wear/load_transfer.h"
#include "wear/slip_models.h"

namespace linerlife {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

/// Per-element amplified volume rates [m2/s] of the three contributions.
struct PartRates {
  std::vector<double> cf, gf, im;  // [m2/s] per element, amplified
};

}  // namespace

double ring_area(const LinerSurface& s) {
  double a = 0;
  for (int k = 0; k < s.segments; ++k) a += segment_area(s, k);
  return a;
}

double max_recession(const LinerSurface& initial, const LinerSurface& worn) {
  double worst = 0;
  const int n0 = initial.n_nodes();
  for (int k = 0; k < worn.segments && k < initial.segments; ++k) {
    const int b0 = initial.segment_begin[k], e0 = initial.segment_begin[k + 1];
    for (int i = worn.segment_begin[k]; i < worn.segment_begin[k + 1]; ++i) {
      const Eigen::Vector2d& p = worn.nodes[i];
      double d = std::numeric_limits<double>::max();
      for (int j = b0; j < e0; ++j) d = std::min(d, point_segment_distance(p, initial.nodes[j], initial.nodes[(j + 1) % n0]));
      worst = std::max(worst, d);  // wear only removes material: every moved node lies inside the old body
    }
  }
  return worst;
}

WearRunResult run_wear(const WearRunInput& in, const ChargeModelEntry& entry) {
  const auto t_start = Clock::now();
  validate_liner_material(in.material);
  WearModel wm = make_wear_model(in.wear, entry);
  if (!(in.model.time_step_s > 0))
    throw InputError("model.time_step_s", fmt::format("time_step_s = {}: allowed > 0", in.model.time_step_s));
  if (!(in.mill.speed_rpm > 0)) throw InputError("mill.speed_rpm", "the wear run needs a mill speed > 0");
  const WearSpec& ws = in.wear;
  const bool one = ws.liner_computation == "one";
  const double h = in.remesh.element_size_m;
  const double rho = in.material.density_kg_m3;
  std::unique_ptr<ChargeModel> charge_model = entry.make();

  WearRunResult res;
  LinerSurface surface = one ? replicate_representatives(in.surface) : in.surface;
  res.initial = surface;
  res.liner_mass_initial_kg_per_m = metrics(surface, in.mill.rotation, rho).mass_kg_per_m;
  double area = ring_area(surface);
  const double area0 = area;

  // ---- drives of the charge model
  ChargeResult charge;
  int steps_since_drive = 0;
  auto drive = [&](const LinerSurface& s) {
    ChargeInput ci;
    ci.mill = in.mill;
    ci.charge = in.charge;
    ci.model = in.model;
    ci.surface = &s;
    ci.revolutions = ws.drive_revolutions;
    ci.seed = in.seed;
    const auto t0 = Clock::now();
    charge = charge_model->run(ci);
    res.charge_wall_s += seconds_since(t0);
    ++res.charge_drives;
    steps_since_drive = 0;
    if (charge.loads.n_elements != s.n_elements())
      throw SimulationError(fmt::format("the charge model \"{}\" returned loads for {} elements on a surface of {}",
                                        entry.name, charge.loads.n_elements, s.n_elements()));
    if (wm.needs_impacts() && !charge.loads.has_impacts)
      throw SimulationError(fmt::format("the charge model \"{}\" returned no impacts although its table entry says "
                                        "it resolves them",
                                        entry.name));
    if (wm.needs_operating_point())
      set_operating_point(wm, operating_point(in.mill, in.charge, &charge.indicators, s));
  };

  // ---- rates on the current surface
  LinerLoads loads;                  // on `surface`; in "one" mode averaged onto the representatives
  std::vector<double> elem_rate;     // [m/s] amplified, per element of the full ring
  std::vector<double> node_rate;     // [m/s] amplified, per node; zero outside the representatives in "one" mode
  PartRates parts;
  const std::vector<int> reps = representative_segments(surface);
  const int rep_lo = *std::min_element(reps.begin(), reps.end());
  const int rep_hi = *std::max_element(reps.begin(), reps.end());
  auto update_rates = [&]() {
    recession_rates(wm, loads, surface, in.material, res.rates);
    res.rates_surface = surface;
    const int n = surface.n_elements();
    elem_rate.assign(static_cast<size_t>(n), 0.0);
    parts.cf.assign(static_cast<size_t>(n), 0.0);
    parts.gf.assign(static_cast<size_t>(n), 0.0);
    parts.im.assign(static_cast<size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
      // in "one" mode every element takes the rate of its representative's element
      int src = i;
      if (one) {
        const int k = surface.element_segment[i];
        const int r = reps[surface.segment_design.empty() ? 0 : surface.segment_design[k]];
        src = surface.segment_begin[r] + (i - surface.segment_begin[k]);
      }
      elem_rate[i] = amplified_rate(wm, res.rates, src);
      parts.cf[i] = ws.amplification_abrasion * res.rates.centrifugal[src] * surface.length[i];
      parts.gf[i] = ws.amplification_abrasion * res.rates.gravitational[src] * surface.length[i];
      parts.im[i] = ws.amplification_impact * res.rates.impact[src] * surface.length[i];
    }
    node_rate = element_to_node_depth(surface, elem_rate);
    if (one) {
      const int b = surface.segment_begin[rep_lo], e = surface.segment_begin[rep_hi + 1];  // e: first node after
      for (int i = 0; i < surface.n_nodes(); ++i)
        if (i < b || i > e) node_rate[i] = 0;
    }
  };

  drive(surface);
  loads = one ? average_onto_representatives(charge.loads, surface) : charge.loads;
  update_rates();

  // ---- time stepping
  const double period = 60.0 / in.mill.speed_rpm;  // [s] one revolution
  const double total = ws.revolutions * period;
  const int n_steps = std::max(1, static_cast<int>(std::llround(total / in.model.time_step_s)));
  const double dt = total / n_steps;
  res.step_s = dt;
  std::vector<double> depth(static_cast<size_t>(surface.n_nodes()), 0.0);
  double since_cf = 0, since_gf = 0, since_im = 0;  // [m2] commanded since the last remesh
  double cum_cf = 0, cum_gf = 0, cum_im = 0;        // [m2] commanded since the start
  std::vector<double> per_segment(static_cast<size_t>(surface.segments), 0.0);  // [m2]
  int steps_since_remesh = 0;
  double t = 0;

  res.snapshots.push_back({0.0, surface});
  std::vector<double> planned;
  for (int j = 1; j <= ws.snapshots; ++j) planned.push_back(total * j / (ws.snapshots + 1));
  size_t next_snapshot = 0;
  const int record_every = std::max(1, n_steps / 1000);
  res.history.segments = surface.segments;
  auto record = [&]() {
    auto& hs = res.history;
    hs.time_s.push_back(t);
    hs.centrifugal_kg_per_m.push_back(rho * cum_cf);
    hs.gravitational_kg_per_m.push_back(rho * cum_gf);
    hs.impact_kg_per_m.push_back(rho * cum_im);
    hs.total_kg_per_m.push_back(rho * (cum_cf + cum_gf + cum_im));
    for (double v : per_segment) hs.per_segment_kg_per_m.push_back(rho * v);
  };
  record();

  const double max_step_depth = 0.5 * h;
  for (int step = 1; step <= n_steps; ++step) {
    // the wear of one step, applied to the profile
    double max_inc = 0, maxd = 0;
    for (size_t i = 0; i < depth.size(); ++i) {
      const double inc = dt * node_rate[i];
      max_inc = std::max(max_inc, inc);
      depth[i] += inc;
      maxd = std::max(maxd, depth[i]);
    }
    if (max_inc > max_step_depth)
      throw SimulationError(fmt::format(
          "one wear step of {:.4g} s removes up to {:.3g} m, more than half the element size ({} m): the "
          "amplification (abrasion {:g}, impact {:g}) is too large for the step; lower it or the time step",
          dt, max_inc, h, ws.amplification_abrasion, ws.amplification_impact));
    for (int i = 0; i < surface.n_elements(); ++i) {
      const double c = dt * parts.cf[i], g = dt * parts.gf[i], m = dt * parts.im[i];
      since_cf += c;
      since_gf += g;
      since_im += m;
      per_segment[static_cast<size_t>(surface.element_segment[i])] += c + g + m;
    }
    t = step * dt;
    ++steps_since_remesh;
    ++steps_since_drive;
    res.steps = step;
    const bool due = steps_since_remesh >= ws.remesh_every_steps || maxd >= max_step_depth || step == n_steps;
    if (due && maxd > 0) {
      const auto t0 = Clock::now();
      // smooth the depth field of this remesh (the representatives, or the ring), conserving its volume
      if (ws.smoothing.method != SmoothingMethod::None) {
        const int b = one ? surface.segment_begin[rep_lo] : 0;
        const int e = one ? surface.segment_begin[rep_hi + 1] : surface.n_nodes();  // exclusive
        const int m = e - b;
        std::vector<double> y(depth.begin() + b, depth.begin() + e), sp(static_cast<size_t>(m)), w(static_cast<size_t>(m));
        for (int q = 0; q < m; ++q) {
          const int i = b + q;
          sp[q] = surface.length[i];
          const int prev = q == 0 ? e - 1 : i - 1;  // periodic over the smoothed range
          w[q] = 0.5 * (surface.length[prev] + surface.length[i]);
        }
        const SmoothingResult sr = smooth_depth(y, sp, w, ws.smoothing, true);
        res.smoothing_max_rel_change = std::max(res.smoothing_max_rel_change, std::abs(sr.relative_change));
        for (int q = 0; q < m; ++q) depth[b + q] = sr.values[q];
        if (one && e < surface.n_nodes()) depth[e] = depth[b];  // the edge node after the representatives
      }
      RemeshResult rr;
      try {
        rr = remesh(surface, depth, in.remesh);
      } catch (const std::runtime_error& e) {
        // the geometry could not be repaired (e.g. a steep wear step at a segment edge)
        throw SimulationError(fmt::format("the worn profile could not be remeshed at t = {:.3f} s ({}); smooth the "
                                          "wear ([wear] smoothing) or remesh more often",
                                          t, e.what()));
      }
      LinerSurface next = one ? replicate_representatives(rr.surface) : rr.surface;
      const double next_area = ring_area(next);
      const double removed = area - next_area;  // [m2]
      area = next_area;
      const double since = since_cf + since_gf + since_im;
      if (since > 0) {
        res.mass_loss_centrifugal_kg_per_m += rho * removed * since_cf / since;
        res.mass_loss_gravitational_kg_per_m += rho * removed * since_gf / since;
        res.mass_loss_impact_kg_per_m += rho * removed * since_im / since;
      }
      cum_cf += since_cf;
      cum_gf += since_gf;
      cum_im += since_im;
      since_cf = since_gf = since_im = 0;
      ++res.remeshes;
      res.remesh_wall_s += seconds_since(t0);
      const bool redrive = ws.feedback && (ws.feedback_every_steps == 0 || steps_since_drive >= ws.feedback_every_steps);
      const LinerSurface previous = std::move(surface);
      surface = std::move(next);
      depth.assign(static_cast<size_t>(surface.n_nodes()), 0.0);
      steps_since_remesh = 0;
      while (next_snapshot < planned.size() && planned[next_snapshot] <= t + 1e-12) {
        res.snapshots.push_back({t, surface});
        ++next_snapshot;
      }
      if (rr.status == RemeshStatus::WornThrough) {
        res.worn_through = true;
        res.message = rr.message;
        record();
        break;
      }
      if (step < n_steps) {
        if (redrive) {
          drive(surface);
          loads = one ? average_onto_representatives(charge.loads, surface) : charge.loads;
        } else {
          loads = transfer_loads(loads, previous, surface);
        }
        update_rates();
      }
    } else if (due) {
      steps_since_remesh = 0;
    }
    if (step % record_every == 0 || step == n_steps) {
      // the commanded totals including the wear not yet remeshed
      const double c0 = cum_cf, g0 = cum_gf, i0 = cum_im;
      cum_cf += since_cf;
      cum_gf += since_gf;
      cum_im += since_im;
      record();
      cum_cf = c0;
      cum_gf = g0;
      cum_im = i0;
    }
    if (in.progress) in.progress(static_cast<double>(step) / n_steps);
  }

  res.final = surface;
  if (res.snapshots.back().time_s < t || res.snapshots.size() == 1) res.snapshots.push_back({t, surface});
  res.liner_mass_final_kg_per_m = metrics(surface, in.mill.rotation, rho).mass_kg_per_m;
  res.mass_loss_kg_per_m = rho * (area0 - area);
  res.commanded_mass_kg_per_m = rho * (cum_cf + cum_gf + cum_im);
  res.mass_balance_rel_error =
      res.commanded_mass_kg_per_m > 0 ? res.mass_loss_kg_per_m / res.commanded_mass_kg_per_m - 1.0 : 0.0;
  res.max_recession_m = max_recession(res.initial, res.final);
  res.simulated_s = t;
  res.wall_s = seconds_since(t_start);
  res.realtime_ratio = res.wall_s > 0 ? res.simulated_s / res.wall_s : 0.0;
  return res;
}

}  // namespace linerlife
