// slip_models.h - the surface slippage velocity of the charge on the liner
// for the Radziszewski abrasion law (thesis §5.4.1, Table B.1 SlippageModel):
// taken from the charge model, or from one of the thesis' two closed forms.
//
// Symbols (Morrell 1996; reference/charge-models.md §1): r_m radius inside the
// liners [m], r_i radius of the inner surface of the charge [m], J filling
// [-], z = (1 - J)^0.4532, N_m mill speed [rev/s]. The layer in contact with
// the liner has its centre at r = r_m - d_b / 2 (d_b the ball diameter).
#pragma once

#include "charge/charge_spec.h"
#include "charge/morrell_c_model.h"
#include "charge/indicators.h"
#include "geometry/liner_surface.h"
#include "geometry/mill.h"

namespace linerlife {

enum class SlipModel {
  ChargeModel,   // <N v_slip> of LinerLoads: the charge model's own sliding speeds
  Morrell,       // thesis eqs. 5.8-5.10 (Morrell 1992; Shi 1999)
  Radziszewski,  // thesis eqs. 5.5-5.7 (Radziszewski 1998, after "Lowrinson" 1974)
};

/// What the closed-form slip models need about the mill and its charge.
struct OperatingPoint {
  bool valid = false;
  double omega_rad_s = 0;      // [rad/s] mill speed
  double radius_m = 0;         // [m] r_m, inside the (possibly worn) liners
  double inner_radius_m = 0;   // [m] r_i, inner surface of the charge (Morrell 1996)
  double filling = 0;          // [-] J
  double ball_diameter_m = 0;  // [m] d_b
  double face_angle_deg = 0;   // [deg] leading face angle of the lifter from the radial (0 without lifter)
};


/// The operating point of `mill` with `charge` on the liner `surface`. Toe and
/// shoulder come from `indicators` when given and finite, else from Morrell's
/// formulas; the face angle is the mean leading face angle of the segments.
OperatingPoint operating_point(const Mill& mill, const ChargeSpec& charge, const Indicators* indicators,
                               const LinerSurface& surface);

/// Thesis eqs. 5.8-5.10 (Morrell 1992): layer speed N_r = N_m r_m (r - z r_i) / (r (r_m - z r_i)),
/// slip V = 2 pi r (N_m - N_r) at the contact layer, which is
///   V = omega z r_i (r_m - r) / (r_m - z r_i)   [m/s].
double morrell_slip_speed(const OperatingPoint& op);

/// Thesis eqs. 5.5-5.7 (Radziszewski 1998), read as a velocity-weakening
/// friction law mu_k = mu_s / (1 + delta V) solved for V:
///   V = (mu_s - mu_k) / (delta mu_k)                              (5.5)
///   mu_k = (1.12 C + 1) / (6 C + 1)                               (5.6)
///   C = omega_r z delta r^2 / (sin(beta) (r - z r_i))             (5.7)
/// omega_r the contact layer's angular speed (eq. 5.8), beta the angle of the
/// lifter's leading face to the shell (90 deg - face angle), delta [s/m] the
/// slippage parameter, mu_s the static friction. V >= 0 [m/s]. The OCR'd
/// thesis text is garbled; this dimensionally consistent reading is
/// documented in docs/models/wear.md §3.2.
double radziszewski_slip_speed(const OperatingPoint& op, double static_friction, double delta_s_per_m);

}  // namespace linerlife
