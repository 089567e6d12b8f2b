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
