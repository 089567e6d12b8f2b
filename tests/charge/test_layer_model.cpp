// The layer model (docs/models/layer.md): conservation, geometry, symmetry,
// independence of the element ordering, time-step convergence against a finer
// run, the effect of a worn lifter, the versions, refused input, the
// incremental bookkeeping against full sweeps, and staggered initial phases.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "bench/worn_profiles.h"
#include "charge/canonical_surface.h"
#include "charge/morrell_c_model.h"
#include "charge/slurry_drag.h"
#include "fixtures.h"
#include "geometry/errors.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"
#include "tests/charge/same_run.h"

using namespace linerlife;
using namespace linerlife::test;

TEST_CASE("element mass is conserved and equals the charge mass", "[charge][layer]") {
  const Config c = mill_config("pilot_test_09.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2);
  in.record_snapshot = true;
  // one ball per element (the default), and agglomerates of 1.5 balls
  // (docs/models/layer.md §1): the element count scales as 1 / edge^2
  const double edge = GENERATE(1.0, 1.5);
  in.model.element_size_diameters = edge;
  INFO("element edge " << edge << " media diameters");
  const ChargeResult r = run_model("layer", in);
  // charge mass: Morrell's bulk density times the charge volume J * free area, per metre
  const double A = metrics(s, c.mill.rotation, 7800).free_area_m2;
  const double rho_c = morrell_charge_density(c.charge.filling, c.charge.ball_filling, c.charge.porosity,
                                              c.charge.slurry_void_fill, 0.0, c.charge.ore_density_kg_m3,
                                              c.charge.ball_density_kg_m3, 1000.0);
  CHECK(r.stats.charge_mass_kg_per_m == Approx(rho_c * c.charge.filling * A).epsilon(1e-12));
  REQUIRE(r.snapshots.size() == 36);
  for (const auto& sn : r.snapshots) CHECK(static_cast<long long>(sn.position.size()) == r.stats.elements);
  CHECK(r.stats.elements == std::lround(c.charge.filling * A / std::pow(edge * c.charge.ball_diameter_m, 2)));
}

TEST_CASE("no element sits inside the liner", "[charge][layer]") {
  const Config c = mill_config("pilot_test_09.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2);
  in.record_snapshot = true;
  const double edge = GENERATE(1.0, 1.5);  // agglomerated elements: docs/models/layer.md §1
  in.model.element_size_diameters = edge;
  INFO("element edge " << edge << " media diameters");
  const ChargeResult r = run_model("layer", in);
  const double a = 0.5 * edge * c.charge.ball_diameter_m;
  double worst = 1e9;
  for (const auto& sn : r.snapshots) {
    // into the frame of the liner, which has turned by liner_angle_rad
    const double co = std::cos(-sn.liner_angle_rad), si = std::sin(-sn.liner_angle_rad);
    for (const auto& p : sn.position) {
      const Eigen::Vector2d q(co * p.x() - si * p.y(), si * p.x() + co * p.y());
      // inside the liner ring (not beyond the shell) and not overlapping its surface
      CHECK(q.norm() < s.shell_radius_m);
      worst = std::min(worst, distance_to_liner(s, q));
    }
  }
  // the ride table stores the smaller edge of each bin; a disc may touch but
  // not overlap by more than 2 % of its radius
  CHECK(worst >= a * 0.98);
}

TEST_CASE("a clockwise mill is the mirror image of the anticlockwise one", "[charge][layer]") {
  Config c = mill_config("pilot_test_09.toml");
  c.liner.design.face_angle_leading_deg = 10;  // asymmetric lifters: the mirror must swap the faces
  c.liner.design.face_angle_trailing_deg = 30;
  c.mill.rotation = Rotation::Ccw;
  // the thesis' held layer, and the release study's pocket (only the ball at
  // the leading face held, docs/models/layer.md §3): which face leads
  const double pocket = GENERATE(-1.0, 0.0);
  INFO("held_pocket_balls " << pocket);
  c.model.held_pocket_balls = pocket;
  // and the pocket loads (docs/models/layer.md §7): which face takes the push
  c.model.pocket_loads = GENERATE(false, true);
  INFO("pocket_loads " << c.model.pocket_loads);
  const LinerSurface s_ccw = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s_ccw, 2);
  const ChargeResult a = run_model("layer", in);
  c.mill.rotation = Rotation::Cw;
  const LinerSurface s_cw = build_liner_surface(c.mill, c.liner);
  // the geometry builder makes the clockwise ring the mirror of the anticlockwise one
  const CanonicalSurface m = make_canonical_surface(s_cw, Rotation::Cw);
  REQUIRE(m.surface.n_nodes() == s_ccw.n_nodes());
  double dn = 0;
  for (int i = 0; i < s_ccw.n_nodes(); ++i) dn = std::max(dn, (m.surface.nodes[i] - s_ccw.nodes[i]).norm());
  REQUIRE(dn < 1e-9);
  ChargeInput in_cw = charge_input(c, s_cw, 2);
  const ChargeResult b = run_model("layer", in_cw);
  const Indicators &A = a.indicators, &B = b.indicators;
  CHECK(angle_diff(B.toe_deg, mirror_deg(A.toe_deg)) < 0.5);
  CHECK(angle_diff(B.shoulder_deg, mirror_deg(A.shoulder_deg)) < 0.5);
  CHECK(angle_diff(B.com_angle_deg, mirror_deg(A.com_angle_deg)) < 0.5);
  CHECK(B.com_radius_m == Approx(A.com_radius_m).epsilon(0.01));
  CHECK(B.net_power_kw == Approx(A.net_power_kw).epsilon(0.01));
  CHECK(B.n_layers == A.n_layers);
  // loads: each element carries the load of its mirror image (matched by midpoints)
  double total = 0, diff = 0;
  for (int e = 0; e < s_cw.n_elements(); ++e) {
    const Eigen::Vector2d mid(-s_cw.midpoint[e].x(), s_cw.midpoint[e].y());
    int best = 0;
    for (int f = 0; f < s_ccw.n_elements(); ++f)
      if ((s_ccw.midpoint[f] - mid).squaredNorm() < (s_ccw.midpoint[best] - mid).squaredNorm()) best = f;
    REQUIRE((s_ccw.midpoint[best] - mid).norm() < 1e-9);
    total += a.loads.normal_force_n_per_m[best];
    diff += std::abs(b.loads.normal_force_n_per_m[e] - a.loads.normal_force_n_per_m[best]);
  }
  CHECK(total > 0);
  CHECK(diff <= 0.02 * total);
}

TEST_CASE("results do not depend on the order of the elements", "[charge][layer]") {
  const Config c = mill_config("pilot_test_09.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2);
  in.seed = 1;
  const ChargeResult a = run_model("layer", in);
  in.seed = 987654321;  // shuffles which id each element gets
  const ChargeResult b = run_model("layer", in);
  CHECK(b.indicators.toe_deg == Approx(a.indicators.toe_deg).epsilon(1e-9));
  CHECK(b.indicators.shoulder_deg == Approx(a.indicators.shoulder_deg).epsilon(1e-9));
  CHECK(b.indicators.net_power_kw == Approx(a.indicators.net_power_kw).epsilon(1e-9));
  CHECK(b.indicators.com_radius_m == Approx(a.indicators.com_radius_m).epsilon(1e-9));
  CHECK(b.loads.impacts.size() == a.loads.impacts.size());
  CHECK(b.stats.flights == a.stats.flights);
}

TEST_CASE("the time step converges to a finer run", "[charge][layer]") {
  // docs/models/layer.md §Time step: the full study is bench_charge_timestep
  const Config c = mill_config("pilot_test_10.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 4);
  in.model.time_step_s = 0.0005;
  const ChargeResult fine = run_model("layer", in);
  for (double dt : {0.005, 0.0025}) {  // Courant 0.41 (near the limit, 0.45) and 0.2 for this mill
    in.model.time_step_s = dt;
    const ChargeResult r = run_model("layer", in);
    INFO("dt = " << dt);
    CHECK(r.stats.substeps == 1);
    CHECK(r.indicators.net_power_kw == Approx(fine.indicators.net_power_kw).epsilon(0.03));
    CHECK(angle_diff(r.indicators.toe_deg, fine.indicators.toe_deg) < 4.0);
    CHECK(angle_diff(r.indicators.shoulder_deg, fine.indicators.shoulder_deg) < 4.0);
  }
}

TEST_CASE("the Qiu mill at its configured 10 ms step agrees with a 1 ms run", "[charge][layer]") {
  // docs/models/layer.md §9. Until the flights' interval checks became events
  // of the step (2026-12-02) this mill's power was +3.7 % and its shoulder
  // +9 deg at 10 ms against 1 ms; now +0.2 % and 0.3 deg over these 3
  // revolutions (the tolerances allow for the two runs' different paths).
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 3);
  REQUIRE(in.model.time_step_s == Approx(0.01));
  const ChargeResult coarse = run_model("layer", in);
  in.model.time_step_s = 0.001;
  const ChargeResult fine = run_model("layer", in);
  CHECK(coarse.indicators.net_power_kw == Approx(fine.indicators.net_power_kw).epsilon(0.015));
  CHECK(angle_diff(coarse.indicators.toe_deg, fine.indicators.toe_deg) < 1.5);
  CHECK(angle_diff(coarse.indicators.shoulder_deg, fine.indicators.shoulder_deg) < 3.0);
}

TEST_CASE("a step beyond the stable range is sub-stepped with a note", "[charge][layer]") {
  const Config c = mill_config("pilot_test_10.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 1, 1);
  in.model.time_step_s = 0.05;
  const ChargeResult r = run_model("layer", in);
  CHECK(r.stats.substeps > 1);
  CHECK(r.stats.time_step_s < 0.05);
  REQUIRE(!r.notes.empty());
  CHECK_THAT(r.notes.front(), Catch::Contains("sub-stepped"));
  // a step a hair past the limit says by how much: "0.45 ... (stable up to
  // 0.45)" read as a contradiction (a review, 2026-12-08)
  const double c_per_s = c.mill.speed_rpm * 2.0 * kPi / 60.0 * 0.5 * metrics(s, c.mill.rotation, c.liner.density_kg_m3).effective_diameter_m /
                         c.charge.ball_diameter_m;  // Courant number per second of step
  in.model.time_step_s = 0.4515 / c_per_s;
  const ChargeResult hair = run_model("layer", in);
  CHECK(hair.stats.substeps == 2);
  REQUIRE(!hair.notes.empty());
  CHECK_THAT(hair.notes.front(), Catch::Contains("moves the shell 0.4515 media diameters per step (stable up to 0.45)"));
}

TEST_CASE("a step longer than the relaxation interval is sub-stepped with a note", "[charge][layer]") {
  // docs/models/layer.md §9: the relaxation runs at most once per step, so
  // the step is cut to the interval (the default interval, half an outer
  // cell, is always longer than the Courant limit's step)
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 0.5, 0.5);
  const ChargeResult def = run_model("layer", in);
  CHECK(def.stats.substeps == 1);
  CHECK(def.stats.relaxation_interval_s > def.stats.time_step_s);
  in.model.relaxation_interval_cells = 0.125;
  const ChargeResult r = run_model("layer", in);
  CHECK(r.stats.relaxation_interval_s == Approx(def.stats.relaxation_interval_s / 4).epsilon(1e-12));
  CHECK(r.stats.substeps == 4);  // 10 ms / 3.12 ms
  CHECK(r.stats.time_step_s <= r.stats.relaxation_interval_s);
  REQUIRE(!r.notes.empty());
  CHECK_THAT(r.notes.front(), Catch::Contains("relaxation interval"));
}

TEST_CASE("the Qiu mill's power converges at first order as the relaxation interval shrinks", "[charge][layer]") {
  // docs/models/layer.md §9, "The relaxation interval" (the study:
  // bench_charge_relax): between two relaxations the charge surface steepens
  // past the angle of repose, which lifts the charge and its power; halving
  // the interval about halves that excess (10 averaged revolutions: +297,
  // +184, +113, +57 kW per halving from 2 cells down). Over 3 revolutions the
  // realisations' scatter is below 0.3 % (18 kW), well under the smallest
  // difference here.
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 3, 1);
  std::vector<double> p;
  for (double cells : {1.0, 0.5, 0.25, 0.125}) {
    in.model.relaxation_interval_cells = cells;
    p.push_back(run_model("layer", in).indicators.net_power_kw);
  }
  const double d1 = p[0] - p[1], d2 = p[1] - p[2], d3 = p[2] - p[3];
  INFO("power " << p[0] << " " << p[1] << " " << p[2] << " " << p[3] << " kW");
  CHECK(d3 > 0);  // monotone: a shorter interval, a lower power
  CHECK(d1 / d2 > 1.2);
  CHECK(d1 / d2 < 3.0);
  CHECK(d2 / d3 > 1.2);
  CHECK(d2 / d3 < 3.0);
}

TEST_CASE("a fast pilot mill converges below a sixteenth of an outer cell of relaxation interval", "[charge][layer]") {
  // docs/models/layer.md §9, "The relaxation interval": pilot test 10 (40 rpm,
  // 19 mm media) changes regime between 1/8 and 1/16 of a cell (the power
  // falls by 10 %, the toe moves 6 deg; why: the known-issue test below) and
  // then stays put: 1/16 and 1/32
  // agree to 0.2 % in power and 0.1 deg in toe over 10 revolutions.
  const Config c = mill_config("pilot_test_10.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 4, 1);
  in.model.relaxation_interval_cells = 1.0 / 16;
  const Indicators a = run_model("layer", in).indicators;
  in.model.relaxation_interval_cells = 1.0 / 32;
  const Indicators b = run_model("layer", in).indicators;
  CHECK(a.net_power_kw == Approx(b.net_power_kw).epsilon(0.01));
  CHECK(angle_diff(a.toe_deg, b.toe_deg) < 1.0);
  CHECK(angle_diff(a.shoulder_deg, b.shoulder_deg) < 1.0);
}

// Known issue, hidden from the default run (run it with
// `test_charge "[known-issue]"`): the regime change above is the relaxation
// rolling held outer-layer elements down in the window between the unheld
// flight angle and their lifter's later release angle (docs/models/layer.md
// §9, "Why the fast pilots change regime"). With one flight angle per layer
// the interval would not matter: a diagnostic build with the lifter's angle in
// the relaxation's test gave 1.037-1.045 kW from 1/2 to 1/32 of a cell (10
// revolutions), where the model as it is gives 1.019 and 0.826 kW. This test
// (4 revolutions) passes with the consistent-angle scratch build described
// there and fails with the model as it is (toe 16 deg apart, direct impacts
// 181 -> 1).
TEST_CASE("a lifter-held outer layer is thrown by its lifter whatever the relaxation interval",
          "[.][charge][layer][known-issue]") {
  const Config c = mill_config("pilot_test_10.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 4, 1);
  in.model.relaxation_interval_cells = 0.5;
  const ChargeResult a = run_model("layer", in);
  in.model.relaxation_interval_cells = 1.0 / 16;
  const ChargeResult b = run_model("layer", in);
  CHECK(a.indicators.net_power_kw == Approx(b.indicators.net_power_kw).epsilon(0.03));
  CHECK(angle_diff(a.indicators.toe_deg, b.indicators.toe_deg) < 3.0);
  auto direct = [](const ChargeResult& r) {
    return std::count_if(r.loads.impacts.begin(), r.loads.impacts.end(), [](const ImpactEvent& e) { return e.direct; });
  };
  CHECK(direct(b) > 0.5 * direct(a));  // the lifters still throw onto the liner
}

TEST_CASE("a run says when and how much the relaxation can take of a held layer's lifter launches", "[charge][layer]") {
  // The known defect above, said where it acts: the share is min(1, window /
  // interval), which the diagnostic counters measured as 16 % on pilot 10
  // (180 of 1,150 outer-layer departures at the default interval), 24 % on
  // pilot 8 (100 of 415) and all of them on pilot 6; the Qiu mill has no
  // window (its lifter lets go before the unheld angle).
  struct Expect {
    const char* mill;
    const char* share;  // "" = no note
  };
  for (const Expect& x : {Expect{"pilot_test_10.toml", "up to about 16 %"}, Expect{"pilot_test_08.toml", "up to about 24 %"},
                          Expect{"pilot_test_06.toml", "up to about 100 %"}, Expect{"qiu2001_sag.toml", ""}}) {
    const Config c = mill_config(x.mill);
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    const ChargeResult r = run_model("layer", charge_input(c, s, 0.1, 0.1));
    std::string note;
    for (const std::string& n : r.notes)
      if (n.find("foot-stability rules' flight angle") != std::string::npos) note = n;
    INFO(x.mill << ": " << note);
    if (std::string(x.share).empty()) {
      CHECK(note.empty());
    } else {
      CHECK_THAT(note, Catch::Contains("layer 0") && Catch::Contains(x.share) && Catch::Contains("docs/models/layer.md"));
    }
  }
}

TEST_CASE("a worn (lower) lifter lowers the shoulder", "[charge][layer]") {
  Config c = load_default_config();
  c.liner.element_size_m = 0.005;
  const LinerSurface s_new = build_liner_surface(c.mill, c.liner);
  // worn below the ball radius: the ball rests on the crest corner, a steeper "face"
  c.liner.design.lifter_height_m = 0.03;
  const LinerSurface s_worn = build_liner_surface(c.mill, c.liner);
  const ChargeResult a = run_model("layer", charge_input(c, s_new, 2));
  const ChargeResult b = run_model("layer", charge_input(c, s_worn, 2));
  // 44.8 -> 42.6 deg (bench_charge_run, 2 and 8 revolutions alike to 0.1 deg)
  CHECK(b.indicators.shoulder_deg < a.indicators.shoulder_deg - 1.5);
  CHECK(b.indicators.diameter_eff_m > a.indicators.diameter_eff_m);
  // with balls sliding out along the face (Powell 1991) the height counts at once
  c.model.lifter_slide = true;
  c.liner.design.lifter_height_m = 0.25;
  const LinerSurface s_tall = build_liner_surface(c.mill, c.liner);
  c.liner.design.lifter_height_m = 0.12;
  const LinerSurface s_low = build_liner_surface(c.mill, c.liner);
  const ChargeResult t = run_model("layer", charge_input(c, s_tall, 2));
  const ChargeResult l = run_model("layer", charge_input(c, s_low, 2));
  CHECK(l.indicators.shoulder_deg < t.indicators.shoulder_deg - 3.0);
}

TEST_CASE("version 1.1 clips the shoulder and version 1.2 confines the layers", "[charge][layer]") {
  const Config c = load_default_config();
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2);
  in.model.variant = "1.0";
  const ChargeResult v10 = run_model("layer", in);
  in.model.variant = "1.1";
  const ChargeResult v11 = run_model("layer", in);
  in.model.variant = "1.2";
  const ChargeResult v12 = run_model("layer", in);
  CHECK(v11.indicators.shoulder_deg < v10.indicators.shoulder_deg - 2.0);
  // 1.2: no layer inside Morrell's inner radius r_i (thesis eq. 4.14)
  const double r_inner = v12.indicators.diameter_eff_m / 2 - v12.indicators.layer_speed_rpm.size() * c.charge.ball_diameter_m;
  CHECK(r_inner >= v12.indicators.inner_radius_m - c.charge.ball_diameter_m);
  CHECK(v12.indicators.layer_speed_rpm.size() <= v10.indicators.layer_speed_rpm.size());
}

TEST_CASE("liner loads and impacts are well formed", "[charge][layer]") {
  const Config c = load_default_config();
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const ChargeResult r = run_model("layer", charge_input(c, s, 2));
  const LinerLoads& L = r.loads;
  REQUIRE(L.n_elements == s.n_elements());
  REQUIRE(L.has_impacts);
  double total = 0;
  for (int e = 0; e < L.n_elements; ++e) {
    CHECK(L.normal_force_n_per_m[e] >= 0);
    CHECK(L.shear_force_n_per_m[e] >= 0);
    CHECK(L.normal_force_n_per_m[e] == Approx(L.centrifugal_force_n_per_m[e] + L.gravitational_force_n_per_m[e]).margin(1e-6));
    total += L.normal_force_n_per_m[e];
  }
  CHECK(total > 0);
  REQUIRE(!L.impacts.empty());
  for (const auto& ev : L.impacts) {
    CHECK(ev.element >= 0);
    CHECK(ev.element < L.n_elements);
    CHECK(ev.normal_speed_m_s > 0);
    CHECK(ev.rate_per_s > 0);
    CHECK(ev.mass_kg == Approx(kPi / 6 * std::pow(c.charge.ball_diameter_m, 3) *
                               (0.5 * c.charge.ball_density_kg_m3 + 0.5 * c.charge.ore_density_kg_m3)).epsilon(1e-9));
  }
  // forces on lifter 0: nothing while it is out of the charge (at the top), most at the bottom
  const auto& ang = r.indicators.lifter_force_angle_deg;
  const auto& fn = r.indicators.lifter_normal_force_n_per_m;
  REQUIRE(ang.size() == fn.size());
  double top = 0, bottom = 0;
  for (size_t i = 0; i < ang.size(); ++i) {
    if (ang[i] > 80 && ang[i] < 100) top = std::max(top, std::abs(fn[i]));
    if (ang[i] > 260 && ang[i] < 300) bottom = std::max(bottom, fn[i]);
  }
  CHECK(top == 0);
  CHECK(bottom > 0);
}

TEST_CASE("the slurry pool's drag takes a ball to its terminal velocity", "[charge][layer][slurry]") {
  SlurryDrag sd;
  sd.fluid_density_kg_m3 = 1800;
  sd.particle_density_kg_m3 = 7800;
  sd.diameter_m = 0.1;
  // terminal velocity: 3/4 C_d rho_f v^2 / (rho_p d) = g (1 - rho_f / rho_p), C_d at its Re
  double vt = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double cd = slurry_drag_coefficient(sd.fluid_density_kg_m3 * vt * sd.diameter_m / sd.viscosity_pa_s);
    vt = std::sqrt(4.0 * kGravity * (1 - 1800.0 / 7800.0) * 7800 * 0.1 / (3.0 * cd * 1800));
  }
  Eigen::Vector2d v(3.0, 0.0);  // thrown sideways into the pool
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector2d w = slurry_drag_step(sd, v, 1e-3);
    CHECK(w.x() >= 0);  // drag never reverses the motion
    v = w;
  }
  CHECK(v.x() == Approx(0).margin(1e-6));
  CHECK(-v.y() == Approx(vt).epsilon(1e-3));
  // Stokes below Re = 1, and the thesis correlation meets it there within 5 %
  CHECK(slurry_drag_coefficient(0.01) == Approx(2400));
  CHECK(slurry_drag_coefficient(1.0) == Approx(24.0).epsilon(0.05));
}

TEST_CASE("an overflow mill: the pool lowers the power, the drag option runs", "[charge][layer][slurry]") {
  Config c = load_default_config();
  c.charge.discharge = Discharge::Overflow;
  c.charge.trunnion_radius_m = 1.5;
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2);
  const ChargeResult dry = run_model("layer", in);
  in.model.slurry_drag = true;
  const ChargeResult wet = run_model("layer", in);
  // the pool sits on the toe side, against the rotation: it lowers the power (Morrell 1996)
  CHECK(dry.indicators.slurry_pool_power_kw < 0);
  CHECK(wet.stats.charge_mass_kg_per_m == dry.stats.charge_mass_kg_per_m);
  CHECK(wet.stats.flights > 0);
}

TEST_CASE("the layer model refuses input it cannot take", "[charge][layer][input]") {
  const Config c = mill_config("pilot_test_09.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  auto refused = [&](auto edit, const char* key) {
    ChargeInput in = charge_input(c, s, 1, 0);
    edit(in);
    try {
      run_model("layer", in);
      FAIL("accepted; expected an InputError for " << key);
    } catch (const InputError& e) {
      CHECK(e.key() == key);
    }
  };
  refused([](ChargeInput& in) { in.charge.filling = 0; }, "charge.filling");
  refused([](ChargeInput& in) { in.model.time_step_s = -0.01; }, "model.time_step_s");
  refused([](ChargeInput& in) { in.model.time_step_s = 1e-9; }, "model.time_step_s");  // never ended
  refused([](ChargeInput& in) { in.model.variant = "2.0"; }, "model.variant");
  refused([](ChargeInput& in) { in.model.slip_model = "magic"; }, "model.slip_model");
  refused([](ChargeInput& in) { in.model.slurry_drag = true; }, "model.slurry_drag");
  refused([](ChargeInput& in) { in.revolutions = -1; }, "--revolutions");
  refused([](ChargeInput& in) { in.model.relaxation_interval_cells = 0; }, "model.relaxation_interval_cells");
  refused([](ChargeInput& in) { in.model.element_size_diameters = 0.5; }, "model.element_size_diameters");
  refused([](ChargeInput& in) { in.model.unheld_friction_coefficient = 2.5; }, "model.unheld_friction_coefficient");
  refused([](ChargeInput& in) { in.model.unheld_friction_coefficient = std::nan(""); }, "model.unheld_friction_coefficient");
  refused([](ChargeInput& in) { in.model.held_pocket_balls = 101; }, "model.held_pocket_balls");
  refused([](ChargeInput& in) { in.model.inner_radius_beta = 0; }, "model.inner_radius_beta");
  refused([](ChargeInput& in) { in.model.inner_radius_beta = 1.5; }, "model.inner_radius_beta");
  refused([](ChargeInput& in) { in.model.inner_radius_beta = std::nan(""); }, "model.inner_radius_beta");
  refused([](ChargeInput& in) { in.model.held_pocket_balls = std::nan(""); }, "model.held_pocket_balls");
  refused([](ChargeInput& in) { in.model.element_size_diameters = 4.5; }, "model.element_size_diameters");
  {  // pilot test 5 (50 mm media in a 0.75 m mill): elements of 2 media diameters leave three layers
    const Config c5 = mill_config("pilot_test_05.toml");
    const LinerSurface s5 = build_liner_surface(c5.mill, c5.liner);
    ChargeInput in = charge_input(c5, s5, 1, 0);
    in.model.element_size_diameters = 2;
    try {
      run_model("layer", in);
      FAIL("accepted elements of 0.1 m in a 0.75 m mill");
    } catch (const InputError& e) {
      CHECK(e.key() == "model.element_size_diameters");
      CHECK_THAT(e.what(), Catch::Contains("four layers"));
    }
  }
  refused([](ChargeInput& in) { in.charge.ball_diameter_m = 0.2; }, "charge.ball_diameter_m");
}

TEST_CASE("the incremental maps and relaxation reproduce full sweeps exactly", "[charge][layer]") {
  // docs/models/layer.md §Incremental maps: the column map, the support
  // sweep and the surface relaxation only look at what may have changed; with
  // model.incremental_maps = false every one of them is a full sweep. The two
  // must give the same run, bit for bit: on the Qiu mill, on its liner worn by
  // a forecast (wide cells of the partial layer, the longest relaxation
  // reach), on a pilot mill and on a clockwise one.
  auto same = [](ChargeInput in) {
    in.model.incremental_maps = true;
    const ChargeResult a = run_model("layer", in);
    in.model.incremental_maps = false;
    const ChargeResult b = run_model("layer", in);
    check_same_run(a, b);
  };
  const Config q = load_default_config();
  SECTION("Qiu, new liner") { same(charge_input(q, build_liner_surface(q.mill, q.liner), 1, 1)); }
  SECTION("Qiu, worn liner") {
    const MeasuredProfile p =
        load_profile_csv(std::string(LINERLIFE_SOURCE_DIR) + "/tests/charge/data/qiu_worn_8659h.csv");
    const LinerSurface s = bench::ring_of(
        q.mill.shell_radius_m(), q.liner.segments,
        measured_profile_to_segment(p, q.mill.shell_radius_m(), q.liner.segments, q.liner.element_size_m));
    same(charge_input(q, s, 1, 1));
  }
  SECTION("pilot test 12, and clockwise") {
    Config c = mill_config("pilot_test_12.toml");
    same(charge_input(c, build_liner_surface(c.mill, c.liner), 1, 1));
    c.mill.rotation = c.mill.rotation == Rotation::Cw ? Rotation::Ccw : Rotation::Cw;
    same(charge_input(c, build_liner_surface(c.mill, c.liner), 1, 1));
  }
  // cases a review found the bookkeeping wrong in (2026-12-01): a partial
  // layer of a few cells more than twice as wide as the outer ring's (the
  // column map's offset wrapping twice), and a plain plate (an unheld outer
  // layer, whose top rolls by the repose rule)
  SECTION("pilot test 4 at 1.25 x its speed") {
    Config c = mill_config("pilot_test_04.toml");
    c.mill.speed_rpm *= 1.25;
    same(charge_input(c, build_liner_surface(c.mill, c.liner), 2, 3));
  }
  SECTION("pilot test 8, staggered phases") {
    const Config c = mill_config("pilot_test_08.toml");
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    ChargeInput in = charge_input(c, s, 2, 3);
    in.model.initial_phases = "staggered";
    same(in);
  }
  SECTION("pilot test 4 on a plain plate") {
    Config c = mill_config("pilot_test_04.toml");
    c.liner.design.lifter_height_m = 0;
    same(charge_input(c, build_liner_surface(c.mill, c.liner), 1, 1));
  }
}

TEST_CASE("a run that averages the charge's rise from rest says so", "[charge][layer]") {
  // The Qiu mill from rest over 0.05 revolution: the charge has not reached
  // its shoulder (1,073 kW against 5,946 kW settled, layer.md §Settling).
  // The note is warranted where it appears, and absent from 0.5 revolution.
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  auto note_of = [](const ChargeResult& r) {
    for (const std::string& n : r.notes)
      if (n.find("settle_revolutions") != std::string::npos) return n;
    return std::string();
  };
  const ChargeResult cold = run_model("layer", charge_input(c, s, 0.05, 0.0));
  const ChargeResult settled = run_model("layer", charge_input(c, s, 1.0, 1.0));
  // what the note warns of: more than half the power missing, the toe 30 deg short
  CHECK(cold.indicators.net_power_w_per_m < 0.5 * settled.indicators.net_power_w_per_m);
  CHECK(cold.indicators.toe_deg < settled.indicators.toe_deg - 30);
  CHECK_THAT(note_of(cold), Catch::Contains("[model] settle_revolutions = 0: ") &&
                                Catch::Contains("100 % of the averaged time is before that") &&
                                Catch::Contains("docs/models/layer.md"));
  CHECK(note_of(settled).empty());
  // the share is of the averaged time before half a revolution
  CHECK_THAT(note_of(run_model("layer", charge_input(c, s, 1.0, 0.25))), Catch::Contains("25 % of the averaged time"));
  CHECK(note_of(run_model("layer", charge_input(c, s, 0.1, 0.5))).empty());
}

TEST_CASE("staggered initial phases change the start, not the settled charge", "[charge][layer]") {
  // docs/models/layer.md §Settling: the layers' phases at t = 0 only decide
  // which lattice the run starts from; averaged over 12 revolutions the two
  // starts agree within the window-to-window scatter of the model (about
  // +-2 % power, +-1.5 deg on the pilot mills, bench_layer_settle).
  const Config c = mill_config("pilot_test_10.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 12, 1);
  in.model.initial_phases = "aligned";
  const ChargeResult a = run_model("layer", in);
  in.model.initial_phases = "staggered";
  const ChargeResult b = run_model("layer", in);
  CHECK(b.indicators.net_power_kw != a.indicators.net_power_kw);  // a different run
  CHECK(b.indicators.net_power_kw == Approx(a.indicators.net_power_kw).epsilon(0.02));
  CHECK(angle_diff(b.indicators.toe_deg, a.indicators.toe_deg) < 1.5);
  CHECK(angle_diff(b.indicators.shoulder_deg, a.indicators.shoulder_deg) < 1.5);
  CHECK(b.stats.charge_mass_kg_per_m == Approx(a.stats.charge_mass_kg_per_m).epsilon(1e-12));
  in.model.initial_phases = "random";
  CHECK_THROWS_AS(run_model("layer", in), InputError);
}

// The release study's options (docs/models/layer.md §3, "The release study").
TEST_CASE("release study: the thesis by default, Davis' angle for unheld layers at mu 0, pockets from the lifter face",
          "[charge][layer]") {
  SECTION("the options at their thesis values are the default run, bit for bit") {
    const Config c = mill_config("qiu2001_sag.toml");
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    const ChargeInput in = charge_input(c, s, 1, 0.5);
    const ChargeResult ref = run_model("layer", in);
    ChargeInput same_mu = in;
    same_mu.model.unheld_friction_coefficient = in.model.friction_coefficient;
    check_same_run(ref, run_model("layer", same_mu));
    // a pocket wider than the plate between two lifters holds the whole
    // layer, as the thesis does; not bit for bit, since an element behind a
    // crest is now launched by the lifter behind it, whose segment's metrics
    // differ from its own in the last digits
    ChargeInput wide = in;
    wide.model.held_pocket_balls = 100;
    const ChargeResult w = run_model("layer", wide);
    CHECK(w.indicators.net_power_kw == Approx(ref.indicators.net_power_kw).epsilon(1e-9));
    CHECK(angle_diff(w.indicators.toe_deg, ref.indicators.toe_deg) < 1e-6);
    CHECK(angle_diff(w.indicators.shoulder_deg, ref.indicators.shoulder_deg) < 1e-6);
    // the Qiu mill's lifter lets layer 0 go at 43.5 deg, before the unheld
    // angle (56.5 deg): with only the ball at the face held, the rest of the
    // outer layer rides on, and the run changes
    ChargeInput pocket = in;
    pocket.model.held_pocket_balls = 0;
    const ChargeResult p = run_model("layer", pocket);
    CHECK(std::abs(p.indicators.net_power_kw / ref.indicators.net_power_kw - 1.0) > 0.01);
  }
  SECTION("Davis' angle (mu 0) lets the unheld layers go earlier: a lower shoulder") {
    const Config c = mill_config("pilot_test_10.toml");
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    ChargeInput in = charge_input(c, s, 2, 1);
    in.model.variant = "1.0";  // no r_i confinement: the flight angles alone
    const ChargeResult ref = run_model("layer", in);
    in.model.unheld_friction_coefficient = 0;
    const ChargeResult davis = run_model("layer", in);
    // along the rotation (pilot 10 turns clockwise: angles fall along it)
    const double sense = c.mill.rotation == Rotation::Ccw ? 1.0 : -1.0;
    const double drop = sense * (ref.indicators.shoulder_deg - davis.indicators.shoulder_deg);
    INFO("shoulder " << ref.indicators.shoulder_deg << " -> " << davis.indicators.shoulder_deg << " deg");
    CHECK(drop > 5.0);
  }
}

// The en-masse share of eq. 4.14 (docs/models/layer-worn.md, "The en-masse share of eq. 4.14").
TEST_CASE("version 1.2 with its own airborne share in eq. 4.14 puts the toe near Morrell's and the DEM's",
          "[charge][layer]") {
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2, 1);
  const ChargeResult a = run_model("layer", in);
  // Morrell's beta (eq. 4.14 from his flight time): about 18 % of the charge
  // in flight; the layer model flies about 9 % of its elements on this mill
  CHECK(a.stats.inner_radius_beta == Approx(0.82).margin(0.01));
  CHECK(a.stats.airborne_fraction > 0.05);
  CHECK(a.stats.airborne_fraction < 0.13);
  {  // Morrell's share given as the study's value: eq. 4.14 gives the same r_i
    ChargeInput same = in;
    same.model.inner_radius_beta = a.stats.inner_radius_beta;
    const ChargeResult m = run_model("layer", same);
    CHECK(m.indicators.inner_radius_m == Approx(a.indicators.inner_radius_m).margin(1e-9));
  }
  // with its own share the band outside r_i is thicker (smaller r_i), so
  // shorter for the same en-masse mass: the toe moves from about 215 deg
  // towards Morrell's (eq. 4.15, 240.4 deg) and the DEM's (233.8 deg,
  // docs/validation/charge.md)
  in.model.inner_radius_beta = 1.0 - a.stats.airborne_fraction;
  const ChargeResult b = run_model("layer", in);
  CHECK(b.stats.inner_radius_beta == Approx(1.0 - a.stats.airborne_fraction).epsilon(1e-12));
  CHECK(b.indicators.inner_radius_m < a.indicators.inner_radius_m - 0.1);
  const double toe_morrell = run_model("empirical", in).indicators.toe_deg;
  INFO("toe " << a.indicators.toe_deg << " -> " << b.indicators.toe_deg << " deg");
  CHECK(std::abs(b.indicators.toe_deg - toe_morrell) < std::abs(a.indicators.toe_deg - toe_morrell) - 10.0);
}

TEST_CASE("the layer model's power does not jump as r_i crosses the middle of the layer it cuts", "[charge][layer]") {
  // docs/models/layer.md §8: version 1.2 opens the layer the circle r_i cuts
  // with the share f of its cells; where f passes one half the charge hardly
  // moves. The power summed over the occupancy grid's en-masse bins (until
  // 2026-12-06) left that layer out while f < 1/2 and took it in above: on
  // the new Qiu liner, r_i 3.715 -> 3.713 m (the share of eq. 4.14, 0.837 ->
  // 0.838), 6,249 -> 6,498 kW (+4.0 %) here, toe and centre of mass within
  // 0.4 deg. The power of every element's torque arm: 6,603 -> 6,634 kW
  // (+0.5 %).
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 10, 1);
  in.model.inner_radius_beta = 0.837;
  const Indicators a = run_model("layer", in).indicators;
  in.model.inner_radius_beta = 0.838;
  const Indicators b = run_model("layer", in).indicators;
  // the cut layer's middle lies between the two r_i (the layers are one ball
  // deep, counted in from the effective radius)
  const double d = c.charge.ball_diameter_m, R = 0.5 * a.diameter_eff_m;
  const double fa = (R - a.inner_radius_m) / d, fb = (R - b.inner_radius_m) / d;
  INFO("bed depth " << fa << " -> " << fb << " layers; power " << a.net_power_kw << " -> " << b.net_power_kw
                    << " kW, toe " << a.toe_deg << " -> " << b.toe_deg);
  REQUIRE(std::floor(fa - 0.5) < std::floor(fb - 0.5));
  CHECK(angle_diff(a.toe_deg, b.toe_deg) < 1.0);
  CHECK(b.net_power_kw == Approx(a.net_power_kw).epsilon(0.015));
}

namespace {

struct LoadPlace {
  double mean_height_m = 0;  // normal-load-weighted height above the plate of the loaded elements
  double plate_share = 0;    // share of the normal load on elements less than 5 mm above the plate
  double power_kw = 0;
  double normal_n_per_m = 0;  // [N/m] the normal load on the whole ring
};

LoadPlace load_place(const Config& c, const LinerSurface& s, double contact_spacing_m) {
  ChargeInput in = charge_input(c, s, 6);
  in.model.load_contact_spacing_m = contact_spacing_m;
  const ChargeResult r = run_model("layer", in);
  const double plate_r = s.shell_radius_m - c.liner.design.plate_thickness_m;
  double tot = 0, h = 0, plate = 0;
  for (int e = 0; e < s.n_elements(); ++e) {
    const double N = r.loads.normal_force_n_per_m[e];
    const double above = plate_r - (0.5 * (s.nodes[e] + s.nodes[s.next(e)])).norm();
    tot += N;
    h += N * above;
    if (above < 0.005) plate += N;
  }
  return {h / tot, plate / tot, r.indicators.net_power_kw, tot};
}

}  // namespace

TEST_CASE("the liner loads land where the disc touches, whatever the contact rays and the element size",
          "[charge][layer][loads]") {
  // docs/models/layer.md §Liner loads, "Where a load lands". Until
  // 2026-12-05 a load went to the element its ride-table bin's smaller edge
  // touches: up to a bin (16 mm on the Qiu mill) towards the crest. On the
  // bundled lifter that put the mean of the normal load 11 mm higher than
  // rays 0.25 mm apart do (0.2031 against 0.1920 m above the plate) and about
  // half the plate's share on the lifter (8.0 against 14.7 %; this test's
  // measures on the old code), and made the forecast's life depend on the
  // element size (docs/validation/forecast.md).
  const Config c = load_default_config();
  const LinerSurface s10 = build_liner_surface(c.mill, c.liner);
  const LinerSurface s25 = surface_with_elements(c, 0.0025);
  const LoadPlace def = load_place(c, s10, 0), ref = load_place(c, s10, 0.00025), mesh = load_place(c, s25, 0);
  INFO("mean height above the plate: default " << def.mean_height_m << " m, rays 0.25 mm apart " << ref.mean_height_m
                                               << " m, elements 2.5 mm " << mesh.mean_height_m << " m; plate share "
                                               << def.plate_share << ", " << ref.plate_share << ", "
                                               << mesh.plate_share);
  // the rays only say where the loads go: the charge moves the same
  CHECK(def.power_kw == ref.power_kw);
  // the default's rays (2 mm) place the load within 1.5 mm of rays 0.25 mm apart
  CHECK(std::abs(def.mean_height_m - ref.mean_height_m) < 0.0015);
  CHECK(std::abs(def.plate_share - ref.plate_share) < 0.01);
  // and elements a quarter as long (same lifter, same rays) change neither
  CHECK(std::abs(mesh.mean_height_m - def.mean_height_m) < 0.0015);
  CHECK(std::abs(mesh.plate_share - def.plate_share) < 0.01);
  // the plate carries a real share: about 15 % (the old rule left 8 %)
  CHECK(ref.plate_share > 0.12);
}

TEST_CASE("a surface rough far below the media size takes the same normal load as a smooth one",
          "[charge][layer][loads]") {
  // docs/models/layer.md §Liner loads, "Where a load lands". The bundled
  // lifter at 2 mm elements with every other node 0.5 mm deeper: a zigzag
  // whose elements tilt by about 27 deg from the smooth surface, the kind of
  // roughness many remeshes of fine elements leave. A ball of 133 mm does not
  // feel it. Until 2026-12-05 the load was split along the touched
  // element's normal, and the forecast's lifter wore 30 mm less over its life
  // at 2 mm elements than at 10 mm (docs/validation/forecast.md).
  const Config c = load_default_config();
  LinerDesign d = c.liner;
  d.element_size_m = 0.002;
  const LinerSurface smooth = build_liner_surface(c.mill, d);
  std::vector<double> depth(static_cast<size_t>(smooth.n_nodes()), 0.0);
  for (size_t i = 0; i < depth.size(); i += 2) depth[i] = 0.0005;
  const LinerSurface rough = displace_nodes(smooth, depth);
  const LoadPlace a = load_place(c, smooth, 0), b = load_place(c, rough, 0);
  INFO("normal load " << a.normal_n_per_m << " N/m smooth, " << b.normal_n_per_m
                      << " N/m rough; mean height above the plate " << a.mean_height_m << " and " << b.mean_height_m
                      << " m; plate share " << a.plate_share << " and " << b.plate_share);
  CHECK(b.normal_n_per_m == Approx(a.normal_n_per_m).epsilon(0.02));
  CHECK(std::abs(b.mean_height_m - a.mean_height_m) < 0.0015);
  CHECK(std::abs(b.plate_share - a.plate_share) < 0.01);
}


TEST_CASE("the direct-impact fraction is the share of the averaged landings, whatever the settling", "[charge][layer]") {
  // Until 2026-12-05 its denominator was every flight of the run, settling
  // included, while the impacts were counted over the averaging window only:
  // it read 0.8 of the share after 1 settling revolution of 5 and 0.57 after
  // 3 of 7, so this ratio was about 0.71. Now both count the averaging
  // window: the share moves only with the realisation (measured here: within
  // a few per cent); 15 % allowed.
  const Config c = mill_config("qiu2001_sag.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const ChargeResult r1 = run_model("layer", charge_input(c, s, 4, 1.0));
  const ChargeResult r3 = run_model("layer", charge_input(c, s, 4, 3.0));
  const double f1 = r1.indicators.direct_impact_fraction, f3 = r3.indicators.direct_impact_fraction;
  INFO("after 1 settling revolution " << f1 << ", after 3 " << f3);
  REQUIRE(f1 > 0.02);  // the Qiu mill throws onto its liner
  CHECK(f1 <= 1.0);
  CHECK(f3 / f1 == Approx(1.0).margin(0.15));
}

// A review (2026-12-06) found two liners on which the layer model is far from
// the 2D DEM without saying so (docs/models/layer.md, "Lifters the layer model
// is not checked on"): lifters lower than half a ball, and rows far apart.
namespace {

/// The notes of half a revolution of `model` on configuration c, one per line.
std::string model_notes(const std::string& model, const Config& c) {
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  std::string all;
  for (const std::string& n : run_model(model, charge_input(c, s, 0.5, 0.5)).notes) all += n + "\n";
  return all;
}

}  // namespace

TEST_CASE("the layer model says when its lifters are lower than half a ball or their rows far apart",
          "[charge][layer]") {
  auto notes_of = [](const Config& c) { return model_notes("layer", c); };
  const Config qiu = mill_config("qiu2001_sag.toml");
  const std::string low = "less than half a media diameter", wide = "media diameters apart";
  const std::string plain = notes_of(qiu);
  CHECK(plain.find(low) == std::string::npos);
  CHECK(plain.find(wide) == std::string::npos);
  Config c = qiu;
  c.liner.design.lifter_height_m = 0.06;  // 0.45 d
  CHECK_THAT(notes_of(c), Catch::Contains("the lowest lifter is 60 mm, less than half a media diameter (133 mm)"));
  c.liner.design.lifter_height_m = 0.07;  // 0.53 d
  CHECK(notes_of(c).find(low) == std::string::npos);
  c = qiu;
  c.liner.segments = 8;
  CHECK_THAT(notes_of(c), Catch::Contains("the 8 lifter rows are 30 media diameters apart"));
  c.liner.segments = 16;  // 15 diameters
  CHECK(notes_of(c).find(wide) == std::string::npos);
  // a plain plate: no row to hold from, the shoulder far from the DEM's
  c = qiu;
  c.liner.design.lifter_height_m = 0;
  const std::string flat = notes_of(c);
  CHECK_THAT(flat, Catch::Contains("the liner has no lifters"));
  CHECK(flat.find(low) == std::string::npos);
  CHECK(plain.find("no lifters") == std::string::npos);
}

TEST_CASE("the charge models say when the filling or the speed is outside what they were checked on",
          "[charge][layer][empirical]") {
  const auto& notes_of = model_notes;
  const Config qiu = mill_config("qiu2001_sag.toml");  // 0.24 filling, 0.773 of critical: inside
  for (const std::string model : {"layer", "empirical"}) {
    INFO(model);
    const std::string who = model == "layer" ? "the layer model" : "Morrell's model";
    CHECK(notes_of(model, qiu).find("outside") == std::string::npos);
    Config c = qiu;
    c.charge.filling = 0.05;  // the review's 193-hour forecast
    c.charge.ball_filling = 0.04;
    CHECK_THAT(notes_of(model, c), Catch::Contains("filling 0.05 is outside 0.18-0.45, the fillings on which " + who +
                                                   " was checked against the 2D DEM"));
    c.charge.filling = 0.18;  // the bound is inside
    CHECK(notes_of(model, c).find("outside") == std::string::npos);
    c.charge.filling = 0.4999;  // as written, not rounded to 0.5 (a review, 2026-12-07)
    CHECK_THAT(notes_of(model, c), Catch::Contains("filling 0.4999 is outside 0.18-0.45"));
    c = qiu;
    c.mill.speed_rpm *= 0.95 / 0.773;
    const std::string fast = notes_of(model, c);
    CHECK_THAT(fast, Catch::Contains("of critical, outside 0.59-0.90, the speeds on which " + who + " was checked"));
    CHECK_THAT(fast, Catch::Contains("to be checked with the DEM ([model] charge = \"dem\")"));
    c.mill.speed_rpm = qiu.mill.speed_rpm * 0.55 / 0.773;
    CHECK_THAT(notes_of(model, c), Catch::Contains("of critical, outside 0.59-0.90"));
    // the bounds are inside, for Morrell's model too, whose critical speed is 42.3 / sqrt(D)
    const LinerSurface s = build_liner_surface(qiu.mill, qiu.liner);
    const double phi_qiu = run_model("layer", charge_input(qiu, s, 0.1, 0.1)).indicators.fraction_critical;
    for (const double phi : {0.59, 0.90}) {
      Config b = qiu;  // speed_fraction_critical = phi, as the configuration resolves it
      b.mill.speed_rpm = qiu.mill.speed_rpm * phi / phi_qiu;
      CHECK(notes_of(model, b).find("of critical, outside") == std::string::npos);
    }
  }
}

TEST_CASE("on the bundled ball mill version 1.2 puts the charge where the DEM does", "[charge][layer]") {
  // The DEM reference of docs/validation/ball-mill.md (media-size discs, 16
  // steps a collision, 12 revolutions): net power 2,282 kW, toe 220.0 deg,
  // centre of mass 303.7 deg. Its 0.12 m lifters (2.4 media diameters) hold
  // three layers; the bed above them rests on the bed, not on the balls the
  // lifters throw (the support rule, docs/models/layer.md §3). When the bed
  // took the lifters' release (until 2026-12-06) V-1.2 gave 3,395 kW (+49 %),
  // toe 233.1 and centre of mass 325.9 deg (+22 deg, up the rising side).
  const Config c = mill_config("ball_mill_5m.toml");
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const Indicators i = run_model("layer", charge_input(c, s, 10)).indicators;
  INFO("power " << i.net_power_kw << " kW, toe " << i.toe_deg << ", centre of mass " << i.com_angle_deg << " deg");
  CHECK(i.net_power_kw == Approx(2282.0).epsilon(0.10));
  CHECK(angle_diff(i.com_angle_deg, 303.7) < 5.0);
  CHECK(angle_diff(i.toe_deg, 220.0) < 15.0);  // 11 deg short of the DEM's toe (docs/validation/ball-mill.md)
}

TEST_CASE("Morrell's model says when its cone term or its power leaves the formulas' domain", "[charge][empirical]") {
  // a review (2026-12-06): a trunnion 0.4 mm inside the shell gave 49 GW with
  // no word (the cone term's 1 / (r_m - r_t)), and filling 0.4999 a negative
  // net power (-51.6 kW at 0.05 of critical)
  const Config qiu = mill_config("qiu2001_sag.toml");
  const std::string cone = "Morrell's cone term gives the conical ends", negative = "gives a negative net power";
  Config c = qiu;
  c.charge.cone_length_m = 1.0;
  c.charge.trunnion_radius_m = 1.5;  // an ordinary trunnion (0.3 D): no note
  const std::string ordinary = model_notes("empirical", c);
  CHECK(ordinary.find(cone) == std::string::npos);
  CHECK(ordinary.find(negative) == std::string::npos);
  c.charge.trunnion_radius_m = 4.95;  // 30 mm inside the shell
  CHECK_THAT(model_notes("empirical", c), Catch::Contains(cone) && Catch::Contains("not physical"));
  c = qiu;  // the review's mill: nearly half full of balls at 0.05 of critical (0.67 rpm)
  c.charge.filling = c.charge.ball_filling = 0.4999;
  c.charge.porosity = 0.6;
  c.mill.speed_rpm = 0.6701;
  CHECK_THAT(model_notes("empirical", c), Catch::Contains(negative));
}
