// Element-size convergence of the worn-profile metrics (issue 2 §6; the
// default liner.element_size_m in data/mills/qiu2001_sag.toml comes from it).
//
// The Qiu liner is worn by the same smooth spatial recession field (deeper on
// the leading side and at the top, the shape the layer model gives) in
// `steps` remeshes of 4 mm, at element sizes from 37.5 mm (the coarsest allowed) down to 2.5 mm. The
// finest run is the reference. Also reports the wall time of one remesh of the
// whole 64-row ring.
//
// Usage: bench_geometry_convergence [steps] [total_scale_m]
//   default 20 steps sharing a total recession scale of 0.08 m
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geometry/build_liner_surface.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"

using namespace linerlife;
using V = Eigen::Vector2d;

namespace {

double g_scale = 0.004;  // [m] recession scale of one step

double field(const V& p) {
  const double th = std::atan2(p.y(), p.x()), t = 5.18 - p.norm();
  return g_scale * (1.0 + 0.6 * std::tanh(th / 0.02)) * (0.3 + (t - 0.075) / 0.25);
}

struct Row {
  double h, height, lead, trail, top, area, ring_remesh_s;
  int nodes;
};

Row run(double h, int steps) {
  Mill m;
  m.diameter_m = 10.36;
  m.speed_rpm = 10.36;
  LinerDesign d;
  d.segments = 64;
  d.design = {0.075, 0.25, 0.15, 20, 20, 0};
  d.element_size_m = h;
  LinerSurface s = build_liner_surface(m, d);
  RemeshOptions opt;
  opt.element_size_m = h;
  for (int k = 0; k < steps; ++k) {
    std::vector<double> depth(s.n_nodes(), 0.0);
    for (int i = 0; i < s.n_nodes(); ++i)
      if (std::abs(std::atan2(s.nodes[i].y(), s.nodes[i].x())) < 1.5 * s.segment_angle_rad())
        depth[i] = field(s.nodes[i]);
    s = remesh(s, depth, opt).surface;
  }
  const SegmentMetrics sm = segment_metrics(s, 0, Rotation::Ccw, 7800);
  // one remesh of the whole ring (every node moving), timed
  const auto t0 = std::chrono::steady_clock::now();
  remesh(s, std::vector<double>(s.n_nodes(), 0.001), opt);
  const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {h, sm.lifter_height_m, sm.face_angle_leading_deg, sm.face_angle_trailing_deg, sm.top_width_m, sm.area_m2, dt,
          s.segment_size(0)};
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
  g_scale = (argc > 2 ? std::atof(argv[2]) : 0.08) / steps;
  const double sizes[] = {0.0375, 0.02, 0.01, 0.005, 0.0025};
  Row rows[5];
  for (int i = 0; i < 5; ++i) rows[i] = run(sizes[i], steps);
  const Row& ref = rows[4];
  std::printf("# %d wear steps; reference = 2.5 mm elements; errors relative to it\n", steps);
  std::printf("%-8s %6s %10s %8s %10s %8s %10s %8s %10s %8s %10s %8s %8s\n", "h_m", "nodes", "height_m", "err%",
              "lead_deg", "err%", "trail_deg", "err%", "top_m", "err%", "area_m2", "err%", "remesh_s");
  for (const Row& r : rows)
    std::printf("%-8g %6d %10.5f %8.3f %10.3f %8.3f %10.3f %8.3f %10.5f %8.3f %10.6f %8.4f %8.3f\n", r.h, r.nodes,
                r.height, 100 * (r.height / ref.height - 1), r.lead, 100 * (r.lead / ref.lead - 1), r.trail,
                100 * (r.trail / ref.trail - 1), r.top, 100 * (r.top / ref.top - 1), r.area,
                100 * (r.area / ref.area - 1), r.ring_remesh_s);
  return 0;
}
