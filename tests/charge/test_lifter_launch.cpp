// McIvor's flight angle (thesis eq. 4.5) and the ball leaving a lifter face.
#include <cmath>

#include <catch2/catch.hpp>

#include "charge/lifter_launch.h"
#include "geometry/mill.h"

using namespace linerlife;

TEST_CASE("McIvor's flight angle satisfies the sliding condition and reduces to Davis", "[charge][mcivor]") {
  // reference/charge-models.md §3: sin(theta + alpha - psi) = k cos(alpha - psi)
  for (double k : {0.2, 0.5, 0.8})
    for (double alpha_deg : {0.0, 10.0, 20.0, 35.0})
      for (double mu : {0.0, 0.3, 0.6}) {
        const double alpha = alpha_deg * kPi / 180, psi = std::atan(mu);
        const double th = mcivor_flight_angle(k, alpha, mu);
        INFO("k " << k << " alpha " << alpha_deg << " mu " << mu);
        CHECK(std::sin(th + alpha - psi) == Approx(k * std::cos(alpha - psi)).margin(1e-12));
      }
  // no lifter, no friction: a ball on a smooth shell, sin(theta) = k (Davis 1919)
  CHECK(mcivor_flight_angle(0.6, 0.0, 0.0) == Approx(std::asin(0.6)).margin(1e-14));
  // a relieved face lets go earlier, friction later
  CHECK(mcivor_flight_angle(0.6, 0.3, 0.3) < mcivor_flight_angle(0.6, 0.0, 0.3));
  CHECK(mcivor_flight_angle(0.6, 0.2, 0.5) > mcivor_flight_angle(0.6, 0.2, 0.2));
  // never released: carried round
  CHECK(std::isinf(mcivor_flight_angle(1.2, 0.0, 0.0)));
}

TEST_CASE("without the slide a ball flies from McIvor's angle with the lifter's velocity", "[charge][mcivor]") {
  const double w = 1.1, r0 = 5.0, a = 0.06;
  const LifterLaunch L = lifter_launch(w, r0, 4.8, a, 20 * kPi / 180, 0.5, false);
  REQUIRE(L.released);
  CHECK(L.launch_rad == Approx(L.release_rad).margin(1e-12));
  CHECK(L.launch_radius_m == Approx(r0).margin(1e-12));
  CHECK(L.v_radial_m_s == Approx(0).margin(1e-12));
  CHECK(L.v_tangential_m_s == Approx(w * r0).epsilon(1e-12));
}

TEST_CASE("with the slide a taller lifter throws later and from its crest", "[charge][mcivor]") {
  const double w = 1.1, r_plate = 5.1, a = 0.06, alpha = 20 * kPi / 180;
  const double r0 = r_plate - a;
  const LifterLaunch tall = lifter_launch(w, r0, r_plate - 0.25, a, alpha, 0.5, true);
  const LifterLaunch low = lifter_launch(w, r0, r_plate - 0.12, a, alpha, 0.5, true);
  REQUIRE(tall.released);
  REQUIRE(low.released);
  CHECK(tall.release_rad == Approx(low.release_rad));  // McIvor does not see the height
  CHECK(tall.slide_time_s > low.slide_time_s);
  CHECK(tall.launch_rad > low.launch_rad);
  // it leaves the face at the latest where its contact point passes the crest
  // (earlier if the Coriolis force pushes it off, Powell 1991)
  CHECK(tall.launch_radius_m >= r_plate - 0.25 - a * std::sin(alpha) - 1e-9);
  CHECK(tall.launch_radius_m < r0);
  // and slides inwards along the face: inward radial velocity
  CHECK(tall.v_radial_m_s < 0);
}
