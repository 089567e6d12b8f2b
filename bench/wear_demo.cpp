// The charts of `linerlife wear --out` (thesis Figs. 5-13, 5-16, 5-17, B-5)
// drawn from the SYNTHETIC test-double charge model (bench/synthetic_charge.h),
// through the same results writer and chart script as the command. Until the
// charge models are merged this is how the charts are made and checked; after
// it `linerlife wear --out DIR` on the bundled mill makes them from the layer model.
//
// Usage: bench_wear_demo OUT_DIR [amplification]   (default 1e6)
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/output_dir.h"
#include "app/plots.h"
#include "app/wear_results.h"
#include "bench/synthetic_charge.h"
#include "bench/wear_common.h"
#include "wear/wear_laws.h"

using namespace linerlife;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_wear_demo OUT_DIR [amplification]\n");
    return 2;
  }
  Config c = load_default_config();
  if (argc > 2) c.wear.amplification_abrasion = c.wear.amplification_impact = std::atof(argv[2]);
  WearRunInput in = bench::wear_input(c);
  in.wear = c.wear;
  const WearRunResult r = run_wear(in, bench::synthetic_entry());
  WearRunInput part = in;
  part.wear.laws = {"abrasion/radziszewski"};
  const WearRunResult abrasion = run_wear(part, bench::synthetic_entry());
  part.wear.laws = {"impact/sheldon_kanhere"};
  const WearRunResult impact = run_wear(part, bench::synthetic_entry());
  const Json j = wear_summary(c, r, in.mill, "synthetic (test double, no charge physics)");
  OutputDir dir(argv[1]);
  dir.prepare();
  const std::string tmp = dir.temp_path("wear.h5");
  write_wear_h5(tmp, c, j, r, &abrasion, &impact);
  dir.commit(tmp, "wear.h5");
  const bool ok = draw_charts("wear", dir.path("wear.h5"), dir.dir());
  std::printf("%s\n", j.dump().c_str());
  return ok ? 0 : 1;
}
