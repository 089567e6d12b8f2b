// Curves of the impact sub-models and laws for docs/validation/wear.md (the
// shapes of thesis Figs. 5-5, 5-6 and 5-7): restitution and friction against
// impact speed, wear volume against impact angle. Prints CSV sections that
// bench/plot_wear_validation.py draws.
//
// Usage: bench_wear_submodels
#include <cmath>
#include <cstdio>

#include "wear/impact_laws.h"
#include "wear/impact_submodels.h"

using namespace linerlife;

int main() {
  const LinerMaterial m;   // Cr-Mo liner 350 BHN, forged steel balls 600 BHN (defaults)
  LinerMaterial soft = m;  // a softer liner, 250 BHN, to show the trend
  soft.hardness_bhn = 250;
  std::printf("# restitution: speed_m_s,e_350bhn,e_250bhn,johnson_asymptote_350bhn\n");
  const double vy = thornton_yield_speed(m);
  for (double v = 0.25; v <= 60.0; v *= 1.08)
    std::printf("%.4f,%.6f,%.6f,%.6f\n", v, restitution(v, m), restitution(v, soft), 1.185 * std::pow(vy / v, 0.25));
  std::printf("\n# friction: speed_m_s,f_d0.05,f_d0.1333,contact_time_s_d0.1333,crater_diameter_m_d0.1333\n");
  for (double v = 0.5; v <= 60.0; v *= 1.08) {
    const ImpactContact c = impact_contact(v, 0.1333, m);
    std::printf("%.4f,%.6f,%.6f,%.6e,%.6e\n", v, impact_contact(v, 0.05, m).friction, c.friction, c.contact_time_s,
                c.crater_diameter_m);
  }
  std::printf(
      "\n# erosion at 8 m/s per kg of 0.1333 m balls [m3/kg]: angle_deg,finnie,bitter_deformation,"
      "bitter_cutting,bitter,rabinowicz,sheldon_kanhere\n");
  const double U = 8;
  for (double a = 1; a <= 90.0; a += 1) {
    const double r = a * M_PI / 180, vn = U * std::sin(r), vt = U * std::cos(r);
    const BitterVolume b = bitter_volume(1, vn, vt, BitterParams{}, m);
    std::printf("%.1f,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e\n", a, finnie_volume(1, vn, vt, FinnieParams{}, m),
                b.deformation_m3, b.cutting_m3, b.total(), rabinowicz_volume(1, vn, vt, 0.1333, RabinowiczParams{}, m),
                sheldon_kanhere_volume(1, vn, vt, SheldonKanhereParams{}, m));
  }
  return 0;
}
