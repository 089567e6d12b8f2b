#include "wear/wear_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "geometry/errors.h"
#include "geometry/metrics.h"
#include "wear/load_transfer.h"
#include "wear/recede.h"
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

/// Amplified volume rates [m2/s per m of mill length] of the three
/// contributions over the ring, and of each segment.
struct PartRates {
  double cf = 0, gf = 0, im = 0;
  std::vector<double> segment;
};

}  // namespace

double ring_area(const LinerSurface& s) {
  double a = 0;
  for (int k = 0; k < s.segments; ++k) a += segment_area(s, k);
  return a;
}

double max_recession(const LinerSurface& initial, const LinerSurface& worn, const std::vector<int>* only) {
  double worst = 0;
  const int n0 = initial.n_nodes();
  for (int k = 0; k < worn.segments && k < initial.segments; ++k) {
    if (only && std::find(only->begin(), only->end(), k) == only->end()) continue;
    const int b0 = initial.segment_begin[k], e0 = initial.segment_begin[k + 1];
    for (int i = worn.segment_begin[k]; i < worn.segment_begin[k + 1]; ++i) {
      const Eigen::Vector2d& p = worn.nodes[i];
      double d = std::numeric_limits<double>::max();
      for (int j = b0; j < e0; ++j)
        d = std::min(d, point_segment_distance(p, initial.nodes[j], initial.nodes[(j + 1) % n0]));
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
  double area = 0, area0 = 0;  // set below, once the representatives are known

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
    add_drive_notes(res.notes, charge.notes, res.charge_drives);
    steps_since_drive = 0;
    if (charge.loads.n_elements != s.n_elements())
      throw SimulationError(fmt::format("the charge model \"{}\" returned loads for {} elements on a surface of {}",
                                        entry.name, charge.loads.n_elements, s.n_elements()));
    if (wm.needs_impacts() && !charge.loads.has_impacts)
      throw SimulationError(
          fmt::format("the charge model \"{}\" returned no impacts although its table entry says "
                      "it resolves them",
                      entry.name));
    if (wm.needs_operating_point()) set_operating_point(wm, operating_point(in.mill, in.charge, &charge.indicators, s));
  };

  // ---- rates on the current surface
  LinerLoads loads;               // on `surface`; in "one" mode averaged onto the representatives
  std::vector<double> elem_rate;  // [m/s] amplified, per element of the full ring
  std::vector<double> node_rate;  // [m/s] amplified, per node; zero outside the representatives in "one" mode
  PartRates parts;
  const std::vector<int> reps = representative_segments(surface);
  const std::vector<int> counts = design_counts(surface);
  auto copies_area = [&](const LinerSurface& s) {  // ring area of a ring of copies of the representatives
    double a = 0;
    for (size_t d = 0; d < reps.size(); ++d) a += counts[d] * segment_area(s, reps[d]);
    return a;
  };
  const int rep_lo = *std::min_element(reps.begin(), reps.end());
  const int rep_hi = *std::max_element(reps.begin(), reps.end());
  double max_node_rate = 0;  // [m/s]
  auto update_rates = [&]() {
    recession_rates(wm, loads, surface, in.material, res.rates);  // on `surface` (res.rates_surface is set at the end)
    const int n = surface.n_elements();
    parts = PartRates{};
    parts.segment.assign(static_cast<size_t>(surface.segments), 0.0);
    auto add = [&](int i, int src, double copies) {  // element i with the rates of element src, counted `copies` times
      const double L = surface.length[i];
      const double r = elem_rate[src] = amplified_rate(wm, res.rates, src);
      parts.cf += copies * ws.amplification_abrasion * res.rates.centrifugal[src] * L;
      parts.gf += copies * ws.amplification_abrasion * res.rates.gravitational[src] * L;
      parts.im += copies * ws.amplification_impact * res.rates.impact[src] * L;
      return r * L;
    };
    elem_rate.assign(static_cast<size_t>(n), 0.0);
    node_rate.assign(static_cast<size_t>(n), 0.0);
    if (!one) {
      for (int i = 0; i < n; ++i) parts.segment[static_cast<size_t>(surface.element_segment[i])] += add(i, i, 1.0);
      node_rate = element_to_node_depth(surface, elem_rate);
    } else {
      // the representatives' elements stand for every liner of their design (the ring is made of their copies)
      for (size_t d = 0; d < reps.size(); ++d) {
        double seg = 0;
        for (int i = surface.segment_begin[reps[d]]; i < surface.segment_begin[reps[d] + 1]; ++i)
          seg += add(i, i, counts[d]);
        for (int k = 0; k < surface.segments; ++k)
          if ((surface.segment_design.empty() ? 0 : surface.segment_design[k]) == static_cast<int>(d))
            parts.segment[static_cast<size_t>(k)] = seg;
      }
      // node rates on the representatives and the edge node after them (element_to_node_depth's
      // length-weighted mean; the element before a node on a segment edge is the copy of a representative's last)
      auto rep_element = [&](int i) {  // the representative's element a ring element is a copy of
        const int k = surface.element_segment[i];
        const int r = reps[surface.segment_design.empty() ? 0 : surface.segment_design[k]];
        return surface.segment_begin[r] + (i - surface.segment_begin[k]);
      };
      const int b = surface.segment_begin[rep_lo], e = surface.segment_begin[rep_hi + 1];
      for (int i = b; i <= e && i < surface.n_nodes() + 1; ++i) {
        const int node = i % surface.n_nodes();
        const int ea = surface.prev(node), eb = node;
        const double la = surface.length[ea], lb = surface.length[eb];
        const double ra = elem_rate[rep_element(ea)], rb = elem_rate[rep_element(eb)];
        node_rate[node] = la + lb > 0 ? (ra * la + rb * lb) / (la + lb) : 0.5 * (ra + rb);
      }
    }
    max_node_rate = *std::max_element(node_rate.begin(), node_rate.end());
  };

  area = area0 = one ? copies_area(surface) : ring_area(surface);
  res.liner_mass_initial_kg_per_m = rho * area0;
  drive(surface);
  loads = one ? average_onto_representatives(charge.loads, surface) : charge.loads;
  update_rates();

  // ---- time stepping
  const double period = 60.0 / in.mill.speed_rpm;  // [s] one revolution
  const double total = ws.revolutions * period;
  const int n_steps = std::max(1, static_cast<int>(std::llround(total / in.model.time_step_s)));
  const double dt = total / n_steps;
  res.step_s = dt;
  std::vector<double> depth;
  double cum_cf = 0, cum_gf = 0, cum_im = 0;  // [m2 per m] commanded, up to the last remesh
  std::vector<double> per_segment(static_cast<size_t>(surface.segments), 0.0);  // [m2 per m] likewise
  int since =
      0;  // steps since the last remesh: their wear is rate x since x dt (the rates are constant between remeshes)
  double t = 0;

  res.snapshots.push_back({0.0, surface});
  std::vector<double> planned;
  for (int j = 1; j <= ws.snapshots; ++j) planned.push_back(total * j / (ws.snapshots + 1));
  size_t next_snapshot = 0;
  const int record_every = std::max(1, n_steps / 1000);
  res.history.segments = surface.segments;
  auto record = [&]() {  // the wear commanded up to now, including the steps not yet remeshed
    const double tau = since * dt;
    auto& hs = res.history;
    hs.time_s.push_back(t);
    hs.centrifugal_kg_per_m.push_back(rho * (cum_cf + parts.cf * tau));
    hs.gravitational_kg_per_m.push_back(rho * (cum_gf + parts.gf * tau));
    hs.impact_kg_per_m.push_back(rho * (cum_im + parts.im * tau));
    hs.total_kg_per_m.push_back(rho * (cum_cf + cum_gf + cum_im + (parts.cf + parts.gf + parts.im) * tau));
    for (size_t k = 0; k < per_segment.size(); ++k)
      hs.per_segment_kg_per_m.push_back(rho * (per_segment[k] + parts.segment[k] * tau));
  };
  record();

  const double max_step_depth = 0.5 * h;
  auto check_step = [&]() {
    if (!(dt * max_node_rate <= max_step_depth))
      throw SimulationError(
          fmt::format("one wear step of {:.4g} s removes up to {:.3g} m, more than half the element size ({} m): the "
                      "amplification (abrasion {:g}, impact {:g}) is too large for the step, or the wear laws' "
                      "constants ([liner] hardness_bhn, [wear]) make the wear that fast; lower the amplification or "
                      "the time step, or check the constants",
                      dt, dt * max_node_rate, h, ws.amplification_abrasion, ws.amplification_impact));
  };
  check_step();
  for (int step = 1; step <= n_steps; ++step) {
    t = step * dt;
    ++since;
    ++steps_since_drive;
    res.steps = step;
    // every step adds dt x rate to the depth of every node; a remesh applies the sum
    const double maxd = since * dt * max_node_rate;
    const bool due = since >= ws.remesh_every_steps || maxd + dt * max_node_rate > max_step_depth || step == n_steps;
    if (due && maxd > 0) {
      const auto t0 = Clock::now();
      const double tau = since * dt;
      depth.resize(node_rate.size());
      for (size_t i = 0; i < depth.size(); ++i) depth[i] = node_rate[i] * tau;
      // smooth the depth field of this remesh (the representatives, or the ring), conserving its volume
      if (ws.smoothing.method != SmoothingMethod::None) {
        const int b = one ? surface.segment_begin[rep_lo] : 0;
        const int e = one ? surface.segment_begin[rep_hi + 1] : surface.n_nodes();  // exclusive
        const int m = e - b;
        std::vector<double> y(depth.begin() + b, depth.begin() + e), sp(static_cast<size_t>(m)),
            w(static_cast<size_t>(m));
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
      bool fast = false;
      LinerSurface next;
      try {
        std::vector<std::vector<Eigen::Vector2d>> chains;
        if (one && recede_segments(surface, depth, in.remesh, reps, chains)) {
          fast = true;  // the representatives alone, then their copies
          next = replicate_chains(surface, chains);
        } else {
          rr = recede(surface, depth, in.remesh, &fast);
          next = one ? replicate_representatives(rr.surface) : std::move(rr.surface);
        }
      } catch (const std::runtime_error& e) {
        // the geometry could not be repaired (e.g. a steep wear step at a segment edge)
        throw SimulationError(
            fmt::format("the worn profile could not be remeshed at t = {:.3f} s ({}); smooth the "
                        "wear ([wear] smoothing) or remesh more often",
                        t, e.what()));
      }
      ++(fast ? res.fast_remeshes : res.remeshes);
      const double next_area = one ? copies_area(next) : ring_area(next);
      const double removed = area - next_area;  // [m2]
      area = next_area;
      const double c = parts.cf * tau, g = parts.gf * tau, im = parts.im * tau;
      if (c + g + im > 0) {
        res.mass_loss_centrifugal_kg_per_m += rho * removed * c / (c + g + im);
        res.mass_loss_gravitational_kg_per_m += rho * removed * g / (c + g + im);
        res.mass_loss_impact_kg_per_m += rho * removed * im / (c + g + im);
      }
      cum_cf += c;
      cum_gf += g;
      cum_im += im;
      for (size_t k = 0; k < per_segment.size(); ++k) per_segment[k] += parts.segment[k] * tau;
      since = 0;
      res.remesh_wall_s += seconds_since(t0);
      const bool redrive =
          ws.feedback && (ws.feedback_every_steps == 0 || steps_since_drive >= ws.feedback_every_steps);
      const LinerSurface previous = std::move(surface);
      surface = std::move(next);
      while (next_snapshot < planned.size() && planned[next_snapshot] <= t + 1e-12) {
        res.snapshots.push_back({t, surface});
        ++next_snapshot;
      }
      if (rr.status == RemeshStatus::WornThrough || step == n_steps) {
        res.rates_surface = previous;  // the last rates were computed on it
        if (rr.status == RemeshStatus::WornThrough) {
          res.worn_through = true;
          res.message = rr.message;
          record();
          break;
        }
      } else {
        if (redrive) {
          drive(surface);
          loads = one ? average_onto_representatives(charge.loads, surface) : charge.loads;
        } else {
          loads = transfer_loads(loads, previous, surface, one ? &reps : nullptr);
        }
        update_rates();
        check_step();
      }
    } else if (due) {
      since = 0;  // nothing wore
    }
    if (step % record_every == 0 || step == n_steps) record();
    if (in.progress) in.progress(static_cast<double>(step) / n_steps);
  }

  if (res.rates_surface.n_nodes() == 0) res.rates_surface = surface;  // no remesh at the end: the rates are on it
  res.final = surface;
  if (res.snapshots.back().time_s < t || res.snapshots.size() == 1) res.snapshots.push_back({t, surface});
  res.liner_mass_final_kg_per_m = rho * area;
  res.mass_loss_kg_per_m = rho * (area0 - area);
  res.commanded_mass_kg_per_m = rho * (cum_cf + cum_gf + cum_im);  // every step's wear is remeshed by the end
  res.mass_balance_rel_error =
      res.commanded_mass_kg_per_m > 0 ? res.mass_loss_kg_per_m / res.commanded_mass_kg_per_m - 1.0 : 0.0;
  res.max_recession_m = max_recession(res.initial, res.final, one ? &reps : nullptr);
  res.simulated_s = t;
  res.wall_s = seconds_since(t_start);
  res.realtime_ratio = res.wall_s > 0 ? res.simulated_s / res.wall_s : 0.0;
  return res;
}

}  // namespace linerlife
