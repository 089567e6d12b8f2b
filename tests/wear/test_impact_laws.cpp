// Impact wear laws (thesis eqs. 5.11-5.28): one hand-computed case each, the
// angle dependence of thesis Fig. 5-7, and analytic limits.
#include <catch2/catch.hpp>
#include <cmath>

#include "wear/impact_laws.h"
#include "wear/impact_submodels.h"

using namespace linerlife;

namespace {

double deg(double d) { return d * M_PI / 180; }

/// Liner hardness of exactly 1 GPa, for round numbers.
LinerMaterial one_gpa() {
  LinerMaterial m;
  m.hardness_bhn = 1e9 / kPascalPerBrinell;
  return m;
}

}  // namespace

TEST_CASE("Finnie: hand-computed volumes on both branches", "[wear][impact][finnie]") {
  const LinerMaterial m = one_gpa();
  const FinnieParams p;  // c = 0.5, K = 2, psi = 2, m r^2 / I = 2.5
  const double U = 10, M = 1;
  // C = c M U^2 / (2 p psi (1 + m r^2/I)) = 0.5 x 100 / (2 x 1e9 x 2 x 3.5) = 3.571429e-9 m3, lambda = 3.5/2 = 1.75
  // a = 10 deg: tan a = 0.1763 < 1/(2 lambda) = 0.2857 -> leaves while cutting,
  //   xdot/U = cos a - 2 lambda sin a = 0.984808 - 3.5 x 0.173648 = 0.377039
  //   V = C (cos^2 a - 0.377039^2) = 3.571429e-9 x (0.969846 - 0.142159) = 2.956028e-9 m3
  CHECK(finnie_volume(M, U * std::sin(deg(10)), U * std::cos(deg(10)), p, m) == Approx(2.956028e-9).epsilon(1e-6));
  // a = 60 deg: cutting stops, V = C cos^2 a = 3.571429e-9 / 4 = 8.928571e-10 m3
  CHECK(finnie_volume(M, U * std::sin(deg(60)), U * std::cos(deg(60)), p, m) == Approx(8.928571e-10).epsilon(1e-6));
  // linear in mass, quadratic in speed
  CHECK(finnie_volume(3, 2 * std::sin(deg(25)), 2 * std::cos(deg(25)), p, m) ==
        Approx(3 * 0.04 * finnie_volume(1, 10 * std::sin(deg(25)), 10 * std::cos(deg(25)), p, m)).epsilon(1e-12));
}

TEST_CASE("Finnie (1960) without rotation reproduces his original two branches", "[wear][impact][finnie]") {
  // Finnie 1960 took m r^2 / I = 2 (lambda = 3/K): V = M U^2/(p psi K) [sin 2a - (6/K) sin^2 a] for tan a <= K/6,
  // V = M U^2/(p psi K) K cos^2 a / 6 beyond, with c = 1.
  const LinerMaterial m = one_gpa();
  FinnieParams p;
  p.cutting_fraction = 1;
  p.inertia_ratio = 2;
  const double K = p.force_ratio, psi = p.depth_ratio, U = 7, M = 0.3, H = 1e9;
  for (double a_deg : {3.0, 10.0, 18.0, 18.4, 18.5, 30.0, 60.0, 89.0}) {
    const double a = deg(a_deg);
    const double f =
        std::tan(a) <= K / 6 ? std::sin(2 * a) - 6 / K * std::pow(std::sin(a), 2) : K * std::pow(std::cos(a), 2) / 6;
    CHECK(finnie_volume(M, U * std::sin(a), U * std::cos(a), p, m) ==
          Approx(M * U * U / (H * psi * K) * f).epsilon(1e-10));
  }
}

TEST_CASE("erosion against impact angle: Finnie peaks low and vanishes at 90 deg, Bitter does not (thesis Fig. 5-7)",
          "[wear][impact]") {
  const LinerMaterial m;  // 350 BHN Cr-Mo liner, steel balls
  const FinnieParams fp;
  const BitterParams bp;
  const double U = 8, M = 1;
  double fmax = 0, fmax_at = 0, bmax = 0, bmax_at = 0;
  for (double a_deg = 0.25; a_deg <= 90.0; a_deg += 0.25) {
    const double a = deg(a_deg), vn = U * std::sin(a), vt = U * std::cos(a);
    const double f = finnie_volume(M, vn, vt, fp, m), b = bitter_volume(M, vn, vt, bp, m).total();
    if (f > fmax) fmax = f, fmax_at = a_deg;
    if (b > bmax) bmax = b, bmax_at = a_deg;
  }
  // Finnie's maximum: d/da [sin 2a - 2 lambda sin^2 a] = 0 -> tan 2a = 1/lambda, lambda = 1.75: a = 14.87 deg
  CHECK(fmax_at == Approx(0.5 * std::atan(1 / 1.75) * 180 / M_PI).margin(0.25));
  CHECK(fmax_at < 30);
  CHECK(finnie_volume(M, U, 0, fp, m) == 0.0);
  CHECK(finnie_volume(M, U * std::sin(deg(89.9)), U * std::cos(deg(89.9)), fp, m) < 1e-5 * fmax);
  // Bitter: deformation wear keeps the normal impact eroding; its peak is at an oblique angle
  const BitterVolume normal = bitter_volume(M, U, 0, bp, m);
  CHECK(normal.total() > 0.1 * bmax);
  CHECK(normal.cutting_m3 == 0.0);
  CHECK(bmax_at < 60);
  // and the deformation part rises monotonically with the angle
  double prev = -1;
  for (double a_deg = 5; a_deg <= 90; a_deg += 5) {
    const double d = bitter_volume(M, U * std::sin(deg(a_deg)), U * std::cos(deg(a_deg)), bp, m).deformation_m3;
    CHECK(d > prev);
    prev = d;
  }
}

TEST_CASE("Bitter: hand-computed deformation and cutting wear on both branches", "[wear][impact][bitter]") {
  LinerMaterial m;       // y = 1 GPa, E = 210 GPa, nu = 0.29, rho_b = 7800
  const BitterParams p;  // eps = 7e10, Q = 5e10 J/m3
  const double U = 10, M = 1;
  // K = 0.1355292 m/s (test_impact_submodels); C = 0.288/1e9 x (7800/1e9)^0.25 = 1.522005e-11
  // K1 = 0.82 x 1e18 x (1e9/7800)^0.25 x (8.722857e-12)^2 = 1.180613e-3 (m/s)^0.5
  SECTION("a = 30 deg: cutting stops during contact (W_C2)") {
    // vn = 5, vt = 8.660254, vn - K = 4.864471
    // W_D = 4.864471^2 / (2 x 7e10) = 1.690220e-10 m3
    // u = C Q 4.864471^2 / sqrt(5) = 8.053272 m/s; vt - 2u < 0 -> W_C2
    // W_C2 = (75 - 1.180613e-3 x 4.864471^1.5) / (2 x 5e10) = 7.498733e-10 m3
    const BitterVolume w = bitter_volume(M, U * std::sin(deg(30)), U * std::cos(deg(30)), p, m);
    CHECK(w.deformation_m3 == Approx(1.690220e-10).epsilon(1e-6));
    CHECK(w.cutting_m3 == Approx(7.498733e-10).epsilon(1e-6));
  }
  SECTION("a = 5 deg: the ball leaves still sliding (W_C1)") {
    // vn = 0.8715574, vt = 9.961947, vn - K = 0.7360283
    // W_D = 0.7360283^2 / 1.4e11 = 3.869554e-12 m3
    // u = C Q 0.7360283^2 / sqrt(0.8715574) = 0.4415980 m/s; vt - 2u > 0 -> W_C1
    // W_C1 = 2 x 0.4415980 / 5e10 x (9.961947 - 0.4415980) = 1.681667e-10 m3
    const BitterVolume w = bitter_volume(M, U * std::sin(deg(5)), U * std::cos(deg(5)), p, m);
    CHECK(w.deformation_m3 == Approx(3.869554e-12).epsilon(1e-6));
    CHECK(w.cutting_m3 == Approx(1.681667e-10).epsilon(1e-6));
  }
  SECTION("below the elastic limit velocity nothing wears") {
    const BitterVolume w = bitter_volume(M, 0.1, 5.0, p, m);
    CHECK(w.total() == 0.0);
  }
  SECTION("W_C1 is the energy form M (U^2 cos^2 a - xdot_end^2) / (2Q) with xdot_end = U cos a - 2u") {
    const double vn = U * std::sin(deg(5)), vt = U * std::cos(deg(5)), k = bitter_elastic_limit_speed(m);
    const double u = 0.288 / 1e9 * std::pow(7800 / 1e9, 0.25) * p.cutting_j_m3 * std::pow(vn - k, 2) / std::sqrt(vn);
    const double xend = vt - 2 * u;
    CHECK(bitter_volume(M, vn, vt, p, m).cutting_m3 ==
          Approx(M * (vt * vt - xend * xend) / (2 * p.cutting_j_m3)).epsilon(1e-12));
  }
}

TEST_CASE("Rabinowicz: hand-computed volume and its limits", "[wear][impact][rabinowicz]") {
  const LinerMaterial m;
  const RabinowiczParams p;  // tan(theta) = 0.1
  // M = 2 kg of 0.1 m balls at vn = 4, vt = 3: alpha = 0.2312559, f = 0.1680026 (test_impact_submodels),
  // KE = 0.5 x 2 x 25 = 25 J, V = 0.2312559 x 25 x 0.1 / (pi x 0.1680026 x 3.432328e9) = 3.191379e-10 m3
  CHECK(rabinowicz_volume(2, 4, 3, 0.1, p, m) == Approx(3.191379e-10).epsilon(1e-5));
  // an elastic impact (below the yield velocity) dissipates nothing and wears nothing
  CHECK(rabinowicz_volume(2, 0.5 * thornton_yield_speed(m), 3, 0.1, p, m) == 0.0);
  // linear in the impacting mass
  CHECK(rabinowicz_volume(6, 4, 3, 0.1, p, m) == Approx(3 * rabinowicz_volume(2, 4, 3, 0.1, p, m)).epsilon(1e-12));
}

TEST_CASE("Sheldon-Kanhere: hand-computed volume, exponent and speed choice", "[wear][impact][sheldon]") {
  const LinerMaterial m;   // HV = 1.05 x 350 BHN = 3.603944e9 Pa, rho_b = 7800
  SheldonKanhereParams p;  // k = 0.07, n = 2.35, normal speed
  // M = 1 kg, vn = 5: D^3 = 6 / (pi 7800) = 2.448538e-4 m3, rho U^2 / HV = 195000 / 3.603944e9 = 5.410739e-5,
  // (5.410739e-5)^1.175 = 9.695640e-6, V = 0.07 x 2.448538e-4 x 9.695640e-6 = 1.661810e-10 m3
  CHECK(sheldon_kanhere_volume(1, 5, 0, p, m) == Approx(1.661810e-10).epsilon(1e-6));
  // the normal component only by default; the thesis' total speed on request
  CHECK(sheldon_kanhere_volume(1, 3, 4, p, m) == Approx(sheldon_kanhere_volume(1, 3, 0, p, m)).epsilon(1e-12));
  p.normal_speed = false;
  CHECK(sheldon_kanhere_volume(1, 3, 4, p, m) == Approx(1.661810e-10).epsilon(1e-6));
  // the original exponent 3 gives the original law k D^3 U^3 (rho / HV)^(3/2)
  p.exponent = 3;
  p.normal_speed = true;
  const double D3 = 6 / (M_PI * 7800);
  CHECK(sheldon_kanhere_volume(1, 5, 0, p, m) ==
        Approx(0.07 * D3 * 125 * std::pow(7800 / m.vickers_pa(), 1.5)).epsilon(1e-12));
  // velocity exponent: doubling the speed multiplies the wear by 2^n
  p.exponent = 2.35;
  CHECK(sheldon_kanhere_volume(1, 10, 0, p, m) / sheldon_kanhere_volume(1, 5, 0, p, m) ==
        Approx(std::pow(2, 2.35)).epsilon(1e-12));
}
