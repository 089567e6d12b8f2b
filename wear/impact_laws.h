// impact_laws.h - volume of liner removed by one impact (thesis §5.4.2,
// eqs. 5.11-5.28). One function per law; all are linear in the impacting mass,
// so an agglomerated charge element (ImpactEvent::mass_kg, per metre of mill
// length) is treated as that mass of balls of ImpactEvent::diameter_m.
//
// Inputs: mass_kg [kg] impacting mass, vn [m/s] > 0 normal speed towards the
// liner, vt [m/s] >= 0 tangential speed, diameter_m [m] of one ball. The
// impact angle from the surface is alpha = atan2(vn, vt). Output: volume
// removed [m3] (per metre of mill length when mass_kg is per metre).
// Parameters and defaults: docs/models/wear.md §4.
#pragma once

#include "wear/liner_material.h"

namespace linerlife {

/// Finnie (1960), Wear 3:87-103, with the particle's rotation as in the
/// revised form quoted in the thesis (eq. 5.11, Finnie 1967/1972):
///   V = c M U^2 / (2 p psi (1 + m r^2 / I)) [cos^2 a - (xdot_t / U)^2].
struct FinnieParams {
  double cutting_fraction = 0.5;  // [-] c, share of particles cutting in the idealised way (Finnie: about half)
  double force_ratio = 2.0;       // [-] K = vertical / horizontal force on the particle (Finnie: 2)
  double depth_ratio = 2.0;       // [-] psi = contact length / cut depth (Finnie: 2)
  double inertia_ratio = 2.5;     // [-] m r^2 / I (a solid sphere: 5/2)
};

/// Finnie's cutting volume [m3]. The flow pressure p is the liner's Brinell
/// hardness. With lambda = (1 + m r^2/I) / K the tip leaves the surface still
/// cutting when tan a <= 1 / (2 lambda), and then xdot_t = U (cos a - 2 lambda sin a);
/// otherwise cutting stops (xdot_t = 0) and V ~ cos^2 a. Zero at normal incidence.
double finnie_volume(double mass_kg, double vn, double vt, const FinnieParams& p, const LinerMaterial& m);

/// Bitter (1963), Wear 6:5-21 and 169-190 (thesis eqs. 5.12-5.18):
/// deformation wear plus cutting wear.
struct BitterParams {
  double deformation_j_m3 = 7.0e10;  // [J/m3] epsilon, energy to remove a unit volume by deformation
  double cutting_j_m3 = 5.0e10;      // [J/m3] Q (the thesis' F_c), energy to remove a unit volume by cutting
};

struct BitterVolume {
  double deformation_m3 = 0;  // W_D
  double cutting_m3 = 0;      // W_C
  double total() const { return deformation_m3 + cutting_m3; }
};

/// Bitter's wear [m3], U = |v|, a the impact angle, K the elastic load limit
/// velocity (bitter_elastic_limit_speed), y the liner's yield stress, rho_b
/// the ball's density:
///   W_D  = M (U sin a - K)^2 / (2 eps)
///   W_C1 = (2 M u / Q) (U cos a - u),  u = C Q (U sin a - K)^2 / (U sin a)^(1/2),
///          C = 0.288 / y (rho_b / y)^(1/4)                 while U cos a - 2u >= 0
///   W_C2 = M [U^2 cos^2 a - K1 (U sin a - K)^(3/2)] / (2 Q),
///          K1 = 0.82 y^2 (y / rho_b)^(1/4) [(1-nu1^2)/E1 + (1-nu2^2)/E2]^2   otherwise
/// (both constants are dimensionless in SI). No wear when U sin a <= K; W_C >= 0.
/// W_C1 = M (U^2 cos^2 a - xdot_end^2) / (2 Q) with xdot_end = U cos a - 2u, so the
/// branch switches (Bitter's a_0) where the particle stops sliding.
BitterVolume bitter_volume(double mass_kg, double vn, double vt, const BitterParams& p, const LinerMaterial& m);

/// Rabinowicz's low-velocity impact wear (thesis eq. 5.19; Rabinowicz's
/// abrasive-wear equation V = tan(theta) W x / (pi H) with the friction work
/// f W x equal to the energy the impact dissipates):
///   V = alpha (1/2 M U^2) tan(theta) / (pi f H),
/// alpha from eq. 5.27 (energy_loss_fraction), f from eq. 5.20 (impact_contact).
struct RabinowiczParams {
  double tan_theta = 0.1;  // [-] tangent of the mean roughness (abrasive) angle of the impacting surface
};

double rabinowicz_volume(double mass_kg, double vn, double vt, double diameter_m, const RabinowiczParams& p,
                         const LinerMaterial& m);

/// Sheldon & Kanhere (1972), Wear 21:195-209 (thesis eq. 5.28):
/// V = k D^3 U^3 (rho_b / H_v)^(3/2). Written as V = k D^3 (rho_b U^2 / H_v)^(n/2)
/// so that the thesis' velocity exponent n = 2.35 keeps the law dimensionally
/// sound (n = 3 is the original), and with D^3 = 6 M / (pi rho_b) so that it
/// is linear in the impacting mass.
struct SheldonKanhereParams {
  double k = 0.07;           // [-]
  double exponent = 2.35;    // [-] n (thesis §5.4.2: wear goes as U^2..U^2.35)
  bool normal_speed = true;  // U = vn (indentation physics); false: U = |v| as in the thesis
};

double sheldon_kanhere_volume(double mass_kg, double vn, double vt, const SheldonKanhereParams& p,
                              const LinerMaterial& m);

}  // namespace linerlife
