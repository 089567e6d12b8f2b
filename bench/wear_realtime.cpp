// Speed of the wear accounting and of the coupled wear run (issue 4 §6;
// docs/benchmarks.md "## Wear"). One thread.
//
//  1. recession_rates() on the Qiu ring (64 liners, 5440 elements) with the
//     synthetic test-double loads: the cost of turning one set of loads into
//     recession rates, for each law set; medians of 200 calls.
//  2. The coupled run of `linerlife wear` on the bundled Qiu mill with its
//     [wear] settings (1.5 revolutions, remesh every 10 steps, csaps, one
//     liner) driven by the synthetic charge model, whose own cost is
//     negligible: the wear run's own throughput; median of `runs` runs.
//  4. The thesis' run length (300 s): the layer model over 1 settling and 51
//     averaged revolutions with the wear accounting; the ratio over the
//     averaged (wear-accounted) time only.
//  5. The coupled run over 51 revolutions (amplification 1e5).
//  3. When a charge model named "layer" is in the table (after the charge
//     models are merged): the layer model over 1.5 revolutions alone, the same
//     plus the wear accounting (recession rates from its loads), and the
//     coupled run; medians of `runs` runs. Until then this part says so.
//
// Usage: bench_wear_realtime [runs]   (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench/bench_main.h"
#include "bench/synthetic_charge.h"
#include "bench/wear_common.h"
#include "geometry/errors.h"
#include "geometry/heap_tuning.h"
#include "wear/wear_laws.h"

using namespace linerlife;
using bench::median;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

int main(int argc, char** argv) {
  keep_freed_memory();  // as linerlife's main() does
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const Config c = load_default_config();
  WearRunInput in = bench::wear_input(c);
  const double revolution = 60.0 / in.mill.speed_rpm;
  std::printf("# Qiu mill (bundled), %d liners, %d surface elements, dt = %g s, one thread\n", in.surface.segments,
              in.surface.n_elements(), in.model.time_step_s);

  // 1. recession rates
  ChargeInput ci;
  ci.mill = in.mill;
  ci.charge = in.charge;
  ci.model = in.model;
  ci.surface = &in.surface;
  ci.revolutions = 1;
  const ChargeResult loads = bench::SyntheticCharge().run(ci);
  std::printf("\n## 1. recession_rates() on the whole ring (%zu impact classes), median of 200 calls\n",
              loads.loads.impacts.size());
  std::printf("%-48s %14s %18s\n", "laws", "us_per_call", "calls_per_step_500x");
  for (const std::vector<std::string>& laws :
       {std::vector<std::string>{"abrasion/radziszewski", "impact/sheldon_kanhere"},
        std::vector<std::string>{"abrasion/archard"}, std::vector<std::string>{"impact/finnie"},
        std::vector<std::string>{"impact/bitter"}, std::vector<std::string>{"impact/rabinowicz"},
        std::vector<std::string>{"abrasion/radziszewski", "abrasion/archard", "impact/finnie", "impact/bitter",
                                 "impact/rabinowicz", "impact/sheldon_kanhere"}}) {
    WearSpec w = in.wear;
    w.laws = laws;
    const WearModel m = make_wear_model(w, bench::synthetic_entry());
    RecessionRates r;
    std::vector<double> t;
    for (int i = 0; i < 200; ++i) {
      const auto t0 = Clock::now();
      recession_rates(m, loads.loads, in.surface, in.material, r);
      t.push_back(seconds(t0));
    }
    // at 500x real time a step of dt has dt / 500 of wall time
    const double us = 1e6 * median(t);
    std::printf("%-48s %14.1f %18.1f\n", law_list_text(laws).c_str(), us, in.model.time_step_s / 500 / median(t));
  }

  // 2. the coupled run
  std::printf(
      "\n## 2. coupled wear run, [wear] of the bundled mill (%g revolutions, remesh every %d steps, %s, %s "
      "liner, amplification %g), synthetic charge model; median of %d\n",
      in.wear.revolutions, in.wear.remesh_every_steps, smoothing_method_name(in.wear.smoothing.method),
      in.wear.liner_computation.c_str(), in.wear.amplification_abrasion, runs);
  for (bool feedback : {false, true}) {
    in.wear.feedback = feedback;
    std::vector<double> wall, remesh, charge;
    WearRunResult r;
    for (int i = 0; i < runs; ++i) {
      r = run_wear(in, bench::synthetic_entry());
      wall.push_back(r.wall_s);
      remesh.push_back(r.remesh_wall_s);
      charge.push_back(r.charge_wall_s);
    }
    std::printf(
        "feedback %-3s: simulated %.3f s, wall %.4f s (remesh %.4f s, charge model %.4f s, %d remeshes, %d "
        "drives) -> %.1f x real time\n",
        feedback ? "on" : "off", r.simulated_s, median(wall), median(remesh), median(charge),
        r.remeshes + r.fast_remeshes, r.charge_drives, r.simulated_s / median(wall));
  }
  in.wear.feedback = false;

  // 3. with the layer model
  std::printf("\n## 3. the layer charge model with the wear accounting\n");
  const ChargeModelEntry* layer = nullptr;
  try {
    layer = &find_charge_model("layer");
  } catch (const InputError& e) {
    std::printf("not measured: %s\n(run again once the charge models are merged)\n", e.what());
    return 0;
  }
  std::unique_ptr<ChargeModel> model = layer->make();
  ci.revolutions = in.wear.revolutions;
  const WearModel wm = make_wear_model(in.wear, *layer);
  std::vector<double> alone, with_rates, coupled;
  for (int i = 0; i < runs; ++i) {
    auto t0 = Clock::now();
    const ChargeResult cr = model->run(ci);
    alone.push_back(seconds(t0));
    WearModel m = wm;
    if (m.needs_operating_point())
      set_operating_point(m, operating_point(in.mill, in.charge, &cr.indicators, in.surface));
    recession_rates(m, cr.loads, in.surface, in.material);
    with_rates.push_back(seconds(t0));
    coupled.push_back(run_wear(in, *layer).wall_s);
  }
  const double sim = in.wear.revolutions * revolution;
  std::printf("layer model alone over %.3f s:            wall %.4f s -> %.0f x real time\n", sim, median(alone),
              sim / median(alone));
  std::printf("layer model + wear accounting:             wall %.4f s -> %.0f x real time\n", median(with_rates),
              sim / median(with_rates));
  std::printf("coupled run (drive, rates, per-step wear, remeshing): wall %.4f s -> %.0f x real time\n",
              median(coupled), sim / median(coupled));

  // 4. The thesis' run length (§3.2.2: 30,000 steps of 10 ms, 300 s; §5.9 measured
  // the simulator with its wear module "on lines similar"): the layer model over
  // its settling revolution and 51 averaged revolutions (296 s), with the wear
  // accounting (loads and impacts accumulated, recession rates from them). The
  // ratio counts only the averaged (wear-accounted) time; the settling's share
  // of a run this long is 2 %, not the 40 % of the 1.5-revolution run above.
  const double long_revs = 51;
  ci.revolutions = long_revs;
  std::vector<double> long_wall;
  double long_sim = 0;
  for (int i = 0; i < runs; ++i) {
    auto t0 = Clock::now();
    const ChargeResult cr = model->run(ci);
    WearModel m = wm;
    if (m.needs_operating_point())
      set_operating_point(m, operating_point(in.mill, in.charge, &cr.indicators, in.surface));
    recession_rates(m, cr.loads, in.surface, in.material);
    long_wall.push_back(seconds(t0));
    long_sim = cr.stats.simulated_s;
  }
  const double accounted = long_revs * revolution;
  std::printf("\n## 4. the thesis' run length: layer model + wear accounting over %.1f s (%.0f s averaged), median of %d\n",
              long_sim, accounted, runs);
  std::printf("wall %.4f s -> %.0f x real time over the averaged time (%.0f x over all the simulated time)\n",
              median(long_wall), accounted / median(long_wall), long_sim / median(long_wall));

  // 5. The coupled run over the same length: `linerlife wear --revolutions 51
  // --amplification 1e5` (the bundled 1e6 would wear the lifter through).
  WearRunInput lin = in;
  lin.wear.revolutions = long_revs;
  lin.wear.amplification_abrasion = lin.wear.amplification_impact = 1e5;
  std::vector<double> lw, lrm;
  WearRunResult lr;
  for (int i = 0; i < runs; ++i) {
    lr = run_wear(lin, *layer);
    lw.push_back(lr.wall_s);
    lrm.push_back(lr.remesh_wall_s);
  }
  std::printf("\n## 5. the coupled run over %.0f revolutions (amplification 1e5), median of %d\n", long_revs, runs);
  std::printf("simulated %.1f s, wall %.4f s (remesh %.4f s, %d remeshes, %d drives) -> %.0f x real time\n",
              lr.simulated_s, median(lw), median(lrm), lr.remeshes + lr.fast_remeshes, lr.charge_drives,
              lr.simulated_s / median(lw));
  return 0;
}
