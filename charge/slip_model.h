// slip_model.h - how fast each layer of the en-masse charge turns (the layer
// speeds, indicator 9 of thesis §4.4): the loss of speed from the shell
// inwards ("slip").
//
// Two laws, chosen by name ([model] slip_model):
//  - "morrell": the linear tangential-speed law of Morrell's C-model,
//      v(r) = v_m (r - z r_i) / (r_m - z r_i),  z = (1 - J)^0.4532,
//    (Morrell 1993, 1996; thesis eq. 4.16 / 5.8 writes it without z; the
//    layer reading in reference/charge-models.md §1 shows this is the law
//    that integrates to Morrell's P_t). Zero at r = z r_i.
//  - "radziszewski": the friction-based law of thesis eqs. 5.5-5.7
//    (Radziszewski 1998), read as a slip speed between neighbouring layers,
//      Delta v_j = C_j = omega_j z delta r_j^2 / (sin(beta) (r_j - z r_i)),
//    so omega_j = omega_{j-1} / (1 + z delta r_j / (sin(beta) (r_j - z r_i))).
//    (docs/models/layer.md §Slip explains the reading.)
#pragma once

#include <string>
#include <vector>

namespace linerlife {

enum class SlipLaw { Morrell, Radziszewski };

/// Parses "morrell" / "radziszewski"; InputError (key "model.slip_model") otherwise.
SlipLaw parse_slip_law(const std::string& name);

struct SlipInput {
  SlipLaw law = SlipLaw::Morrell;
  double mill_omega_rad_s = 0;   // [rad/s] omega, magnitude
  double mill_radius_m = 0;      // [m] r_m, inside the liners
  double inner_radius_m = 0;     // [m] r_i, inner surface of the circulating charge
  double filling = 0;            // [-] J
  double slip_parameter = 0;     // [-] delta (radziszewski)
  double lifter_angle_rad = 0;   // [rad] beta, angle of the lifter face to the shell (radziszewski)
};

/// Angular speed [rad/s] of layers at radii `r` (outermost first, decreasing).
/// Layers at or inside z r_i get 0 (they cannot carry charge up).
std::vector<double> layer_angular_speeds(const SlipInput& in, const std::vector<double>& r);

}  // namespace linerlife
