#include "wear/impact_submodels.h"

#include <algorithm>
#include <cmath>

#include "geometry/mill.h"

namespace linerlife {

double ball_mass_kg(double d, double rho) { return rho * kPi * d * d * d / 6.0; }

double bitter_elastic_limit_speed(const LinerMaterial& m) {
  // Bitter (1963) part I, eq. for K (thesis eq. 5.13). The constant pi^2/(2 sqrt 10)
  // = 1.5605 follows from Hertz: p0 = (2 E*/pi) (5 pi rho v^2 / (4 E*))^(1/5) = 1.59 y.
  const double inv_e = 1.0 / m.contact_modulus_pa();  // [1/Pa]
  const double c = kPi * kPi / (2.0 * std::sqrt(10.0));
  return c * std::pow(1.59 * m.yield_stress_pa, 2.5) / std::sqrt(m.ball.density_kg_m3) * inv_e * inv_e;
}

double thornton_yield_speed(const LinerMaterial& m) {
  // Thornton (1997): V_y = 1.56 (p_y^5 / (E*^4 rho))^(1/2), the same Hertz
  // relation with the limiting contact pressure p_y in place of 1.59 y.
  const double py = m.limiting_pressure_pa(), es = m.contact_modulus_pa();
  return 1.5605 * std::pow(py, 2.5) / (std::sqrt(m.ball.density_kg_m3) * es * es);
}

double restitution(double vn, const LinerMaterial& m) {
  const double vy = thornton_yield_speed(m);
  if (!(vn > vy)) return 1.0;
  // Thornton (1997): e = sqrt(6 sqrt3 / 5) sqrt(1 - r^2/6) [r / (r + 2 sqrt(6/5 - r^2/5))]^(1/4), r = V_y / V_i
  const double r = vy / vn;
  const double a = std::sqrt(6.0 * std::sqrt(3.0) / 5.0);
  const double b = std::sqrt(1.0 - r * r / 6.0);
  const double c = std::pow(r / (r + 2.0 * std::sqrt(6.0 / 5.0 - r * r / 5.0)), 0.25);
  return std::min(1.0, a * b * c);
}

double hertz_contact_time(double vn, double radius_m, const LinerMaterial& m) {
  // Johnson (1985) eqs. 11.20-11.24: (1/2) m v^2 = (8/15) E* R^(1/2) delta^(5/2); t = 2.94 delta / v.
  const double mass = m.ball.density_kg_m3 * 4.0 / 3.0 * kPi * radius_m * radius_m * radius_m;
  const double delta = std::pow(15.0 * mass * vn * vn / (16.0 * m.contact_modulus_pa() * std::sqrt(radius_m)), 0.4);
  return 2.94 * delta / vn;
}

double crater_volume(double vn, double e, double ball_mass, const LinerMaterial& m) {
  // Yabuki (1999), thesis eq. 5.26: plastic work over the indentation pressure.
  return 0.5 * ball_mass * vn * vn * (1.0 - e * e) / m.hardness_pa();
}

double crater_diameter(double volume_m3, double radius_m) {
  // thesis eq. 5.25: shallow spherical cap, v = pi h^2 R with h = d^2 / (8 R).
  return std::pow(64.0 * radius_m * volume_m3 / kPi, 0.25);
}

ImpactContact impact_contact(double vn, double diameter_m, const LinerMaterial& m) {
  ImpactContact c;
  const double R = 0.5 * diameter_m;
  const double mass = ball_mass_kg(diameter_m, m.ball.density_kg_m3);
  c.restitution = restitution(vn, m);
  c.contact_time_s = hertz_contact_time(vn, R, m);
  c.crater_volume_m3 = crater_volume(vn, c.restitution, mass, m);
  c.crater_diameter_m = crater_diameter(c.crater_volume_m3, R);
  // Yabuki (1999), thesis eq. 5.20: f = [A s + A' p'] / [m (1 + e) vn / dt]
  const double d = c.crater_diameter_m;
  const double area = kPi * d * d / 8.0;                                            // [m2] mean contact area A
  const double plough = d * d * d / (12.0 * R);                                     // [m2] crater cross-section A'
  const double tangential = area * m.shear_strength_pa + plough * m.hardness_pa();  // [N]
  const double normal = mass * (1.0 + c.restitution) * vn / c.contact_time_s;       // [N]
  c.friction = tangential / normal;
  return c;
}

double energy_loss_fraction(double vn, double vt, double e) {
  // thesis eq. 5.27 with the total kinetic energy in the denominator
  const double v2 = vn * vn + vt * vt;
  return v2 > 0 ? vn * vn * (1.0 - e * e) / v2 : 0.0;
}

}  // namespace linerlife
