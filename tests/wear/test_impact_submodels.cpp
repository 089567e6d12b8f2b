// Impact sub-models (thesis eqs. 5.13, 5.20-5.27): analytic limits, the shapes
// of thesis Figs. 5-5 and 5-6, and hand-computed values.
#include <catch2/catch.hpp>
#include <cmath>

#include "wear/impact_submodels.h"

using namespace linerlife;

namespace {

/// Steel on steel: E = 210 GPa, nu = 0.29 for both; liner 350 BHN, yield 1 GPa,
/// shear strength 0.7 GPa; balls 7800 kg/m3, 600 BHN (the defaults).
LinerMaterial steel() { return LinerMaterial{}; }

}  // namespace

TEST_CASE("contact modulus and the elastic limit velocities by hand", "[wear][impact]") {
  const LinerMaterial m = steel();
  // 1/E* = 2 (1 - 0.29^2) / 210e9 = 2 x 0.9159 / 210e9 = 8.722857e-12 1/Pa  ->  E* = 1.146413e11 Pa
  CHECK(m.contact_modulus_pa() == Approx(1.146413e11).epsilon(1e-6));
  // Bitter K = pi^2 / (2 sqrt 10) (1.59e9)^2.5 / sqrt(7800) x (8.722857e-12)^2
  //          = 1.560521 x 1.008075e23 / 88.31761 x 7.608824e-23 = 0.1355292 m/s
  CHECK(bitter_elastic_limit_speed(m) == Approx(0.1355292).epsilon(1e-6));
  // Thornton V_y with p_y = 350 BHN = 3.432328e9 Pa (the softer of liner and ball):
  // 1.5605 x (3.432328e9)^2.5 / (88.3176 x (1.146413e11)^2) = 0.92791 m/s
  CHECK(thornton_yield_speed(m) == Approx(0.927910).epsilon(1e-5));
}

TEST_CASE("restitution falls with impact speed and stays between 0 and 1 (thesis Fig. 5-5)", "[wear][impact]") {
  const LinerMaterial m = steel();
  const double vy = thornton_yield_speed(m);
  // elastic below the yield velocity, continuous at it
  CHECK(restitution(0.5 * vy, m) == 1.0);
  CHECK(restitution(vy * (1 + 1e-9), m) == Approx(1.0).epsilon(1e-6));
  double prev = 1.0;
  for (double v = 1.01 * vy; v < 100; v *= 1.2) {
    const double e = restitution(v, m);
    CHECK(e > 0);
    CHECK(e < 1);
    CHECK(e < prev);  // strictly falling
    prev = e;
  }
  // Fig. 5-5 range: hardened steel balls at 10-60 m/s rebound with e about 0.4-0.7
  CHECK(restitution(10, m) == Approx(0.6469).epsilon(1e-3));
  CHECK(restitution(60, m) > 0.35);
  CHECK(restitution(60, m) < 0.5);
  // Johnson (1985) §11.5 asymptote of the elastic-plastic theory: e -> 1.185 (V_y / v)^(1/4)
  const double v = 1e4 * vy;
  CHECK(restitution(v, m) == Approx(1.185 * std::pow(vy / v, 0.25)).epsilon(2e-3));
  // by hand at v = 10 V_y, r = 0.1: sqrt(6 sqrt3/5) sqrt(1 - 0.01/6) (0.1 / (0.1 + 2 sqrt(1.2 - 0.002)))^(1/4)
  //   = 1.441687 x 0.999166 x (0.1 / 2.289064)^0.25 = 1.441687 x 0.999166 x 0.457178 = 0.658558
  CHECK(restitution(10 * vy, m) == Approx(0.658558).epsilon(1e-5));
}

TEST_CASE("Hertz contact time: two forms of thesis eq. 5.21 agree and scale as v^-1/5", "[wear][impact]") {
  const LinerMaterial m = steel();
  const double R = 0.05;
  for (double v : {0.5, 2.0, 10.0}) {
    // rho form: 2.94 (5 pi rho / (4 E*))^(2/5) R v^(-1/5)
    const double rho_form =
        2.94 * std::pow(5 * M_PI * 7800 / (4 * m.contact_modulus_pa()), 0.4) * R * std::pow(v, -0.2);
    CHECK(hertz_contact_time(v, R, m) == Approx(rho_form).epsilon(1e-12));
  }
  CHECK(hertz_contact_time(32, R, m) / hertz_contact_time(1, R, m) == Approx(0.5).epsilon(1e-12));  // 32^(-1/5)
  // by hand, d = 0.1 m, v = 4 m/s: m = 7800 pi 0.1^3 / 6 = 4.084070 kg,
  // delta = (15 x 4.084070 x 16 / (16 x 1.146413e11 x sqrt(0.05)))^0.4 = 3.559125e-4 m, t = 2.94 delta / 4
  // = 2.615957e-4 s
  CHECK(hertz_contact_time(4, R, m) == Approx(2.615957e-4).epsilon(1e-6));
}

TEST_CASE("crater of a shallow cap and the impact friction by hand (thesis eqs. 5.20, 5.25, 5.26)", "[wear][impact]") {
  const LinerMaterial m = steel();
  // cap volume pi h^2 (3R - h)/3 with h = d^2/(8R): eq. 5.25 inverts its shallow limit pi h^2 R
  const double R = 0.05, d = 0.004, h = d * d / (8 * R);
  const double cap = M_PI * h * h * (3 * R - h) / 3;
  CHECK(crater_diameter(cap, R) == Approx(d).epsilon(1e-4));
  // d = 0.1 m ball at vn = 4 m/s: e = 0.7991637 (Thornton),
  // crater = 0.5 x 4.084070 x 16 x (1 - 0.7991637^2) / 3.432328e9 = 3.439595e-9 m3,
  // d = (64 x 0.05 x 3.439595e-9 / pi)^(1/4) = 7.693551e-3 m,
  // A = pi d^2 / 8 = 2.324415e-5 m2, A' = d^3 / (12 R) = 7.589782e-7 m2,
  // f = (A 0.7e9 + A' 3.432328e9) x 2.615957e-4 / (4.084070 x 1.7991637 x 4) = 0.1680026
  const ImpactContact c = impact_contact(4.0, 0.1, m);
  CHECK(c.restitution == Approx(0.7991637).epsilon(1e-6));
  CHECK(c.crater_volume_m3 == Approx(3.439595e-9).epsilon(1e-5));
  CHECK(c.crater_diameter_m == Approx(7.693551e-3).epsilon(1e-5));
  CHECK(c.friction == Approx(0.1680026).epsilon(1e-5));
  // thesis eq. 5.27 on the same impact with vt = 3 m/s: (16 - 16 e^2) / 25
  CHECK(energy_loss_fraction(4, 3, c.restitution) == Approx(0.2312559).epsilon(1e-6));
  CHECK(energy_loss_fraction(4, 0, 1.0) == 0.0);
}

TEST_CASE("the impact friction stays in a physical range (thesis Fig. 5-6)", "[wear][impact]") {
  const LinerMaterial m = steel();
  // Fig. 5-6 shows measured and predicted friction of 0.15-0.3 for steel and
  // brass shot; over mill impact speeds the estimate stays between 0 and 0.5,
  // grows with speed and does not depend on the ball size (a scale-free model).
  for (double d : {0.02, 0.05, 0.1333}) {
    double prev = 0;
    for (double v = 1.0; v <= 60; v *= 1.5) {
      const double f = impact_contact(v, d, m).friction;
      CHECK(f > 0);
      CHECK(f < 0.5);
      CHECK(f > prev);
      prev = f;
    }
    CHECK(impact_contact(10, d, m).friction == Approx(impact_contact(10, 0.05, m).friction).epsilon(1e-9));
    CHECK(impact_contact(10, d, m).friction > 0.15);
    CHECK(impact_contact(40, d, m).friction < 0.3);
  }
}
