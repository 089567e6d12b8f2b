// impact_submodels.h - what happens in one ball-liner impact: elastic limit,
// restitution, contact time, crater and friction (thesis §5.4.2, eqs.
// 5.13 and 5.20-5.27). The Rabinowicz and Bitter impact laws read them.
//
// Every function is one formula of contact mechanics with its source next to
// it. A ball of radius R [m] and density rho_b (LinerMaterial::ball) hits a
// flat liner with normal speed vn [m/s] > 0. The liner is taken as a rigid
// half-space of infinite mass (a liner weighs tonnes, a ball kilograms).
// Where the thesis' OCR'd transcription is garbled the physics used is stated
// in docs/models/wear.md §3.
#pragma once

#include "wear/liner_material.h"

namespace linerlife {

/// Mass [kg] of one ball of diameter d_m [m] and density rho [kg/m3].
double ball_mass_kg(double diameter_m, double density_kg_m3);

/// Bitter's (1963, part I) elastic load limit velocity K [m/s] (thesis eq.
/// 5.13): the normal speed at which a Hertzian impact first yields the liner,
///   K = (pi^2 / (2 sqrt 10)) (1.59 y)^(5/2) rho_b^(-1/2) [(1-nu1^2)/E1 + (1-nu2^2)/E2]^2,
/// y the liner's yield stress (Hertz: first yield when p0 = 1.59 y).
double bitter_elastic_limit_speed(const LinerMaterial& m);

/// Thornton's (1997) yield velocity V_y [m/s] for a limiting contact pressure p_y
/// (LinerMaterial::limiting_pressure_pa): V_y = 1.56 (p_y^5 / (E*^4 rho_b))^(1/2).
double thornton_yield_speed(const LinerMaterial& m);

/// Coefficient of restitution e(vn) (thesis eqs. 5.22-5.24, Tabor 1953's
/// elastic-plastic impact theory, in the complete closed form of Thornton
/// 1997, J. Appl. Mech. 64:383-386): with r = V_y / vn,
///   e = 1                                                       for vn <= V_y
///   e = (6 sqrt3 / 5)^(1/2) [1 - r^2/6]^(1/2) [ r / (r + 2 sqrt(6/5 - r^2/5)) ]^(1/4)   for vn > V_y.
/// Continuous at V_y, falling as vn^(-1/4) (Johnson 1985 §11.5: e ~ 1.185 (V_y/vn)^(1/4)).
double restitution(double vn, const LinerMaterial& m);

/// Hertz contact duration [s] of a ball of radius R on a half-space (thesis eq.
/// 5.21, Zhang 2002 / Wharton; Johnson 1985 §11.1):
///   t_c = 2.94 delta_max / vn,  delta_max = (15 m vn^2 / (16 E* R^(1/2)))^(2/5),
/// m the ball's mass. Equivalently 2.94 (5 pi rho_b / (4 E*))^(2/5) R vn^(-1/5).
double hertz_contact_time(double vn, double radius_m, const LinerMaterial& m);

/// Crater volume [m3] (thesis eq. 5.26, Yabuki 1999): the energy absorbed
/// plastically, (1/2) m vn^2 (1 - e^2), divided by the pressure of the fully
/// plastic indentation, the liner hardness: v = m vn^2 (1 - e^2) / (2 H).
double crater_volume(double vn, double e, double ball_mass_kg, const LinerMaterial& m);

/// Crater diameter [m] of a shallow spherical cap of volume v [m3] left by a
/// ball of radius R (thesis eq. 5.25): depth h = d^2 / (8 R), v = pi h^2 R,
/// so d = (64 R v / pi)^(1/4).
double crater_diameter(double volume_m3, double radius_m);

/// Everything eq. 5.20 needs for one impact, and its result.
struct ImpactContact {
  double restitution = 1;        // [-] e
  double contact_time_s = 0;     // [s] Delta t
  double crater_volume_m3 = 0;   // [m3]
  double crater_diameter_m = 0;  // [m] d
  double friction = 0;           // [-] f, tangential over normal force
};

/// Yabuki's (1999) impact friction coefficient (thesis eq. 5.20): the
/// tangential force of shearing the contact area and ploughing the crater
/// over the mean normal force of the impact,
///   f = [ (pi d^2 / 8) s + (d^3 / (12 R)) p' ] / [ m (1 + e) vn / Delta t ],
/// with (pi d^2/8) the mean contact area (half the crater's), d^3/(12 R) the
/// cross-section of the crater cap, s the liner's shear strength and p' = H
/// the pressure that removes liner material. e, Delta t, d from the
/// functions above.
ImpactContact impact_contact(double vn, double diameter_m, const LinerMaterial& m);

/// Fraction of the impact's kinetic energy lost (thesis eq. 5.27):
/// alpha = (vn^2 - vn'^2) / (vn^2 + vt^2) with vn' = e vn, the rebound.
double energy_loss_fraction(double vn, double vt, double e);

}  // namespace linerlife
