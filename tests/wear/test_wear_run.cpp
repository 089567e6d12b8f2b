// The per-step coupled wear run (issue 4 §4, §6) on a test double of the
// charge model: constant, known loads on the lifters. Invariants: the mass
// lost is the area the profile lost times the density; zero loads give zero
// wear; twice the amplification gives twice one step's wear; feedback
// re-drives the charge on the worn surface; a too large amplification is
// detected.
#include <catch2/catch.hpp>
#include <cmath>

#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "geometry/metrics.h"
#include "wear/wear_run.h"

using namespace linerlife;

namespace {

/// What the test double puts on the liner, and what it saw.
struct FakeSetup {
  double normal = 1000;  // [N/m] on every element of a lifter standing 2 cm above the plate
  double slip = 0.1;     // [m/s]
  bool impacts = true;   // one impact a second on each liner's lifter foot
  int calls = 0;
  std::vector<double> seen_area;  // ring area of every surface the model was driven on
};
FakeSetup g_fake;

class FakeCharge : public ChargeModel {
 public:
  ChargeResult run(const ChargeInput& in) const override {
    const LinerSurface& s = *in.surface;
    ++g_fake.calls;
    g_fake.seen_area.push_back(ring_area(s));
    ChargeResult r;
    r.model = "fake";
    r.loads.reset(s.n_elements(), 60.0 / in.mill.speed_rpm * in.revolutions);
    r.loads.has_impacts = true;
    const double R = s.shell_radius_m;
    for (int i = 0; i < s.n_elements(); ++i) {
      if (R - s.midpoint[i].norm() < 0.075 + 0.02) continue;  // plate: no load
      const double n = g_fake.normal;
      r.loads.normal_force_n_per_m[i] = n;
      r.loads.centrifugal_force_n_per_m[i] = 0.4 * n;
      r.loads.gravitational_force_n_per_m[i] = 0.6 * n;
      r.loads.shear_force_n_per_m[i] = 0.3 * n;
      r.loads.slip_speed_m_s[i] = n > 0 ? g_fake.slip : 0;
      r.loads.normal_slip_power_w_per_m[i] = n * g_fake.slip;
      r.loads.shear_work_rate_w_per_m[i] = 0.3 * n * g_fake.slip;
    }
    if (g_fake.impacts)
      for (int k = 0; k < s.segments; ++k) {
        // the element of the lifter's leading foot: first loaded element of the segment
        for (int i = s.segment_begin[k]; i < s.segment_begin[k + 1]; ++i)
          if (r.loads.normal_force_n_per_m[i] > 0) {
            ImpactEvent e;
            e.element = i;
            e.normal_speed_m_s = 5;
            e.tangential_speed_m_s = 3;
            e.mass_kg = 1;
            e.diameter_m = 0.1333;
            e.rate_per_s = 1;
            r.loads.impacts.push_back(e);
            break;
          }
      }
    r.stats.simulated_s = r.loads.duration_s;
    return r;
  }
};

std::unique_ptr<ChargeModel> make_fake() { return std::make_unique<FakeCharge>(); }
const ChargeModelEntry kFake{"fake", "test double", true, true, &make_fake};

const LinerSurface& qiu_surface() {
  static const LinerSurface s = [] {
    Mill mill;
    mill.diameter_m = 10.36;
    mill.length_m = 5;
    mill.speed_rpm = 10.36;
    LinerDesign d;
    d.segments = 64;
    d.design.plate_thickness_m = 0.075;
    d.design.lifter_height_m = 0.25;
    d.design.top_width_m = 0.15;
    d.design.face_angle_leading_deg = 20;
    d.design.face_angle_trailing_deg = 20;
    d.element_size_m = 0.01;
    d.density_kg_m3 = 7800;
    return build_liner_surface(mill, d);
  }();
  return s;
}

/// A short run: 0.2 revolutions of the Qiu mill (116 steps of 0.01 s), amplified
/// so that the lifters lose a few millimetres.
WearRunInput short_run(double revolutions = 0.2, double amplification = 2e5) {
  WearRunInput in;
  in.mill.diameter_m = 10.36;
  in.mill.length_m = 5;
  in.mill.speed_rpm = 10.36;
  in.charge.filling = 0.24;
  in.charge.ball_filling = 0.12;
  in.charge.ball_diameter_m = 0.1333;
  in.charge.ball_density_kg_m3 = 7800;
  in.model.charge = "fake";
  in.model.time_step_s = 0.01;
  in.surface = qiu_surface();
  in.wear.revolutions = revolutions;
  in.wear.amplification_abrasion = amplification;
  in.wear.amplification_impact = amplification;
  in.wear.smoothing.method = SmoothingMethod::None;
  in.remesh.element_size_m = 0.01;
  return in;
}

void reset_fake() { g_fake = FakeSetup{}; }

}  // namespace

TEST_CASE("wear run: the mass lost is what the profile lost", "[wear][run]") {
  reset_fake();
  const WearRunResult r = run_wear(short_run(), kFake);
  REQUIRE(r.steps == 116);
  CHECK(r.remeshes + r.fast_remeshes == 12);
  CHECK(r.fast_remeshes > 0);  // small steps take recede()'s fast path
  CHECK(r.charge_drives == 1);
  // bookkeeping to round-off: density x area lost = mass before - mass after
  CHECK(r.mass_loss_kg_per_m > 1);
  // (geometry's metrics() measures the two rings independently of the run's bookkeeping)
  const double before = metrics(r.initial, Rotation::Ccw, 7800).mass_kg_per_m;
  const double after = metrics(r.final, Rotation::Ccw, 7800).mass_kg_per_m;
  CHECK(r.mass_loss_kg_per_m == Approx(before - after).epsilon(1e-9));
  CHECK(r.liner_mass_final_kg_per_m == Approx(after).epsilon(1e-12));
  CHECK(r.mass_loss_kg_per_m == Approx(7800 * (ring_area(r.initial) - ring_area(r.final))).epsilon(1e-9));
  CHECK(r.mass_loss_centrifugal_kg_per_m + r.mass_loss_gravitational_kg_per_m + r.mass_loss_impact_kg_per_m ==
        Approx(r.mass_loss_kg_per_m).epsilon(1e-12));
  // the profile realises the wear the laws asked for up to the remesh discretisation
  CHECK(std::abs(r.mass_balance_rel_error) < 0.01);
  // the split follows the loads: 40 % centrifugal, 60 % gravitational of the abrasion
  CHECK(r.mass_loss_centrifugal_kg_per_m / r.mass_loss_gravitational_kg_per_m == Approx(0.4 / 0.6).epsilon(1e-9));
  CHECK(r.mass_loss_impact_kg_per_m > 0);
  // one liner computed, every liner alike: the per-segment histories are equal and sum to the total
  const auto& h = r.history;
  const size_t last = h.time_s.size() - 1, ns = static_cast<size_t>(h.segments);
  double sum = 0;
  for (size_t k = 0; k < ns; ++k) {
    sum += h.per_segment_kg_per_m[last * ns + k];
    CHECK(h.per_segment_kg_per_m[last * ns + k] == Approx(h.per_segment_kg_per_m[last * ns]).epsilon(1e-9));
  }
  CHECK(sum == Approx(r.commanded_mass_kg_per_m).epsilon(1e-9));
  CHECK(h.total_kg_per_m[last] == Approx(r.commanded_mass_kg_per_m).epsilon(1e-12));
  CHECK(h.time_s[last] == Approx(r.simulated_s));
  // snapshots: initial, 5 between, final
  CHECK(r.snapshots.size() == 7);
  CHECK(r.snapshots.front().time_s == 0.0);
  CHECK(r.snapshots.back().time_s == Approx(r.simulated_s));
  // the lifter got lower; the worn depth is about rate x time
  const SegmentMetrics m0 = segment_metrics(r.initial, 0, Rotation::Ccw, 7800);
  const SegmentMetrics m1 = segment_metrics(r.final, 0, Rotation::Ccw, 7800);
  CHECK(m1.lifter_height_m < m0.lifter_height_m);
  // at least the abrasion of a loaded element, Radziszewski 0.02 x 1000 x 0.1 / (pi H) / L x A, over the run,
  // at most the fastest element's amplified rate over the run (plus the change of the rates as the profile wears)
  const double abrasion = 0.02 * 1000 * 0.1 / (M_PI * 350 * 9.80665e6) / 0.0125 * 2e5;
  double fastest = 0;
  for (size_t i = 0; i < r.rates.total.size(); ++i) fastest = std::max(fastest, 2e5 * r.rates.total[i]);
  CHECK(r.max_recession_m > 0.5 * abrasion * r.simulated_s);
  CHECK(r.max_recession_m < 1.5 * fastest * r.simulated_s);
  CHECK(r.realtime_ratio > 0);
}

TEST_CASE("wear run: zero loads give zero wear", "[wear][run]") {
  reset_fake();
  g_fake.normal = 0;
  g_fake.impacts = false;
  const WearRunResult r = run_wear(short_run(), kFake);
  CHECK(r.mass_loss_kg_per_m == 0.0);
  CHECK(r.commanded_mass_kg_per_m == 0.0);
  CHECK(r.max_recession_m == 0.0);
  CHECK(r.remeshes + r.fast_remeshes == 0);
  REQUIRE(r.final.n_nodes() == r.initial.n_nodes());
  for (int i = 0; i < r.final.n_nodes(); ++i) CHECK(r.final.nodes[i] == r.initial.nodes[i]);
}

TEST_CASE("wear run: twice the amplification removes twice the wear of a step", "[wear][run]") {
  reset_fake();
  const double one_step = 0.01 / (60 / 10.36);  // revolutions of one 0.01 s step
  const WearRunResult a = run_wear(short_run(one_step, 1e5), kFake);
  const WearRunResult b = run_wear(short_run(one_step, 2e5), kFake);
  REQUIRE(a.steps == 1);
  REQUIRE(b.steps == 1);
  CHECK(b.commanded_mass_kg_per_m == Approx(2 * a.commanded_mass_kg_per_m).epsilon(1e-12));
  // the profile's loss doubles up to the second-order corner terms of the offset
  CHECK(b.mass_loss_kg_per_m / a.mass_loss_kg_per_m == Approx(2).epsilon(1e-3));
  CHECK(b.mass_loss_impact_kg_per_m / a.mass_loss_impact_kg_per_m == Approx(2).epsilon(1e-3));
}

TEST_CASE("wear run: feedback drives the charge again on the worn profile", "[wear][run]") {
  reset_fake();
  WearRunInput in = short_run();
  in.wear.remesh_every_steps = 40;
  const WearRunResult nf = run_wear(in, kFake);
  CHECK(g_fake.calls == 1);
  CHECK(nf.charge_drives == 1);
  reset_fake();
  in.wear.feedback = true;
  const WearRunResult f = run_wear(in, kFake);
  // a drive at the start and after every remesh but the last: 116 steps, remeshes at 40, 80, 116
  CHECK(g_fake.calls == 3);
  CHECK(f.charge_drives == 3);
  REQUIRE(g_fake.seen_area.size() == 3);
  CHECK(g_fake.seen_area[1] < g_fake.seen_area[0]);
  CHECK(g_fake.seen_area[2] < g_fake.seen_area[1]);
  // with feedback every 80 steps: the start and the remesh at 80
  reset_fake();
  in.wear.feedback_every_steps = 80;
  run_wear(in, kFake);
  CHECK(g_fake.calls == 2);
}

TEST_CASE("wear run: one liner and all liners agree for loads alike on every liner", "[wear][run]") {
  reset_fake();
  WearRunInput in = short_run(0.02);  // 12 steps, 2 remeshes
  const WearRunResult one = run_wear(in, kFake);
  in.wear.liner_computation = "all";
  const WearRunResult all = run_wear(in, kFake);
  CHECK(all.commanded_mass_kg_per_m == Approx(one.commanded_mass_kg_per_m).epsilon(1e-9));
  CHECK(all.mass_loss_kg_per_m == Approx(one.mass_loss_kg_per_m).epsilon(1e-3));
  CHECK(all.max_recession_m == Approx(one.max_recession_m).epsilon(1e-3));
}

TEST_CASE("wear run: smoothing keeps the mass and the bookkeeping", "[wear][run]") {
  reset_fake();
  WearRunInput in = short_run();
  in.wear.smoothing.method = SmoothingMethod::Csaps;
  const WearRunResult r = run_wear(in, kFake);
  CHECK(r.smoothing_max_rel_change < 0.005);
  CHECK(r.mass_loss_kg_per_m == Approx(metrics(r.initial, Rotation::Ccw, 7800).mass_kg_per_m -
                                       metrics(r.final, Rotation::Ccw, 7800).mass_kg_per_m)
                                    .epsilon(1e-9));
  CHECK(std::abs(r.mass_balance_rel_error) < 0.01);
}

TEST_CASE("wear run: failures are detected and input refused", "[wear][run]") {
  reset_fake();
  // 1e9 x 1.9e-8 m/s x 0.01 s = 0.19 m a step, far more than half an element
  CHECK_THROWS_AS(run_wear(short_run(0.2, 1e9), kFake), SimulationError);
  WearRunInput in = short_run();
  in.material.hardness_bhn = -1;
  CHECK_THROWS_AS(run_wear(in, kFake), InputError);
  in = short_run();
  in.wear.laws = {"impact/finnie"};
  const ChargeModelEntry no_impacts{"fake", "test double", false, true, &make_fake};
  CHECK_THROWS_AS(run_wear(in, no_impacts), InputError);
}
