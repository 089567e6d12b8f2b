// Wall time of one remesh of the whole Qiu ring (64 rows, 10 mm elements,
// every node receding 1 mm), median of N repetitions.
//
// Usage: bench_remesh_timing [repetitions=7] [element_size_m=0.01]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "geometry/build_liner_surface.h"
#include "geometry/remesh.h"

using namespace linerlife;

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 7;
  const double h = argc > 2 ? std::atof(argv[2]) : 0.01;
  Mill m;
  m.diameter_m = 10.36;
  m.speed_rpm = 10.36;
  LinerDesign d;
  d.segments = 64;
  d.design = {0.075, 0.25, 0.15, 20, 20, 0};
  d.element_size_m = h;
  const LinerSurface s = build_liner_surface(m, d);
  RemeshOptions opt;
  opt.element_size_m = h;
  const std::vector<double> depth(s.n_nodes(), 0.001);
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const RemeshResult res = remesh(s, depth, opt);
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (res.surface.n_nodes() == 0) return 1;
  }
  std::sort(t.begin(), t.end());
  std::printf("ring of %d nodes, h = %g m: remesh median %.4f s (min %.4f, max %.4f, %d runs); per segment %.2f ms\n",
              s.n_nodes(), h, t[t.size() / 2], t.front(), t.back(), reps, 1000 * t[t.size() / 2] / 64);
}
