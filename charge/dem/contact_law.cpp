#include "charge/dem/contact_law.h"

#include <cmath>
#include <stdexcept>

namespace linerlife {

namespace {

constexpr double kPiC = 3.14159265358979323846;

struct HertzImpactNd {
  double restitution = 0;  // -x' when x returns to 0
  double duration = 0;     // s at that moment
  double max_overlap = 0;  // largest x
};

/// RK4 integration of x'' = -x^1.5 - alpha x^0.25 x' from x = 0, x' = 1 until
/// x returns to zero (Tsuji et al. 1992, nondimensional form). The crossing is
/// located by linear interpolation within the last step; the force vanishes
/// there, so the velocity is nearly linear in s and the error is O(h^3).
HertzImpactNd hertz_impact_nd(double alpha) {
  auto acc = [alpha](double x, double v) {
    const double xp = x > 0 ? x : 0.0;
    return -xp * std::sqrt(xp) - alpha * std::sqrt(std::sqrt(xp)) * v;
  };
  const double h = 5e-5;
  double x = 0, v = 1, s = 0;
  HertzImpactNd r;
  for (long it = 0; it < 4000000; ++it) {  // s <= 200, far beyond any contact
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn > r.max_overlap) r.max_overlap = xn;
    if (s > 0 && xn <= 0) {
      const double f = x / (x - xn);  // fraction of the step to the crossing
      r.restitution = -(v + f * (vn - v));
      r.duration = s + f * h;
      return r;
    }
    x = xn, v = vn, s += h;
  }
  r.restitution = 0;  // never left: fully damped
  r.duration = s;
  return r;
}

}  // namespace

double linear_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(kPiC * kPiC + l * l);
}

double hertz_damping_alpha(double e, double* duration_nd, double* max_overlap_nd) {
  double alpha = 0;
  HertzImpactNd r = hertz_impact_nd(0.0);
  if (e < 1.0) {
    // e(alpha) decreases monotonically; bracket, then bisect to 1e-9 in alpha.
    double lo = 0, hi = 1;
    while (hertz_impact_nd(hi).restitution > e) {
      lo = hi;
      hi *= 2;
      if (hi > 1e4) throw std::invalid_argument("restitution too small for the hertz law");
    }
    while (hi - lo > 1e-9 * (1 + hi)) {
      const double mid = 0.5 * (lo + hi);
      (hertz_impact_nd(mid).restitution > e ? lo : hi) = mid;
    }
    alpha = 0.5 * (lo + hi);
    r = hertz_impact_nd(alpha);
  }
  if (duration_nd) *duration_nd = r.duration;
  if (max_overlap_nd) *max_overlap_nd = r.max_overlap;
  return alpha;
}

ContactParams make_contact_params(ContactLaw law, double e, double mu, double mu_r, double t_c, double stiffness,
                                  double v_ref) {
  if (!(e > 0 && e <= 1)) throw std::invalid_argument("restitution must lie in (0, 1]");
  if (!(mu >= 0) || !(mu_r >= 0)) throw std::invalid_argument("friction coefficients must be >= 0");
  if ((t_c > 0) == (stiffness > 0)) throw std::invalid_argument("give exactly one of collision time and stiffness");
  ContactParams p;
  p.law = law;
  p.restitution = e;
  p.friction = mu;
  p.rolling_resistance = mu_r;
  if (law == ContactLaw::Linear) {
    const double zeta = linear_damping_ratio(e);
    p.gamma = 2 * zeta;  // c = 2 zeta sqrt(k m*)
    if (t_c > 0) {
      // t_c = pi sqrt(m*/k) / sqrt(1 - zeta^2)  =>  k / m* = (pi^2 + ln^2 e) / t_c^2
      const double l = std::log(e);
      p.k_per_mass = (kPiC * kPiC + l * l) / (t_c * t_c);
    } else {
      p.k_fixed = stiffness;
    }
  } else {
    p.gamma = hertz_damping_alpha(e, &p.hertz_duration_nd, &p.hertz_max_overlap_nd);
    if (t_c > 0) {
      if (!(v_ref > 0)) throw std::invalid_argument("the hertz law needs a reference impact speed");
      // t_c = s_c (m*/k)^0.4 v^-0.2  =>  k / m* = (s_c / (t_c v^0.2))^2.5
      p.k_per_mass = std::pow(p.hertz_duration_nd / (t_c * std::pow(v_ref, 0.2)), 2.5);
    } else {
      p.k_fixed = stiffness;
    }
  }
  return p;
}

double collision_time(const ContactParams& p, double m_eff, double v) {
  const double k = p.stiffness(m_eff);
  if (p.law == ContactLaw::Linear) {
    const double zeta = 0.5 * p.gamma;
    return kPiC * std::sqrt(m_eff / k) / std::sqrt(1 - zeta * zeta);
  }
  return p.hertz_duration_nd * std::pow(m_eff / k, 0.4) * std::pow(v, -0.2);
}

double max_overlap(const ContactParams& p, double m_eff, double v) {
  const double k = p.stiffness(m_eff);
  if (p.law == ContactLaw::Linear) {
    const double zeta = 0.5 * p.gamma;
    const double wn = std::sqrt(k / m_eff);
    const double sq = std::sqrt(1 - zeta * zeta);
    return v / wn * std::exp(-zeta / sq * std::atan2(sq, zeta));
  }
  return p.hertz_max_overlap_nd * std::pow(m_eff * v * v / k, 0.4);
}

double linear_compressive_impulse_share(double e) {
  // x(t) = (v/wd) exp(-a t) sin(wd t), omega_n = 1, a = zeta. The force
  // -m x'' vanishes where x'' = 0: tan(wd t*) = -2 a wd / (wd^2 - a^2), with
  // wd t* in (pi/2, pi]. The compressive impulse is m (v - x'(t*)).
  const double zeta = linear_damping_ratio(e);
  const double wd = std::sqrt(1 - zeta * zeta), a = zeta;
  const double ts = (kPiC - std::atan2(2 * a * wd, wd * wd - a * a)) / wd;
  const double xdot = std::exp(-a * ts) * (std::cos(wd * ts) - a / wd * std::sin(wd * ts));  // < 0
  return (1 - xdot) / (1 + e);
}

}  // namespace linerlife
