// liner_material.h - the two materials in contact: the liner being worn and
// the grinding media (balls) hitting and sliding on it. Docs:
// docs/models/wear.md §2.
//
// Defaults: a Cr-Mo steel liner of 350 BHN (reference/wear-facts.md: Cr-Mo
// liners 300-380 BHN, 7800 kg/m3) and forged steel balls. Elastic constants of
// steel: E = 210 GPa, nu = 0.29. Yield and shear strength from the usual
// steel correlations UTS [MPa] ~ 3.45 BHN (ASTM A370 / E140 tables): 350 BHN
// -> UTS ~ 1.2 GPa, yield ~ 0.85 UTS ~ 1.0 GPa, shear strength ~ 0.6 UTS.
#pragma once

namespace linerlife {

/// Converts a Brinell hardness number (kgf/mm2) to a pressure [Pa].
constexpr double kPascalPerBrinell = 9.80665e6;  // [Pa per kgf/mm2]
inline double brinell_to_pa(double bhn) { return bhn * kPascalPerBrinell; }

/// The impacting and sliding media.
struct BallMaterial {
  double density_kg_m3 = 7800;        // [kg/m3] ([charge] ball_density_kg_m3)
  double elastic_modulus_pa = 210e9;  // [Pa]
  double poisson_ratio = 0.29;        // [-]
  double hardness_bhn = 600;          // [BHN] forged/cast media are harder than the liner (55-65 HRC)
};

/// The liner being worn, and the media acting on it.
struct LinerMaterial {
  double density_kg_m3 = 7800;        // [kg/m3] ([liner] density_kg_m3)
  double hardness_bhn = 350;          // [BHN] ([liner] hardness_bhn)
  double elastic_modulus_pa = 210e9;  // [Pa]
  double poisson_ratio = 0.29;        // [-]
  double yield_stress_pa = 1.0e9;     // [Pa] elastic load limit (Bitter 1963's y)
  double shear_strength_pa = 0.7e9;   // [Pa] (Yabuki 1999's s, eq. 5.20)
  BallMaterial ball;

  double hardness_pa() const { return brinell_to_pa(hardness_bhn); }  // [Pa] Brinell
  /// Vickers hardness [Pa]: HV ~ 1.05 HB for steels below 450 HB (ASTM E140).
  double vickers_pa() const { return 1.05 * hardness_pa(); }
  /// Limiting contact pressure [Pa] of a ball-liner impact: the softer of the two
  /// (Thornton 1997's p_y; the mean pressure of a fully plastic indentation is the hardness).
  double limiting_pressure_pa() const {
    return brinell_to_pa(hardness_bhn < ball.hardness_bhn ? hardness_bhn : ball.hardness_bhn);
  }
  /// Effective contact modulus E* [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Hertz; Johnson 1985 eq. 4.22).
  double contact_modulus_pa() const {
    return 1.0 / ((1 - ball.poisson_ratio * ball.poisson_ratio) / ball.elastic_modulus_pa +
                  (1 - poisson_ratio * poisson_ratio) / elastic_modulus_pa);
  }
};

/// Checks every property is physical; throws InputError naming the
/// configuration key (e.g. "liner.hardness_bhn"), the value and the allowed
/// range. Call once at setup (recession_rates does not check).
void validate_liner_material(const LinerMaterial& m);

}  // namespace linerlife
