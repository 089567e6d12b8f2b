#include "wear/slip_models.h"

#include <algorithm>
#include <cmath>

#include "geometry/metrics.h"

namespace linerlife {

OperatingPoint operating_point(const Mill& mill, const ChargeSpec& charge, const Indicators* ind,
                               const LinerSurface& surface) {
  OperatingPoint op;
  const LinerMetrics lm = metrics(surface, mill.rotation, 1.0);
  op.radius_m = 0.5 * lm.effective_diameter_m;
  op.omega_rad_s = mill.omega_rad_s();
  op.filling = charge.filling;
  op.ball_diameter_m = charge.ball_diameter_m;
  double sum = 0;
  int n = 0;
  for (const auto& s : lm.segments)
    if (s.has_lifter && std::isfinite(s.face_angle_leading_deg)) {
      sum += s.face_angle_leading_deg;
      ++n;
    }
  op.face_angle_deg = n ? sum / n : 0.0;
  double toe = 0, shoulder = 0;
  const bool given = ind && std::isfinite(ind->toe_deg) && std::isfinite(ind->shoulder_deg) &&
                     !(ind->toe_deg == 0 && ind->shoulder_deg == 0);
  if (given) {
    // physical frame -> Morrell's anticlockwise frame (DESIGN.md §3: a clockwise mill is the mirror image)
    auto to_morrell = [&](double deg) {
      double a = (mill.rotation == Rotation::Ccw ? deg : 180.0 - deg) * kPi / 180.0;
      return a;
    };
    toe = std::fmod(to_morrell(ind->toe_deg) + 4 * kPi, 2 * kPi);            // about 4 rad
    shoulder = std::fmod(to_morrell(ind->shoulder_deg) + 4 * kPi, 2 * kPi);  // about 0.8 rad
    if (shoulder > kPi) shoulder -= 2 * kPi;
  } else {
    // Morrell (1996) via the charge module, with the phi_c guard (reference/charge-models.md §1)
    const double phi = mill.speed_rpm / critical_speed_rpm(lm.effective_diameter_m);
    if (phi > 0.35 * (3.364 - charge.filling)) {
      toe = shoulder = 0.5 * kPi;
    } else {
      toe = morrell_toe_rad(charge.filling, phi);
      shoulder = morrell_shoulder_rad(charge.filling, phi, toe);
    }
  }
  op.inner_radius_m = morrell_inner_radius(op.radius_m, mill.speed_rpm / 60.0, charge.filling, toe, shoulder).inner_radius_m;
  op.valid = true;
  return op;
}

namespace {

/// z = (1 - J)^0.4532 (Morrell 1996) and the contact layer radius r = r_m - d_b/2.
void layer(const OperatingPoint& op, double& z, double& r) {
  z = std::pow(1.0 - op.filling, 0.4532);
  r = op.radius_m - 0.5 * op.ball_diameter_m;
}

}  // namespace

double morrell_slip_speed(const OperatingPoint& op) {
  double z, r;
  layer(op, z, r);
  const double zri = z * op.inner_radius_m;
  // thesis eqs. 5.8-5.10: V = 2 pi r (N_m - N_r) = omega z r_i (r_m - r) / (r_m - z r_i)
  return std::max(0.0, op.omega_rad_s * zri * (op.radius_m - r) / (op.radius_m - zri));
}

double radziszewski_slip_speed(const OperatingPoint& op, double mu_s, double delta) {
  double z, r;
  layer(op, z, r);
  const double zri = z * op.inner_radius_m;
  // eq. 5.8: angular speed of the contact layer
  const double omega_r = op.omega_rad_s * op.radius_m * (r - zri) / (r * (op.radius_m - zri));
  const double beta = (90.0 - std::clamp(op.face_angle_deg, 0.0, 85.0)) * kPi / 180.0;  // leading face to the shell
  const double c = omega_r * z * delta * r * r / (std::sin(beta) * (r - zri));          // eq. 5.7 [-]
  const double mu_k = (1.12 * c + 1.0) / (6.0 * c + 1.0);                               // eq. 5.6
  return std::max(0.0, (mu_s - mu_k) / (delta * mu_k));                                 // eq. 5.5 [m/s]
}

}  // namespace linerlife
