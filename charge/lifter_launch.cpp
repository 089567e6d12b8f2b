#include "charge/lifter_launch.h"

#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "geometry/mill.h"

namespace linerlife {

double mcivor_flight_angle(double k, double beta, double mu) {
  const double psi = std::atan(mu);
  const double s = k * std::cos(beta - psi);
  if (s >= 1.0) return std::numeric_limits<double>::infinity();
  return psi - beta + std::asin(s);  // McIvor (1983); thesis eq. 4.5
}

LifterLaunch lifter_launch(double w, double r0, double r_crest, double a, double alpha, double mu, bool slide,
                           double release, double min_release) {
  using V = Eigen::Vector2d;
  LifterLaunch L;
  const double k = w * w * r0 / kGravity;
  double th0 = mcivor_flight_angle(k, alpha, mu);
  if (std::isfinite(th0) && min_release > th0) th0 = min_release;
  if (std::isfinite(release)) th0 = std::min(th0, release);
  if (!std::isfinite(th0)) return L;  // carried round: never released
  L.released = true;
  L.release_rad = th0;
  const V er(std::cos(th0), std::sin(th0)), et(-std::sin(th0), std::cos(th0));
  const V P0 = r0 * er;
  const V d = -er * std::cos(alpha) - et * std::sin(alpha);  // along the face, towards its tip
  const V n = et * std::cos(alpha) - er * std::sin(alpha);   // face normal, into the ball
  const double r_tip = r_crest - a * std::sin(alpha);         // centre radius when the contact point reaches the crest
  auto finish = [&](double T, double s, double sd) {
    const V P = P0 + s * d;
    const V vrel = sd * d;
    const V vrot = vrel + w * V(-P.y(), P.x());
    const double c = std::cos(w * T), sn = std::sin(w * T);
    const V p(c * P.x() - sn * P.y(), sn * P.x() + c * P.y());
    const V v(c * vrot.x() - sn * vrot.y(), sn * vrot.x() + c * vrot.y());
    L.slide_time_s = T;
    L.launch_radius_m = p.norm();
    L.launch_rad = std::atan2(p.y(), p.x());
    const V e_r = p / L.launch_radius_m, e_t(-e_r.y(), e_r.x());
    L.v_radial_m_s = v.dot(e_r);
    L.v_tangential_m_s = v.dot(e_t);
  };
  if (r0 <= r_tip || !slide) {
    finish(0, 0, 0);
    return L;
  }
  // Sliding in the frame turning with the lifter (Powell 1991). State (s, s').
  auto accel = [&](double t, double s, double sd, bool& off) {
    const V P = P0 + s * d;
    const V g(-kGravity * std::sin(w * t), -kGravity * std::cos(w * t));  // gravity seen from the turning frame
    const V cor = -2.0 * w * sd * V(-d.y(), d.x());                    // Coriolis, -2 w z x v_rel
    const V f = w * w * P + g;                                          // centrifugal + gravity
    const double N = -(f + cor).dot(n);                                 // face reaction per unit mass
    off = N < 0;
    double acc = f.dot(d) - mu * std::max(N, 0.0);
    if (sd <= 0 && acc < 0) acc = 0;  // static friction holds it
    return acc;
  };
  const double T_rev = 2.0 * kPi / w;
  const int n_max = 4000;
  const double h = T_rev / n_max;
  double t = 0, s = 0, sd = 0;
  for (int i = 0; i < n_max; ++i) {
    bool off = false;
    // Runge-Kutta-Nystrom (4th order) on s'' = acc(t, s, s')
    const double a1 = accel(t, s, sd, off);
    if (off) break;
    bool o2, o3, o4;
    const double a2 = accel(t + 0.5 * h, s + 0.5 * h * sd + h * h / 8.0 * a1, sd + 0.5 * h * a1, o2);
    const double a3 = accel(t + 0.5 * h, s + 0.5 * h * sd + h * h / 8.0 * a1, sd + 0.5 * h * a2, o3);
    const double a4 = accel(t + h, s + h * sd + 0.5 * h * h * a3, sd + h * a3, o4);
    const double s_new = s + h * sd + h * h / 6.0 * (a1 + a2 + a3);
    const double sd_new = sd + h / 6.0 * (a1 + 2 * a2 + 2 * a3 + a4);
    const double r_new = (P0 + s_new * d).norm();
    if (r_new <= r_tip) {
      // leave within this step: interpolate linearly on the radius
      const double r_old = (P0 + s * d).norm();
      const double f = r_old > r_new ? (r_old - r_tip) / (r_old - r_new) : 1.0;
      finish(t + f * h, s + f * (s_new - s), sd + f * (sd_new - sd));
      return L;
    }
    t += h;
    s = s_new;
    sd = std::max(0.0, sd_new);
  }
  if (t >= T_rev * 0.999) {  // never reached the tip within a revolution: carried round
    L.released = false;
    return L;
  }
  finish(t, s, sd);  // pushed off the face before the tip (reaction vanished)
  return L;
}

}  // namespace linerlife
