// contact_law.h - normal, tangential and rolling contact of two discs (or a
// disc and the liner) in the 2D soft-disc DEM: the parameters derived once at
// setup from restitution and collision time (or stiffness), and the analytic
// single-impact results the verification tests compare with.
//
// The discs are cylinders of unit length (docs/models/dem.md §1): masses are
// per metre of mill length [kg/m], forces [N/m], stiffnesses [N/m per m].
//
// For a contact of effective mass m* = m_i m_j / (m_i + m_j) (m* = m_i against
// the liner) and overlap delta > 0:
//   stiffness  k = k_fixed + k_per_mass m*                  (one term is zero)
//   damping    c = gamma sqrt(k m*)
//   linear:    F_n = k delta + c delta_dot                  (Cundall & Strack 1979)
//   hertz:     F_n = k delta^1.5 + c delta^0.25 delta_dot   (Tsuji, Tanaka & Ishida 1992)
// F_n is not clipped at zero, so the measured restitution is exactly the input
// (the damped oscillator's relation); friction and rolling use max(F_n, 0).
// Tangential: spring-dashpot with history, k_t = k_n,inc / 3 and c_t = c / 3
// (k_n,inc = dF_n/d delta), capped by Coulomb mu max(F_n, 0) (Cundall & Strack
// 1979). The ratio 1/3 gives a disc equal normal and tangential oscillation
// periods: its tangential effective mass is m*/3 (I = m r^2 / 2), the 2D
// analogue of 2/7 for spheres (Schaefer, Dippel & Wolf 1996).
// Rolling resistance: constant directional torque mu_r max(F_n, 0) R* against
// the relative rotation (Zhou et al. 1999; Ai et al. 2011, model A).
#pragma once

namespace linerlife {

enum class ContactLaw { Linear, Hertz };

/// One kind of contact, derived by make_contact_params().
struct ContactParams {
  ContactLaw law = ContactLaw::Linear;
  double restitution = 1;         // [-] e
  double friction = 0;            // [-] Coulomb mu
  double rolling_resistance = 0;  // [-] mu_r
  double k_fixed = 0;             // [N/m per m] linear, [N/m^1.5 per m] hertz
  double k_per_mass = 0;          // [1/s2] linear, [1/(s2 m^0.5)] hertz
  double gamma = 0;               // [-] linear: 2 zeta; hertz: alpha(e) of Tsuji et al. (1992)
  double kt_ratio = 1.0 / 3.0;    // [-] k_t / k_n,inc
  double ct_ratio = 1.0 / 3.0;    // [-] c_t / c_n
  // Hertz only: the nondimensional impact x'' = -x^1.5 - alpha x^0.25 x' (x = delta / delta_s,
  // s = t v / delta_s, delta_s = (m* v^2 / k)^0.4), from x = 0, x' = 1.
  double hertz_duration_nd = 0;   // [-] contact duration in units of delta_s / v
  double hertz_max_overlap_nd = 0;  // [-] largest overlap in units of delta_s

  double stiffness(double m_eff) const { return k_fixed + k_per_mass * m_eff; }
};

/// Derives the parameters of one contact kind.
///   collision_time_s > 0: every contact lasts this long (linear), or lasts it
///     at the impact speed reference_speed_m_s (hertz): k proportional to m*.
///   otherwise stiffness > 0 is k for every pair.
/// Throws std::invalid_argument for e outside (0, 1], mu < 0, both or neither
/// of collision time and stiffness (the caller turns that into an InputError).
ContactParams make_contact_params(ContactLaw law, double restitution, double friction, double rolling_resistance,
                                  double collision_time_s, double stiffness, double reference_speed_m_s);

/// zeta = -ln e / sqrt(pi^2 + ln^2 e): damping ratio of the linear
/// spring-dashpot that rebounds with restitution e (e.g. Ting & Corkum 1992;
/// reference/charge-models.md §4).
double linear_damping_ratio(double restitution);

/// alpha(e) for the hertz law: found by bisection on the nondimensional impact
/// (Tsuji et al. 1992 showed e depends on alpha only), integrated by RK4.
/// Also returns the nondimensional duration and largest overlap.
double hertz_damping_alpha(double restitution, double* duration_nd = nullptr, double* max_overlap_nd = nullptr);

/// Contact duration [s] of a normal impact at speed v [m/s] with effective
/// mass m_eff [kg/m]. Linear: pi / omega_d, independent of v. Hertz:
/// duration_nd (m*/k)^0.4 v^-0.2, shorter for faster impacts.
double collision_time(const ContactParams& p, double m_eff, double v);

/// Largest overlap [m] of a normal impact at speed v [m/s] (no friction, no
/// gravity). Linear, analytic: (v / omega_n) exp(-zeta / sqrt(1 - zeta^2)
/// atan2(sqrt(1 - zeta^2), zeta)). Hertz: max_overlap_nd (m* v^2 / k)^0.4, which
/// for e = 1 is (5 m* v^2 / (4 k))^0.4 (Hertz 1882; Johnson 1985 §11.4).
double max_overlap(const ContactParams& p, double m_eff, double v);

/// The compressive impulse of a linear contact, the integral of max(F_n, 0)
/// over the contact, divided by the total normal impulse m* v (1 + e). Above 1
/// because the unclipped dashpot pulls at the end of a damped contact; a
/// Coulomb slide gets mu times the compressive impulse. 1 for e = 1.
double linear_compressive_impulse_share(double restitution);

}  // namespace linerlife
