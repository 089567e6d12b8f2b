// Issue 7 §6: forecasts on random valid mills. None may crash or hang, every
// output is finite, the liner only loses mass, the lifter crest only gets
// lower and the relining date is after the start date.
//
// The configurations are drawn inside the documented ranges
// (docs/configuration.md) from ball mills to SAG mills, with the layer model
// (all three versions) driving the wear (Morrell's model gives no liner
// loads); the
// forecast is cut down (2 revolutions a drive, 20 mm elements or finer for
// small lifters, a coarse refresh): a few seconds a run. The fast suite runs
// 20 of them, the slow one 100; LINERLIFE_SOAK_RUNS sets another count.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "cli_runner.h"
#include "tests/app/json_lite.h"

using namespace linerlife;
using namespace linerlife::test;
namespace fs = std::filesystem;

namespace {

struct RandomMill {
  std::string toml, summary;
};

RandomMill random_mill(std::mt19937& rng) {
  auto U = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](std::initializer_list<const char*> v) {
    return *(v.begin() + std::uniform_int_distribution<int>(0, static_cast<int>(v.size()) - 1)(rng));
  };
  const double D = U(2.0, 11.0);
  const double L = D * U(0.3, 1.5);
  const double phi = U(0.60, 0.85);
  const double J = U(0.15, 0.40);
  const bool ball_mill = U(0, 1) < 0.3;
  const double Jb = ball_mill ? J : J * U(0.2, 0.8);
  const double db = ball_mill ? U(0.04, 0.08) : U(0.08, 0.14);
  // lifters: height up to an eighth of the radius, at least 50 mm
  const double plate = U(0.04, 0.10);
  const double h = U(0.05, std::max(0.06, D / 16));
  const double top = h * U(0.4, 1.0);
  const double lead = U(5, 40), trail = U(5, 40);
  // segments so that a lifter and its faces take at most half a segment and
  // the media fit between lifters with room (the loader refuses balls wider
  // than the gap at the plate)
  const double foot = top + h * (std::tan(lead * M_PI / 180) + std::tan(trail * M_PI / 180));
  const int seg_max = static_cast<int>(M_PI * (D - 2 * plate) / std::max(2 * foot, foot + 1.5 * db));
  const int segments = std::uniform_int_distribution<int>(std::max(8, seg_max / 3), std::max(8, seg_max))(rng);
  const double element = std::min(0.02, 0.9 * std::min(h, top) / 4);  // the loader asks for a quarter
  const char* model = "layer";  // Morrell's model gives no liner loads to wear with
  const char* variant = pick({"1.0", "1.1", "1.2"});
  const char* rotation = pick({"ccw", "cw"});
  const double min_h = h * U(0.3, 0.8);
  RandomMill m;
  m.toml = fmt::format(R"([mill]
diameter_m = {D}
length_m = {L}
speed_fraction_critical = {phi}
rotation = "{rotation}"
[charge]
filling = {J}
ball_filling = {Jb}
ball_diameter_m = {db}
[liner]
segments = {segments}
plate_thickness_m = {plate}
lifter_height_m = {h}
lifter_top_width_m = {top}
face_angle_leading_deg = {lead}
face_angle_trailing_deg = {trail}
element_size_m = {element}
[model]
charge = "{model}"
variant = "{variant}"
[forecast]
revolutions_per_drive = 2
refresh_tol_m = {refresh}
min_lifter_height_m = {min_h}
)",
                       fmt::arg("D", D), fmt::arg("L", L), fmt::arg("phi", phi), fmt::arg("rotation", rotation),
                       fmt::arg("J", J), fmt::arg("Jb", Jb), fmt::arg("db", db), fmt::arg("segments", segments),
                       fmt::arg("plate", plate), fmt::arg("h", h), fmt::arg("top", top), fmt::arg("lead", lead),
                       fmt::arg("trail", trail), fmt::arg("element", element), fmt::arg("model", model),
                       fmt::arg("variant", variant), fmt::arg("refresh", std::max(0.002, h / 25)),
                       fmt::arg("min_h", min_h));
  m.summary = fmt::format("D {:.2f} m, phi {:.2f}, J {:.2f}, J_B {:.2f}, lifter {:.3f} m x {} rows, {} {}", D, phi, J,
                          Jb, h, segments, model, variant);
  return m;
}

bool finite_all(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

void soak(int runs, unsigned seed) {
  const char* env = std::getenv("LINERLIFE_SOAK_RUNS");
  if (env) runs = std::atoi(env);
  const fs::path dir = temp_dir("soak" + std::to_string(seed));
  std::mt19937 rng(seed);
  int reached = 0, height_rises = 0, rising_runs = 0;
  double max_crest_rise = 0;  // [m] the largest rise of the crest between two records, over all runs
  for (int k = 0; k < runs; ++k) {
    const RandomMill m = random_mill(rng);
    const fs::path cfg = dir / fmt::format("mill{:03d}.toml", k);
    write_file(cfg, m.toml);
    // a hang shows as the timeout's exit code 124 (a run takes a few seconds;
    // LINERLIFE_TIMEOUT_SCALE stretches the limit for sanitizer builds)
    const char* scale = std::getenv("LINERLIFE_TIMEOUT_SCALE");
    const int limit = static_cast<int>(120 * (scale ? std::max(1.0, std::atof(scale)) : 1.0));
    const RunResult r = run_linerlife("forecast " + cfg.string() + " --json --quiet", limit);
    INFO("run " << k << ": " << m.summary << "\n" << m.toml << "\n" << r.err);
    REQUIRE(r.code == 0);
    const JsonValue j = parse_json(r.out);
    const JsonValue& hist = j["history"];
    const std::vector<double> hours = hist["hours"].nums(), lifter = hist["lifter_height_m"].nums(),
                              mass = hist["liner_mass_kg_per_m"].nums(), thin = hist["min_thickness_m"].nums(),
                              crest = hist["crest_thickness_m"].nums();
    REQUIRE(hours.size() >= 2);
    CHECK(finite_all(hours));
    CHECK(finite_all(lifter));
    CHECK(finite_all(mass));
    CHECK(finite_all(thin));
    CHECK(finite_all(crest));
    CHECK(finite_all(hist["face_angle_leading_deg"].nums()));
    CHECK(std::isfinite(j["operating_hours"].num()));
    CHECK(j["operating_hours"].num() > 0);
    CHECK(j["end_date"].str() > j["start_date"].str());  // ISO dates order as strings
    // a relining date only where a criterion was reached, and then the end
    if (j["reached"].b) CHECK(j["relining_date"].str() == j["end_date"].str());
    else CHECK(j["relining_date"].kind == JsonValue::Kind::Null);
    for (size_t i = 1; i < hours.size(); ++i) {
      CHECK(hours[i] > hours[i - 1]);
      CHECK(mass[i] <= mass[i - 1] * (1 + 1e-12));
      // the crest never rises (recession is never negative, a remesh only
      // removes material). It is measured on the polygon of surface nodes;
      // between remeshes that is the displaced ring, which a fold (a notch
      // node passing through a needle-shaped lifter) made rise by up to
      // 3.8 mm before the forecast remeshed at every fold
      // (docs/reliability.md, Soak); 1 um is allowed for round-off. The
      // height above the worn plate may rise: where the plate wears faster
      // than the crest it grows; the count is reported below and in
      // docs/reliability.md
      max_crest_rise = std::max(max_crest_rise, crest[i] - crest[i - 1]);
      CHECK(crest[i] <= crest[i - 1] + 1e-6);
      if (lifter[i] > lifter[i - 1] + 1e-9) ++height_rises;
    }
    if (j["reached"].b) ++reached;
    if (height_rises > 0) ++rising_runs;
    height_rises = 0;
  }
  WARN(runs << " random mills: " << reached << " reached a criterion; in " << rising_runs
            << " the lifter height above the worn plate rose at some point; the largest rise of the crest "
            << "between two records was " << max_crest_rise * 1e3 << " mm");
  // most random mills wear out within the 50,000 h horizon
  CHECK(reached >= runs / 2);
  fs::remove_all(dir);  // a failed run's mill is in its INFO above
}

}  // namespace

// CI: 20 mills (about 2 minutes); the 100 of issue 7 §6 run with the
// benchmarks (a tall lifter in a big mill takes up to half a minute).
TEST_CASE("forecasts on 20 random valid mills end cleanly with a liner that only wears", "[app][soak][forecast]") {
  soak(20, 7);
}

TEST_CASE("forecasts on 100 random valid mills end cleanly with a liner that only wears",
          "[app][soak][forecast][slow]") {
  soak(100, 2026);
}

// Run 90 of the 100-mill soak (seed 2026), kept as a regression: a ball mill
// whose 0.27 m lifters wear into needles leaning to one side. The remesh
// leaves notches smaller than the depth between remeshes at the needle's tip;
// a notch node then passed through the needle, the displaced ring folded and
// the crest read on it rose 3.8 mm over 200 h (20,200 to 20,400 h) until the
// next remesh. The forecast now remeshes where the ring starts to fold.
// The soak ran the layer model's former start (aligned phases, 3 settling
// revolutions), kept here so that the run reaches the needle as it did.
// Since the layer model's loads land where the disc touches (2026-12-05,
// docs/models/layer.md §Liner loads) this mill's lifter wears evenly down to
// its limit, at 16,788 h, and no needle forms (with the limit at 0.03 m the
// life ends on the face angle at 18,450 h, no needle either): the run is
// kept as a long life whose gauges must never rise, and the fold itself is
// tested directly (test_forecast.cpp, "a displaced ring that crosses itself
// is seen as folded"). About 20 s (Release).
TEST_CASE("a lifter worn into a needle: the crest read between remeshes never rises", "[app][soak][forecast]") {
  const fs::path dir = temp_dir("needle");
  const fs::path cfg = dir / "mill090.toml";
  write_file(cfg, R"([mill]
diameter_m = 9.043993900046525
length_m = 7.282022592828505
speed_fraction_critical = 0.6305426486605296
rotation = "ccw"
[charge]
filling = 0.3305011042510201
ball_filling = 0.3305011042510201
ball_diameter_m = 0.04660809963004417
[liner]
segments = 40
plate_thickness_m = 0.09836400255424145
lifter_height_m = 0.2698288025472616
lifter_top_width_m = 0.11398964909729994
face_angle_leading_deg = 5.260346053457269
face_angle_trailing_deg = 6.678552512805253
element_size_m = 0.02
[model]
charge = "layer"
variant = "1.1"
settle_revolutions = 3
initial_phases = "aligned"
[forecast]
revolutions_per_drive = 2
refresh_tol_m = 0.010793152101890463
min_lifter_height_m = 0.1894413861069493
)");
  const char* scale = std::getenv("LINERLIFE_TIMEOUT_SCALE");
  const RunResult r = run_linerlife("forecast " + cfg.string() + " --json --quiet",
                                    static_cast<int>(300 * (scale ? std::max(1.0, std::atof(scale)) : 1.0)));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  const std::vector<double> hours = j["history"]["hours"].nums(), crest = j["history"]["crest_thickness_m"].nums(),
                            mass = j["history"]["liner_mass_kg_per_m"].nums();
  // Until 2026-12-05 the needle formed after about 20,000 h; the run had to
  // get past the records at 20,200 to 20,400 h where the crest rose, and a
  // fold remesh at 20,490 h took the needle's tip away, ending the life. Now
  // the lifter reaches its limit at 16,788 h: a long life with 24 remeshes.
  REQUIRE(hours.back() > 15000);
  CHECK(j["criterion"].str() == "min_lifter_height");
  CHECK(j["lifter_height_m_final"].num() <= 0.1894413861069493);
  for (size_t i = 1; i < hours.size(); ++i) {
    INFO("record " << i << " at " << hours[i] << " h");
    CHECK(crest[i] <= crest[i - 1] + 1e-6);
    CHECK(mass[i] <= mass[i - 1] * (1 + 1e-12));
  }
  fs::remove_all(dir);
}
