// The forecast family of commands end to end (issue 5 §5): forecast, compare,
// calibrate and plot on a shortened Qiu mill. The physics of the integrator is
// tested in tests/forecast; here: what a user gets from the command line.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cctype>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "app/commands.h"
#include "app/h5_reader.h"
#include "forecast/calibrate.h"
#include "forecast/forecast.h"
#include "forecast/measured_history.h"
#include "cli_runner.h"
#include "geometry/measured_profile.h"
#include "geometry/resample.h"
#include "tests/app/json_lite.h"

using namespace linerlife;
using namespace linerlife::test;
namespace fs = std::filesystem;

namespace {

/// The bundled Qiu mill cut down for tests: 2 revolutions a drive, a coarse
/// refresh, 20 mm elements, and a life that ends at 0.20 m of lifter (about
/// 3,500 h; a second of wall time). Extra `[forecast]` / `[wear]` lines are
/// added under their headers.
std::string fast_qiu(const std::string& forecast_extra = "", const std::string& wear_extra = "") {
  std::string t = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  t = std::regex_replace(t, std::regex("element_size_m = 0.01\n"), "element_size_m = 0.02\n");
  t = std::regex_replace(t, std::regex("min_lifter_height_m = 0.075\n"), "min_lifter_height_m = 0.2\n");
  t = std::regex_replace(t, std::regex("\\[forecast\\]\n"),
                         "[forecast]\nrevolutions_per_drive = 2\nrefresh_tol_m = 0.01\n" + forecast_extra);
  t = std::regex_replace(t, std::regex("\\[wear\\]\n"), "[wear]\n" + wear_extra);
  return t;
}

bool python_charts_available() {
  return std::system("/usr/bin/python3 -c 'import matplotlib, h5py' >/dev/null 2>&1") == 0;
}

bool is_iso_date(const std::string& s) { return std::regex_match(s, std::regex("\\d{4}-\\d{2}-\\d{2}")); }

/// The profiles of segment 0 a forecast wrote (forecast.h5, /forecast/profiles),
/// each in the unrolled frame of docs/profile-csv.md, with their hours.
struct ForecastProfiles {
  std::vector<double> hours;
  std::vector<std::vector<Eigen::Vector2d>> profile;
  std::vector<std::vector<Eigen::Vector2d>> nodes;  // the same in the mill frame, as the file holds them
  double shell_radius_m = 0;
  int segments = 0;
};

/// Runs `linerlife forecast CONFIG --quiet --out OUT` and reads its profiles.
ForecastProfiles forecast_profiles(const fs::path& config, const fs::path& out) {
  const RunResult f = run_linerlife("forecast " + config.string() + " --quiet --out " + out.string(), 300);
  INFO(f.err);
  REQUIRE(f.code == 0);
  const H5Reader h5((out / "forecast.h5").string());
  const auto xy = h5.doubles("/forecast/profiles/nodes");
  const auto off = h5.ints("/forecast/profiles/offset");
  ForecastProfiles fp;
  fp.shell_radius_m = h5.attr_double("/surface", "shell_radius_m");
  fp.segments = static_cast<int>(h5.attr_int("/surface", "segments"));
  fp.hours = h5.doubles("/forecast/profiles/hours");
  for (size_t i = 0; i < fp.hours.size(); ++i) {
    std::vector<Eigen::Vector2d> nodes;
    for (long long k = off[i]; k < off[i + 1]; ++k) nodes.emplace_back(xy[2 * k], xy[2 * k + 1]);
    fp.profile.push_back(segment_to_profile_xy(nodes, fp.shell_radius_m, 0.0, 2 * M_PI / fp.segments));
    fp.nodes.push_back(std::move(nodes));
  }
  return fp;
}

/// The caveats of `linerlife forecast FILE --json --out OUT` whose text
/// contains `key`, each checked to be on stderr and in OUT/forecast.h5's
/// `caveat` attribute as well (the three places a caveat goes).
std::vector<std::string> forecast_caveats_with(const fs::path& file, const fs::path& out, const std::string& key) {
  const RunResult r = run_linerlife("forecast " + file.string() + " --json --out " + out.string());
  INFO(file.filename().string() << ": " << r.err);
  REQUIRE(r.code == 0);
  std::vector<std::string> found;
  const JsonValue j = parse_json(r.out);
  for (const auto& c : j["caveats"].items()) {
    const std::string text = c["text"].str();
    if (text.find(key) == std::string::npos) continue;
    CHECK(r.err.find(text) != std::string::npos);
    CHECK_THAT(H5Reader((out / "forecast.h5").string()).attr_string("/forecast", "caveat"), Catch::Contains(text));
    found.push_back(text);
  }
  return found;
}

}  // namespace

TEST_CASE("a forecast horizon beyond 1,000,000 calendar days gets its own date", "[app][cli][forecast]") {
  // a review: the calendar stopped at 1,000,000 days without saying so (no
  // wear, 1e6 h at availability 0.01: 4764-11-27 for 4,166,667 days); at 0.02
  // the horizon is 2,083,333 days away, in 7730
  const fs::path dir = temp_dir("fc_horizon");
  std::string t = fast_qiu("max_operating_hours = 1e6\n");
  t = std::regex_replace(t, std::regex("availability = 0.92\n"), "availability = 0.02\n");
  t = std::regex_replace(t, std::regex("\\[wear\\]\n"), "[wear]\nlaws = \"none\"\n");
  write_file(dir / "m.toml", t);
  RunResult r = run_linerlife("forecast " + (dir / "m.toml").string() + " --json --out " + (dir / "o").string(), 120);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  CHECK(j["criterion"].str() == "horizon");
  {
    const H5Reader h5((dir / "o" / "forecast.h5").string());  // the same in the results file
    CHECK(h5.attr_string("/forecast", "end_date") == "7730-12-22");
    CHECK(h5.attr_string("/forecast", "relining_date").empty());
  }
  CHECK(j["operating_hours"].num() == Approx(1e6));
  CHECK(j["calendar_days"].num() == Approx(1e6 / 0.48).epsilon(1e-9));
  // the run ended on the horizon: that date is end_date, and there is no
  // relining date (a script reading one got the horizon's, a review found)
  CHECK(j["end_date"].str() == "7730-12-22");
  CHECK(j["relining_date"].kind == JsonValue::Kind::Null);
  CHECK_FALSE(j["reached"].b);
  // at 0.01 the horizon's date would pass 9999-12-31: refused before any work
  write_file(dir / "m.toml", std::regex_replace(t, std::regex("availability = 0.02\n"), "availability = 0.01\n"));
  r = run_linerlife("forecast " + (dir / "m.toml").string() + " --json", 30);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains("max_operating_hours = 1000000 h ends on +13434-12-12"));
  CHECK_THAT(r.err, Catch::Contains("cannot be written as a date"));
  fs::remove_all(dir);
}

TEST_CASE("forecast --json gives the relining date, the criterion and the history along the life",
          "[app][cli][forecast]") {
  const fs::path dir = temp_dir("fc_json");
  write_file(dir / "m.toml", fast_qiu());
  const RunResult r = run_linerlife("forecast " + (dir / "m.toml").string() + " --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  CHECK(j["method"].str() == "ode");
  CHECK(j["criterion"].str() == "min_lifter_height");
  CHECK(is_iso_date(j["relining_date"].str()));
  CHECK(j["relining_date"].str() > "2027-01-01");
  const double hours = j["operating_hours"].num();
  CHECK(hours > 1000);
  CHECK(hours < 20000);
  // tonnes = operating hours x throughput (1500 t/h in the bundled mill)
  CHECK(j["tonnes"].num() == Approx(1500.0 * hours).epsilon(1e-9));
  // the root finder stops on the criterion: 0.2 m within CVODE's atol scale
  CHECK(j["lifter_height_m_final"].num() == Approx(0.2).margin(1e-5));
  CHECK(j["face_angle_leading_deg_final"].num() > 20.0);  // the leading face lays back as it wears
  CHECK(j["charge_redrives"].num() >= 2);
  CHECK(j["cvode_steps"].num() > 0);
  CHECK(j["rhs_evals"].num() >= j["cvode_steps"].num());
  CHECK(j["wall_s"].num() > 0);

  const JsonValue& h = j["history"];
  const auto t = h["hours"].nums(), ht = h["lifter_height_m"].nums(), fa = h["face_angle_leading_deg"].nums(),
             pw = h["net_power_kw"].nums();
  REQUIRE(t.size() >= 3);
  CHECK(ht.size() == t.size());
  CHECK(fa.size() == t.size());
  CHECK(pw.size() == t.size());
  CHECK(t.front() == 0.0);
  CHECK(t.back() == Approx(hours).epsilon(1e-9));
  CHECK(ht.front() == Approx(0.25).margin(1e-4));  // the new lifter of the bundled mill
  for (size_t i = 1; i < t.size(); ++i) {
    CHECK(t[i] > t[i - 1]);
    CHECK(std::isfinite(pw[i]));
    CHECK(pw[i] > 0);
  }
  // the caveat on the layer model's power is there exactly when its history
  // departs from the new-liner value by more than the threshold
  double dev = 0;
  for (double p : pw) dev = std::max(dev, std::abs(p / pw.front() - 1.0));
  const auto& cav = j["caveats"].items();
  CHECK(cav.size() == (dev > kWornPowerCaveatFraction ? 1u : 0u));
  for (const auto& c : cav) CHECK(r.err.find(c["text"].str()) != std::string::npos);  // also printed as a note
  fs::remove_all(dir);
}

TEST_CASE("an explicit method's step longer than a tenth of the life carries a caveat", "[app][forecast]") {
  // the steps and lives of docs/validation/forecast.md (the bundled Qiu mill), at 10 rpm: 6 s a revolution
  ForecastSpec spec;
  ForecastResult f;
  spec.method = ForecastMethod::Amplify;
  f.operating_hours = 2908;  // amplification 1e7: one step of 1.5 x 6 s x 1e7 = 25,000 h
  std::string c = explicit_step_caveat(spec, 10.0, f);
  CHECK(c.find("the amplify method stepped 25000 h at a time") != std::string::npos);
  CHECK(c.find("amplification = 1e+07 on 1.5 revolutions") != std::string::npos);
  CHECK(c.find("860 % of this 2908 h life") != std::string::npos);
  spec.amplification = 1e5;  // 250 h steps at 10 rpm over 7,433 h: within 1.1 % of the ode method
  f.operating_hours = 7433;
  CHECK(explicit_step_caveat(spec, 10.0, f).empty());
  spec.amplification = 1e6;  // 2,500 h steps over 6,613 h: 10 % early
  f.operating_hours = 6613;
  CHECK_FALSE(explicit_step_caveat(spec, 10.0, f).empty());
  spec.method = ForecastMethod::Euler;
  spec.euler_step_h = 800;  // 14 % of 5,561 h: 24 % early
  f.operating_hours = 5561;
  c = explicit_step_caveat(spec, 10.0, f);
  CHECK(c.find("the euler method stepped 800 h at a time (euler_step_h = 800), 14 % of this 5561 h life") !=
        std::string::npos);
  spec.euler_step_h = 400;  // 5 % of 7,352 h: within 0.6 %
  f.operating_hours = 7352;
  CHECK(explicit_step_caveat(spec, 10.0, f).empty());
  // the threshold itself: a step of exactly a tenth is not flagged, just over it is
  spec.euler_step_h = 100;
  f.operating_hours = 1000;
  CHECK(explicit_step_caveat(spec, 10.0, f).empty());
  f.operating_hours = 999;
  CHECK_FALSE(explicit_step_caveat(spec, 10.0, f).empty());
  // the ode method has no fixed step
  spec.method = ForecastMethod::Ode;
  CHECK(explicit_step_caveat(spec, 10.0, f).empty());
}

TEST_CASE("a hi-lo forecast by the layer model says how far its charge on worn hi-lo rings is checked", "[app][cli][forecast]") {
  // docs/models/layer-worn.md, "Caught behind": the layer model's charge on
  // worn hi-lo rings is checked against the DEM on one mill only, and its
  // relining date is 32 % before a DEM-driven forecast's there; the note says
  // so and names the way out, and it goes with the results (JSON, forecast.h5)
  const fs::path dir = temp_dir("fc_hilo");
  std::string t = fast_qiu("max_operating_hours = 200\n");
  t = std::regex_replace(t, std::regex("\\[liner\\]\n"),
                         "[liner]\npattern = \"hi-lo\"\nlow_lifter_height_m = 0.125\nlow_lifter_top_width_m = 0.15\n");
  write_file(dir / "hilo.toml", t);
  write_file(dir / "uniform.toml", fast_qiu("max_operating_hours = 200\n"));
  for (const char* which : {"hilo", "uniform"}) {
    const auto found = forecast_caveats_with(dir / (std::string(which) + ".toml"), dir / which, "a hi-lo liner:");
    CHECK(found.size() == (std::string(which) == "hilo" ? 1u : 0u));
    for (const std::string& c : found)
      CHECK_THAT(c, Catch::Contains("checked against the 2D DEM only") && Catch::Contains("charge = \"dem\"") &&
                        Catch::Contains("layer-worn.md"));
  }
  // The low lifters are reported beside the high ones (a review, 2026-12-08: a
  // hi-lo forecast gave only the high lifter, while the low one's crest wore
  // more and the plate beside it ended the life): in the summary, the JSON
  // history and forecast.h5; a uniform ring has none.
  const RunResult text = run_linerlife("forecast " + (dir / "hilo.toml").string());
  REQUIRE(text.code == 0);
  CHECK_THAT(text.out, Catch::Contains("m (the high lifters)\n") && Catch::Contains("  low lifter height            0.1250 m  -> ") &&
                           Catch::Contains("  low leading face angle         20.0 deg -> "));
  const JsonValue h = parse_json(run_linerlife("forecast " + (dir / "hilo.toml").string() + " --json").out)["history"];
  const auto low = h["low_lifter_height_m"].nums(), high = h["lifter_height_m"].nums();
  REQUIRE(low.size() == high.size());
  REQUIRE(low.size() >= 2);
  CHECK(low.front() == Approx(0.125).margin(1e-4));  // its design height, not the high lifter's 0.25
  CHECK(high.front() == Approx(0.25).margin(1e-4));
  CHECK(low.back() < low.front());  // it wears
  CHECK(h["low_face_angle_leading_deg"].nums().front() == Approx(20.0).margin(0.5));
  const std::vector<double> low_h5 = H5Reader((dir / "hilo" / "forecast.h5").string()).doubles("/forecast/history/low_lifter_height_m");
  CHECK(low_h5.front() == Approx(0.125).margin(1e-4));
  const RunResult uni = run_linerlife("forecast " + (dir / "uniform.toml").string() + " --json");
  CHECK_FALSE(parse_json(uni.out)["history"].has("low_lifter_height_m"));
  CHECK_THAT(uni.out, !Catch::Contains("low lifter"));
  for (double v : H5Reader((dir / "uniform" / "forecast.h5").string()).doubles("/forecast/history/low_lifter_height_m"))
    CHECK(std::isnan(v));
  fs::remove_all(dir);
}

TEST_CASE("a layer forecast whose lifter wears below whole media diameters carries a caveat", "[app][forecast]") {
  // docs/models/layer-worn.md, "One ball's height": the layer model's lifter
  // holds layer j while j d < h, and its charge steps where h passes j d
  const std::vector<double> t{0, 1000, 2000, 3000};
  // 0.1 m balls: 3 layers held down to 0.2 m, passed between 1000 and 2000 h
  const std::string c = one_ball_caveat("layer", 0.1, t, {0.25, 0.22, 0.19, 0.17});
  CHECK_THAT(c, Catch::Contains("below 2 media diameters (0.200 m) at about 1667 h"));
  CHECK_THAT(c, Catch::Contains("\"One ball's height\"") && Catch::Contains("charge = \"dem\""));
  // one diameter, and the first passage only (0.3 and 0.2 m within one interval)
  CHECK_THAT(one_ball_caveat("layer", 0.1333, t, {0.15, 0.14, 0.13, 0.12}),
             Catch::Contains("below 1 media diameter (0.133 m) at about 1670 h"));
  CHECK_THAT(one_ball_caveat("layer", 0.1, t, {0.35, 0.32, 0.18, 0.17}),
             Catch::Contains("below 3 media diameters (0.300 m) at about 1143 h"));
  // none: no whole diameter passed, below one diameter (one layer held
  // whatever the height), a lifter that rises (the plate wearing faster),
  // another charge model, a history without heights
  CHECK(one_ball_caveat("layer", 0.1, t, {0.25, 0.24, 0.22, 0.205}).empty());
  CHECK(one_ball_caveat("layer", 0.1333, t, {0.13, 0.11, 0.09, 0.07}).empty());
  CHECK(one_ball_caveat("layer", 0.1, t, {0.19, 0.2, 0.21, 0.22}).empty());
  CHECK(one_ball_caveat("dem", 0.1, t, {0.25, 0.22, 0.19, 0.17}).empty());
  CHECK(one_ball_caveat("empirical", 0.1, t, {0.25, 0.22, 0.19, 0.17}).empty());
  const double nan = std::nan("");
  CHECK(one_ball_caveat("layer", 0.1, t, {nan, nan, nan, nan}).empty());
  CHECK(one_ball_caveat("layer", 0.1, {0}, {0.25}).empty());
}

TEST_CASE("a forecast whose lifter wears below two media diameters says so, in the JSON, on stderr and in the file",
          "[app][cli][forecast]") {
  // the test mill with 0.124 m balls: its 0.25 m lifter holds three layers
  // until it wears to 0.248 m, at about 600 h; the bundled 0.1333 m balls:
  // two layers to 0.133 m, not reached in 800 h
  const fs::path dir = temp_dir("fc_one_ball");
  const std::string t = fast_qiu("max_operating_hours = 800\n");
  REQUIRE(t.find("ball_diameter_m = 0.1333\n") != std::string::npos);
  write_file(dir / "small.toml", std::regex_replace(t, std::regex("ball_diameter_m = 0.1333\n"), "ball_diameter_m = 0.124\n"));
  write_file(dir / "bundled.toml", t);
  for (const char* which : {"small", "bundled"}) {
    const auto found = forecast_caveats_with(dir / (std::string(which) + ".toml"), dir / which, "media diameter");
    CHECK(found.size() == (std::string(which) == "small" ? 1u : 0u));
    for (const std::string& c : found)
      CHECK_THAT(c, Catch::StartsWith("the lifter wore below 2 media diameters (0.248 m) at about"));
  }
  fs::remove_all(dir);
}

TEST_CASE("the layer model's power history carries a caveat when it departs from the new liner's by more than 15 %",
          "[app][forecast]") {
  const std::vector<double> h{0, 1000, 2000, 3000};
  // the bundled forecast's shape: +59 % at mid-life
  const std::string c = worn_power_caveat("layer", h, {5959, 6500, 9446, 8528});
  CHECK(c.find("+59 %") != std::string::npos);
  CHECK(c.find("9446 kW at 2000 h") != std::string::npos);
  CHECK(c.find("docs/models/layer-worn.md") != std::string::npos);
  // a fall counts as well; the largest departure is the one named
  CHECK(worn_power_caveat("layer", h, {6000, 5500, 4800, 5900}).find("-20 %") != std::string::npos);
  // within the threshold, or another model: none
  CHECK(worn_power_caveat("layer", h, {6000, 6500, 6890, 6100}).empty());
  CHECK(worn_power_caveat("empirical", h, {5959, 6500, 9446, 8528}).empty());
  CHECK(worn_power_caveat("dem", h, {5959, 6500, 9446, 8528}).empty());
  // a history without indicators (NaN) or of one record: none
  const double nan = std::nan("");
  CHECK(worn_power_caveat("layer", h, {nan, nan, nan, nan}).empty());
  CHECK(worn_power_caveat("layer", {0}, {5959}).empty());
  CHECK(worn_power_caveat("layer", h, {6000, nan, 9000, 6100}).find("+50 %") != std::string::npos);
}

TEST_CASE("compare explains the worn-power caveat once and gives each case its figures", "[app][compare]") {
  const std::vector<double> h{0, 1000, 2000, 3000};
  const std::string a = worn_power_caveat("layer", h, {5959, 6500, 9446, 8528});
  const std::string b = worn_power_caveat("layer", h, {6000, 5500, 4800, 5900});
  const std::vector<std::string> l = case_note_lines({"x=1", "x=2", "x=3"}, {{a, ""}, {"", "step"}, {b}});
  REQUIRE(l.size() == 3);
  CHECK(l[0] == "linerlife: note: x=1: " + a);  // whole, the first time
  CHECK(l[1] == "linerlife: note: x=2: step");
  CHECK(l[2].find("x=3: the layer model's net power moves by -20 % over this life") != std::string::npos);
  CHECK(l[2].find("(docs/models/layer-worn.md)") == std::string::npos);
  CHECK_THAT(l[2], Catch::EndsWith("its power on worn liners is checked only on the Qiu mill (the note on x=1)"));
  CHECK(case_note_lines({"x=1"}, {{""}}).empty());
}

// A review (2026-12-06): a forecast of the bundled mill set at 0.995 of
// critical failed after about 2,000 h, where its worn liner had brought it to
// 1.0001, with only "layer model: no room left for a landing element". The
// failure now says when, how near critical the worn liner is, and what to do.
TEST_CASE("a forecast that fails as its worn liner reaches critical speed says when and why", "[app][cli][forecast]") {
  const fs::path dir = temp_dir("fc_critical");
  const std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  REQUIRE(text.find("speed_rpm = 10.36\n") != std::string::npos);
  write_file(dir / "m.toml", std::regex_replace(text, std::regex("speed_rpm = 10.36\n"), "speed_fraction_critical = 0.995\n"));
  const RunResult r = run_linerlife("forecast " + (dir / "m.toml").string() + " --quiet", 120);
  INFO(r.err);
  CHECK(r.code == 3);
  const std::regex msg("linerlife: simulation failed: at ([0-9]+) operating hours, on the liner worn so far: layer model: "
                       "no room left for a landing element: every layer the charge may fill is full \\(this liner: "
                       "([0-9.]+) of critical speed at an effective diameter of [0-9.]+ m\\); near critical speed the "
                       "charge centrifuges: run the mill slower");
  std::smatch m;
  REQUIRE(std::regex_search(r.err, m, msg));
  CHECK(std::stod(m[1]) > 500);    // worn for a while: the new liner runs (at 0.995)
  CHECK(std::stod(m[2]) > 0.995);  // the worn liner is nearer critical than the new one
  CHECK(r.out.empty());
  fs::remove_all(dir);
}

TEST_CASE("a measured profile denser than 1 mm carries a caveat", "[app][forecast]") {
  LinerDesign L;
  CHECK(dense_profile_caveat(L).empty());  // parametric
  L.measured = true;
  auto line = [&](double spacing) {  // a straight profile 0.5 m long
    L.profile.points.clear();
    for (double x = 0; x <= 0.5 + 1e-12; x += spacing) L.profile.points.emplace_back(x, 0.075);
  };
  line(0.0002);
  const std::string c = dense_profile_caveat(L);
  CHECK_THAT(c, Catch::Contains("0.20 mm apart (median)"));
  CHECK_THAT(c, Catch::Contains("docs/profile-csv.md"));
  line(0.0016);  // a scan's spacing: none
  CHECK(dense_profile_caveat(L).empty());
  line(0.00099);
  CHECK_FALSE(dense_profile_caveat(L).empty());
  // the median, not the smallest gap: a few close points at corners do not count
  line(0.0016);
  for (int i = 0; i < 20; ++i) L.profile.points.emplace_back(0.5 + 1e-4 * (i + 1), 0.075);
  CHECK(dense_profile_caveat(L).empty());
}

TEST_CASE("a forecast from a dense measured profile says so, in the JSON, on stderr and in the file",
          "[app][cli][forecast]") {
  // the new lifter of the test mill as a profile CSV, every element cut into
  // pieces of at most 0.25 mm (a dense scan), and as its nodes alone
  const fs::path dir = temp_dir("fc_dense");
  write_file(dir / "m.toml", fast_qiu("max_operating_hours = 200\n"));
  const RunResult f = run_linerlife("forecast " + (dir / "m.toml").string() + " --quiet --out " + (dir / "new").string());
  INFO(f.err);
  REQUIRE(f.code == 0);
  const H5Reader h5((dir / "new" / "forecast.h5").string());
  const auto xy = h5.doubles("/forecast/profiles/nodes");
  const auto off = h5.ints("/forecast/profiles/offset");
  const double R = h5.attr_double("/surface", "shell_radius_m");
  std::vector<Eigen::Vector2d> nodes;
  for (long long k = off[0]; k < off[1]; ++k) nodes.emplace_back(xy[2 * k], xy[2 * k + 1]);
  const auto p = segment_to_profile_xy(nodes, R, 0.0, 2 * M_PI / 64);
  std::ofstream dense(dir / "dense.csv"), coarse(dir / "coarse.csv");
  for (const Eigen::Vector2d& q : p) coarse << q.x() << "," << q.y() << "\n";
  const std::vector<Eigen::Vector2d> d = resample_polyline(p, 0.00025);
  for (size_t k = 0; k < d.size(); ++k) {
    // no point within 1.5 mm of a segment edge but the ends (a radial step there is refused)
    const bool end = k == 0 || k + 1 == d.size();
    if (!end && (d[k].x() < 0.0015 || d[k].x() > d.back().x() - 0.0015)) continue;
    dense << fmt::format("{:.9f},{:.9f}\n", d[k].x(), d[k].y());
  }
  dense.close();
  coarse.close();
  for (const char* which : {"dense", "coarse"}) {
    std::string t = fast_qiu("max_operating_hours = 200\n");
    t = std::regex_replace(t, std::regex("\\[liner\\]\n"), std::string("[liner]\nprofile_csv = \"") + which + ".csv\"\n");
    write_file(dir / (std::string(which) + ".toml"), t);
    const RunResult r = run_linerlife("forecast " + (dir / (std::string(which) + ".toml")).string() + " --json --out " +
                                      (dir / which).string());
    INFO(which << ": " << r.err);
    REQUIRE(r.code == 0);
    const JsonValue j = parse_json(r.out);
    int dense_caveats = 0;
    for (const auto& c : j["caveats"].items())
      if (c["text"].str().find("points are") != std::string::npos) {
        ++dense_caveats;
        CHECK(r.err.find(c["text"].str()) != std::string::npos);  // also printed as a note
        CHECK_THAT(H5Reader((dir / which / "forecast.h5").string()).attr_string("/forecast", "caveat"),
                   Catch::Contains(c["text"].str()));
      }
    CHECK(dense_caveats == (std::string(which) == "dense" ? 1 : 0));
  }
  // compare says it once for the comparison
  const RunResult c = run_linerlife("compare " + (dir / "dense.toml").string() +
                                    " --vary forecast.max_operating_hours=100,200 --json --jobs 1");
  INFO(c.err);
  REQUIRE(c.code == 0);
  const JsonValue jc = parse_json(c.out);
  int n = 0;
  for (const auto& cv : jc["caveats"].items()) n += cv["text"].str().find("points are") != std::string::npos;
  CHECK(n == 1);
  fs::remove_all(dir);
}

TEST_CASE("forecast --out writes the results file and its charts, and plot redraws them", "[app][cli][forecast][plot]") {
  const fs::path dir = temp_dir("fc_out");
  // a 0.23 m lifter worn to 0.20 m: 30 mm of wear, three refresh tolerances,
  // so the run prints a caveat (few_drives_caveat()) for the file to keep
  const std::string text = fast_qiu();
  REQUIRE(text.find("\nlifter_height_m = 0.25\n") != std::string::npos);
  write_file(dir / "m.toml", std::regex_replace(text, std::regex("\nlifter_height_m = 0.25\n"), "\nlifter_height_m = 0.23\n"));
  const RunResult r = run_linerlife("forecast " + (dir / "m.toml").string() + " --quiet --out " + (dir / "run").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("relining") || Catch::Contains("Relining"));
  REQUIRE(fs::exists(dir / "run" / "forecast.h5"));
  for (const auto& e : fs::directory_iterator(dir / "run"))  // no temporary file left behind
    CHECK(e.path().filename().string().find(".tmp") == std::string::npos);

  const H5Reader h5((dir / "run" / "forecast.h5").string());
  CHECK(h5.attr_string("/forecast", "criterion") == "min_lifter_height");
  CHECK(h5.attr_string("/forecast", "method") == "ode");
  const auto hours = h5.doubles("/forecast/history/hours");
  const auto mass = h5.doubles("/forecast/history/liner_mass_kg_per_m");
  REQUIRE(mass.size() == hours.size());
  for (size_t i = 1; i < mass.size(); ++i) CHECK(mass[i] <= mass[i - 1] + 1e-9);  // wear only removes steel
  const auto ph = h5.doubles("/forecast/profiles/hours");
  CHECK(ph.size() >= 2);
  // the file keeps the caveat the run printed
  const std::string cav = h5.attr_string("/forecast", "caveat");
  CHECK_THAT(cav, Catch::Contains("times refresh_tol_m"));
  CHECK(r.err.find(cav) != std::string::npos);

  if (!python_charts_available()) {
    WARN("matplotlib/h5py missing for /usr/bin/python3: charts not checked");
  } else {
    for (const char* png : {"forecast_profiles.png", "forecast_lifter.png", "forecast_charge.png"}) {
      INFO(png);
      CHECK(fs::exists(dir / "run" / png));
    }
    const RunResult p = run_linerlife("plot " + (dir / "run" / "forecast.h5").string() + " --out " +
                                      (dir / "redrawn").string());
    INFO(p.err);
    CHECK(p.code == 0);
    for (const char* png : {"forecast_profiles.png", "forecast_lifter.png", "forecast_charge.png"}) {
      INFO(png);
      CHECK(fs::exists(dir / "redrawn" / png));
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("plot refuses a results file whose drawn data hold NaN or infinite values, naming the file and dataset",
          "[app][cli][forecast][plot][input]") {
  // a review: a forecast.h5 whose profile nodes were NaN was drawn (blank
  // profiles, exit 0)
  if (!python_charts_available()) {
    WARN("matplotlib/h5py missing for /usr/bin/python3: plot not checked");
    return;
  }
  const fs::path dir = temp_dir("plot_nan");
  write_file(dir / "m.toml", fast_qiu("max_operating_hours = 300\n"));
  RunResult r = run_linerlife("forecast " + (dir / "m.toml").string() + " --quiet --out " + (dir / "run").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  r = run_linerlife("geometry --out " + (dir / "geo").string());
  REQUIRE(r.code == 0);
  // each case: the file, a Python statement damaging its open h5py File `f`, the dataset named
  struct Damage {
    fs::path file;
    std::string python, dataset;
  };
  const std::vector<Damage> cases = {
      {dir / "run" / "forecast.h5", "v = f['/forecast/profiles/nodes']; v[3, 1] = float('nan')",
       "/forecast/profiles/nodes: 1 of "},
      {dir / "run" / "forecast.h5", "v = f['/forecast/profiles/nodes']; v[...] = float('nan')",
       "/forecast/profiles/nodes: "},
      {dir / "run" / "forecast.h5", "v = f['/forecast/history/hours']; v[1] = float('inf')",
       "/forecast/history/hours: 1 of "},
      {dir / "geo" / "geometry.h5", "v = f['/surface/nodes']; v[0, 0] = float('-inf')", "/surface/nodes: 1 of "},
      // finite but absurd: matplotlib failed with a singular matrix, a traceback and exit 1 (a review, 2026-12-04)
      {dir / "run" / "forecast.h5", "v = f['/forecast/profiles/nodes']; v[1, 0] = 1e155",
       "/forecast/profiles/nodes: 1 of 360 values are beyond +-1e+12, which no results file holds (the first, 1e+155, "
       "at [1, 0])"},
  };
  for (const Damage& c : cases) {
    INFO(c.python);
    const fs::path bad_dir = dir / "bad", bad = bad_dir / "bad.h5";
    fs::remove_all(bad_dir);
    fs::create_directories(bad_dir);
    fs::copy_file(c.file, bad);
    const std::string py = "/usr/bin/python3 -c \"import h5py; f = h5py.File('" + bad.string() + "', 'r+'); " +
                           c.python + "; f.close()\"";
    REQUIRE(std::system(py.c_str()) == 0);
    // into a new folder; the first case also beside the file
    std::vector<std::string> outs = {" --out " + (dir / "charts" / "sub").string()};
    if (&c == &cases.front()) outs.push_back("");
    for (const std::string& out : outs) {
      r = run_linerlife("plot " + bad.string() + out);
      INFO(out << "\n" << r.err);
      CHECK(r.code == 2);
      CHECK_THAT(r.err, Catch::StartsWith("linerlife: error: results file " + bad.string() + " is damaged: dataset " +
                                          c.dataset));
      CHECK_THAT(r.err, Catch::Contains("allowed only finite numbers there"));
      CHECK(r.out.empty());
      CHECK_FALSE(fs::exists(dir / "charts"));  // nothing written: not even the folder
      CHECK(std::distance(fs::directory_iterator(bad_dir), fs::directory_iterator()) == 1);  // bad.h5 alone
    }
  }
  // A dataset missing that only the third chart draws: refused with nothing
  // drawn (a review, 2026-12-06: the first two charts were left, beside the
  // file or in the new folder, with exit 2)
  {
    const fs::path bad_dir = dir / "bad", bad = bad_dir / "bad.h5";
    fs::remove_all(bad_dir);
    fs::create_directories(bad_dir);
    fs::copy_file(dir / "run" / "forecast.h5", bad);
    const std::string py = "/usr/bin/python3 -c \"import h5py; f = h5py.File('" + bad.string() +
                           "', 'r+'); del f['/forecast/history/net_power_kw']; f.close()\"";
    REQUIRE(std::system(py.c_str()) == 0);
    for (const std::string& out : {" --out " + (dir / "charts" / "sub").string(), std::string()}) {
      r = run_linerlife("plot " + bad.string() + out);
      INFO(out << "\n" << r.err);
      CHECK(r.code == 2);
      CHECK_THAT(r.err, Catch::Contains("is damaged or incomplete"));
      CHECK_FALSE(fs::exists(dir / "charts"));
      CHECK(std::distance(fs::directory_iterator(bad_dir), fs::directory_iterator()) == 1);  // bad.h5 alone
    }
  }
  // (undamaged files draw: "forecast --out writes the results file and its charts, and plot redraws them")
  fs::remove_all(dir);
}

TEST_CASE("forecast runs each method from the command line, and euler agrees with the ODE", "[app][cli][forecast]") {
  const fs::path dir = temp_dir("fc_methods");
  write_file(dir / "m.toml", fast_qiu());
  double life[3] = {0, 0, 0};
  const char* methods[3] = {"ode", "euler", "amplify"};
  for (int i = 0; i < 3; ++i) {
    const RunResult r = run_linerlife("forecast " + (dir / "m.toml").string() + " --json --method " + methods[i]);
    INFO(methods[i] << ": " << r.err);
    REQUIRE(r.code == 0);
    const JsonValue j = parse_json(r.out);
    CHECK(j["method"].str() == methods[i]);
    life[i] = j["operating_hours"].num();
    CHECK(life[i] > 0);
    // amplify's default step (1e7 x 1.5 revolutions, thousands of hours) is
    // longer than a tenth of the life: it says its life depends on the step
    // (a review found it 60 % early without a word); the ode method never does
    bool step_caveat = false;
    for (const auto& cv : j["caveats"].items())
      step_caveat = step_caveat || cv["text"].str().find("method stepped") != std::string::npos;
    if (i == 0) CHECK_FALSE(step_caveat);
    if (i == 2) CHECK(step_caveat);
  }
  // Euler with feedback (default step) follows the same physics as the ODE:
  // within 5 % here (docs/validation/forecast.md has the convergence study).
  CHECK(life[1] == Approx(life[0]).epsilon(0.05));
  fs::remove_all(dir);
}

TEST_CASE("compare --vary forecasts one case per value and ranks them in a table", "[app][cli][compare]") {
  const fs::path dir = temp_dir("fc_compare");
  write_file(dir / "m.toml", fast_qiu());
  const RunResult r =
      run_linerlife("compare " + (dir / "m.toml").string() + " --vary liner.lifter_height_m=0.23,0.25 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  const auto& cases = j["cases"].items();
  REQUIRE(cases.size() == 2);
  CHECK(cases[0]["case"].str() == "liner.lifter_height_m=0.23");
  CHECK(cases[1]["case"].str() == "liner.lifter_height_m=0.25");
  // both end at 0.20 m of lifter: the taller new lifter lasts longer
  CHECK(cases[1]["operating_hours"].num() > cases[0]["operating_hours"].num());
  for (const auto& c : cases) {
    CHECK(c["mean_net_power_kw"].num() > 0);
    CHECK(is_iso_date(c["relining_date"].str()));
    CHECK(c["end_date"].str() == c["relining_date"].str());  // reached: the run ended on the relining date
    // a case's caveats are printed with its label (a worn-power caveat with
    // its figures each time and its explanation once: case_note_lines(), and
    // its own test)
    for (const auto& cv : c["caveats"].items()) {
      const std::string text = cv["text"].str();
      CHECK(r.err.find(c["case"].str() + ": " + text.substr(0, text.find(kWornPowerCaveatWhy))) != std::string::npos);
    }
  }
  // the 0.23 m lifter wears 30 mm, three refresh tolerances: its case has a caveat
  REQUIRE(cases[0]["caveats"].items().size() >= 1);
  CHECK(r.err.find(kWornPowerCaveatWhy) == r.err.rfind(kWornPowerCaveatWhy));
  // a value the schema refuses names the case and the key
  const RunResult bad = run_linerlife("compare " + (dir / "m.toml").string() + " --vary liner.lifter_height_m=0.25,-1");
  CHECK(bad.code == 2);
  CHECK_THAT(bad.err, Catch::Contains("lifter_height_m"));
  fs::remove_all(dir);
}

// docs/validation/forecast.md, "Element size". Until 2026-12-05 the layer
// model put each load on the element its ride-table bin's smaller edge
// touched, split along that element's normal: elements finer than the bins
// (16 mm on this mill) were loaded in a comb and tilted on the roughness it
// left, and the life went from 9,173 h at 10 mm to 19,047 h at 1.5 mm. This
// run to 2,500 h (2 revolutions a drive) then gave lifters 7.5 mm apart
// (0.2104 and 0.2180 m) and liners 507 kg/m apart (1.2 %); with the loads
// where the disc touches 1.1 mm and 51 kg/m, and with the rate field
// smoothed over 10 mm at every element size (smoothing_passes()) 0.2 mm
// and 13 kg/m.
TEST_CASE("the forecast's wear does not depend on the element size", "[app][cli][forecast]") {
  const fs::path dir = temp_dir("fc_element_size");
  std::string t = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  t = std::regex_replace(t, std::regex("\\[forecast\\]\n"),
                         "[forecast]\nrevolutions_per_drive = 2\nmax_operating_hours = 2500\n");
  write_file(dir / "m10.toml", t);
  write_file(dir / "m25.toml",
             std::regex_replace(t, std::regex("element_size_m = 0.01\n"), "element_size_m = 0.0025\n"));
  double lifter[2], mass[2], thin[2];
  for (int k = 0; k < 2; ++k) {
    const RunResult r = run_linerlife("forecast " + (dir / (k ? "m25.toml" : "m10.toml")).string() + " --json --quiet");
    INFO(r.err);
    REQUIRE(r.code == 0);
    const JsonValue j = parse_json(r.out);
    REQUIRE(j["operating_hours"].num() == Approx(2500));
    lifter[k] = j["lifter_height_m_final"].num();
    mass[k] = j["liner_mass_kg_per_m_final"].num();
    thin[k] = j["min_thickness_m_final"].num();
  }
  INFO("at 2,500 h, 10 mm and 2.5 mm elements: lifter " << lifter[0] << " and " << lifter[1] << " m, liner "
                                                        << mass[0] << " and " << mass[1] << " kg/m, thinnest "
                                                        << thin[0] << " and " << thin[1] << " m");
  CHECK(std::abs(lifter[1] - lifter[0]) < 0.003);
  CHECK(mass[1] == Approx(mass[0]).epsilon(0.005));
  CHECK(std::abs(thin[1] - thin[0]) < 0.0015);
  fs::remove_all(dir);
}

TEST_CASE("compare --vary varies values that hold commas, written as TOML", "[app][cli][compare]") {
  const fs::path dir = temp_dir("fc_compare_commas");
  write_file(dir / "m.toml", fast_qiu());
  const RunResult r = run_linerlife(
      "compare " + (dir / "m.toml").string() +
      " --vary 'wear.laws=\"abrasion/radziszewski\",\"abrasion/radziszewski, impact/sheldon_kanhere\"'"
      " --vary 'forecast.shutdowns=[],[{start=2027-02-01,days=30},{start=2027-06-01,days=10}]' --json --jobs 1");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  const auto& cases = j["cases"].items();
  REQUIRE(cases.size() == 4);
  CHECK(cases[0]["vary"]["wear.laws"].str() == "\"abrasion/radziszewski\"");
  CHECK(cases[3]["vary"]["wear.laws"].str() == "\"abrasion/radziszewski, impact/sheldon_kanhere\"");
  CHECK(cases[1]["vary"]["forecast.shutdowns"].str() == "[{start=2027-02-01,days=30},{start=2027-06-01,days=10}]");
  // impact wear on top of abrasion: the liner lasts fewer hours
  CHECK(cases[2]["operating_hours"].num() < cases[0]["operating_hours"].num());
  // shutdowns move the date, not the operating hours
  for (int k : {0, 2}) {
    CHECK(cases[k + 1]["operating_hours"].num() == cases[k]["operating_hours"].num());
    CHECK(cases[k + 1]["relining_date"].str() > cases[k]["relining_date"].str());
  }
  fs::remove_all(dir);
}

// A review (2026-12-07): the summary rounded the calendar days to the whole
// day (441.76 read as 442 beside a date 441 days on) and did not say that 14
// of the 153 days of a 3,000 h life at 0.9 were a shutdown.
TEST_CASE("forecast's summary gives the calendar days to a tenth and the shutdown days in them",
          "[app][cli][forecast]") {
  const fs::path dir = temp_dir("fc_calendar_days");
  write_file(dir / "m.toml", fast_qiu("shutdowns = [{ start = 2027-02-01, days = 14 }]\n"));
  const RunResult j = run_linerlife("forecast " + (dir / "m.toml").string() + " --json --quiet");
  REQUIRE(j.code == 0);
  const JsonValue v = parse_json(j.out);
  const double days = v["calendar_days"].num();
  REQUIRE(days > 45);  // past the shutdown's end (day 31 + 14)
  const RunResult t = run_linerlife("forecast " + (dir / "m.toml").string() + " --quiet");
  REQUIRE(t.code == 0);
  CHECK_THAT(t.out, Catch::Contains(fmt::format("({:.1f} calendar days at", days)));
  CHECK_THAT(t.out, Catch::Contains("availability, 14 of them shut down)"));
  // the effort line's counts, in the singular where there is one ("1 remeshes": the same review)
  const int drives = static_cast<int>(v["charge_redrives"].num()), remeshes = static_cast<int>(v["remeshes"].num());
  CHECK_THAT(t.out, Catch::Contains(fmt::format("{} charge drive{}, {} remesh{},", drives, drives == 1 ? "" : "s",
                                                remeshes, remeshes == 1 ? "" : "es")));
  // the power is a drive's mean, over more revolutions than `charge` averages
  // by default (the same review: 1,702 kW against charge's 1,734 kW, no word why)
  CHECK_THAT(t.out, Catch::Contains(" kW (each the mean of a drive's 2 revolutions)\n"));
  write_file(dir / "none.toml", fast_qiu());
  const RunResult n = run_linerlife("forecast " + (dir / "none.toml").string() + " --quiet");
  REQUIRE(n.code == 0);
  CHECK_THAT(n.out, !Catch::Contains("shut down"));
  // the amplify method's drives after the first average amplify_revolutions
  write_file(dir / "amplify.toml", fast_qiu("method = \"amplify\"\n"));
  const RunResult a = run_linerlife("forecast " + (dir / "amplify.toml").string() + " --quiet");
  REQUIRE(a.code == 0);
  CHECK_THAT(a.out, Catch::Contains("  net power  "));
  CHECK_THAT(a.out, !Catch::Contains("revolutions)"));
  fs::remove_all(dir);
}

TEST_CASE("compare of lifter designs by the layer model says its ranking is to be checked with the DEM",
          "[app][compare]") {
  const Config base = load_config_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  Config taller = base, longer = base, dem = base, dem_taller = base;
  taller.liner.design.lifter_height_m = 0.27;
  longer.mill.length_m = 5.0;  // an operating choice, not the liner
  dem.model.charge = dem_taller.model.charge = "dem";
  dem_taller.liner.design.lifter_height_m = 0.27;
  const std::string c = design_ranking_caveat({&base, &taller});
  CHECK(c.find("docs/validation/ball-mill.md") != std::string::npos);
  CHECK(c.find("charge = \"dem\"") != std::string::npos);
  CHECK(design_ranking_caveat({&base, &dem_taller}) == c);  // one layer case is enough
  // the same liner (an operating choice), or the DEM throughout: none
  CHECK(design_ranking_caveat({&base, &longer}).empty());
  // the liner's mesh or material is not its design
  Config mesh = base, hard = base;
  mesh.liner.element_size_m = 0.02;
  hard.liner.hardness_bhn = 450;
  CHECK(design_ranking_caveat({&base, &mesh, &hard}).empty());
  CHECK(design_ranking_caveat({&dem, &dem_taller}).empty());
  CHECK(design_ranking_caveat({&base}).empty());
  // the thesis' release names the slide launch as the ball mill's better screen;
  // with the slide on in every layer case, the note is about the slide
  CHECK(c.find("lifter_slide = \"on\" 11 of 15") != std::string::npos);
  Config slide = base, slide_taller = taller;
  slide.model.lifter_slide = slide_taller.model.lifter_slide = true;
  const std::string s = design_ranking_caveat({&slide, &slide_taller});
  CHECK(s.find("with lifter_slide = \"on\" ordered the example ball mill's six lifter designs") != std::string::npos);
  CHECK(s.find("charge = \"dem\"") != std::string::npos);
  CHECK(design_ranking_caveat({&slide, &taller}) == c);  // one case with the thesis' release: that note
  CHECK(design_ranking_caveat({&slide, &dem_taller}) == s);  // the DEM's case has no release of its own
}

TEST_CASE("compare of mill speeds by the layer model V-1.2 says its power goes the wrong way", "[app][compare]") {
  const Config base = load_config_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  Config faster = base, slightly = base, v10 = base, v10_faster = base, dem = base, dem_faster = base;
  faster.mill.speed_rpm = v10_faster.mill.speed_rpm = dem_faster.mill.speed_rpm = 1.1 * base.mill.speed_rpm;
  slightly.mill.speed_rpm = 1.005 * base.mill.speed_rpm;  // a diameter's change at a fixed fraction of critical
  v10.model.variant = v10_faster.model.variant = "1.0";
  dem.model.charge = dem_faster.model.charge = "dem";
  const std::string c = speed_trend_caveat({&base, &faster});
  CHECK(c.find("docs/validation/charge.md, \"Operating trends\"") != std::string::npos);
  // not a trend for every mill: on the example ball mill V-1.2's power rose
  // with the speed under a note that said it falls (a review, 2026-12-07)
  CHECK(c.find("does not give the speed's effect on power reliably: on the bundled Qiu mill") != std::string::npos);
  CHECK(c.find("draws less power as the speed rises") == std::string::npos);
  CHECK(speed_trend_caveat({&dem, &base, &dem_faster}) == c);  // one V-1.2 case is enough
  CHECK(speed_trend_caveat({&base, &slightly}).empty());
  CHECK(speed_trend_caveat({&v10, &v10_faster}).empty());
  CHECK(speed_trend_caveat({&dem, &dem_faster}).empty());
  CHECK(speed_trend_caveat({&base}).empty());
  // what the note says, on the bundled mill: V-1.2's power falls from 70 to
  // 86 % of critical (6,151 -> 5,414 kW; 7,266 -> 5,414 before the support
  // rule of 2026-12-06) where Morrell's rises (5,504 -> 6,975 kW; the DEM
  // 5,316 -> 6,666, bench/operating_trend.py): when a repair turns V-1.2's
  // trend, this fails and the note is to be revised
  const fs::path dir = temp_dir("speed_trend");
  auto power = [&](const std::string& phi, const std::string& model) {
    std::string t = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
    t = std::regex_replace(t, std::regex("speed_rpm = 10.36\n"), "speed_fraction_critical = " + phi + "\n");
    const fs::path cfg = dir / ("q" + phi + ".toml");
    write_file(cfg, t);
    const RunResult r = run_linerlife("charge " + cfg.string() + " --model " + model + " --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    return parse_json(r.out)["net_power_kw"].num();
  };
  CHECK(power("0.86", "layer") < 0.95 * power("0.70", "layer"));
  CHECK(power("0.86", "empirical") > 1.2 * power("0.70", "empirical"));
  // the figures it gives: 6,190 -> 4,971 kW from 0.66 to 0.90 (-20 %; it said -13 %, a figure from before the
  // power sum of 2026-12-06, until 2026-12-08)
  CHECK(c.find("falls by 20 % from 66 to 90 % of critical") != std::string::npos);
  CHECK(power("0.90", "layer") / power("0.66", "layer") == Approx(0.80).margin(0.015));
  fs::remove_all(dir);
}

TEST_CASE("compare says when one fraction of critical runs its cases at different speeds", "[app][compare]") {
  // A review (2026-12-08): lifters of 0.15, 0.2 and 0.23 m at 0.76 of critical
  // ran at 12.14-12.19 rpm (each case's speed from its own new liners), and
  // nothing said so
  const Config ball = load_config_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/ball_mill_5m.toml");
  REQUIRE(ball.speed_fraction_critical);  // the example ball mill gives its speed so
  Config taller = ball, faster = ball, rpm = ball, rpm_taller = ball;
  taller.mill.speed_rpm *= 1.004;  // what a taller lifter's smaller diameter resolves to
  faster.speed_fraction_critical = 0.8;
  faster.mill.speed_rpm *= 0.8 / 0.75;
  rpm.speed_fraction_critical.reset();
  rpm_taller.speed_fraction_critical.reset();
  const std::string c = resolved_speed_caveat({&ball, &taller});
  CHECK(c.find("speed_fraction_critical = 0.75") != std::string::npos);
  CHECK(c.find(fmt::format("the cases run at {:.4g} to {:.4g} rpm (+0.40 %)", ball.mill.speed_rpm,
                           taller.mill.speed_rpm)) != std::string::npos);
  CHECK(c.find("give [mill] speed_rpm") != std::string::npos);
  CHECK(resolved_speed_caveat({&ball, &ball}).empty());    // the same speed
  CHECK(resolved_speed_caveat({&ball, &faster}).empty());  // the speed varied on purpose
  CHECK(resolved_speed_caveat({&rpm, &rpm_taller}).empty());
  CHECK(resolved_speed_caveat({&ball}).empty());
  Config wider = taller;
  wider.mill.diameter_m *= 1.04;  // mills of other sizes compared at one fraction of critical: no note
  CHECK(resolved_speed_caveat({&ball, &wider}).empty());
  // compare gives each case's speed as resolved, and the note
  const fs::path dir = temp_dir("resolved_speed");
  write_file(dir / "b.toml", read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/ball_mill_5m.toml"));
  const RunResult r = run_linerlife("compare " + (dir / "b.toml").string() +
                                    " --vary liner.lifter_height_m=0.09,0.12 --json --jobs 2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto cases = parse_json(r.out)["cases"].items();
  REQUIRE(cases.size() == 2);
  CHECK(cases[1]["speed_rpm"].num() > cases[0]["speed_rpm"].num());  // the taller lifter: less room, faster
  CHECK_THAT(r.err, Catch::Contains("the speed is given as a fraction of critical"));
  fs::remove_all(dir);
}

TEST_CASE("compare of fillings by the layer model V-1.2 says its power hardly follows them", "[app][compare]") {
  // A review (2026-12-08): compare of the example ball mill at fillings 0.28,
  // 0.35 and 0.42 had V-1.2's power fall and the life rise by 64 %, with no
  // note, where the DEM's power rises with the filling
  const Config base = load_config_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/ball_mill_5m.toml");
  Config fuller = base, slightly = base, dem = base, dem_fuller = base, emp = base, emp_fuller = base;
  fuller.charge.filling = dem_fuller.charge.filling = emp_fuller.charge.filling = 0.45;
  slightly.charge.filling = 1.005 * base.charge.filling;
  dem.model.charge = dem_fuller.model.charge = "dem";
  emp.model.charge = emp_fuller.model.charge = "empirical";
  const std::string c = filling_trend_caveat({&base, &fuller});
  CHECK(c.find("the cases differ in filling") != std::string::npos);
  CHECK(c.find("docs/validation/charge.md, \"Operating trends\"") != std::string::npos);
  CHECK(filling_trend_caveat({&dem, &base, &dem_fuller}) == c);  // one V-1.2 case is enough
  CHECK(filling_trend_caveat({&base, &slightly}).empty());
  CHECK(filling_trend_caveat({&dem, &dem_fuller}).empty());
  CHECK(filling_trend_caveat({&emp, &emp_fuller}).empty());
  CHECK(filling_trend_caveat({&base}).empty());
  // what it says, on the ball mill (filling = ball_filling): V-1.2 within
  // 5 % from 0.25 to 0.45, Morrell's C-model up by more than 30 %; when a
  // repair makes V-1.2 follow the filling, this fails and the note is to be
  // revised
  const fs::path dir = temp_dir("filling_trend");
  auto power = [&](const std::string& J, const std::string& model) {
    std::string t = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/ball_mill_5m.toml");
    t = std::regex_replace(t, std::regex("\nfilling = [^\n]*\n"), "\nfilling = " + J + "\n");
    t = std::regex_replace(t, std::regex("\nball_filling = [^\n]*\n"), "\nball_filling = " + J + "\n");
    const fs::path cfg = dir / ("b" + J + ".toml");
    write_file(cfg, t);
    const RunResult r = run_linerlife("charge " + cfg.string() + " --model " + model + " --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    return parse_json(r.out)["net_power_kw"].num();
  };
  CHECK(power("0.45", "layer") / power("0.25", "layer") == Approx(1.015).margin(0.05));
  CHECK(power("0.45", "empirical") > 1.3 * power("0.25", "empirical"));
  // and compare says it, on stderr and in --json
  write_file(dir / "b.toml", read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/ball_mill_5m.toml"));
  const RunResult r = run_linerlife("compare " + (dir / "b.toml").string() +
                                    " --vary charge.filling=0.35,0.40 --json --jobs 2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains("the cases differ in filling"));
  CHECK_THAT(r.out, Catch::Contains("the cases differ in filling"));
  fs::remove_all(dir);
}

TEST_CASE("compare says which case's forecast failed", "[app][cli][compare]") {
  // a review (2026-12-06): exit 3 with the integrator's text and no case. At
  // 0.995 of critical the worn liner brings the mill to critical speed and
  // the layer model finds no room for a landing element (the forecast test
  // "a forecast that fails as its worn liner reaches critical speed ...")
  const fs::path dir = temp_dir("fc_compare_fail");
  // the fast settings, worn to the mill's own lifter limit (0.075 m), so
  // that the 0.995 case wears far enough to reach critical speed
  write_file(dir / "m.toml",
             std::regex_replace(fast_qiu(), std::regex("min_lifter_height_m = 0.2\n"), "min_lifter_height_m = 0.075\n"));
  const RunResult r = run_linerlife("compare " + (dir / "m.toml").string() +
                                    " --vary mill.speed_fraction_critical=0.77,0.995 --jobs 1 --out " +
                                    (dir / "out").string());
  INFO(r.err);
  CHECK(r.code == 3);
  CHECK_THAT(r.err, Catch::Contains("linerlife: simulation failed: case 2 (mill.speed_fraction_critical=0.995): "));
  CHECK_FALSE(fs::exists(dir / "out" / "compare.h5"));
  fs::remove_all(dir);
}

TEST_CASE("compare with two --vary forecasts every combination of their values", "[app][cli][compare]") {
  // a lifter design is a height and a face angle together
  const fs::path dir = temp_dir("fc_compare_grid");
  write_file(dir / "m.toml", fast_qiu());
  const RunResult r = run_linerlife("compare --vary liner.lifter_height_m=0.23,0.25 " + (dir / "m.toml").string() +
                                    " --vary liner.face_angle_leading_deg=15,22 --json --jobs 1");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  const auto& cases = j["cases"].items();
  REQUIRE(cases.size() == 4);
  // the first key varies slowest
  const char* labels[] = {"liner.lifter_height_m=0.23 liner.face_angle_leading_deg=15",
                          "liner.lifter_height_m=0.23 liner.face_angle_leading_deg=22",
                          "liner.lifter_height_m=0.25 liner.face_angle_leading_deg=15",
                          "liner.lifter_height_m=0.25 liner.face_angle_leading_deg=22"};
  for (size_t i = 0; i < 4; ++i) CHECK(cases[i]["case"].str() == labels[i]);
  // each case's values by key, as given (not re-formatted)
  CHECK(cases[1]["vary"]["liner.lifter_height_m"].str() == "0.23");
  CHECK(cases[1]["vary"]["liner.face_angle_leading_deg"].str() == "22");
  // designs ranked by the layer model: the caveat, once, in the JSON and on stderr
  REQUIRE(j["caveats"].items().size() == 1);
  CHECK(r.err.find(j["caveats"].items()[0]["text"].str()) != std::string::npos);
  // each case has both values: at either face angle the taller new lifter
  // lasts longer to the same 0.20 m, and a case equals its one-key run
  CHECK(cases[2]["operating_hours"].num() > cases[0]["operating_hours"].num() * 1.1);
  CHECK(cases[3]["operating_hours"].num() > cases[1]["operating_hours"].num() * 1.1);
  const RunResult one = run_linerlife("compare " + (dir / "m.toml").string() +
                                      " --vary liner.face_angle_leading_deg=15,22 --json --jobs 1 --vary liner.lifter_height_m=0.23"
                                      " --out " + (dir / "out").string());
  INFO(one.err);
  REQUIRE(one.code == 0);
  const JsonValue j1 = parse_json(one.out);
  const auto& c1 = j1["cases"].items();
  REQUIRE(c1.size() == 2);
  CHECK(c1[1]["case"].str() == "liner.face_angle_leading_deg=22 liner.lifter_height_m=0.23");
  CHECK(c1[1]["operating_hours"].num() == cases[1]["operating_hours"].num());
  CHECK(c1[1]["mean_net_power_kw"].num() == cases[1]["mean_net_power_kw"].num());
  REQUIRE(fs::exists(dir / "out" / "compare.h5"));
  if (python_charts_available()) CHECK(fs::exists(dir / "out" / "compare.png"));
  // the file keeps the caveats as forecast.h5 does: the ranking's on /cases,
  // a case's power caveat on its forecast (the layer model's power rises with wear)
  {
    const H5Reader h5((dir / "out" / "compare.h5").string());
    CHECK(h5.attr_string("/cases", "caveat") == j1["caveats"].items()[0]["text"].str());
    // the varied keys in --vary order and each case's values (the chart's ticks), not parsed from the labels
    CHECK(h5.attr_string("/cases", "varied_keys") == "liner.face_angle_leading_deg\nliner.lifter_height_m");
    CHECK(h5.attr_string("/cases/0", "varied_values") == "15\n0.23");
    CHECK(h5.attr_string("/cases/1", "varied_values") == "22\n0.23");
    size_t with = 0;
    for (size_t i = 0; i < 2; ++i)
      for (const auto& cv : c1[i]["caveats"].items()) {
        ++with;
        CHECK(h5.attr_string("/cases/" + std::to_string(i) + "/forecast", "caveat") == cv["text"].str());
      }
    CHECK(with >= 1);  // the 0.23 m lifters wear 30 mm, three refresh tolerances (few_drives_caveat())
  }
  fs::remove_all(dir);
}

TEST_CASE("compare runs its forecasts at once with the results of one after the other", "[app][cli][compare]") {
  // --jobs: each worker takes the next case; the table, the JSON and the
  // results file must not depend on how many run at once or in which order
  // they finish (three cases on two workers: one worker takes two).
  const fs::path dir = temp_dir("fc_compare_jobs");
  write_file(dir / "m.toml", fast_qiu());
  const std::string cmd =
      "compare " + (dir / "m.toml").string() + " --vary liner.face_angle_leading_deg=15,20,22 --json --jobs ";
  const RunResult one = run_linerlife(cmd + "1");
  const RunResult two = run_linerlife(cmd + "2");
  INFO(one.err << two.err);
  REQUIRE(one.code == 0);
  REQUIRE(two.code == 0);
  CHECK(two.out == one.out);
  const JsonValue j = parse_json(two.out);
  const auto& cases = j["cases"].items();
  REQUIRE(cases.size() == 3);
  CHECK(cases[0]["case"].str() == "liner.face_angle_leading_deg=15");
  CHECK(cases[2]["case"].str() == "liner.face_angle_leading_deg=22");
  // the three designs differ, so a case's result cannot have gone to another
  CHECK(cases[0]["operating_hours"].num() != cases[1]["operating_hours"].num());
  CHECK(cases[1]["operating_hours"].num() != cases[2]["operating_hours"].num());
  fs::remove_all(dir);
}

// The README's bundled calibration example (data/measured/qiu2001_synthetic_scans.csv)
// is the bundled forecast's own profiles at every calibration factor 1.3. The
// model moved them by 6.6 mm rms at 4,000 h between 2026-12-05 and
// 2026-12-07, and the example's fit stalled (exit 3) with nothing to say so
// until a review followed the README; its run (about 100 s) is too long for
// this suite, so this checks the cause: the file against the model's forecast
// of today (docs/measured-profiles.md, "The example goes stale with the model").
TEST_CASE("the bundled example scans are the bundled forecast's profiles at factor 1.3", "[app][cli][calibrate]") {
  const fs::path dir = temp_dir("fc_example_scans");
  std::string t = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  for (const char* k : {"calibration_centrifugal", "calibration_gravitational", "calibration_impact"}) {
    const std::regex line(std::string("\n") + k + " = [^\n]*\n");
    if (std::regex_search(t, line)) t = std::regex_replace(t, line, std::string("\n") + k + " = 1.3\n");
    else t = std::regex_replace(t, std::regex("\\[wear\\]\n"), std::string("[wear]\n") + k + " = 1.3\n");
  }
  write_file(dir / "k13.toml", t);
  const ForecastProfiles fp = forecast_profiles(dir / "k13.toml", dir / "fc");
  const std::vector<double>& ph = fp.hours;
  // the scans as calibrate reads them, measured against each profile as its fit measures them
  const MeasuredHistory scans = load_measured_history(std::string(LINERLIFE_SOURCE_DIR) +
                                                      "/data/measured/qiu2001_synthetic_scans.csv");
  REQUIRE(scans.snapshots.size() == 2);
  for (const MeasuredSnapshot& m : scans.snapshots) {
    size_t i = 0;  // the forecast's profile nearest the scan's hours (bench/scan_from_forecast.py)
    for (size_t k = 1; k < ph.size(); ++k)
      if (std::abs(ph[k] - m.hours) < std::abs(ph[i] - m.hours)) i = k;
    const std::vector<double> r =
        profile_residuals(unrolled_to_mill(m.points, fp.shell_radius_m, fp.segments), fp.nodes[i]);
    double sum = 0;
    for (double x : r) sum += x * x;
    const double rms = std::sqrt(sum / static_cast<double>(r.size()));
    INFO("scan at " << m.hours << " h: rms " << 1000 * rms << " mm from the forecast at " << ph[i]
                    << " h; remake the file with the commands in its header (docs/measured-profiles.md)");
    CHECK(std::abs(ph[i] - m.hours) < 1.0);
    CHECK(rms < 1e-3);  // 1 mm, what a scan resolves: the example must be the model's own forecast
  }
  fs::remove_all(dir);
}

TEST_CASE("calibrate recovers the wear factor of synthetic scans from the command line", "[app][cli][calibrate]") {
  // Scans: the forecast of the same mill with every calibration factor 1.3.
  const fs::path dir = temp_dir("fc_calibrate");
  const std::string k13 = "calibration_centrifugal = 1.3\ncalibration_gravitational = 1.3\ncalibration_impact = 1.3\n";
  write_file(dir / "true.toml", fast_qiu("output_interval_h = 500\n", k13));
  write_file(dir / "m.toml", fast_qiu("output_interval_h = 500\n"));
  const ForecastProfiles fp = forecast_profiles(dir / "true.toml", dir / "truth");
  const std::vector<double>& ph = fp.hours;
  std::ofstream csv(dir / "scans.csv");
  csv << "# synthetic scans: forecast with calibration factors 1.3\nhours,x_m,y_m\n";
  int scans = 0;
  for (size_t i = 1; i < ph.size() && scans < 2; ++i) {
    if (ph[i] < 900) continue;  // two scans, well into the life
    const std::vector<Eigen::Vector2d>& p = fp.profile[i];
    for (size_t k = 0; k < p.size(); ++k)  // every second node, and both ends of the segment
      if (k % 2 == 0 || k + 1 == p.size()) csv << ph[i] << "," << p[k].x() << "," << p[k].y() << "\n";
    ++scans;
  }
  csv.close();
  REQUIRE(scans == 2);

  const RunResult r = run_linerlife("calibrate " + (dir / "m.toml").string() + " --measured " +
                                    (dir / "scans.csv").string() + " --fit abrasion --json --out " +
                                    (dir / "cal").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  const auto& params = j["parameters"].items();
  REQUIRE(params.size() == 1);
  // One factor for all wear: the fit is a rescaling of time, and impact wear
  // is a small share here, so the abrasion factor carries it (issue 5 §8: 2 %).
  CHECK(params[0]["factor"].num() == Approx(1.3).epsilon(0.02));
  CHECK(j["rms_m"].num() < 0.2 * j["rms_initial_m"].num());
  // the life spread from the fit's uncertainty: P10 is the early date
  CHECK(j["remaining_hours_p10"].num() <= j["remaining_hours_p50"].num());
  CHECK(j["remaining_hours_p50"].num() <= j["remaining_hours_p90"].num());
  CHECK(j["relining_date_p10"].str() <= j["relining_date_p90"].str());
  // calibrate.h5 holds the fit's result as --json gives it
  {
    const H5Reader cal((dir / "cal" / "calibrate.h5").string());
    CHECK(cal.attr_string("/calibrate", "parameters") == params[0]["name"].str());
    REQUIRE(cal.doubles("/calibrate/factor").size() == 1);
    CHECK(cal.doubles("/calibrate/factor")[0] == params[0]["factor"].num());
    CHECK(cal.doubles("/calibrate/sigma_ln")[0] == params[0]["sigma_ln"].num());
    CHECK(cal.attr_string("/calibrate", "relining_date_p50") == j["relining_date_p50"].str());
    CHECK(cal.attr_string("/calibrate", "criterion") == j["criterion"].str());
    CHECK(cal.attr_double("/calibrate", "calibration_gravitational") == j["calibration_gravitational"].num());
    CHECK(cal.doubles("/calibrate/rms_per_profile_m").size() == 2);
    CHECK(cal.doubles("/calibrate/sigma_ln_independent")[0] ==
          params[0]["sigma_ln_independent"].num());
    CHECK(cal.attr_double("/calibrate", "residual_lag1") == j["residual_lag1"].num());
  }
  // the misfit's correlation along the scans (serial_covariance())
  CHECK(j["residual_lag1"].num() >= 0);
  CHECK(j["residual_lag1"].num() <= 1);
  CHECK_THAT(r.err, !Catch::Contains("the misfit is the model's"));
  // the calibrated configuration carries the fitted factor and loads again
  REQUIRE(fs::exists(dir / "cal" / "calibrated.toml"));
  const std::string cal_toml = read_file((dir / "cal" / "calibrated.toml").string());
  CHECK_THAT(cal_toml, Catch::Contains("calibration_gravitational"));
  // with the fit's factor, its uncertainty and the life it gives, as comments
  CHECK_THAT(cal_toml, Catch::Contains(fmt::format("#   abrasion: factor {:.4g}, 1-sigma x/ {:.3f}",
                                                   params[0]["factor"].num(), std::exp(params[0]["sigma_ln"].num()))));
  CHECK_THAT(cal_toml, Catch::Contains("P50 " + fmt::format("{:.0f}", j["remaining_hours_p50"].num()) + " h (" +
                                       j["relining_date_p50"].str() + ")"));
  const double widen = params[0]["sigma_ln"].num() / params[0]["sigma_ln_independent"].num();
  CHECK_THAT(cal_toml, Catch::Contains(fmt::format("#   misfit correlated along the scans with lag-1 {:.2f}: "
                                                   "sigmas x{:.2f} those of independent points",
                                                   j["residual_lag1"].num(), widen)));
  const RunResult again = run_linerlife("geometry " + (dir / "cal" / "calibrated.toml").string() + " --json");
  CHECK(again.code == 0);

  // The same scans with a wave of 5 mm along each (one period over the
  // scan, nothing at its ends, which must match round the ring: a shape no
  // factor of the wear laws makes): the misfit stays above what a scan
  // resolves and neighbouring points share it, so a note says the factors
  // absorb the model's misfit (the fit still gives them)
  {
    std::vector<std::string> head, rows;
    std::istringstream in(read_file((dir / "scans.csv").string()));
    for (std::string line; std::getline(in, line);)
      (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0])) ? rows : head).push_back(line);
    std::string wavy;
    for (const std::string& h : head) wavy += h + "\n";
    for (size_t a = 0; a < rows.size();) {  // one scan: the rows with the same hours
      const std::string hours = rows[a].substr(0, rows[a].find(','));
      size_t b = a;
      while (b < rows.size() && rows[b].substr(0, rows[b].find(',')) == hours) ++b;
      for (size_t k = a; k < b; ++k) {
        const auto c2 = rows[k].rfind(',');
        const double y = std::stod(rows[k].substr(c2 + 1)) + 5e-3 * std::sin(2 * M_PI * (k - a) / (b - a - 1));
        wavy += rows[k].substr(0, c2 + 1) + fmt::format("{:.6f}", y) + "\n";
      }
      a = b;
    }
    write_file(dir / "wavy.csv", wavy);
    const RunResult w = run_linerlife("calibrate " + (dir / "m.toml").string() + " --measured " +
                                      (dir / "wavy.csv").string() + " --fit abrasion --json");
    INFO(w.err);
    REQUIRE(w.code == 0);
    const JsonValue jw = parse_json(w.out);
    CHECK(jw["rms_m"].num() > 1e-3);
    CHECK(jw["residual_lag1"].num() > 0.8);
    CHECK_THAT(w.err, Catch::Contains(fmt::format("linerlife: note: the fit misses the scans by {:.2f} mm rms, and "
                                                  "neighbouring points miss together (lag-1 {:.2f}): the misfit is the "
                                                  "model's",
                                                  1000 * jw["rms_m"].num(), jw["residual_lag1"].num())));
  }

  // A last scan that already meets a relining criterion: the liner is due
  // now. Said before the fit, which still gives the factor; the remaining
  // life is 0 h (before: exit 2 after the fit, "at the start", naming neither
  // the scan nor the criterion's line).
  write_file(dir / "due.toml", std::regex_replace(fast_qiu("output_interval_h = 500\n"),
                                                  std::regex("min_lifter_height_m = 0.2\n"),
                                                  "min_lifter_height_m = 0.245\n"));
  const RunResult due = run_linerlife("calibrate " + (dir / "due.toml").string() + " --measured " +
                                      (dir / "scans.csv").string() + " --fit abrasion --json");
  INFO(due.err);
  REQUIRE(due.code == 0);
  const JsonValue jd = parse_json(due.out);
  CHECK(jd["parameters"].items()[0]["factor"].num() == params[0]["factor"].num());
  CHECK(jd["remaining_hours_p10"].num() == 0);
  CHECK(jd["remaining_hours_p90"].num() == 0);
  CHECK(jd["criterion"].str() == "min_lifter_height");
  CHECK_THAT(due.err, Catch::Contains("the last measured profile (" + (dir / "scans.csv").string() + " at "));
  CHECK_THAT(due.err, Catch::Contains("already meets the relining criterion min_lifter_height (lifter height 0.2"));
  CHECK_THAT(due.err, Catch::Contains("[forecast] min_lifter_height_m = 0.245 m at " + (dir / "due.toml").string() + ":"));

  // The same scans labelled a millionth of their hours: the fit asks for a
  // factor beyond [wear]'s range, and the refusal names the scans, not a line
  // of the configuration that never held the value (a review, 2026-12-06:
  // "m.toml:185: wear.calibration_centrifugal = 162754.79...: out of range")
  {
    std::string fast;
    std::istringstream in(read_file((dir / "scans.csv").string()));
    for (std::string line; std::getline(in, line);) {
      const auto comma = line.find(',');
      if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0])) && comma != std::string::npos)
        line = fmt::format("{}", std::stod(line.substr(0, comma)) / 1e6) + line.substr(comma);
      fast += line + "\n";
    }
    write_file(dir / "fast.csv", fast);
    const RunResult bad = run_linerlife("calibrate " + (dir / "m.toml").string() + " --measured " +
                                        (dir / "fast.csv").string() + " --fit abrasion --out " + (dir / "cal2").string());
    INFO(bad.err);
    CHECK(bad.code == 2);
    CHECK_THAT(bad.err, Catch::Contains((dir / "fast.csv").string() + ": the fit to these profiles asks for [wear] "
                                        "calibration_centrifugal = "));
    CHECK_THAT(bad.err, Catch::Contains("Check the hours of the profiles"));
    CHECK_THAT(bad.err, !Catch::Contains("m.toml:"));
    CHECK_FALSE(fs::exists(dir / "cal2" / "calibrate.h5"));
  }
  fs::remove_all(dir);
}

// The rest of the life runs up to the forecast's horizon counted from the new
// liner, as `linerlife forecast` counts it (a review, 2026-12-07: it ran the
// whole horizon again from the last scan, so a 4,500 h horizon gave a
// relining at 5,431 h, exit 0, and scans labelled 1e12 h a date past the
// year 9999; 1e30 h made the fit's forecast ask for 1e21 records).
TEST_CASE("calibrate forecasts the rest of the life up to the horizon counted from the new liner",
          "[app][cli][calibrate]") {
  const fs::path dir = temp_dir("fc_calibrate_horizon");
  const std::string scans = std::string(LINERLIFE_SOURCE_DIR) + "/data/measured/qiu2001_synthetic_scans.csv";
  // the fast mill's life on the plate is about 5,400 h from new with these
  // scans' factor (the last scan at 4,000 h); the horizon ends it at 4,500 h
  write_file(dir / "m.toml", std::regex_replace(fast_qiu("max_operating_hours = 4500\n"),
                                                std::regex("min_lifter_height_m = 0.2\n"), "min_lifter_height_m = 0.1\n"));
  const RunResult r = run_linerlife("calibrate " + (dir / "m.toml").string() + " --measured " + scans +
                                    " --fit abrasion --jobs 1 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const JsonValue j = parse_json(r.out);
  CHECK(j["last_measured_hours"].num() == 4000);
  CHECK(j["criterion"].str() == "horizon");
  for (const char* q : {"p10", "p50", "p90"}) {
    CHECK(j[std::string("remaining_hours_") + q].num() == Approx(500).margin(1e-6));
    CHECK(j[std::string("relining_date_") + q].kind == JsonValue::Kind::Null);  // not reached: no date
  }
  // the horizon's date is the forecast's end date for the same file
  const RunResult f = run_linerlife("forecast " + (dir / "m.toml").string() + " --json --quiet");
  REQUIRE(f.code == 0);
  const JsonValue jf = parse_json(f.out);
  REQUIRE(jf["criterion"].str() == "horizon");
  CHECK(j["horizon_date"].str() == jf["end_date"].str());
  // the text says so instead of giving a date
  const RunResult t = run_linerlife("calibrate " + (dir / "m.toml").string() + " --measured " + scans +
                                    " --fit abrasion --jobs 1");
  REQUIRE(t.code == 0);
  CHECK_THAT(t.out, Catch::Contains("remaining life from 4000 h: not reached within the horizon: more than 500 h (the "
                                    "horizon, " + jf["end_date"].str() + ")"));
  // the text and --json count the same forecasts (a review, 2026-12-07: 19 and 21)
  const int all = static_cast<int>(j["forecasts"].num()), fit = static_cast<int>(j["fit_forecasts"].num());
  CHECK(fit > 2);
  CHECK(all > fit);
  CHECK_THAT(t.out, Catch::Contains(fmt::format("; {} forecasts ({} for the fit, {} for the remaining life)", all, fit,
                                                all - fit)));

  // a last scan at or beyond the horizon leaves nothing to forecast: refused
  // before any work, naming the scan's line, its hours and the horizon's line
  write_file(dir / "short.toml", fast_qiu("max_operating_hours = 4000\n"));
  const std::string text = read_file((dir / "short.toml").string());
  const long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(text.find("max_operating_hours = 4000")), '\n');
  const RunResult s = run_linerlife("calibrate " + (dir / "short.toml").string() + " --measured " + scans +
                                    " --fit abrasion --jobs 1 --out " + (dir / "out").string());
  INFO(s.err);
  CHECK(s.code == 2);
  const std::string scan_text = read_file(scans);  // the line of the 4,000 h scan's first row
  const long scan_line =
      1 + std::count(scan_text.begin(), scan_text.begin() + static_cast<long>(scan_text.find("\n4000,") + 1), '\n');
  CHECK_THAT(s.err, Catch::Contains(scans + ":" + std::to_string(scan_line) +
                                    ": hours = 4000: the profile is measured at or beyond the forecast's "
                                    "horizon, [forecast] max_operating_hours = 4000 h (" +
                                    (dir / "short.toml").string() + ":" + std::to_string(line) + ")"));
  CHECK_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// A review (2026-12-06): a liner that wears only a few refresh_tol_m is
// forecast on a few charge drives, and its life may not have converged in the
// tolerance (a 0.2 m mill: 15,833 h on 1 drive, 13,711 h on 25).
TEST_CASE("an ode forecast whose liner wears less than five refresh_tol_m says so", "[app][forecast]") {
  ForecastSpec spec;
  spec.method = ForecastMethod::Ode;
  spec.refresh_tol_m = 0.002;
  ForecastResult f;
  f.stats.charge_redrives = 3;
  LifeRecord a, b;
  a.min_thickness_m = 0.005, a.lifter_height_m = 0.025;
  b.min_thickness_m = 0.001, b.lifter_height_m = 0.0253;  // the plate wears, the lifter stands higher over it
  f.history = {a, b};
  const std::string c = few_drives_caveat(spec, f);
  CHECK_THAT(c, Catch::StartsWith("the liner wore 4.0 mm over this life, 2.0 times refresh_tol_m = 0.002 m, and the "
                                  "charge was driven 3 times"));
  CHECK_THAT(c, Catch::EndsWith("(0.0008 m here)"));
  // ten tolerances of wear, the explicit methods, or a drive every right-hand side: none
  b.min_thickness_m = a.min_thickness_m - 0.011;
  f.history = {a, b};
  CHECK(few_drives_caveat(spec, f).empty());
  b.min_thickness_m = 0.001, b.lifter_height_m = 0.015;  // the lifter's drop counts as well: 10 mm
  f.history = {a, b};
  CHECK(few_drives_caveat(spec, f).empty());
  b.lifter_height_m = 0.0253;
  f.history = {a, b};
  spec.method = ForecastMethod::Euler;
  CHECK(few_drives_caveat(spec, f).empty());
  spec.method = ForecastMethod::Ode;
  spec.refresh_always = true;
  CHECK(few_drives_caveat(spec, f).empty());
}

TEST_CASE("compare says when the key it varies is not used beside profile_csv", "[app][cli]") {
  const fs::path dir = temp_dir("vary_unused");
  std::string t = fast_qiu("max_operating_hours = 200\n");
  t = std::regex_replace(t, std::regex("\\[liner\\]\n"),
                         "[liner]\nprofile_csv = \"" + std::string(LINERLIFE_SOURCE_DIR) +
                             "/tests/fuzz/corpus/profile_csv/seed_lifter.csv\"\n");
  t = std::regex_replace(t, std::regex("\nlifter_height_m = [^\n]*\n"), "\n");
  write_file(dir / "measured.toml", t);
  const RunResult r = run_linerlife("compare " + (dir / "measured.toml").string() +
                                    " --vary liner.lifter_height_m=0.2,0.22 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  // the file's note once, then each case's, whose varied key is among the unused
  const std::string file_note = "[liner] plate_thickness_m, lifter_top_width_m, face_angle_leading_deg, "
                                "face_angle_trailing_deg are not used: profile_csv gives the liner's profile";
  CHECK(r.err.find(file_note) != std::string::npos);
  CHECK(r.err.find(file_note) == r.err.rfind(file_note));
  for (const std::string v : {"0.2", "0.22"})
    CHECK_THAT(r.err, Catch::Contains("linerlife: note: liner.lifter_height_m=" + v + ": "));
  CHECK_THAT(r.err, Catch::Contains("[liner] lifter_height_m is not used: profile_csv gives the liner's profile"));
  fs::remove_all(dir);
}
