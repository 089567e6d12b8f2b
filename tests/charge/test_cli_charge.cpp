// `linerlife charge`: the contractual JSON keys, the output folder, and bad
// input refused with exit 2 (issue 3 §6, §8).
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "../app/cli_runner.h"
#include "app/config.h"

using namespace linerlife::test;
namespace fs = std::filesystem;

namespace {

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  const std::regex re("\"" + key + "\": (-?[0-9.eE+-]+)");
  REQUIRE(std::regex_search(json, m, re));
  return std::stod(m[1]);
}

/// The bundled default with `key = value` in `section` replaced or added.
std::string edited(const std::string& section, const std::string& key, const std::string& value) {
  std::string text = linerlife::default_config_text();
  const std::string header = "[" + section + "]";
  const auto sec = text.find(header);
  REQUIRE(sec != std::string::npos);
  const auto pos = text.find("\n" + key + " = ", sec);
  const auto next = text.find("\n[", sec + 1);
  if (pos != std::string::npos && (next == std::string::npos || pos < next)) {
    const auto end = text.find('\n', pos + 1);
    text.replace(pos + 1, end - pos - 1, key + " = " + value);
  } else {
    text.insert(sec + header.size(), "\n" + key + " = " + value);
  }
  return text;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream f(p);
  f << text;
}

}  // namespace

TEST_CASE("charge --json gives the contractual keys", "[charge][cli]") {
  const RunResult r = run_linerlife("charge --json --revolutions 1");
  REQUIRE(r.code == 0);
  for (const char* k : {"model", "filling", "fraction_critical", "diameter_eff_m", "toe_deg", "shoulder_deg",
                        "com_angle_deg", "com_radius_m", "net_power_kw", "gross_power_kw", "n_layers",
                        "n_trajectories", "charge_area_m2", "layer_speed_rpm", "simulated_s", "wall_s",
                        "realtime_ratio"})
    CHECK_THAT(r.out, Catch::Contains(std::string("\"") + k + "\":"));
  CHECK_THAT(r.out, Catch::Contains("\"model\": \"layer\""));
  CHECK(json_number(r.out, "filling") == 0.24);
  // the mill's speed and length, which the powers are for (a review: with the
  // speed given as a fraction of critical the rpm was nowhere in --json)
  CHECK(json_number(r.out, "speed_rpm") == 10.36);  // data/mills/qiu2001_sag.toml
  CHECK(json_number(r.out, "length_m") == 5.0);
  CHECK_THAT(r.out, Catch::Contains("\"angle_convention\": \"degrees anticlockwise from 3 o'clock"));
  CHECK(json_number(r.out, "diameter_eff_m") == Approx(9.9608).margin(1e-3));
  // an anticlockwise mill: toe lower left, shoulder upper right (DESIGN.md §3)
  const double toe = json_number(r.out, "toe_deg"), sh = json_number(r.out, "shoulder_deg");
  CHECK(toe > 180);
  CHECK(toe < 270);
  CHECK(sh > 0);
  CHECK(sh < 90);
  CHECK(json_number(r.out, "gross_power_kw") > json_number(r.out, "net_power_kw"));
  CHECK(json_number(r.out, "realtime_ratio") > 1);
  // indicators.md's "also reported", as in charge.h5 (a review, 2026-12-07:
  // only the HDF5 file had them); the text summary gives the fraction too
  CHECK(json_number(r.out, "media_diameter_m") == 0.1333);  // data/mills/qiu2001_sag.toml
  const double direct = json_number(r.out, "direct_impact_fraction");
  CHECK(direct > 0.02);  // the Qiu mill throws some of its charge onto the liner (about 0.16)
  CHECK(direct < 0.5);
  const RunResult t = run_linerlife("charge --revolutions 1");
  REQUIRE(t.code == 0);
  CHECK_THAT(t.out, Catch::Contains(fmt::format("direct liner impacts     {:>9.3f} of the charge landing from flight",
                                                direct)));
}

TEST_CASE("charge --model empirical --variant and the clockwise pilot mill", "[charge][cli]") {
  RunResult r = run_linerlife("charge --model empirical --json");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("\"model\": \"empirical\""));
  CHECK_THAT(r.out, Catch::Contains("\"n_trajectories\": null"));
  CHECK_THAT(r.out, Catch::Contains("\"direct_impact_fraction\": null"));  // no flights in Morrell's model
  CHECK(json_number(r.out, "toe_deg") == Approx(240.44).margin(0.01));
  r = run_linerlife("charge " + std::string(LINERLIFE_SOURCE_DIR) +
                    "/data/mills/pilot_test_01.toml --variant 1.1 --revolutions 1 --json");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("\"variant\": \"1.1\""));
  // the model's notes are in the JSON as on the standard error (a review,
  // 2026-12-06: only on stderr): this pilot's 10 ms step is sub-stepped
  CHECK_THAT(r.err, Catch::Contains("sub-stepped 2 times (0.005 s)"));
  CHECK_THAT(r.out, Catch::Contains("\"notes\": [") && Catch::Contains("sub-stepped 2 times (0.005 s)"));
  // a clockwise mill, in the same physical frame: toe lower right, shoulder upper left
  CHECK(json_number(r.out, "toe_deg") > 270);
  CHECK(json_number(r.out, "shoulder_deg") > 90);
  CHECK(json_number(r.out, "shoulder_deg") < 180);
}

TEST_CASE("charge --json gives null for an indicator the model does not give", "[charge][cli]") {
  // the DEM has no inner surface radius (Morrell's eq. 4.14): it said 0 m (a
  // review, 2026-12-06); the layer and empirical models give one
  const std::string pilot = std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/pilot_test_13.toml";  // ~60 discs
  RunResult r = run_linerlife("charge " + pilot + " --model dem --revolutions 1 --json");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("\"inner_radius_m\": null"));
  r = run_linerlife("charge " + pilot + " --model layer --revolutions 1 --json");
  REQUIRE(r.code == 0);
  CHECK(json_number(r.out, "inner_radius_m") > 0);
}

TEST_CASE("charge's summary says how each model's gross power is made up", "[charge][cli]") {
  // Morrell's gross carries his k = 1.26 on the net (docs/models/empirical.md);
  // the layer model's and the DEM's is no-load + net (docs/models/indicators.md):
  // the same line must not read as the same definition for both. The second
  // power figure is the layer model's energy rate and the empirical model's
  // Hogg-Fuerstenau; the DEM has none (it printed "Hogg-Fuerstenau net nan kW").
  const std::regex line("power, net / gross +([0-9.]+) / ([0-9.]+) kW for [0-9.]+ m \\(no-load ([0-9.]+) kW([^)]*)\\)");
  const std::string pilot = std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/pilot_test_13.toml";  // ~60 discs
  for (const std::string model : {"empirical", "layer", "dem"}) {
    const RunResult r =
        run_linerlife("charge " + (model == "dem" ? pilot : std::string()) + " --model " + model +
                      (model == "empirical" ? "" : " --revolutions 1"));
    REQUIRE(r.code == 0);
    std::smatch m;
    INFO(r.out);
    REQUIRE(std::regex_search(r.out, m, line));
    const double net = std::stod(m[1]), gross = std::stod(m[2]), no_load = std::stod(m[3]);
    if (model == "empirical") {
      CHECK(m[4].str() == "; gross = no-load + k x net, Morrell's k = 1.26");
      CHECK(gross == Approx(no_load + 1.26 * net).margin(0.15));  // printed to 0.1 kW
    } else {
      CHECK(m[4].str().empty());
      CHECK(gross == Approx(no_load + net).margin(0.15));
    }
    CHECK((r.out.find("Hogg-Fuerstenau net") != std::string::npos) == (model == "empirical"));
    CHECK((r.out.find("energy-rate net power") != std::string::npos) == (model == "layer"));
    CHECK(r.out.find("nan") == std::string::npos);
    // the count of layers is the indicator, the speeds the model's rings: each
    // line says which (a review, 2026-12-08: "7 / 4" above eight speeds)
    const std::regex speeds("layer speeds \\[rpm\\] +((?:[0-9.]+ )+)\\(([0-9]+) rings, outermost first\\)\n");
    REQUIRE(std::regex_search(r.out, m, speeds));
    std::istringstream in(m[1].str());
    int n = 0;
    for (double v; in >> v;) ++n;
    CHECK(n == std::stoi(m[2]));
    CHECK_THAT(r.out, Catch::Contains(" (en-masse depth through the centre of mass / streams in flight)\n"));
  }
}

TEST_CASE("charge --out writes the results file and the charts", "[charge][cli]") {
  const fs::path dir = temp_dir("charge_out");
  const RunResult r = run_linerlife("charge --revolutions 1 --out " + (dir / "run").string());
  REQUIRE(r.code == 0);
  CHECK(fs::exists(dir / "run" / "charge.h5"));
  CHECK(fs::exists(dir / "run" / "charge_snapshot.png"));
  CHECK(fs::exists(dir / "run" / "lifter_forces.png"));
  const std::string check =
      "/usr/bin/python3 -c \"import h5py,sys; f=h5py.File(sys.argv[1]); "
      "c=f['charge']; assert c.attrs['model']=='layer'; assert c.attrs['variant']=='1.2'; "
      "assert 180<c.attrs['toe_deg']<270; "
      "assert f['snapshots/position_m'].shape[0]==36 and f['snapshots/position_m'].shape[2]==2; "
      "assert f['loads/normal_force_n_per_m'].shape[0]==f['surface/nodes'].shape[0]; "
      "assert len(f['loads/impacts/normal_speed_m_s'])>0; print('ok')\" " +
      (dir / "run" / "charge.h5").string();
  FILE* p = popen(check.c_str(), "r");
  char buf[16] = {0};
  const size_t n = fread(buf, 1, sizeof buf - 1, p);
  CHECK(pclose(p) == 0);
  CHECK(std::string(buf, n) == "ok\n");
  // the empirical model into the same folder draws no lifter forces: the
  // layer run's chart goes with its charge.h5 (a review, 2026-12-06: it stayed
  // beside the empirical results)
  const RunResult e = run_linerlife("charge --model empirical --out " + (dir / "run").string());
  REQUIRE(e.code == 0);
  CHECK(fs::exists(dir / "run" / "charge_snapshot.png"));
  CHECK_FALSE(fs::exists(dir / "run" / "lifter_forces.png"));
  // the layer model's version is the layer model's only: the DEM's chart was
  // titled "dem model, version 1.2" from it (a review, 2026-12-07)
  const std::string no_variant = "/usr/bin/python3 -c \"import h5py,sys; c=h5py.File(sys.argv[1])['charge']; "
                                 "assert c.attrs['model']=='empirical' and 'variant' not in c.attrs\" " +
                                 (dir / "run" / "charge.h5").string();
  CHECK(std::system(no_variant.c_str()) == 0);
  fs::remove_all(dir);
}

TEST_CASE("charge refuses bad input with exit 2 and creates no output", "[charge][cli][input]") {
  const fs::path dir = temp_dir("charge_bad");
  const fs::path out = dir / "out";
  auto refused = [&](const std::string& text, const std::string& fragment) {
    write(dir / "bad.toml", text);
    const RunResult r = run_linerlife("charge " + (dir / "bad.toml").string() + " --out " + out.string());
    INFO(fragment);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(fragment));
    CHECK_FALSE(fs::exists(out));
  };
  refused(edited("charge", "filling", "0.0"), "filling = 0");
  refused(edited("charge", "ball_diameter_m", "0.3"), "spacing between lifters");
  refused(edited("model", "time_step_s", "-0.01"), "time_step_s = -0.01");
  refused(edited("model", "slurry_drag", "\"on\""), "slurry_drag");
  refused(edited("mill", "discharge", "\"overflow\""), "trunnion_diameter_m");
  refused(edited("model", "slip_model", "\"magic\""), "slip_model");
  RunResult r = run_linerlife("charge --model magic");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("magic"));
  r = run_linerlife("charge --variant 2.0");
  CHECK(r.code == 2);
  r = run_linerlife("charge --revolutions -1");
  CHECK(r.code == 2);
  // the closed-form model has no run length: refused, not ignored (a review
  // found it ran and exited 0, as if the 50 revolutions had been simulated)
  r = run_linerlife("charge --model empirical --revolutions 50 --out " + out.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--revolutions 50") && Catch::Contains("empirical model is closed-form"));
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}
