// Remesh-interval study of the coupled wear run (issue 4 §4; the default
// [wear] remesh_every_steps comes from it, docs/models/wear.md §6.2).
//
// The bundled Qiu mill is worn for 1.5 revolutions with the synthetic
// test-double loads (bench/synthetic_charge.h), amplification A, remeshing
// every k steps for k from 1 (the reference: every charge time step, as the
// thesis does) to once per run (a remesh still happens whenever a node has
// receded half an element), without smoothing and with the default csaps,
// with and without feedback. Reports the final lifter height, leading face
// angle, mass lost, the largest distance of the final profile of liner 0
// from the reference one, the mass balance and the wall time.
//
// Usage: bench_wear_remesh_interval [amplification] [runs]
//   default 1e6 (1.5 revolutions ~ 100 days); wall times are medians of `runs` (default 5) runs
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "bench/synthetic_charge.h"
#include "bench/wear_common.h"
#include "geometry/metrics.h"

using namespace linerlife;

namespace {

/// Largest distance of a node of `a` from the polyline `b` (segment 0 only).
double profile_distance(const LinerSurface& a, const LinerSurface& b) {
  double worst = 0;
  for (int i = a.segment_begin[0]; i <= a.segment_begin[1]; ++i) {
    const Eigen::Vector2d& p = a.nodes[i % a.n_nodes()];
    double d = std::numeric_limits<double>::max();
    for (int j = b.segment_begin[0]; j < b.segment_begin[1]; ++j) {
      const Eigen::Vector2d q0 = b.nodes[j], q1 = b.nodes[(j + 1) % b.n_nodes()];
      const Eigen::Vector2d ab = q1 - q0;
      const double t = std::clamp((p - q0).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      d = std::min(d, (q0 + t * ab - p).norm());
    }
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  const double amp = argc > 1 ? std::atof(argv[1]) : 1e6;
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  auto timed = [&](const WearRunInput& in, double& wall) {  // the result, and the median wall time of `runs` runs
    std::vector<double> t;
    WearRunResult r;
    for (int i = 0; i < runs; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      r = run_wear(in, bench::synthetic_entry());
      t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    wall = t[t.size() / 2];
    return r;
  };
  const Config c = load_default_config();
  WearRunInput base = bench::wear_input(c);
  base.wear.amplification_abrasion = base.wear.amplification_impact = amp;
  base.wear.snapshots = 0;
  std::printf(
      "# Qiu mill, synthetic loads, %.2f revolutions, dt = %g s, amplification %g, liner_computation one; "
      "wall_s: median of %d runs\n",
      base.wear.revolutions, base.model.time_step_s, amp, runs);
  for (int variant = 0; variant < 4; ++variant) {
    const bool feedback = variant % 2 == 1;
    base.wear.feedback = feedback;
    base.wear.smoothing.method = variant < 2 ? SmoothingMethod::None : SmoothingMethod::Csaps;
    std::printf("\n## smoothing %s, feedback %s\n", smoothing_method_name(base.wear.smoothing.method),
                feedback ? "on (a drive after every remesh)" : "off");
    std::printf("%6s %9s %9s %11s %11s %12s %12s %9s %9s\n", "k", "remeshes", "drives", "height_m", "face_deg",
                "mass_kg_m", "dist_ref_mm", "mb_err", "wall_s");
    LinerSurface ref;
    for (int k : {1, 2, 5, 10, 20, 50, 100, 200, 1000}) {
      WearRunInput in = base;
      in.wear.remesh_every_steps = k;
      double wall = 0;
      const WearRunResult r = timed(in, wall);
      if (k == 1) ref = r.final;
      const SegmentMetrics m = segment_metrics(r.final, 0, in.mill.rotation, in.material.density_kg_m3);
      std::printf("%6d %9d %9d %11.5f %11.3f %12.3f %12.4f %9.2e %9.3f\n", k, r.remeshes + r.fast_remeshes,
                  r.charge_drives, m.lifter_height_m, m.face_angle_leading_deg, r.mass_loss_kg_per_m,
                  1e3 * std::max(profile_distance(r.final, ref), profile_distance(ref, r.final)),
                  r.mass_balance_rel_error, wall);
      std::fflush(stdout);
    }
  }
  // the thesis' nonlinear choice (Tukey 3RRSHRRSRR, then csaps): not linear, so
  // smoothing every remesh is not smoothing the whole, and it needs its mass corrected
  base.wear.feedback = false;
  base.wear.smoothing.method = SmoothingMethod::TukeyCsaps;
  base.wear.smoothing.tukey = "3RRSHRRSRR";
  std::printf("\n## smoothing tukey_csaps (3RRSHRRSRR), feedback off\n");
  std::printf("%6s %9s %11s %11s %12s %12s %14s %9s\n", "k", "remeshes", "height_m", "face_deg", "mass_kg_m",
              "dist_ref_mm", "smooth_corr", "wall_s");
  LinerSurface ref;
  for (int k : {1, 10, 100}) {
    WearRunInput in = base;
    in.wear.remesh_every_steps = k;
    double wall = 0;
    const WearRunResult r = timed(in, wall);
    if (k == 1) ref = r.final;
    const SegmentMetrics m = segment_metrics(r.final, 0, in.mill.rotation, in.material.density_kg_m3);
    std::printf("%6d %9d %11.5f %11.3f %12.3f %12.4f %14.4f %9.3f\n", k, r.remeshes + r.fast_remeshes,
                m.lifter_height_m, m.face_angle_leading_deg, r.mass_loss_kg_per_m,
                1e3 * std::max(profile_distance(r.final, ref), profile_distance(ref, r.final)),
                r.smoothing_max_rel_change, wall);
    std::fflush(stdout);
  }
  return 0;
}
