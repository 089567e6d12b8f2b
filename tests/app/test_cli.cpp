// The command line: exit codes, messages, JSON and atomic output (issue 2 §2, §5).
#include <filesystem>
#include <fstream>
#include <regex>

#include <catch2/catch.hpp>

#include "cli_runner.h"

using namespace linerlife::test;
namespace fs = std::filesystem;

namespace {

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  const std::regex re("\"" + key + "\": (-?[0-9.eE+-]+)");
  REQUIRE(std::regex_search(json, m, re));
  return std::stod(m[1]);
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream f(p);
  f << text;
}

}  // namespace

TEST_CASE("the version and help options and usage errors", "[app][cli]") {
  RunResult r = run_linerlife("--version");
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("0."));
  r = run_linerlife("--help");
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("geometry"));
  CHECK_THAT(r.out, Catch::Contains("defaults"));
  r = run_linerlife("");
  CHECK(r.code == 2);
  r = run_linerlife("geometry --bogus");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--bogus"));
  r = run_linerlife("frobnicate");
  CHECK(r.code == 2);
}

TEST_CASE("geometry on the bundled mill reports its metrics", "[app][cli]") {
  RunResult r = run_linerlife("geometry");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("lifter height above plate"));
  r = run_linerlife("geometry --json");
  REQUIRE(r.code == 0);
  CHECK(json_number(r.out, "segments") == 64);
  CHECK(json_number(r.out, "lifter_height_m") == Approx(0.25).margin(1e-9));
  CHECK(json_number(r.out, "face_angle_leading_deg") == Approx(20).margin(3e-3));
  CHECK(json_number(r.out, "face_angle_trailing_deg") == Approx(20).margin(3e-3));
  CHECK(json_number(r.out, "top_width_m") == Approx(0.15).margin(1e-9));
  CHECK(json_number(r.out, "plate_thickness_m") == Approx(0.075).margin(1e-9));
  CHECK(json_number(r.out, "liner_mass_kg_per_m") > 40000);
  CHECK(json_number(r.out, "n_surface_elements") > 1000);
}

TEST_CASE("the defaults file runs to the same result as the bundled mill", "[app][cli]") {
  const fs::path dir = temp_dir("defaults");
  RunResult d = run_linerlife("defaults");
  REQUIRE(d.code == 0);
  write(dir / "mine.toml", d.out);
  const RunResult a = run_linerlife("geometry --json"), b = run_linerlife("geometry --json " + (dir / "mine.toml").string());
  REQUIRE(b.code == 0);
  for (const char* k : {"lifter_height_m", "liner_mass_kg_per_m", "diameter_eff_m", "n_surface_elements"})
    CHECK(json_number(a.out, k) == json_number(b.out, k));
  fs::remove_all(dir);
}

TEST_CASE("bad input exits 2 with a message and creates no output", "[app][cli][input]") {
  const fs::path dir = temp_dir("badinput");
  write(dir / "bad.toml", "[mill]\ndiameter_m = 10.36\nlenght_m = 5.0\n");
  const fs::path out = dir / "out";
  RunResult r = run_linerlife("geometry " + (dir / "bad.toml").string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("bad.toml:3"));
  CHECK_THAT(r.err, Catch::Contains("lenght_m"));
  CHECK_FALSE(fs::exists(out));
  r = run_linerlife("geometry " + (dir / "missing.toml").string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("does not exist"));
  r = run_linerlife("geometry " + dir.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("is a directory"));
  // an output folder that cannot be created
  write(dir / "file", "x");
  r = run_linerlife("geometry --out " + (dir / "file" / "sub").string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("cannot be created"));
  fs::remove_all(dir);
}

TEST_CASE("the out folder gets the results file and the charts, atomically", "[app][cli]") {
  const fs::path dir = temp_dir("out");
  const RunResult r = run_linerlife("geometry --out " + (dir / "run").string());
  REQUIRE(r.code == 0);
  CHECK(fs::exists(dir / "run" / "geometry.h5"));
  CHECK(fs::exists(dir / "run" / "liner_segment.png"));
  CHECK(fs::exists(dir / "run" / "liner_ring.png"));
  for (const auto& e : fs::directory_iterator(dir / "run"))
    CHECK(e.path().filename().string().find(".tmp.") == std::string::npos);
  // the layout of docs/output.md, read back with h5py
  const std::string check = "/usr/bin/python3 -c \"import h5py,sys; f=h5py.File(sys.argv[1]); "
                            "assert f['surface/nodes'].shape[1]==2; assert f.attrs['program']=='linerlife'; "
                            "assert 'diameter_m = 10.36' in f['config'][()].decode(); "
                            "assert abs(f['metrics/lifter_height_m'][0]-0.25)<1e-9; "
                            "assert f['lifter_grid/fraction'].shape==(60,60); print('ok')\" " +
                            (dir / "run" / "geometry.h5").string();
  FILE* p = popen(check.c_str(), "r");
  char buf[16] = {0};
  const size_t n = fread(buf, 1, sizeof buf - 1, p);
  CHECK(pclose(p) == 0);
  CHECK(std::string(buf, n) == "ok\n");
  fs::remove_all(dir);
}
