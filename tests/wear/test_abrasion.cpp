// Slip models of thesis §5.4.1 (eqs. 5.5-5.10) and Morrell's charge shape.
#include <catch2/catch.hpp>
#include <cmath>

#include "geometry/build_liner_surface.h"
#include "wear/slip_models.h"

using namespace linerlife;

namespace {

OperatingPoint simple_point() {
  OperatingPoint op;
  op.valid = true;
  op.omega_rad_s = 1.0;
  op.radius_m = 5.0;
  op.inner_radius_m = 3.0;
  op.filling = 0.3;
  op.ball_diameter_m = 0.1;
  op.face_angle_deg = 20;
  return op;
}

}  // namespace

TEST_CASE("Morrell slip (thesis eqs. 5.8-5.10) by hand and as 2 pi r (N_m - N_r)", "[wear][slip]") {
  const OperatingPoint op = simple_point();
  // z = 0.7^0.4532 = 0.8507431, z r_i = 2.552229, r = 5 - 0.05 = 4.95
  // V = 1 x 2.552229 x 0.05 / (5 - 2.552229) = 0.05213375 m/s
  CHECK(morrell_slip_speed(op) == Approx(0.05213375).epsilon(1e-6));
  // the same from the layer speed law: N_r = N_m r_m (r - z r_i) / (r (r_m - z r_i))
  const double z = std::pow(0.7, 0.4532), r = 4.95, nm = 1 / (2 * M_PI);
  const double nr = nm * 5 * (r - z * 3) / (r * (5 - z * 3));
  CHECK(morrell_slip_speed(op) == Approx(2 * M_PI * r * (nm - nr)).epsilon(1e-12));
  // vanishes for an infinitely thin contact layer (the liner moves with the mill)
  OperatingPoint thin = op;
  thin.ball_diameter_m = 0;
  CHECK(morrell_slip_speed(thin) == 0.0);
}

TEST_CASE("Radziszewski slip (thesis eqs. 5.5-5.7) by hand and its trends", "[wear][slip]") {
  const OperatingPoint op = simple_point();
  // omega_r = 1 x 5 x (4.95 - 2.552229) / (4.95 x 2.447771) = 0.9894679 rad/s, beta = 70 deg
  // C = 0.9894679 x 0.8507431 x 5 x 4.95^2 / (sin 70 x (4.95 - 2.552229)) = 45.77065
  // mu_k = (1.12 C + 1) / (6 C + 1) = 0.1896175, V = (0.3 - 0.1896175) / (5 x 0.1896175) = 0.1164264 m/s
  CHECK(radziszewski_slip_speed(op, 0.3, 5.0) == Approx(0.1164264).epsilon(1e-6));
  // mu_k lies between 1.12/6 and 1, so no slip when mu_s is below 1.12/6
  CHECK(radziszewski_slip_speed(op, 0.18, 5.0) == 0.0);
  // a steeper (more radial) leading face holds the charge: less slip
  OperatingPoint steep = op, relieved = op;
  steep.face_angle_deg = 0;
  relieved.face_angle_deg = 45;
  CHECK(radziszewski_slip_speed(steep, 0.3, 5.0) < radziszewski_slip_speed(relieved, 0.3, 5.0));
}

TEST_CASE("Morrell's toe, shoulder and inner radius match the reference oracle", "[wear][slip]") {
  // reference/charge-models.md: J = 0.30, phi = 0.75 gives theta_T = 231.77 deg, theta_S = 47.32 deg
  double toe = 0, shoulder = 0;
  toe = morrell_toe_rad(0.30, 0.75);
  shoulder = morrell_shoulder_rad(0.30, 0.75, toe);
  CHECK(toe * 180 / M_PI == Approx(231.77).margin(0.01));
  CHECK(shoulder * 180 / M_PI == Approx(47.32).margin(0.01));
  // the inner radius lies inside the mill and shrinks with the filling
  const double ri30 = morrell_inner_radius(5, 0.2, 0.30, toe, shoulder).inner_radius_m;
  CHECK(ri30 > 0);
  CHECK(ri30 < 5);
  toe = morrell_toe_rad(0.40, 0.75);
  shoulder = morrell_shoulder_rad(0.40, 0.75, toe);
  CHECK(morrell_inner_radius(5, 0.2, 0.40, toe, shoulder).inner_radius_m < ri30);
}

TEST_CASE("the operating point of the Qiu mill", "[wear][slip]") {
  Mill mill;
  mill.diameter_m = 10.36;
  mill.length_m = 5;
  mill.speed_rpm = 10.36;
  LinerDesign d;
  d.segments = 64;
  d.design.plate_thickness_m = 0.075;
  d.design.lifter_height_m = 0.25;
  d.design.top_width_m = 0.15;
  d.design.face_angle_leading_deg = 20;
  d.design.face_angle_trailing_deg = 20;
  d.element_size_m = 0.01;
  d.density_kg_m3 = 7800;
  const LinerSurface s = build_liner_surface(mill, d);
  ChargeSpec c;
  c.filling = 0.24;
  c.ball_diameter_m = 0.1333;
  const OperatingPoint op = operating_point(mill, c, nullptr, s);
  CHECK(op.valid);
  CHECK(op.face_angle_deg == Approx(20).margin(0.05));
  CHECK(op.radius_m < 5.18);
  CHECK(op.radius_m > 4.9);  // the liners take about 0.2 m off the 5.18 m shell radius
  CHECK(op.inner_radius_m > 0.3 * op.radius_m);
  CHECK(op.inner_radius_m < op.radius_m);
  // a few centimetres per second of slip at the liner, as the thesis' layer speeds give
  CHECK(morrell_slip_speed(op) > 0.01);
  CHECK(morrell_slip_speed(op) < 0.5);
  // indicators in the physical frame of a clockwise mill are mirrored back (theta -> 180 - theta)
  Indicators ccw, cw;
  ccw.toe_deg = 230;
  ccw.shoulder_deg = 45;
  cw.toe_deg = 180 - 230 + 360;
  cw.shoulder_deg = 180 - 45;
  Mill cwm = mill;
  cwm.rotation = Rotation::Cw;
  CHECK(operating_point(cwm, c, &cw, s).inner_radius_m ==
        Approx(operating_point(mill, c, &ccw, s).inner_radius_m).epsilon(1e-9));
}
