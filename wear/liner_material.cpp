#include "wear/liner_material.h"

#include <fmt/format.h>

#include <cmath>

#include "geometry/errors.h"

namespace linerlife {
namespace {

/// lo < v <= hi (or lo <= v when lo_closed), else InputError naming the key.
/// lo < v <= hi (lo <= v when lo_closed), all in the unit of the key; else
/// InputError naming the key, the value and the range.
void check(const char* key, double v, double lo, double hi, bool lo_closed, const char* unit) {
  const bool ok = std::isfinite(v) && (lo_closed ? v >= lo : v > lo) && v <= hi;
  if (!ok)
    throw InputError(key, fmt::format("{} = {}: out of range; allowed {} {} value <= {}{}", key, v, lo,
                                      lo_closed ? "<=" : "<", hi, unit));
}

}  // namespace

void validate_liner_material(const LinerMaterial& m) {
  check("liner.density_kg_m3", m.density_kg_m3, 0, 1e5, false, " kg/m3");
  check("liner.hardness_bhn", m.hardness_bhn, 0, 1000, false, " BHN");
  check("wear.liner_elastic_modulus_gpa", m.elastic_modulus_pa / 1e9, 0, 2000, false, " GPa");
  check("wear.liner_poisson_ratio", m.poisson_ratio, 0, 0.5, true, "");
  check("wear.liner_yield_stress_mpa", m.yield_stress_pa / 1e6, 0, 20000, false, " MPa");
  check("wear.liner_shear_strength_mpa", m.shear_strength_pa / 1e6, 0, 20000, false, " MPa");
  check("charge.ball_density_kg_m3", m.ball.density_kg_m3, 0, 1e5, false, " kg/m3");
  check("wear.ball_elastic_modulus_gpa", m.ball.elastic_modulus_pa / 1e9, 0, 2000, false, " GPa");
  check("wear.ball_poisson_ratio", m.ball.poisson_ratio, 0, 0.5, true, "");
  check("wear.ball_hardness_bhn", m.ball.hardness_bhn, 0, 1000, false, " BHN");
}

}  // namespace linerlife
