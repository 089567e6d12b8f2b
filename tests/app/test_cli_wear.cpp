// `linerlife wear`: bad input refused at setup with exit 2 and no output; the
// run itself once a charge model is in the table (issue 4 §4, §6).
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <filesystem>
#include <fstream>
#include <regex>

#include "app/config.h"
#include "app/forecast_setup.h"
#include "charge/charge_model.h"
#include "cli_runner.h"
#include "wear/wear_laws.h"

using namespace linerlife;
using namespace linerlife::test;
namespace fs = std::filesystem;

namespace {

/// The bundled mill with extra lines appended to its [wear] section (the last one).
/// The bundled mill with `wear_lines` added to its [wear] section.
std::string bundled_with(const std::string& wear_lines) {
  std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  const auto sec = text.find("\n[wear]\n");
  REQUIRE(sec != std::string::npos);
  text.insert(sec + 8, wear_lines);
  return text;
}

bool has_model(const std::string& name) {
  for (const auto& e : charge_models())
    if (name == e.name) return true;
  return false;
}

}  // namespace

TEST_CASE("wear: options and bad input exit 2 before any work", "[app][cli][wear]") {
  RunResult r = run_linerlife("wear --help");
  CHECK(r.code == 0);
  for (const char* opt : {"--revolutions", "--amplification", "--feedback", "--rotation", "--json", "--out"})
    CHECK_THAT(r.out, Catch::Contains(opt));
  const fs::path dir = temp_dir("wear_bad");
  const fs::path out = dir / "out";
  struct Case {
    std::string args, says;
  };
  for (const Case& c : {Case{"--amplification 0", "--amplification"}, Case{"--amplification -1e7", "--amplification"},
                        Case{"--amplification 1e12", "--amplification"}, Case{"--revolutions 0", "--revolutions"},
                        Case{"--rotation sideways", "--rotation"}}) {
    r = run_linerlife("wear " + c.args + " --out " + out.string());
    INFO(c.args << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(c.says));
    CHECK_FALSE(fs::exists(out));
  }
  // configuration errors name the key, the value and the line
  struct ConfigCase {
    std::string text, says;
  };
  for (const ConfigCase& c :
       {ConfigCase{bundled_with("laws = \"abrasion/radziszewski, impact/bogus\"\n"), "impact/bogus"},
        ConfigCase{bundled_with("laws = \"impact/finnie, impact/finnie\"\n"), "twice"},
        ConfigCase{bundled_with("calibration_impact = 0.0\n"), "calibration_impact"},
        ConfigCase{bundled_with("finnie_cutting_fraction = 1.5\n"), "finnie_cutting_fraction"},
        ConfigCase{bundled_with("smoothing_tukey = \"3RZ\"\n"), "smoothing_tukey"},
        ConfigCase{bundled_with("liner_poisson_ratio = 0.7\n"), "liner_poisson_ratio"}}) {
    const fs::path cfg = dir / "bad.toml";
    write_file(cfg, c.text);
    r = run_linerlife("wear " + cfg.string() + " --out " + out.string());
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(c.says));
    CHECK_FALSE(fs::exists(out));
  }
  // a negative hardness is refused by the [liner] range
  std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  text = std::regex_replace(text, std::regex("hardness_bhn = 350.0"), "hardness_bhn = -350.0");
  write_file(dir / "neg.toml", text);
  r = run_linerlife("wear " + (dir / "neg.toml").string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("hardness_bhn"));
  fs::remove_all(dir);
}

TEST_CASE("wear: an impact law with a charge model that gives no impacts is refused", "[app][cli][wear]") {
  // every model in the table that resolves no impacts must be refused with an impact law
  const fs::path dir = temp_dir("wear_combo");
  int checked = 0;
  for (const auto& e : charge_models()) {
    if (e.resolves_impacts) continue;
    std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
    text = std::regex_replace(text, std::regex("charge = \"layer\""), std::string("charge = \"") + e.name + "\"");
    text = std::regex_replace(text, std::regex("\\[wear\\]\n"), "[wear]\nlaws = \"impact/bitter\"\n");
    write_file(dir / "c.toml", text);
    const RunResult r = run_linerlife("wear " + (dir / "c.toml").string());
    INFO(e.name << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("impact spectra"));
    ++checked;
  }
  SUCCEED("models without impacts checked: " << checked);
  fs::remove_all(dir);
}

TEST_CASE("wear: the bundled mill runs, or says which charge model is missing", "[app][cli][wear]") {
  const RunResult r = run_linerlife("wear --json --revolutions 0.05");
  if (!has_model("layer")) {
    // before the charge models are merged
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("charge model \"layer\" is not available"));
    return;
  }
  REQUIRE(r.code == 0);
  for (const char* key : {"mass_loss_kg_per_m", "liner_mass_kg_per_m", "max_recession_m", "impact_fraction",
                          "lifter_height_m", "face_angle_leading_deg", "simulated_s", "wall_s", "realtime_ratio"})
    CHECK_THAT(r.out, Catch::Contains(std::string("\"") + key + "\""));
}

// A review (2026-12-07): the bundled ball mill's file sets no amplification,
// so `wear` ran at the built-in 1 and printed a deepest recession of 0.0000 m
// without a word, where `linerlife defaults` shows the Qiu file's 1e6.
TEST_CASE("wear: a file that sets no amplification is told that its wear run is not amplified",
          "[app][cli][wear]") {
  if (!has_model("layer")) return;
  const std::string ball = std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/ball_mill_5m.toml";
  const RunResult r = run_linerlife("wear " + ball + " --revolutions 0.2");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains("ball_mill_5m.toml sets neither [wear] amplification_abrasion nor "
                                    "amplification_impact, so the wear is not amplified"));
  CHECK_THAT(r.err, Catch::Contains("give --amplification"));
  CHECK_THAT(r.out, Catch::Contains("amplification 1/1"));
  // asked for on the command line, set in the file (the bundled mill), or set to 1 on purpose: no note
  for (const std::string& args : {"wear " + ball + " --revolutions 0.2 --amplification 1e6",
                                  std::string("wear --revolutions 0.05")}) {
    const RunResult q = run_linerlife(args);
    INFO(args << "\n" << q.err);
    REQUIRE(q.code == 0);
    CHECK_THAT(q.err, !Catch::Contains("not amplified"));
  }
  const fs::path dir = temp_dir("wear_amp_one");
  REQUIRE(read_file(ball).find("\n[wear]") == std::string::npos);  // the file has no [wear] section
  write_file(dir / "one.toml", read_file(ball) + "\n[wear]\namplification_abrasion = 1\n");
  const RunResult one = run_linerlife("wear " + (dir / "one.toml").string() + " --revolutions 0.2");
  REQUIRE(one.code == 0);
  CHECK_THAT(one.err, !Catch::Contains("not amplified"));
  fs::remove_all(dir);
}

TEST_CASE("wear: a run that wears through says how many revolutions it ran", "[app][cli][wear]") {
  // a review: at amplification 1e7 the bundled liner wears through after
  // 1.65 s of 3 revolutions (5.8 s each), and the header, the JSON and the
  // charts all said "3 revolutions"
  if (!has_model("layer")) return;
  const RunResult j = run_linerlife("wear --json --amplification 1e7 --revolutions 3");
  REQUIRE(j.code == 0);
  CHECK_THAT(j.out, Catch::Contains("\"worn_through\": true"));
  const std::smatch m = [&] {
    std::smatch x;
    std::regex_search(j.out, x, std::regex("\"revolutions_simulated\": ([0-9.eE+-]+)"));
    return x;
  }();
  REQUIRE(m.size() == 2);
  const double ran = std::stod(m[1]);
  CHECK(ran > 0);
  CHECK(ran < 3);
  const RunResult t = run_linerlife("wear --amplification 1e7 --revolutions 3");
  REQUIRE(t.code == 0);
  CHECK_THAT(t.out, Catch::Contains(fmt::format("{:.2f} of 3 revolutions, stopped", ran)));
}

TEST_CASE("wear: the charge model's notes reach the user, counted over the drives", "[app][cli][wear]") {
  if (!has_model("layer")) return;
  // a 20 ms step moves the Qiu shell 0.81 media diameters: the layer model
  // sub-steps it and says so in every drive (with feedback, one per remesh)
  const fs::path dir = temp_dir("wear_notes");
  std::string text = run_linerlife("defaults").out;
  const auto pos = text.find("\ntime_step_s = ");
  REQUIRE(pos != std::string::npos);
  text.replace(pos + 1, text.find('\n', pos + 1) - pos - 1, "time_step_s = 0.02");
  write_file(dir / "notes.toml", text);
  const RunResult r = run_linerlife(
      "wear " + (dir / "notes.toml").string() + " --json --revolutions 0.3 --feedback", 60);
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::smatch m;
  REQUIRE(std::regex_search(r.out, m, std::regex("\"charge_drives\": ([0-9]+)")));
  const int drives = std::stoi(m[1]);
  CHECK(drives > 2);
  CHECK_THAT(r.err, Catch::Contains(fmt::format("linerlife: note: in {} of {} charge drives (first in drive 1): "
                                                "time_step_s = 0.02 s",
                                                drives, drives)));
  CHECK_THAT(r.err, Catch::Contains("sub-stepped 2 times"));
  CHECK(std::regex_search(r.out, std::regex("\"charge_notes\": \\[\\s*\\{\\s*\"text\": \"time_step_s = 0.02 s")));
  CHECK(std::regex_search(r.out, std::regex("\"drives\": " + std::to_string(drives) + "\\b")));
  fs::remove_all(dir);
}

// docs/validation/speed-accuracy.md: the DEM's coarse-graining changes its
// wear rate by up to 40 % on the pilot mills, so a wear run (and a forecast)
// on a coarse-grained DEM warns.
TEST_CASE("wear: a coarse-grained DEM warns that its wear loads may be off", "[app][cli][wear][dem]") {
  if (!has_model("dem")) return;
  const fs::path dir = temp_dir("wear_cg");
  std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/pilot_test_01.toml");
  text = std::regex_replace(text, std::regex("charge = \"layer\"\n"), "charge = \"dem\"\n");
  for (const char* cg : {"1.2", "1.0"}) {
    const fs::path cfg = dir / "pilot.toml";
    write_file(cfg, text + "\n[dem]\ncoarse_grain = " + cg + "\nthreads = 1\nsettle_revolutions = 0.2\n");
    const RunResult r = run_linerlife("wear " + cfg.string() + " --json --revolutions 0.2", 120);
    INFO("coarse_grain " << cg << "\n" << r.err);
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Catch::Contains("\"mass_loss_kg_per_m\""));
    if (std::string(cg) == "1.2") {
      CHECK_THAT(r.err, Catch::Contains("warning: [dem] coarse_grain = 1.2 changes the DEM's wear rate"));
      CHECK_THAT(r.err, Catch::Contains("speed-accuracy.md"));
    } else {
      CHECK_THAT(r.err, !Catch::Contains("coarse_grain"));
    }
  }
  fs::remove_all(dir);
}

// docs/validation/ball-mill.md: with the default wear constants (the thesis',
// used with its layer model) the DEM wears the new liner 7.4-9.4 times as
// fast as the layer model, so a DEM wear run or forecast with a calibration
// factor left at 1 says which; one with all three set, or the layer model,
// does not.
TEST_CASE("the DEM with uncalibrated wear constants warns that its wear comes out several times faster",
          "[app][cli][wear][dem]") {
  if (!has_model("dem")) return;
  const fs::path dir = temp_dir("wear_cal");
  const std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/pilot_test_01.toml");
  REQUIRE(text.find("[wear]") == std::string::npos);  // the cases below add the section
  const std::string dem = std::regex_replace(text, std::regex("charge = \"layer\"\n"), "charge = \"dem\"\n") +
                          "\n[dem]\nthreads = 1\nsettle_revolutions = 0.2\n";
  struct Case {
    std::string config, at_one;  // the factors the warning names ("": none)
  };
  const std::string all3 = "calibration_centrifugal, calibration_gravitational, calibration_impact";
  for (const Case& k : {Case{dem, all3}, Case{dem + "\n[wear]\ncalibration_impact = 0.5\n",
                                              "calibration_centrifugal, calibration_gravitational"},
                        Case{dem + "\n[wear]\ncalibration_impact = 0.5\ncalibration_centrifugal = 0.2\n"
                                   "calibration_gravitational = 0.2\n", ""},
                        Case{text, ""}}) {
    const fs::path cfg = dir / "pilot.toml";
    write_file(cfg, k.config);
    const RunResult r = run_linerlife("wear " + cfg.string() + " --json --revolutions 0.2", 120);
    INFO(k.config << "\n" << r.err);
    REQUIRE(r.code == 0);
    if (k.at_one.empty()) {
      CHECK_THAT(r.err, !Catch::Contains("calibration"));
    } else {
      CHECK_THAT(r.err, Catch::Contains("the DEM drives the wear with [wear] " + k.at_one + " = 1"));
      CHECK_THAT(r.err, Catch::Contains("ball-mill.md") && Catch::Contains("linerlife calibrate"));
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("calibrate's fitted factors do not count as uncalibrated", "[app][wear][dem]") {
  Config c = load_config_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/pilot_test_01.toml");
  c.model.charge = "dem";
  CHECK(warn_wear_loads(c));                       // all three at 1
  CHECK(!warn_wear_loads(c, {true, true, true}));  // --fit all, or the three
  CHECK(warn_wear_loads(c, {false, false, true})); // --fit impact: the abrasion factors stay at 1
  CHECK(warn_wear_loads(c, {true, true, false}));  // --fit abrasion: the impact factor stays at 1
  c.wear.calibration_impact = 0.3;
  CHECK(!warn_wear_loads(c, {true, true, false}));
  c.model.charge = "layer";
  CHECK(!warn_wear_loads(c));
}

// compare: each warning once, naming the cases it concerns (it printed one
// unlabelled copy per case).
TEST_CASE("compare's warnings are printed once each with the cases they concern", "[app][wear]") {
  const std::vector<std::string> labels = {"a=1", "a=2", "a=3"};
  const std::vector<std::string> l = case_warning_lines(labels, {{"X", "Y"}, {"X"}, {"X", "Z"}});
  REQUIRE(l.size() == 3);
  CHECK(l[0] == "linerlife: warning: all 3 cases: X");
  CHECK(l[1] == "linerlife: warning: a=1: Y");
  CHECK(l[2] == "linerlife: warning: a=3: Z");
  const std::vector<std::string> m = case_warning_lines(labels, {{"Y"}, {}, {"Y"}});
  REQUIRE(m.size() == 1);
  CHECK(m[0] == "linerlife: warning: a=1, a=3: Y");
  CHECK(case_warning_lines(labels, {{}, {}, {}}).empty());
}

TEST_CASE("compare names the cases whose DEM wear is uncalibrated", "[app][cli][compare][dem]") {
  if (!has_model("dem")) return;
  const fs::path dir = temp_dir("compare_warn");
  // a DEM forecast of pilot test 1 cut down to a few seconds
  const std::string text = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/pilot_test_01.toml");
  REQUIRE(text.find("[forecast]") == std::string::npos);
  write_file(dir / "p.toml", std::regex_replace(text, std::regex("charge = \"layer\"\n"), "charge = \"dem\"\n") +
                                 "\n[dem]\nthreads = 1\nsettle_revolutions = 0.2\n\n[forecast]\n"
                                 "revolutions_per_drive = 0.5\nmin_lifter_height_m = 0.024\nmin_plate_thickness_m = 0.001\n");
  const RunResult r =
      run_linerlife("compare " + (dir / "p.toml").string() + " --vary wear.calibration_impact=1,0.5,0.7 --jobs 1", 120);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string all3 = "the DEM drives the wear with [wear] calibration_centrifugal, calibration_gravitational, "
                           "calibration_impact = 1";
  const std::string two = "the DEM drives the wear with [wear] calibration_centrifugal, calibration_gravitational = 1";
  CHECK_THAT(r.err, Catch::Contains("warning: wear.calibration_impact=1: " + all3));
  CHECK_THAT(r.err, Catch::Contains("warning: wear.calibration_impact=0.5, wear.calibration_impact=0.7: " + two));
  // once each
  CHECK(r.err.find(all3) == r.err.rfind(all3));
  CHECK(r.err.find(two + ",") == r.err.rfind(two + ","));
  fs::remove_all(dir);
}
