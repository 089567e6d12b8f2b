// Where a media-sized disc touches the liner, and the exact crossing of a
// flight parabola with that curve.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "charge/liner_ride_table.h"
#include "fixtures.h"
#include "geometry/measured_profile.h"
#include "geometry/mill.h"

using namespace linerlife;
using namespace linerlife::test;

namespace {

LinerSurface plain_ring(double R, double plate, double h) {
  Mill m;
  m.diameter_m = 2 * R;
  m.length_m = 1;
  m.speed_rpm = 10;
  LinerDesign d;
  d.segments = 16;
  d.design.plate_thickness_m = plate;
  d.design.lifter_height_m = 0;
  d.design.top_width_m = 0.1;
  d.element_size_m = h;
  d.density_kg_m3 = 7800;
  return build_liner_surface(m, d);
}

}  // namespace

TEST_CASE("on a plain shell the ride radius is the plate radius less the disc radius", "[charge][ride]") {
  const double R = 2.0, plate = 0.05, a = 0.04, h = 0.01;
  const LinerSurface s = plain_ring(R, plate, h);
  const LinerRideTable t = build_liner_ride_table(s, a);
  const double rp = R - plate, sag = h * h / (8 * rp);  // chords of the polygon sag inside the circle
  for (int b = 0; b < t.n_bins; ++b) {
    CHECK(t.ride_radius_m[b] <= rp - a + 1e-9);
    CHECK(t.ride_radius_m[b] >= rp - a - sag - 1e-9);
  }
}

TEST_CASE("a disc at the ride radius touches the liner and does not overlap it", "[charge][ride]") {
  const Config c = load_default_config();
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const double a = 0.5 * c.charge.ball_diameter_m;
  const LinerRideTable t = build_liner_ride_table(s, a, 4);
  // at the exact edge points the disc touches; anywhere in a bin at the bin's
  // (smaller-edge) radius it does not overlap by more than a small fraction of a
  for (int b = 0; b < t.n_bins; b += 7) {
    const Eigen::Vector2d e = t.point(b);
    CHECK(distance_to_liner(s, e) == Approx(a).epsilon(1e-9));
    for (double f : {0.25, 0.5, 0.75}) {
      const double th = (b + f) * t.bin_rad;
      const Eigen::Vector2d p = t.ride_radius_m[b] * Eigen::Vector2d(std::cos(th), std::sin(th));
      CHECK(distance_to_liner(s, p) >= a * (1 - 1e-2));
    }
  }
}

TEST_CASE("a ball released from a smooth shell lands where the analytic parabola meets the circle",
          "[charge][ride]") {
  // reference/charge-models.md §3: on a smooth shell a ball whose centre turns
  // on radius r leaves at sin(theta0) = omega^2 r / g; its free flight is a
  // parabola that meets the circle of radius r again.
  const double R = 2.0, plate = 0.05, a = 0.04;
  const LinerSurface s = plain_ring(R, plate, 0.002);
  const LinerRideTable t = build_liner_ride_table(s, a, 16);
  const double r = R - plate - a, omega = 0.8 * std::sqrt(kGravity / r);
  const double th0 = std::asin(omega * omega * r / kGravity);
  const Eigen::Vector2d p0 = r * Eigen::Vector2d(std::cos(th0), std::sin(th0));
  const Eigen::Vector2d v0 = omega * r * Eigen::Vector2d(-std::sin(th0), std::cos(th0));
  const Eigen::Vector2d g(0, -kGravity);
  // analytic: |p(t)| = r, by bisection to machine precision on a bracketing interval
  auto f = [&](double tt) { return (p0 + v0 * tt + 0.5 * g * tt * tt).norm() - r; };
  double lo = 0.05, hi = 3.0;
  REQUIRE(f(lo) < 0);
  REQUIRE(f(hi) > 0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  double t_hit;
  int bin;
  // fixed shell (rotation 0), searched over successive short intervals as the model does
  bool found = false;
  for (double ta = 0.01; ta < 3.0 && !found; ta += 0.01)
    found = first_ride_crossing(t, 0.0, p0, v0, g, ta, ta + 0.01, t_hit, bin);
  REQUIRE(found);
  // the ride polyline is made of chords of a circle of radius r - (sagitta), so
  // the crossing is exact up to the sagitta over the normal speed
  const Eigen::Vector2d v_hit = v0 + g * lo;
  const double sag = std::pow(t.bin_rad * r, 2) / (8 * r) + std::pow(0.002, 2) / (8 * r);
  CHECK(t_hit == Approx(lo).margin(2 * sag / (0.5 * v_hit.norm())));
  const Eigen::Vector2d p_hit = p0 + v0 * t_hit + 0.5 * g * t_hit * t_hit;
  CHECK(p_hit.norm() == Approx(r).margin(2 * sag));
}

namespace {

/// Distance [m] from p to element e of s.
double element_distance(const LinerSurface& s, int e, const Eigen::Vector2d& p) {
  const Eigen::Vector2d a = s.nodes[e], ab = s.nodes[s.next(e)] - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

/// Checks every contact ray from ray j0 to j1: the element the table names
/// is the one nearest the disc's centre at the ride radius on that ray
/// (found here by marching out from inside the charge and bisecting on the
/// distance to every element, not with the table's capsule geometry).
void check_contact_rays(const LinerSurface& s, const LinerRideTable& t, double a, int j0, int j1) {
  const int m = t.contact_rays_per_bin;
  int checked = 0, between = 0;
  for (int j = j0; j < j1; ++j) {
    const double psi = j * t.bin_rad / m;
    const Eigen::Vector2d u(std::cos(psi), std::sin(psi));
    auto gap = [&](double r) { return distance_to_liner(s, r * u) - a; };
    double lo = t.min_ride_m - a, hi = lo;
    REQUIRE(gap(lo) > 0);
    while (gap(hi) > 0) {
      lo = hi;
      hi += a / 8;
    }
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (gap(mid) > 0 ? lo : hi) = mid;
    }
    const Eigen::Vector2d c = lo * u;
    const double nearest = distance_to_liner(s, c);
    const int e = t.contact(psi);
    INFO("ray " << j << " (bin " << j / m << ", " << j % m << " of " << m << "): element " << e << " at "
                << element_distance(s, e, c) << " m from the disc's centre, the nearest at " << nearest << " m");
    CHECK(element_distance(s, e, c) <= nearest + 1e-9 * a);
    ++checked;
    if (j % m != 0) ++between;
  }
  CHECK(between >= checked / 2);
}

}  // namespace

TEST_CASE("the contact rays name the element the disc touches, checked against every element", "[charge][ride]") {
  // docs/models/layer.md §Liner loads, "Where a load lands": the table finds a
  // ray's element among those between its bin's two edge elements.
  const Config c = load_default_config();
  const double a = 0.5 * c.charge.ball_diameter_m;
  SECTION("the new lifter at the default 10 mm elements, rays 2 mm apart") {
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    const LinerRideTable t = build_liner_ride_table(s, a, 4, 0.002);
    CHECK(t.contact_spacing_m(s.shell_radius_m) <= 0.002);
    CHECK(t.contact_spacing_m(s.shell_radius_m) > 0.001);
    CHECK(t.contact_rays_per_bin == 8);
    CHECK(load_contact_spacing_m(s) == 0.002);
    const int per_segment = t.n_bins * t.contact_rays_per_bin / s.segments;
    check_contact_rays(s, t, a, 0, per_segment + 3);
  }
  SECTION("a worn lifter (a forecast's at 8,659 h) at 2.5 mm elements, rays 1 mm apart") {
    LinerDesign d = c.liner;
    d.element_size_m = 0.0025;
    const MeasuredProfile p =
        load_profile_csv(std::string(LINERLIFE_SOURCE_DIR) + "/tests/charge/data/qiu_worn_8659h.csv");
    const std::vector<Eigen::Vector2d> seg =
        measured_profile_to_segment(p, c.mill.shell_radius_m(), d.segments, d.element_size_m);
    const LinerSurface s = assemble_ring(c.mill.shell_radius_m(), d.segments, {seg}, std::vector<int>(d.segments, 0));
    // three quarters of the median element (the scan's points are kept as nodes: under 2.5 mm)
    CHECK(load_contact_spacing_m(s) <= 0.75 * d.element_size_m);
    CHECK(load_contact_spacing_m(s) > 0.5 * 0.75 * d.element_size_m);
    const LinerRideTable t = build_liner_ride_table(s, a, 4, 0.001);
    CHECK(t.contact_rays_per_bin == 16);
    const int per_segment = t.n_bins * t.contact_rays_per_bin / s.segments;
    check_contact_rays(s, t, a, per_segment * 5, per_segment * 6 + 3);
  }
}

TEST_CASE("a half-ray index gives the bin and the contact ray that the angle gives", "[charge][ride]") {
  // LinerRideTable::half_rays(), used by LayerSim::sample() where it knows the
  // index without an atan2: for any psi strictly between two half-ray points
  // (and beyond 2 pi, which the masks wrap) the same bin and element as bin()
  // and contact(). A wrong shift (log2 m instead of log2 2 m) or rounding of
  // the ray (iz / 2 instead of (iz + 1) / 2) fails here.
  const Config c = load_default_config();
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  for (const double spacing : {0.0, 0.002, 0.0005}) {
    const LinerRideTable t = build_liner_ride_table(s, 0.5 * c.charge.ball_diameter_m, 4, spacing);
    const LinerRideTable::HalfRays hr = t.half_rays();
    const double step = 0.5 / t.inv_contact_ray;  // [rad] between half-ray points
    const int n_half = 2 * static_cast<int>(t.contact_element.size());
    int checked = 0, mismatched = 0;
    for (int iz = 0; iz < 2 * n_half; ++iz)  // every half-ray interval of two turns
      for (const double f : {1e-6, 0.3, 0.5, 0.7, 1.0 - 1e-6}) {
        const double psi = (iz + f) * step;
        ++checked;
        if (hr.bin(iz) != t.bin(psi) || hr.contact(iz) != t.contact(psi)) ++mismatched;
      }
    INFO("contact spacing " << spacing << " m, " << t.contact_rays_per_bin << " rays per bin");
    CHECK(checked == 10 * n_half);
    CHECK(mismatched == 0);
  }
}
