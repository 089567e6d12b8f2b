// The shared indicator definitions (docs/models/indicators.md) on a charge of
// known shape: an annular sector filled with media-sized bodies.
#include <cmath>

#include <catch2/catch.hpp>

#include "charge/charge_occupancy.h"
#include "fixtures.h"
#include "geometry/mill.h"

using namespace linerlife;
using namespace linerlife::test;

namespace {

/// Fills the sector th0 < theta < th1 [deg], R - n d < r < R with bodies of
/// area d^2 on the rings' cells, for one sample of 1 s. sense +1 anticlockwise.
ChargeOccupancy sector(double R, double d, int n, double th0, double th1, double sense) {
  ChargeOccupancy o(R, d, sense);
  for (int j = 0; j < n; ++j) {
    const double r = R - (j + 0.5) * d;
    const int nc = static_cast<int>(std::lround(2 * kPi * r / d));
    for (int i = 0; i < nc; ++i) {
      double th = (i + 0.5) * 360.0 / nc;
      double u = std::fmod(th - th0 + 720.0, 360.0);
      if (u > std::fmod(th1 - th0 + 720.0, 360.0)) continue;
      const double t = th * kPi / 180;
      o.add(Eigen::Vector2d(r * std::cos(t), r * std::sin(t)), d * d, 1.0, 1.0);
    }
  }
  o.add_time(1.0);
  return o;
}

}  // namespace

TEST_CASE("toe, shoulder, centre of mass, area and layers of a known sector", "[charge][indicators]") {
  const double R = 5.0, d = 0.1;
  const int n = 8;
  const double toe = 230.0, shoulder = 45.0;  // anticlockwise: from 230 through 270, 360 to 405
  const OccupancyIndicators o = sector(R, d, n, toe, shoulder, +1).evaluate();
  REQUIRE(o.valid);
  const double bin_deg = d / R * 180 / kPi;  // about one body wide
  CHECK(angle_diff(o.toe_deg, toe) < bin_deg);
  CHECK(angle_diff(o.shoulder_deg, shoulder) < bin_deg);
  // analytic centroid of the sector r_i < r < R, span 175 deg
  const double ri = R - n * d, span = (shoulder + 360 - toe) * kPi / 180;
  const double rc = 2.0 / 3.0 * (R * R * R - ri * ri * ri) / (R * R - ri * ri) * std::sin(span / 2) / (span / 2);
  CHECK(angle_diff(o.com_angle_deg, toe + 0.5 * (shoulder + 360 - toe)) < 0.5);
  CHECK(o.com_radius_m == Approx(rc).margin(0.5 * d));
  const double area = 0.5 * span * (R * R - ri * ri);
  CHECK(o.charge_area_m2 == Approx(area).epsilon(0.03));
  CHECK(o.n_layers == n);
}

TEST_CASE("a clockwise mill's toe is where its charge enters, in the same physical frame", "[charge][indicators]") {
  // the mirror image of the sector above: from 135 (shoulder) to 310 (toe)
  const OccupancyIndicators o = sector(5.0, 0.1, 8, 135.0, 310.0, -1).evaluate();
  REQUIRE(o.valid);
  CHECK(angle_diff(o.toe_deg, 310.0) < 1.2);
  CHECK(angle_diff(o.shoulder_deg, 135.0) < 1.2);
}

TEST_CASE("a body moving round a ring adds exactly the time it spent to the bins it crossed", "[charge][indicators]") {
  ChargeOccupancy o(5.0, 0.1, +1);
  // 1.7 s from 0.3 rad to 2.0 rad on ring 3
  const double th0 = 0.3, th1 = 2.0, T = 1.7;
  o.add_arc(3, th0, th1, T / (th1 - th0), 0.01, 2.0);
  o.add_time(T);
  double area_time = 0;
  for (int i = 0; i < o.n_angular(3); ++i) area_time += o.occupancy(3, i) * o.bin_area(3) * T;
  CHECK(area_time == Approx(0.01 * T).epsilon(1e-12));
  // a bin fully crossed gets the crossing time of one bin
  const int i_mid = o.angular_bin(3, 1.0);
  CHECK(o.occupancy(3, i_mid) * o.bin_area(3) * T == Approx(0.01 * T / (th1 - th0) * 2 * kPi / o.n_angular(3)).epsilon(1e-9));
}
