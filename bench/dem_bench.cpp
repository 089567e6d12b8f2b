// DEM speed benchmark (issue 6 §4; docs/benchmarks.md, ## DEM).
//
//   bench_dem scaling N THREADS REPS [STEPS]
//     An all-ball charge in the Qiu mill (10.36 m, 64 lifters, 10.36 rpm,
//     J = 0.24) with the ball size chosen for about N discs. The charge is
//     placed and run for 1.5 s of mill time (the bed forms and starts to
//     turn), then REPS times a fresh system on that state runs STEPS steps
//     (default 2000) with THREADS threads. One line per repetition:
//     particles, threads, steps, wall seconds, particle-steps/s, contacts/s.
//
//   bench_dem state CONFIG.toml THREADS REPS [STEPS]
//     The same timing on the charge of a configuration file.
//
//   bench_dem restitution
//     The restitution a disc bouncing on a wall comes back with against the
//     steps per contact (docs/models/dem.md §2).
//
//   bench_dem timestep CONFIG.toml SPC...
//     The dem model (2 threads, settle 1 revolution, average 2) with the time
//     step at collision time / SPC for each SPC, also below the accepted range:
//     outcome, toe, shoulder, power (docs/models/dem.md §2).
//
//   bench_dem realtime CONFIG.toml THREADS REPS [REVOLUTIONS]
//     The whole dem model (settling 1 revolution, then REVOLUTIONS, default 1,
//     averaged, indicators and loads) on a configuration; THREADS 0 is the
//     model's default (all cores, adapting to the load). One line per
//     repetition: particles, threads, simulated s, wall s, real-time ratio,
//     particle-steps/s.
//
// bench/dem_bench.sh runs both and prints the medians.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/config.h"
#include "bench/bench_main.h"
#include "charge/dem/dem_model.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"

using namespace linerlife;

namespace {

int scaling(int n_target, int threads, int reps, long long steps, const char* config = nullptr) {
  Config c = config ? load_config_file(config) : load_default_config();  // the Qiu mill
  if (!config) {
    c.charge.ball_filling = c.charge.filling;  // balls only: one size, so N follows from the diameter
    // N = phi J A / (pi d^2 / 4) for the mean disc of [0.9 d, d]: d from N
    const double A = 0.25 * kPi * 9.96 * 9.96, phi = c.model.dem.packing_fraction_2d;
    const double mean_sq = (0.81 + 0.9 + 1.0) / 3;  // <d^2> / d^2 for spread 0.1
    c.charge.ball_diameter_m = std::sqrt(phi * c.charge.filling * A / (n_target * kPi / 4 * mean_sq));
  }
  const LinerSurface surface = build_liner_surface(c.mill, c.liner);
  ChargeInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.model.dem.threads = 2;
  in.surface = &surface;
  DemSetup setup = make_dem_setup(in);
  DemSystem warm(setup.settings, setup.walls, setup.initial);
  warm.advance(std::llround(1.5 / setup.settings.dt));
  DemParticles state;
  state.x = warm.x(), state.y = warm.y(), state.vx = warm.vx(), state.vy = warm.vy(), state.w = warm.w();
  state.radius = warm.radius(), state.mass = warm.mass();
  DemSettings set = setup.settings;
  set.threads = threads;
  set.wall_angle0 = warm.wall_angle();
  for (int r = 0; r < reps; ++r) {
    DemSystem sys(set, setup.walls, state);
    sys.advance(10);  // first list build and force evaluation outside the timing
    const long long c0 = sys.pair_contact_steps() + sys.wall_contact_steps();
    const auto t0 = std::chrono::steady_clock::now();
    sys.advance(steps);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const long long contacts = sys.pair_contact_steps() + sys.wall_contact_steps() - c0;
    std::printf("scaling particles %d threads %d steps %lld wall_s %.4f particle_steps_per_s %.4g contacts_per_s %.4g "
                "dt %.4g list_entries_per_disc %.2g contacts_per_disc %.2g builds %lld\n",
                sys.size(), threads, steps, wall, sys.size() * static_cast<double>(steps) / wall, contacts / wall,
                set.dt, sys.list_entries_per_disc(), static_cast<double>(contacts) / steps / sys.size(),
                sys.list_builds());
    std::fflush(stdout);
  }
  return 0;
}

/// Restitution measured on a disc hitting a wall against the steps per contact,
/// averaged (and the largest error) over five onset phases within a step.
int restitution() {
  std::printf("| law | e | steps a contact | mean error | largest error |\n|---|---|---|---|---|\n");
  for (ContactLaw law : {ContactLaw::Linear, ContactLaw::Hertz})
    for (double e : {0.725, 0.8})
      for (double spc : {3.0, 5.0, 8.0, 10.0, 15.0, 20.0, 50.0}) {
        const double tc = 1e-3, v = 2.0, r = 0.05, m = 10;
        const ContactParams cp = make_contact_params(law, e, 0, 0, tc, 0, v);
        DemSettings s;
        s.particle = s.wall = cp;
        s.gravity_y = 0;
        const double tcw = collision_time(cp, m, v);
        s.dt = tcw / spc;
        double mean = 0, worst = 0;
        for (int ph = 0; ph < 5; ++ph) {
          DemParticles p;
          p.x = {0}, p.y = {r + v * s.dt * (3 + ph / 5.0)}, p.vx = {0}, p.vy = {-v}, p.w = {0}, p.radius = {r};
          p.mass = {m};
          DemSystem sys(s, make_wall_mesh({{-1, 0}, {1, 0}}, false), p);
          sys.advance(static_cast<long long>(4 + 3 * spc));
          const double err = sys.vy()[0] / v - e;
          mean += err / 5;
          worst = std::max(worst, std::abs(err));
        }
        std::printf("| %s | %.3f | %.0f | %+.4f | %.4f |\n", law == ContactLaw::Linear ? "linear" : "hertz", e, spc,
                    mean, worst);
      }
  return 0;
}

/// The dem model on a configuration with dt = collision time / spc, below the
/// accepted range too: where the run blows up and how the indicators move.
int timestep(const char* path, int argc, char** argv) {
  const Config c = load_config_file(path);
  const LinerSurface surface = build_liner_surface(c.mill, c.liner);
  ChargeInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.model.dem.threads = 2;
  in.model.dem.settle_revolutions = 1;
  in.revolutions = 2;
  in.surface = &surface;
  std::printf("| steps a contact | time step [s] | outcome | toe [deg] | shoulder [deg] | power [W/m] | largest wall overlap / r |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int a = 0; a < argc; ++a) {
    const double spc = std::atof(argv[a]);
    DemSetup setup = make_dem_setup(in);
    setup.settings.dt = setup.collision_time_s / spc;
    DemRunInfo info;
    try {
      const ChargeResult r = run_dem(in, setup, &info);
      std::printf("| %g | %.3g | ran | %.1f | %.1f | %.4g | %.2f |\n", spc, setup.settings.dt, r.indicators.toe_deg,
                  r.indicators.shoulder_deg, r.indicators.net_power_w_per_m, info.max_wall_overlap_ratio);
    } catch (const SimulationError& e) {
      std::string what = e.what();
      std::printf("| %g | %.3g | stopped (exit 3): %s | | | | |\n", spc, setup.settings.dt,
                  what.substr(0, what.find(':')).c_str());
    }
    std::fflush(stdout);
  }
  return 0;
}

int realtime(const char* path, int threads, int reps, double revolutions) {
  const Config c = load_config_file(path);
  const LinerSurface surface = build_liner_surface(c.mill, c.liner);
  ChargeInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.model.dem.threads = threads;
  in.model.dem.settle_revolutions = 1;
  in.revolutions = revolutions;
  in.surface = &surface;
  for (int r = 0; r < reps; ++r) {
    DemRunInfo info;
    const ChargeResult res = run_dem(in, &info);
    std::printf("realtime config %s particles %d threads %d simulated_s %.4f wall_s %.4f realtime_ratio %.4f "
                "particle_steps_per_s %.4g dt %.4g\n",
                path, info.particles, threads, res.stats.simulated_s, res.stats.wall_s, res.stats.realtime_ratio,
                info.particle_steps_per_s, info.time_step_s);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return bench::guarded_main([&] {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "scaling" && argc >= 5)
      return scaling(std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4]), argc > 5 ? std::atoll(argv[5]) : 2000);
    if (mode == "restitution") return restitution();
    if (mode == "timestep" && argc >= 4) return timestep(argv[2], argc - 3, argv + 3);
    if (mode == "state" && argc >= 5)
      return scaling(0, std::atoi(argv[3]), std::atoi(argv[4]), argc > 5 ? std::atoll(argv[5]) : 2000, argv[2]);
    if (mode == "realtime" && argc >= 5)
      return realtime(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), argc > 5 ? std::atof(argv[5]) : 1.0);
    std::fprintf(stderr,
                 "usage: bench_dem scaling N THREADS REPS [STEPS]\n"
                 "       bench_dem state CONFIG.toml THREADS REPS [STEPS]\n"
                 "       bench_dem restitution\n"
                 "       bench_dem timestep CONFIG.toml SPC...\n"
                 "       bench_dem realtime CONFIG.toml THREADS REPS [REVOLUTIONS]\n");
    return 2;
  });
}
