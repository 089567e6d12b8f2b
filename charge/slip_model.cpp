#include "charge/slip_model.h"

#include <cmath>

#include <fmt/format.h>

#include "geometry/errors.h"

namespace linerlife {

SlipLaw parse_slip_law(const std::string& name) {
  if (name == "morrell") return SlipLaw::Morrell;
  if (name == "radziszewski") return SlipLaw::Radziszewski;
  throw InputError("model.slip_model",
                   fmt::format("slip_model = \"{}\": allowed one of \"morrell\", \"radziszewski\"", name));
}

std::vector<double> layer_angular_speeds(const SlipInput& in, const std::vector<double>& r) {
  std::vector<double> w(r.size(), 0.0);
  const double z = std::pow(1.0 - in.filling, 0.4532);  // Morrell (1996)
  const double zri = z * in.inner_radius_m;
  const double rm = in.mill_radius_m;
  if (in.law == SlipLaw::Morrell) {
    // v(r) = v_m (r - z r_i) / (r_m - z r_i) (Morrell 1993; thesis eq. 4.16 with z).
    const double vm = in.mill_omega_rad_s * rm;
    for (size_t j = 0; j < r.size(); ++j)
      w[j] = r[j] > zri ? vm * (r[j] - zri) / ((rm - zri) * r[j]) : 0.0;
  } else {
    // Thesis eqs. 5.5-5.7 (Radziszewski 1998): slip speed of layer j on the
    // one outside it, C_j = omega_j z delta r_j^2 / (sin beta (r_j - z r_i)).
    const double sb = std::max(1e-3, std::sin(in.lifter_angle_rad));
    double outer = in.mill_omega_rad_s;
    for (size_t j = 0; j < r.size(); ++j) {
      if (!(r[j] > zri)) break;
      w[j] = outer / (1.0 + z * in.slip_parameter * r[j] / (sb * (r[j] - zri)));
      outer = w[j];
    }
  }
  return w;
}

}  // namespace linerlife
