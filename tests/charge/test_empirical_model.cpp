// The empirical model: Morrell's C-model on the diameter inside the actual
// (possibly worn) liner; a clockwise mill is its mirror image.
#include <cmath>

#include <catch2/catch.hpp>

#include "charge/morrell_c_model.h"
#include "fixtures.h"
#include "geometry/metrics.h"

using namespace linerlife;
using namespace linerlife::test;

TEST_CASE("the empirical model uses the diameter inside the liner and Morrell's equations", "[charge][empirical]") {
  const Config c = load_default_config();
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const ChargeResult r = run_model("empirical", charge_input(c, s, 0));
  const double D = metrics(s, c.mill.rotation, 7800).effective_diameter_m;
  CHECK(r.indicators.diameter_eff_m == Approx(D).epsilon(1e-12));
  const double phi = c.mill.speed_rpm / (42.3 / std::sqrt(D));
  CHECK(r.indicators.fraction_critical == Approx(phi).epsilon(1e-12));
  const double toe = morrell_toe_rad(c.charge.filling, phi);
  CHECK(r.indicators.toe_deg == Approx(toe * 180 / kPi).epsilon(1e-12));
  CHECK(r.indicators.shoulder_deg ==
        Approx(morrell_shoulder_rad(c.charge.filling, phi, toe) * 180 / kPi).epsilon(1e-12));
  // gross = no-load + k (P_t + P_c), k = 1.26 (Morrell 1996)
  CHECK(r.indicators.gross_power_kw ==
        Approx(r.indicators.no_load_power_kw + 1.26 * r.indicators.net_power_kw).epsilon(1e-12));
  CHECK(r.indicators.n_trajectories < 0);  // not a quantity of the C-model
  CHECK_FALSE(r.loads.has_impacts);
  // the centre of mass lies in the annular sector between r_i and the shell
  CHECK(r.indicators.com_radius_m > r.indicators.inner_radius_m * 0.5);
  CHECK(r.indicators.com_radius_m < 0.5 * D);
}

TEST_CASE("a worn liner changes the empirical result through its diameter", "[charge][empirical]") {
  Config c = load_default_config();
  const LinerSurface s_new = build_liner_surface(c.mill, c.liner);
  c.liner.design.lifter_height_m = 0.10;  // worn lifters: more room inside, a larger diameter
  const LinerSurface s_worn = build_liner_surface(c.mill, c.liner);
  const ChargeResult a = run_model("empirical", charge_input(c, s_new, 0));
  const ChargeResult b = run_model("empirical", charge_input(c, s_worn, 0));
  CHECK(b.indicators.diameter_eff_m > a.indicators.diameter_eff_m + 0.05);
  // same rpm on a larger diameter: closer to critical, more power
  CHECK(b.indicators.fraction_critical > a.indicators.fraction_critical);
  CHECK(b.indicators.net_power_kw > a.indicators.net_power_kw);
}

TEST_CASE("a clockwise mill gives the mirror image in the physical frame", "[charge][empirical]") {
  Config c = load_default_config();
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const ChargeResult a = run_model("empirical", charge_input(c, s, 0));
  c.mill.rotation = Rotation::Cw;
  const LinerSurface s_cw = build_liner_surface(c.mill, c.liner);
  const ChargeResult b = run_model("empirical", charge_input(c, s_cw, 0));
  CHECK(b.indicators.toe_deg == Approx(mirror_deg(a.indicators.toe_deg)).margin(1e-9));
  CHECK(b.indicators.shoulder_deg == Approx(mirror_deg(a.indicators.shoulder_deg)).margin(1e-9));
  CHECK(b.indicators.com_angle_deg == Approx(mirror_deg(a.indicators.com_angle_deg)).margin(1e-9));
  CHECK(b.indicators.net_power_kw == Approx(a.indicators.net_power_kw).epsilon(1e-9));
}

TEST_CASE("a bed thinner than half a ball is one layer, with its speed at the bed's middle", "[charge][empirical]") {
  // the input sweep of 2026-12-07: at 1 % filling the C-model's annulus
  // r_i < r < r_m is a few centimetres deep, and the count rounded to none
  Config c = load_default_config();
  c.charge.filling = 0.01;  // the least allowed, with 0.1333 m balls
  c.charge.ball_filling = 0.01;
  c.mill.speed_rpm = 13.0;  // 0.97 of critical: the bed thins below half a ball (0.067 m at 10.36 rpm)
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const ChargeResult r = run_model("empirical", charge_input(c, s, 0));
  const double rm = 0.5 * r.indicators.diameter_eff_m, ri = r.indicators.inner_radius_m;
  REQUIRE(rm - ri > 0);
  REQUIRE(rm - ri < 0.5 * c.charge.ball_diameter_m);  // the case: thinner than half a ball
  CHECK(r.indicators.n_layers == 1);
  REQUIRE(r.indicators.layer_speed_rpm.size() == 1);
  // Morrell's linear law (thesis eq. 4.16 with z) at the bed's middle: slower
  // than the shell, faster than nothing
  const double v = r.indicators.layer_speed_rpm[0];
  CHECK(v > 0);
  CHECK(v < c.mill.speed_rpm);
  // the default charge: the rounded count, one speed per layer, as before
  const ChargeResult d = run_model("empirical", charge_input(load_default_config(), s, 0));
  const double rm0 = 0.5 * d.indicators.diameter_eff_m, ri0 = d.indicators.inner_radius_m;
  CHECK(d.indicators.n_layers == std::lround((rm0 - ri0) / c.charge.ball_diameter_m));
  CHECK(d.indicators.layer_speed_rpm.size() == static_cast<size_t>(d.indicators.n_layers));
}
