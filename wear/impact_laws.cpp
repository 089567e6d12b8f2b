#include "wear/impact_laws.h"

#include <algorithm>
#include <cmath>

#include "geometry/mill.h"
#include "wear/impact_submodels.h"

namespace linerlife {

double finnie_volume(double mass, double vn, double vt, const FinnieParams& p, const LinerMaterial& m) {
  const double u2 = vn * vn + vt * vt;
  if (!(u2 > 0)) return 0.0;
  const double u = std::sqrt(u2);
  const double sa = vn / u, ca = vt / u;  // sin, cos of the impact angle
  // Finnie (1960) with rotation (thesis eq. 5.11): C = c M U^2 / (2 p psi (1 + m r^2/I))
  const double rot = 1.0 + p.inertia_ratio;
  const double c = p.cutting_fraction * mass * u2 / (2.0 * m.hardness_pa() * p.depth_ratio * rot);
  const double lambda = rot / p.force_ratio;
  const double xdot = ca - 2.0 * lambda * sa;        // tip speed / U when it leaves the surface
  if (xdot > 0) return c * (ca * ca - xdot * xdot);  // leaves still cutting: tan a < 1/(2 lambda)
  return c * ca * ca;                                // horizontal motion stops first
}

BitterVolume bitter_volume(double mass, double vn, double vt, const BitterParams& p, const LinerMaterial& m) {
  BitterVolume w;
  const double k = bitter_elastic_limit_speed(m);  // [m/s] eq. 5.13
  if (!(vn > k)) return w;                         // elastic impact: no wear
  const double y = m.yield_stress_pa, rho = m.ball.density_kg_m3;
  const double excess = vn - k;  // U sin a - K
  // Bitter part I (thesis eq. 5.12): deformation wear
  w.deformation_m3 = mass * excess * excess / (2.0 * p.deformation_j_m3);
  // Bitter part II (thesis eqs. 5.14-5.17): cutting wear
  const double cb = 0.288 / y * std::pow(rho / y, 0.25);                   // [1/(Pa sqrt(m/s))]
  const double u = cb * p.cutting_j_m3 * excess * excess / std::sqrt(vn);  // [m/s]
  if (vt - 2.0 * u >= 0) {
    w.cutting_m3 = 2.0 * mass * u / p.cutting_j_m3 * (vt - u);  // W_C1, a < a0
  } else {
    const double inv_e = 1.0 / m.contact_modulus_pa();
    const double k1 = 0.82 * y * y * std::pow(y / rho, 0.25) * inv_e * inv_e;  // [(m/s)^(1/2)]
    w.cutting_m3 = std::max(0.0, mass * (vt * vt - k1 * std::pow(excess, 1.5)) / (2.0 * p.cutting_j_m3));  // W_C2
  }
  return w;
}

double rabinowicz_volume(double mass, double vn, double vt, double diameter, const RabinowiczParams& p,
                         const LinerMaterial& m) {
  if (!(vn > 0) || !(diameter > 0)) return 0.0;
  const ImpactContact c = impact_contact(vn, diameter, m);
  const double alpha = energy_loss_fraction(vn, vt, c.restitution);  // eq. 5.27
  if (!(alpha > 0) || !(c.friction > 0)) return 0.0;                 // elastic impact: nothing dissipated
  const double ke = 0.5 * mass * (vn * vn + vt * vt);
  // thesis eq. 5.19: Q = W v^2 alpha tan(theta) / (2 pi f g P) = alpha KE tan(theta) / (pi f P)
  return alpha * ke * p.tan_theta / (kPi * c.friction * m.hardness_pa());
}

double sheldon_kanhere_volume(double mass, double vn, double vt, const SheldonKanhereParams& p,
                              const LinerMaterial& m) {
  const double u2 = p.normal_speed ? vn * vn : vn * vn + vt * vt;
  if (!(u2 > 0)) return 0.0;
  const double rho = m.ball.density_kg_m3;
  const double d3 = 6.0 * mass / (kPi * rho);  // [m3] D^3 of the impacting mass
  // Sheldon & Kanhere (1972), thesis eq. 5.28 with exponent n: V = k D^3 (rho U^2 / H_v)^(n/2)
  return p.k * d3 * std::pow(rho * u2 / m.vickers_pa(), 0.5 * p.exponent);
}

}  // namespace linerlife
