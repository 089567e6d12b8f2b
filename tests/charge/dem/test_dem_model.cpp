// The dem charge model on a pilot mill: indicators and loads from particle
// data, the frame of a clockwise mill, repeatability, refusals (issue 6 §1, §3).
#include <algorithm>
#include <cmath>
#include <numeric>

#include <catch2/catch.hpp>

#include "charge/charge_model.h"
#include "charge/dem/dem_model.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "tests/charge/same_run.h"

using namespace linerlife;

namespace {

/// Pilot test 13 of thesis Table 4.1 (data/mills/pilot_test_13.toml): 0.762 m
/// mill, 29 rpm, 4 lifters, 30 % filling of 0.05 m balls: about 60 discs.
struct Pilot {
  Mill mill;
  LinerDesign liner;
  LinerSurface surface;
  ChargeInput in;
  explicit Pilot(Rotation rot = Rotation::Cw, double ball_d = 0.05) {
    mill.diameter_m = 0.762;
    mill.length_m = 0.381;
    mill.speed_rpm = 29;
    mill.rotation = rot;
    liner.segments = 4;
    liner.design = {0.005, 0.025, 0.025, 5, 5, 0};
    liner.element_size_m = 0.002;
    liner.density_kg_m3 = 7800;
    surface = build_liner_surface(mill, liner);
    in.mill = mill;
    in.charge.filling = 0.3;
    in.charge.ball_filling = 0.3;
    in.charge.ball_diameter_m = ball_d;
    in.charge.ball_density_kg_m3 = 7800;
    in.charge.ore_density_kg_m3 = 2700;
    in.model.charge = "dem";
    in.model.dem.threads = 1;
    in.model.dem.settle_revolutions = 1;
    in.model.dem.revolutions = 2;
    in.surface = &surface;
  }
};

}  // namespace

TEST_CASE("dem is a row of the charge-model table", "[dem][model]") {
  const ChargeModelEntry& e = find_charge_model("dem");
  CHECK(std::string(e.name) == "dem");
  CHECK(e.resolves_impacts);
  CHECK(e.resolves_abrasion);
  CHECK(e.make() != nullptr);
}

TEST_CASE("a pilot-mill run gives indicators and liner loads from particle data", "[dem][model]") {
  Pilot p;
  DemRunInfo info;
  const ChargeResult r = run_dem(p.in, &info);
  const Indicators& I = r.indicators;
  CHECK(r.model == "dem");
  INFO("toe " << I.toe_deg << " shoulder " << I.shoulder_deg << " power " << I.net_power_w_per_m);
  // A clockwise mill in the physical frame: the charge rises on the left, the
  // toe lies lower right (near 310 deg), the shoulder upper left (near 135 deg).
  CHECK(I.toe_deg > 280);
  CHECK(I.toe_deg < 340);
  CHECK(I.shoulder_deg > 110);
  CHECK(I.shoulder_deg < 190);
  CHECK(I.com_angle_deg > 180);
  CHECK(I.com_angle_deg < 270);
  CHECK(I.com_radius_m > 0.1);
  CHECK(I.com_radius_m < 0.381);
  CHECK(I.charge_area_m2 > 0.5 * 0.3 * 0.44);
  CHECK(I.charge_area_m2 < 2.0 * 0.3 * 0.44);
  // Power P = T omega from the contact forces on the liner agrees with the torque
  // arm of the charge's weight, omega g sum m x (thesis eq. 4.3), averaged over the
  // same revolutions: in a steady charge the two torques balance.
  CHECK(I.net_power_w_per_m > 0);
  CHECK(info.torque_arm_power_w_per_m == Approx(I.net_power_w_per_m).epsilon(0.05));
  CHECK(I.net_power_kw == Approx(I.net_power_w_per_m * 0.381 / 1000).epsilon(1e-12));
  CHECK(I.gross_power_kw > I.net_power_kw);
  CHECK(I.fraction_critical == Approx(29 / critical_speed_rpm(I.diameter_eff_m)).epsilon(1e-12));
  CHECK(I.n_layers >= 1);
  CHECK(!I.lifter_force_angle_deg.empty());
  // Liner loads, per surface element.
  const LinerLoads& L = r.loads;
  REQUIRE(L.n_elements == p.surface.n_elements());
  CHECK(L.duration_s == Approx(2 * 60 / 29.0).epsilon(0.01));
  double sum_n = 0;
  for (int e = 0; e < L.n_elements; ++e) {
    CHECK(L.normal_force_n_per_m[e] >= 0);
    CHECK(L.shear_force_n_per_m[e] >= 0);
    if (L.normal_force_n_per_m[e] == 0) CHECK(L.slip_speed_m_s[e] == 0);
    CHECK(L.shear_work_rate_w_per_m[e] >= 0);
    sum_n += L.normal_force_n_per_m[e];
  }
  const double weight = info.charge_mass_kg_per_m * 9.81;
  CHECK(sum_n > 0.5 * weight);  // the liner carries the charge (more with the centrifugal part)
  CHECK(sum_n < 4.0 * weight);
  REQUIRE(L.has_impacts);
  REQUIRE(!L.impacts.empty());
  for (const auto& ev : L.impacts) {
    CHECK(ev.normal_speed_m_s >= p.in.model.dem.impact_min_speed_m_s);
    CHECK(ev.mass_kg == Approx(7800 * 3.14159265358979 * std::pow(ev.diameter_m, 3) / 6).epsilon(1e-9));
    CHECK(ev.rate_per_s > 0);
  }
  CHECK(I.direct_impact_fraction >= 0);
  CHECK(I.direct_impact_fraction <= 1);
  // statistics for `linerlife charge --json`
  CHECK(r.stats.elements == info.particles);
  CHECK(r.stats.time_step_s == info.time_step_s);
  CHECK(r.stats.particle_steps_per_s > 0);
  CHECK(r.stats.simulated_s == Approx(3 * 60 / 29.0).epsilon(0.01));
}

TEST_CASE("a clockwise mill is the mirror image of an anticlockwise one", "[dem][model]") {
  Pilot cw(Rotation::Cw), ccw(Rotation::Ccw);
  for (Pilot* p : {&cw, &ccw}) p->in.model.dem.revolutions = 3;
  const Indicators a = run_dem(cw.in).indicators, b = run_dem(ccw.in).indicators;
  auto mirror = [](double deg) { return std::fmod(540.0 - deg, 360.0); };  // theta -> 180 - theta
  INFO("cw toe " << a.toe_deg << " shoulder " << a.shoulder_deg << "; ccw toe " << b.toe_deg << " shoulder "
                 << b.shoulder_deg);
  CHECK(mirror(b.toe_deg) == Approx(a.toe_deg).margin(8));  // statistical: different discs, same mill
  CHECK(mirror(b.shoulder_deg) == Approx(a.shoulder_deg).margin(8));
  CHECK(b.net_power_w_per_m == Approx(a.net_power_w_per_m).epsilon(0.1));
}

TEST_CASE("dem runs repeat exactly for a seed whatever the thread count (1 to 3)", "[dem][model]") {
  // The work is cut into fixed partitions whatever the thread count, so even
  // 1 and 2 threads give the same bits. Three threads on this 2-core machine
  // deal the 8 partitions into uneven lanes (2, 3, 3) and take each other's
  // items whenever one of them is descheduled.
  Pilot one;
  one.in.model.dem.threads = 1;
  one.in.model.dem.revolutions = 0.5;
  one.in.model.dem.settle_revolutions = 0.5;
  const ChargeResult ref = run_dem(one.in);
  for (int threads : {1, 2, 3}) {
    Pilot p;
    p.in.model.dem.threads = threads;
    p.in.model.dem.revolutions = 0.5;
    p.in.model.dem.settle_revolutions = 0.5;
    const ChargeResult& a = ref;
    const ChargeResult b = run_dem(p.in);
    INFO(threads << " threads");
    test::check_same_run(a, b);
  }
  // another seed gives another (but similar) run
  Pilot p;
  p.in.model.dem.revolutions = 0.5;
  p.in.model.dem.settle_revolutions = 0.5;
  const double a = run_dem(p.in).indicators.net_power_w_per_m;
  p.in.model.dem.seed = 7;
  CHECK(run_dem(p.in).indicators.net_power_w_per_m != a);
}

TEST_CASE("a dem run that averages the charge's rise from rest says so", "[dem][model]") {
  // the discs start in rows at the bottom; the same rule and note as the
  // layer model's (charge/settling_note.h)
  Pilot p;
  p.in.model.dem.revolutions = 0.2;
  p.in.model.dem.settle_revolutions = 0.1;
  const ChargeResult cold = run_dem(p.in);
  std::string note;
  for (const std::string& n : cold.notes)
    if (n.find("settle_revolutions") != std::string::npos) note = n;
  CHECK_THAT(note, Catch::Contains("[dem] settle_revolutions = 0.1: ") &&
                       Catch::Contains("100 % of the averaged time is before that"));
  p.in.model.dem.settle_revolutions = 0.5;
  const ChargeResult settled = run_dem(p.in);
  CHECK(std::none_of(settled.notes.begin(), settled.notes.end(),
                     [](const std::string& n) { return n.find("settle_revolutions") != std::string::npos; }));
  CHECK(settled.stats.simulated_s > cold.stats.simulated_s);
}

TEST_CASE("a dem run reports its progress, rising to 1, and the report changes nothing", "[dem][model]") {
  // `linerlife charge --model dem` shows it on a terminal (tens of seconds on
  // the bundled mill): one report per sampling chunk (72 a revolution),
  // settling included
  Pilot p;
  p.in.model.dem.revolutions = 0.5;
  p.in.model.dem.settle_revolutions = 0.5;
  const ChargeResult quiet = run_dem(p.in);
  std::vector<double> f;
  p.in.progress = [&f](double x) { f.push_back(x); };
  const ChargeResult told = run_dem(p.in);
  test::check_same_run(quiet, told);
  REQUIRE(f.size() >= 70);  // 36 + 36 chunks, up to rounding
  CHECK(f.size() <= 74);
  CHECK(f.front() > 0);
  CHECK(f.front() < 0.05);
  for (size_t i = 1; i < f.size(); ++i) CHECK(f[i] > f[i - 1]);
  CHECK(f.back() == 1.0);
  // half the steps are the settling's
  const auto half = std::lower_bound(f.begin(), f.end(), 0.5 - 1e-9);
  REQUIRE(half != f.end());
  CHECK(*half == Approx(0.5).margin(0.02));
}

TEST_CASE("dem refuses time steps beyond the stable range and coarse-graining the mill cannot take",
          "[dem][model]") {
  auto refused = [](const ChargeInput& in, const std::string& key, const std::string& fragment) {
    try {
      make_dem_setup(in);
      FAIL("accepted; expected a refusal naming " << key);
    } catch (const InputError& e) {
      CHECK(e.key() == key);
      CHECK_THAT(e.what(), Catch::Contains(fragment));
    }
  };
  {
    Pilot p;
    const DemSetup s = make_dem_setup(p.in);  // the derived step is echoed
    CHECK(s.settings.dt == Approx(s.collision_time_s / p.in.model.dem.steps_per_collision).epsilon(1e-12));
    p.in.model.dem.time_step_s = s.collision_time_s / 4;
    refused(p.in, "dem.time_step_s", "stable");
    p.in.model.dem.time_step_s = s.collision_time_s / 6;
    CHECK_NOTHROW(make_dem_setup(p.in));
  }
  {
    Pilot p;
    p.in.model.dem.steps_per_collision = 4;
    refused(p.in, "dem.steps_per_collision", "stable");
  }
  {
    Pilot p(Rotation::Cw, 0.019);  // 19 mm balls: a 25 mm lifter holds discs up to 25 mm
    p.in.model.dem.coarse_grain = 1.3;
    CHECK_NOTHROW(make_dem_setup(p.in));
    p.in.model.dem.coarse_grain = 2;
    refused(p.in, "dem.coarse_grain", "allowed");
  }
  {
    Pilot p;
    p.in.model.dem.collision_time_s = 1e-3;
    p.in.model.dem.stiffness = 1e6;
    refused(p.in, "dem.stiffness", "not both");
  }
}

TEST_CASE("coarse-graining keeps the charge mass and stretches the collision time", "[dem][model]") {
  Pilot fine(Rotation::Cw, 0.019), coarse(Rotation::Cw, 0.019);
  coarse.in.model.dem.coarse_grain = 1.25;
  const DemSetup a = make_dem_setup(fine.in), b = make_dem_setup(coarse.in);
  const auto mass = [](const DemSetup& s) {
    return std::accumulate(s.particles.mass_kg_per_m.begin(), s.particles.mass_kg_per_m.end(), 0.0);
  };
  CHECK(mass(b) == Approx(mass(a)).epsilon(0.02));  // counts are rounded
  CHECK(static_cast<double>(b.particles.size()) == Approx(a.particles.size() / (1.25 * 1.25)).epsilon(0.02));
  CHECK(b.collision_time_s == Approx(1.25 * a.collision_time_s).epsilon(0.05));  // from the smallest disc
  // an impact still reports the real ball
  CHECK(b.particles.real_diameter_m[0] == Approx(2 * b.particles.radius_m[0] / 1.25).epsilon(1e-12));
}

// docs/models/dem.md §3 (wall loads under coarse-graining): the forces on the
// liner are the charge's whatever the disc size, and the slip at the wall and
// the real impact rate are scaled back by 1/s, so a coarse-grained run gives
// the media-size run's wall loads. Without the 1/s the real impact rate came
// out +30 % and the slip power +15 % at s = 1.3 on this mill (pilot test 12
// of thesis Table 4.1: 8 lifters, 45 % filling of 19 mm balls, 40 rpm); with
// it, 0.0 % and -12 %. The slip-power bound is a range, not a discriminator.
TEST_CASE("coarse-graining keeps the wall loads of the media-size run", "[dem][model]") {
  auto run = [](double s) {
    Pilot p(Rotation::Cw, 0.019);
    p.mill.speed_rpm = 40;
    p.liner.segments = 8;
    p.surface = build_liner_surface(p.mill, p.liner);
    p.in.mill = p.mill;
    p.in.surface = &p.surface;
    p.in.charge.filling = p.in.charge.ball_filling = 0.45;
    p.in.model.dem.revolutions = 8;
    p.in.model.dem.coarse_grain = s;
    const ChargeResult r = find_charge_model("dem").make()->run(p.in);
    struct Sums {
      double normal = 0, slip_power = 0, impacts_per_s = 0;
    } sums;
    for (double f : r.loads.normal_force_n_per_m) sums.normal += f;
    for (double w : r.loads.normal_slip_power_w_per_m) sums.slip_power += w;
    for (const ImpactEvent& e : r.loads.impacts) sums.impacts_per_s += e.rate_per_s;
    return sums;
  };
  const auto fine = run(1.0), coarse = run(1.3);
  INFO("normal " << fine.normal << " / " << coarse.normal << ", slip power " << fine.slip_power << " / "
                 << coarse.slip_power << ", real impacts per s " << fine.impacts_per_s << " / " << coarse.impacts_per_s);
  CHECK(coarse.normal == Approx(fine.normal).epsilon(0.05));
  CHECK(coarse.slip_power == Approx(fine.slip_power).epsilon(0.15));
  CHECK(coarse.impacts_per_s == Approx(fine.impacts_per_s).epsilon(0.15));
}

// The charge chart turns the liner by the snapshot's liner angle
// (app/plots/plot_charge.py); the DEM left it at 0, so its discs were drawn on
// a liner that had not turned.
TEST_CASE("dem snapshots carry the angle the liner has turned", "[dem][model]") {
  for (Rotation rot : {Rotation::Cw, Rotation::Ccw}) {
    Pilot p(rot);
    p.in.model.dem.settle_revolutions = 0.5;
    p.in.model.dem.revolutions = 1;
    p.in.record_snapshot = true;
    const ChargeResult r = make_dem_model()->run(p.in);
    REQUIRE(!r.snapshots.empty());
    const double omega = p.mill.sense() * p.mill.speed_rpm * 2 * kPi / 60;
    for (const ChargeSnapshot& s : r.snapshots) {
      INFO("t = " << s.time_s);
      CHECK(s.time_s > 0);
      CHECK(s.liner_angle_rad == Approx(omega * s.time_s).epsilon(1e-12));
    }
  }
}
