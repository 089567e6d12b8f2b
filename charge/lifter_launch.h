// lifter_launch.h - where a ball held by a lifter is let go, and how it
// leaves the lifter (docs/models/layer.md §Flight angle).
//
// Angles: polar angle in the canonical anticlockwise mill frame, i.e. the
// angle above the horizontal on the rising side (3 o'clock = 0).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace linerlife {

/// McIvor's flight angle (McIvor 1983; thesis eq. 4.5):
///   theta = psi - beta + asin(k cos(beta - psi)),  psi = atan(mu),  k = omega^2 r / g,
/// the angle at which a ball resting on a lifter face inclined at beta from
/// the radial (beta > 0 relieved) starts to slide along it (the sliding
/// condition of reference/charge-models.md §3). With beta = 0 and mu = 0 it
/// is the release of a ball from a smooth shell, sin(theta) = k (Davis 1919).
/// Returns +infinity when the ball is never released (k cos(beta - psi) >= 1).
double mcivor_flight_angle(double k, double face_angle_rad, double friction_coefficient);

/// The layers of balls a lifter of height h above its plate holds in the
/// layer model: those that still touch its face or crest, j d < h, and at
/// least the outer one, max(1, ceil(h / d)) (docs/models/layer.md §3; the
/// 1e-9 keeps h = j d to rounding at j). d: the element edge (one media
/// diameter by default).
inline int lifter_held_layers(double lifter_height_m, double element_m) {
  return std::max(1, static_cast<int>(std::ceil(lifter_height_m / element_m - 1e-9)));
}

/// The state of a ball as it leaves a lifter face.
struct LifterLaunch {
  bool released = false;       // false: carried round (never slides off)
  double release_rad = 0;      // [rad] McIvor angle where sliding starts
  double slide_time_s = 0;     // [s] from release to leaving the face
  double launch_rad = 0;       // [rad] polar angle of the ball centre at launch
  double launch_radius_m = 0;  // [m] radius of the ball centre at launch
  double v_radial_m_s = 0;     // [m/s] fixed-frame velocity, outward component
  double v_tangential_m_s = 0; // [m/s] fixed-frame velocity, anticlockwise component
};

/// Release by McIvor's angle. Without `slide` (the thesis' simulator) the
/// free flight starts there, from the ball's place in the pocket with the
/// lifter's velocity. With `slide`, the ball first slides along the straight
/// face as a point mass in the frame turning with the lifter (Powell 1991:
/// centrifugal, Coriolis and gravity, Coulomb friction mu on the face) until
/// its contact point passes the crest, where the free flight starts.
/// start_radius_m: ball centre at release; crest_radius_m: radius of the
/// lifter crest; a: ball radius. A ball whose centre is already above the
/// crest leaves at once (launch = release).
/// release_rad, when finite, replaces McIvor's angle (a release forced
/// earlier, as by the shoulder clipping of thesis §4.6.1).
/// min_release_rad: the ball is held at least up to this angle by something
/// other than the face (the layer it rests on); McIvor's angle is raised to it
/// (before release_rad applies). A ball never released stays so.
LifterLaunch lifter_launch(double omega_rad_s, double start_radius_m, double crest_radius_m, double ball_radius_m,
                           double face_angle_rad, double friction_coefficient, bool slide,
                           double release_rad = std::numeric_limits<double>::quiet_NaN(),
                           double min_release_rad = -std::numeric_limits<double>::infinity());

}  // namespace linerlife
