// Issue 7 §1: a forecast killed with SIGKILL at any moment and continued with
// --resume ends with the same results as the uninterrupted run, and never
// leaves a half-written results or checkpoint file behind.
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/h5_reader.h"
#include "cli_runner.h"
#include "tests/app/json_lite.h"

using namespace linerlife;
using namespace linerlife::test;
namespace fs = std::filesystem;

namespace {

/// The bundled Qiu mill shortened as in test_cli_forecast.cpp, checkpointing
/// after every charge drive so that a kill lands between checkpoints as well
/// as during one.
std::string resumable_qiu() {
  std::string t = read_file(std::string(LINERLIFE_SOURCE_DIR) + "/data/mills/qiu2001_sag.toml");
  t = std::regex_replace(t, std::regex("element_size_m = 0.01\n"), "element_size_m = 0.02\n");
  t = std::regex_replace(t, std::regex("min_lifter_height_m = 0.075\n"), "min_lifter_height_m = 0.2\n");
  t = std::regex_replace(t, std::regex("\\[forecast\\]\n"),
                         "[forecast]\nrevolutions_per_drive = 2\nrefresh_tol_m = 0.01\ncheckpoint_interval_s = 0\n");
  return t;
}

/// Starts `linerlife ARGS...` with its output to files in dir; returns the pid.
pid_t spawn(const std::vector<std::string>& args, const fs::path& dir) {
  std::fflush(stdout);  // the child must not write out the parent's buffers
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
    if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(err.c_str(), "w", stderr)) _exit(127);
    std::vector<char*> argv;
    std::string bin = LINERLIFE_BINARY;
    argv.push_back(bin.data());
    std::vector<std::string> a = args;
    for (std::string& s : a) argv.push_back(s.data());
    argv.push_back(nullptr);
    execv(bin.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

int wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? -WTERMSIG(status) : -1000;
}

/// Names in dir that are not finished output: temporaries of an atomic write.
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> t;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.find(".tmp") != std::string::npos || n.find(".part") != std::string::npos || n[0] == '.') t.push_back(n);
  }
  return t;
}

}  // namespace

TEST_CASE("a forecast killed with SIGKILL at random moments and resumed ends as the uninterrupted run",
          "[app][cli][forecast][resume]") {
  const fs::path dir = temp_dir("fc_kill");
  write_file(dir / "m.toml", resumable_qiu());
  const std::string cfg = (dir / "m.toml").string();

  // the uninterrupted run, timed to place the kills
  const fs::path whole_dir = dir / "whole";
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult whole = run_linerlife("forecast " + cfg + " --json --out " + whole_dir.string());
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  INFO(whole.err);
  REQUIRE(whole.code == 0);
  const JsonValue w = parse_json(whole.out);
  REQUIRE(w["charge_redrives"].num() >= 4);

  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> when(0.05, 0.95);
  for (int trial = 0; trial < 3; ++trial) {
    const fs::path out = dir / ("killed" + std::to_string(trial));
    int kills = 0, resumes = 0, code = -1;
    // kill at random moments until a run gets through; the first attempt is
    // a fresh start, later ones --resume (which starts afresh when the kill
    // came before the first checkpoint)
    for (int attempt = 0; attempt < 12 && code != 0; ++attempt) {
      std::vector<std::string> args = {"forecast", cfg, "--json", "--out", out.string()};
      if (attempt > 0) {
        args.push_back("--resume");
        ++resumes;
      }
      const pid_t pid = spawn(args, dir);
      if (attempt < 4) {
        // The moment is set by the run's progress, not the clock alone (a
        // loaded machine stretches a run): wait for a random number of new
        // checkpoints (the run writes one after every drive), then a random
        // fraction of a drive, then kill - unless the run ends first.
        const int target = std::uniform_int_distribution<int>(0, 6)(rng);
        const double extra_ms = when(rng) * wall_ms / w["charge_redrives"].num();
        const fs::path cp = out / "checkpoint.h5";
        fs::file_time_type last{};
        int seen = 0;
        bool ended = false;
        while (seen < target && !ended) {
          std::error_code ec;
          const auto t = fs::last_write_time(cp, ec);
          if (!ec && t != last) last = t, ++seen;
          int status = 0;
          ended = waitpid(pid, &status, WNOHANG) == pid;
          if (ended) code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
          std::this_thread::sleep_for(std::chrono::microseconds(500));
        }
        if (ended) {
          if (code == 0) break;
          continue;
        }
        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(extra_ms));
        kill(pid, SIGKILL);
      }
      code = wait_exit(pid);
      if (code == -SIGKILL) ++kills;
      if (code != 0 && fs::exists(out)) {
        // after a kill: a half-written file can only be a temporary (removed
        // by the next run); the checkpoint, if any, reads back whole, and a
        // forecast.h5 (a kill after it was committed) is a complete one
        INFO("after kill " << kills << ": " << read_file((dir / "stderr.txt").string()));
        CHECK(code == -SIGKILL);
        if (fs::exists(out / "checkpoint.h5")) CHECK_NOTHROW(H5Reader((out / "checkpoint.h5").string()));
        if (fs::exists(out / "forecast.h5")) CHECK(H5Reader((out / "forecast.h5").string()).attr_int("/", "partial") == 0);
      }
    }
    INFO("trial " << trial << ": " << kills << " kills, " << resumes << " resumes; "
                  << read_file((dir / "stderr.txt").string()));
    REQUIRE(code == 0);
    CHECK(kills >= 1);
    const JsonValue k = parse_json(read_file((dir / "stdout.txt").string()));
    // identical results: same thread count, same checkpointed state
    CHECK(k["operating_hours"].num() == w["operating_hours"].num());
    CHECK(k["criterion"].str() == w["criterion"].str());
    CHECK(k["relining_date"].str() == w["relining_date"].str());
    CHECK(k["charge_redrives"].num() == w["charge_redrives"].num());
    CHECK(k["history"]["hours"].nums() == w["history"]["hours"].nums());
    CHECK(k["history"]["lifter_height_m"].nums() == w["history"]["lifter_height_m"].nums());
    CHECK(k["history"]["net_power_kw"].nums() == w["history"]["net_power_kw"].nums());
    CHECK(fs::exists(out / "forecast.h5"));
    CHECK_FALSE(fs::exists(out / "checkpoint.h5"));  // removed once the run is complete
    const std::vector<std::string> left = temporaries(out);
    INFO("left in " << out.string() << ": " << fmt::format("{}", fmt::join(left, ", ")));
    CHECK(left.empty());
  }
  fs::remove_all(dir);
}

// CI, 2026-12-07: the test above failed once with a temporary chart left in
// the folder of a finished run. A kill that landed while the charts were
// drawn had left the plotting script running on (popen): it held its
// temporary past the next run's clean-up and would have renamed the dead
// run's charts over the next run's. The script now dies with linerlife.
TEST_CASE("a linerlife killed while its charts are drawn takes the plotting script with it", "[app][cli][resume]") {
  const fs::path dir = temp_dir("kill_charts");
  const fs::path out = dir / "out", started = dir / "started", outlived = dir / "outlived";
  // a stand-in for the plotting script, run by /bin/sh: says it started, then
  // after 3 s leaves a mark it can only leave if it outlives linerlife
  write_file(dir / "plot.sh", fmt::format("touch '{}'\nsleep 3\ntouch '{}'\n", started.string(), outlived.string()));
  ::setenv("LINERLIFE_PYTHON", "/bin/sh", 1);
  ::setenv("LINERLIFE_PLOT_SCRIPT", (dir / "plot.sh").c_str(), 1);
  const pid_t pid = spawn({"geometry", "--out", out.string()}, dir);
  ::unsetenv("LINERLIFE_PYTHON");
  ::unsetenv("LINERLIFE_PLOT_SCRIPT");
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(started) && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  REQUIRE(fs::exists(started));  // linerlife got as far as its charts
  kill(pid, SIGKILL);
  CHECK(wait_exit(pid) == -SIGKILL);
  std::this_thread::sleep_for(std::chrono::seconds(4));
  CHECK_FALSE(fs::exists(outlived));
  CHECK(fs::exists(out / "geometry.h5"));  // the results file was committed before the charts
  fs::remove_all(dir);
}

// Issue 7 §5: a simulation that fails part-way ends with exit 3 and a
// diagnostic, and the results up to the failure are written whole and marked
// partial. The failure is injected at a charge drive (LINERLIFE_FAIL_AT_DRIVE,
// app/cmd_forecast.cpp) as a charge model that blew up would throw it.
TEST_CASE("forecast --resume without a checkpoint says so, with --quiet and --json too, and starts afresh",
          "[app][cli][forecast][resume]") {
  // a review: with --quiet the run started over without a word
  const fs::path dir = temp_dir("fc_no_checkpoint");
  const fs::path cfg = dir / "qiu.toml", out = dir / "out";
  write_file(cfg, std::regex_replace(resumable_qiu(), std::regex("\\[forecast\\]\n"),
                                     "[forecast]\nmax_operating_hours = 300\n"));
  const std::string note = "linerlife: note: --resume: no checkpoint in " + out.string() + " (" +
                           (out / "checkpoint.h5").string() + " does not exist): the forecast starts from the new liner";
  RunResult r = run_linerlife("forecast " + cfg.string() + " --quiet --out " + out.string() + " --resume", 120);
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains(note + "\n"));
  CHECK_THAT(r.out, Catch::Contains("300 h from 2027-01-01"));
  CHECK(fs::exists(out / "forecast.h5"));
  // the folder now holds the results of a run that ended: they are replaced
  r = run_linerlife("forecast " + cfg.string() + " --json --quiet --out " + out.string() + " --resume", 120);
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains(note + "; the forecast.h5 there, of a run that ended, is replaced when it ends"));
  CHECK(parse_json(r.out)["operating_hours"].num() == Approx(300));  // stdout holds the JSON alone
  CHECK_FALSE(fs::exists(out / "checkpoint.h5"));
  fs::remove_all(dir);
}

TEST_CASE("a forecast that fails part-way exits 3 and leaves its results marked partial", "[app][cli][forecast]") {
  const fs::path dir = temp_dir("partial");
  const fs::path cfg = dir / "qiu.toml", out = dir / "out";
  write_file(cfg, resumable_qiu());
  // the whole run, for comparison
  const RunResult whole = run_linerlife("forecast " + cfg.string() + " --json --quiet", 300);
  REQUIRE(whole.code == 0);
  const JsonValue w = parse_json(whole.out);
  const long long drives = static_cast<long long>(w["charge_redrives"].num());
  REQUIRE(drives >= 6);
  const long long fail_at = drives / 2;
  // a chart an earlier run left in the folder: not to be read as the partial file's
  fs::create_directories(out);
  write_file(out / "forecast_lifter.png", "an earlier run's chart");
  ::setenv("LINERLIFE_FAIL_AT_DRIVE", std::to_string(fail_at).c_str(), 1);
  const RunResult r = run_linerlife("forecast " + cfg.string() + " --json --quiet --out " + out.string(), 300);
  ::unsetenv("LINERLIFE_FAIL_AT_DRIVE");
  INFO(r.err);
  CHECK(r.code == 3);
  CHECK_THAT(r.err, Catch::Contains("linerlife: simulation failed: "));
  CHECK_THAT(r.err, Catch::Contains(fmt::format("charge drive {} failed", fail_at)));
  CHECK_THAT(r.err, Catch::Contains("marked partial"));
  CHECK(r.out.empty());  // no JSON result for a failed run
  REQUIRE(fs::exists(out / "forecast.h5"));
  CHECK(temporaries(out).empty());
  CHECK_FALSE(fs::exists(out / "forecast_lifter.png"));  // removed with the partial file written
  const H5Reader h5((out / "forecast.h5").string());
  CHECK(h5.attr_int("/", "partial") == 1);
  CHECK(h5.attr_int("/forecast", "partial") == 1);
  // its end on the calendar is where it stopped (it said 2000-01-01, 0 days, 0 t)
  const double stopped_h = h5.attr_double("/forecast", "operating_hours");
  CHECK(stopped_h > 0);
  CHECK(h5.attr_double("/forecast", "calendar_days") > 0);
  CHECK(h5.attr_double("/forecast", "tonnes") > 0);
  CHECK(h5.attr_string("/forecast", "end_date") > "2027-01-01");  // after resumable_qiu()'s start_date
  CHECK(h5.attr_string("/forecast", "end_date") < w["end_date"].str());
  CHECK(h5.attr_string("/forecast", "relining_date").empty());
  // the partial history is the start of the whole run's, up to the failure
  const std::vector<double> hours = h5.doubles("/forecast/history/hours");
  const std::vector<double> whole_hours = w["history"]["hours"].nums();
  REQUIRE(!hours.empty());
  CHECK(hours.size() < whole_hours.size());
  for (size_t i = 0; i + 1 < hours.size(); ++i) CHECK(hours[i] == whole_hours[i]);
  const std::vector<double> lifter = h5.doubles("/forecast/history/lifter_height_m");
  REQUIRE(lifter.size() == hours.size());
  for (double v : lifter) CHECK(std::isfinite(v));
  fs::remove_all(dir);
}

// A damaged checkpoint is refused before any work: exit 2 naming the file and
// the dataset, nothing written, the checkpoint left as it was. Before the
// checks, a checkpoint whose profile_offset pointed past its profile_nodes
// crashed --resume (segfault, rc 139), and rates or drive states of the wrong
// size were used unchecked. The checkpoint is a real one (a run failed at its
// fifth drive leaves the one of its fourth), damaged with h5py in place.
TEST_CASE("a damaged checkpoint is refused naming the file and the dataset and nothing is written",
          "[app][cli][forecast][resume]") {
  const fs::path dir = temp_dir("fc_damaged");
  const fs::path cfg = dir / "qiu.toml", out = dir / "out";
  write_file(cfg, resumable_qiu());
  ::setenv("LINERLIFE_FAIL_AT_DRIVE", "5", 1);
  const RunResult failed = run_linerlife("forecast " + cfg.string() + " --json --quiet --out " + out.string(), 300);
  ::unsetenv("LINERLIFE_FAIL_AT_DRIVE");
  INFO(failed.err);
  REQUIRE(failed.code == 3);
  const fs::path cp = out / "checkpoint.h5", good = dir / "good.h5";
  REQUIRE(fs::exists(cp));
  REQUIRE(H5Reader(cp.string()).attr_int("/checkpoint", "have_prev") == 1);  // y_prev, r_prev in use
  fs::rename(cp, good);
  fs::remove(out / "forecast.h5");  // the failed run's partial results

  // each case: a Python statement on the open checkpoint `c` (h5py group
  // /checkpoint), and the dataset or attribute the refusal must name
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"v = c['profile_offset'][()]; v[1] = 10**9; c['profile_offset'][...] = v", "/checkpoint/profile_offset"},
      {"v = c['profile_offset'][()]; v[1] = 3; c['profile_offset'][...] = v", "/checkpoint/profile_offset"},
      {"v = c['r_now'][:3]; del c['r_now']; c['r_now'] = v", "/checkpoint/r_now"},
      {"v = c['y_prev'][:-1]; del c['y_prev']; c['y_prev'] = v", "/checkpoint/y_prev"},
      {"v = c['r_prev'][:0]; del c['r_prev']; c['r_prev'] = v", "/checkpoint/r_prev"},
      {"v = c['y_drive'][()]; v[0] = float('nan'); c['y_drive'][...] = v", "/checkpoint/y_drive"},
      {"v = c['y'][:5]; del c['y']; c['y'] = v", "/checkpoint/y"},
      {"v = c['base_segment_begin'][()]; v[1], v[2] = v[2], v[1]; c['base_segment_begin'][...] = v",
       "/checkpoint/base_segment_begin"},
      {"v = c['base_segment_design'][()]; v[3] = 1; c['base_segment_design'][...] = v",
       "/checkpoint/base_segment_design"},
      {"v = c['base_segment_design'][:-1]; del c['base_segment_design']; c['base_segment_design'] = v",
       "/checkpoint/base_segment_design"},
      {"c.attrs['next_extra'] = 5", "/checkpoint@next_extra"},
      // found by a review (2026-12-04): a NaN hour crashed the resumed run
      // (SIGSEGV in the calendar, a temporary left); the others ran to exit 0
      // with a liner of -11.8 m, a history out of order, or null statistics
      {"v = c['history_hours'][()]; v[3] = float('nan'); c['history_hours'][...] = v", "/checkpoint/history_hours"},
      {"v = c['history_hours'][()]; c['history_hours'][...] = v[::-1]", "/checkpoint/history_hours"},
      {"v = c['y'][()]; v[:] = 10.0; c['y'][...] = v", "/checkpoint/y"},
      {"v = c['history_lifter_height_m'][()]; v[3] = 1e300; c['history_lifter_height_m'][...] = v",
       "/checkpoint/history_lifter_height_m"},
      {"v = c['history_net_power_kw'][()]; v[2] = float('inf'); c['history_net_power_kw'][...] = v",
       "/checkpoint/history_net_power_kw"},
      {"c.attrs['net_power_kw'] = float('nan')", "/checkpoint@net_power_kw"},
      {"v = c['stats_double'][()]; v[0] = float('nan'); c['stats_double'][...] = v", "/checkpoint/stats_double"},
      {"v = c['stats_int'][()]; v[4] = -5; c['stats_int'][...] = v", "/checkpoint/stats_int"},
      {"c.attrs['provider_drives'] = -7", "/checkpoint@provider_drives"},
      {"c.attrs['have_prev'] = 7", "/checkpoint@have_prev"},
      // found by a review (2026-12-04): changes that leave every value
      // plausible (4 of 40 random 4-bit flips, one moving the power +23 %)
      // resumed without a word; the checksum written with the values catches them
      {"v = c['y'][()]; v[2] = -v[2] - 1e-4; c['y'][...] = v", "/checkpoint@checksum"},
      {"v = c['history_net_power_kw'][()]; v[1] *= 1.23; c['history_net_power_kw'][...] = v", "/checkpoint@checksum"},
      {"v = c['profile_nodes'][()]; v[7] += 1e-9; c['profile_nodes'][...] = v", "/checkpoint@checksum"},
      {"c.attrs['toe_deg'] = c.attrs['toe_deg'] + 0.5", "/checkpoint@checksum"},
      {"del c.attrs['checksum']", "/checkpoint@checksum"},
  };
  for (const auto& [damage, name] : cases) {
    INFO("damage: " << damage);
    fs::copy_file(good, cp, fs::copy_options::overwrite_existing);
    const std::string py = "/usr/bin/python3 -c \"import h5py; f = h5py.File('" + cp.string() +
                           "', 'r+'); c = f['checkpoint']; " + damage + "; f.close()\"";
    REQUIRE(std::system(py.c_str()) == 0);
    const std::string before = read_file(cp.string());
    const RunResult r =
        run_linerlife("forecast " + cfg.string() + " --json --quiet --out " + out.string() + " --resume", 120);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("linerlife: error: " + cp.string() + ": " + name + ": "));
    CHECK_THAT(r.err, Catch::Contains("the checkpoint is damaged: run without --resume"));
    CHECK(r.out.empty());
    CHECK_FALSE(fs::exists(out / "forecast.h5"));
    CHECK(read_file(cp.string()) == before);  // left for a look
    CHECK(temporaries(out).empty());
  }
  // a checkpoint of another configuration is refused naming the keys that
  // differ (a review: "made with another configuration" said not which)
  {
    fs::copy_file(good, cp, fs::copy_options::overwrite_existing);
    const fs::path cfg2 = dir / "qiu2.toml";
    std::string t = std::regex_replace(resumable_qiu(), std::regex("availability = 0.92\n"), "availability = 0.9\n");
    t = std::regex_replace(t, std::regex("length_m = 5.0\n"), "length_m = 5.5\n");
    write_file(cfg2, t);
    const RunResult r = run_linerlife("forecast " + cfg2.string() + " --json --quiet --out " + out.string() + " --resume", 60);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("was made with another configuration ([forecast] availability = 0.92 in the "
                                      "checkpoint, 0.9 now; [mill] length_m = 5.0 in the checkpoint, 5.5 now)"));
    CHECK_FALSE(fs::exists(out / "forecast.h5"));
  }
  // the undamaged checkpoint resumes
  fs::copy_file(good, cp, fs::copy_options::overwrite_existing);
  const RunResult ok = run_linerlife("forecast " + cfg.string() + " --json --quiet --out " + out.string() + " --resume", 300);
  INFO(ok.err);
  CHECK(ok.code == 0);
  CHECK(fs::exists(out / "forecast.h5"));
  fs::remove_all(dir);
}
