// Parametric lifters on curved plates: shape, areas and refusals.
#include <catch2/catch.hpp>

#include "fixtures.h"
#include "geometry/errors.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"

using namespace linerlife;
using namespace linerlife::test;
using V = Eigen::Vector2d;

namespace {

/// The analytic cross-section of one Qiu segment, built independently of the
/// discretisation: plate annulus sector + lifter polygon (top corners and the
/// two feet found by bisection on the face-angle definition) + the circular
/// segment between the feet chord and the plate arc.
double analytic_segment_area(double R, int segments, const LifterDesign& d) {
  const double rp = R - d.plate_thickness_m, xt = rp - d.lifter_height_m;
  const double r_mid = rp - 0.5 * d.lifter_height_m;
  const double seg = 2 * M_PI / segments;
  auto foot = [&](V top, double alpha, double s) {
    // bisection on the direction angle psi of the face (from +x) so that the
    // angle to the radial at mid-height equals alpha
    auto angle_error = [&](double psi) {
      const V dir(std::cos(psi), std::sin(psi));
      const double b = top.dot(dir), c = top.squaredNorm() - r_mid * r_mid;
      const V m = top + (-b + std::sqrt(b * b - c)) * dir;
      const V er = m.normalized(), et = s * V(-er.y(), er.x());
      return std::atan2(dir.dot(et), dir.dot(er)) - alpha;
    };
    double lo = -1.5, hi = 1.5;
    if (s < 0) std::swap(lo, hi);
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (angle_error(mid) > 0 ? hi : lo) = mid;
    }
    const double psi = 0.5 * (lo + hi);
    const V dir(std::cos(psi), std::sin(psi));
    const double b = top.dot(dir), c = top.squaredNorm() - rp * rp;
    return V(top + (-b + std::sqrt(b * b - c)) * dir);
  };
  const V tl(xt, 0.5 * d.top_width_m), tt(xt, -0.5 * d.top_width_m);
  const V fl = foot(tl, d.face_angle_leading_deg * M_PI / 180, +1);
  const V ft = foot(tt, d.face_angle_trailing_deg * M_PI / 180, -1);
  const double lifter_poly = std::abs(polygon_area({ft, tt, tl, fl}));
  const double phi = std::atan2(fl.y(), fl.x()) - std::atan2(ft.y(), ft.x());
  const double cap = 0.5 * rp * rp * (phi - std::sin(phi));  // between the feet chord and the plate arc
  return 0.5 * (R * R - rp * rp) * seg + lifter_poly + cap;
}

}  // namespace

TEST_CASE("a parametric segment has the analytic cross-section area", "[geometry][build]") {
  for (double h : {0.01, 0.005}) {
    const LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner(h));
    const double expected = analytic_segment_area(5.18, 64, qiu_liner().design);
    // plate arcs are discretised by chords lying inside the circle: the
    // surface adds the chord sagittas, n c^3 / (12 r) = L h^2 / (12 r^2) for
    // an arc of length L, to the liner
    const double plate_arc = 0.5012 - 0.345, sagittas = plate_arc * h * h / (12 * 5.105 * 5.105);
    CHECK(segment_area(s, 0) == Approx(expected + sagittas).margin(0.2 * sagittas));
    CHECK(metrics(s, Rotation::Ccw, 7800).area_m2 == Approx(64 * (expected + sagittas)).margin(64 * 0.2 * sagittas));
  }
}

TEST_CASE("a plain plate (no lifter) is an annulus", "[geometry][build]") {
  LinerDesign d = qiu_liner();
  d.design.lifter_height_m = 0;
  const LinerSurface s = build_liner_surface(qiu_mill(), d);
  const double R = 5.18, rp = 5.105;
  // the inscribed polygon of n = 3208 chords: n rp^2 sin(2 pi / n) / 2
  const int n = s.n_nodes();
  CHECK(metrics(s, Rotation::Ccw, 7800).area_m2 ==
        Approx(M_PI * R * R - 0.5 * n * rp * rp * std::sin(2 * M_PI / n)).epsilon(1e-12));
  const SegmentMetrics m = segment_metrics(s, 3, Rotation::Ccw, 7800);
  CHECK_FALSE(m.has_lifter);
  CHECK(std::isnan(m.face_angle_leading_deg));
  CHECK(m.min_thickness_m == Approx(0.075).margin(1e-12));
}

TEST_CASE("surface elements are short, oriented and joined round the ring", "[geometry][build]") {
  const LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner(0.01));
  REQUIRE(s.segments == 64);
  REQUIRE(static_cast<int>(s.segment_begin.size()) == 65);
  CHECK(s.segment_begin.back() == s.n_nodes());
  for (int i = 0; i < s.n_elements(); ++i) {
    CHECK(s.length[i] <= 0.01 + 1e-12);
    CHECK(s.length[i] > 0);
    CHECK(s.normal[i].norm() == Approx(1.0));
  }
  // the point just off each element along its normal is inside the free region
  const std::vector<V> ring(s.nodes.begin(), s.nodes.end());
  int outside = 0;
  for (int i = 0; i < s.n_elements(); i += 7)
    if (winding(ring, s.midpoint[i] + 1e-5 * s.normal[i]) != 1) ++outside;
  CHECK(outside == 0);
  // segment edge nodes lie on their radial lines, in the middle of the plate
  for (int k = 0; k < s.segments; ++k) {
    const V& p = s.nodes[s.segment_begin[k]];
    CHECK(std::remainder(std::atan2(p.y(), p.x()) - s.segment_start_rad(k), 2 * M_PI) == Approx(0).margin(1e-12));
    CHECK(p.norm() == Approx(5.105).epsilon(1e-12));
  }
  CHECK_FALSE(polyline_self_intersects(ring));
}

TEST_CASE("a clockwise mill gets the mirror image of the anticlockwise liner", "[geometry][build]") {
  LinerDesign d = qiu_liner();
  d.design.face_angle_leading_deg = 30;
  d.design.face_angle_trailing_deg = 10;
  const LinerSurface ccw = build_liner_surface(qiu_mill(Rotation::Ccw), d);
  const LinerSurface cw = build_liner_surface(qiu_mill(Rotation::Cw), d);
  // segment 0 is centred on the x axis: mirror y -> -y maps one onto the other
  const auto a = segment_chain(ccw, 0), b = segment_chain(cw, 0);
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const V m = b[b.size() - 1 - i];
    CHECK(a[i].x() == Approx(m.x()).margin(1e-12));
    CHECK(a[i].y() == Approx(-m.y()).margin(1e-12));
  }
  // the leading face is the one facing the rotation in both
  for (auto [s, r] : {std::pair{&ccw, Rotation::Ccw}, std::pair{&cw, Rotation::Cw}}) {
    const SegmentMetrics m = segment_metrics(*s, 0, r, 7800);
    CHECK(m.face_angle_leading_deg == Approx(30).margin(3e-3));
    CHECK(m.face_angle_trailing_deg == Approx(10).margin(3e-3));
  }
}

TEST_CASE("a hi-lo pattern alternates the two lifters", "[geometry][build]") {
  LinerDesign d = qiu_liner();
  d.hi_lo = true;
  d.low = d.design;
  d.low.lifter_height_m = 0.15;
  d.low.top_width_m = 0.1;
  const LinerSurface s = build_liner_surface(qiu_mill(), d);
  const LinerMetrics m = metrics(s, Rotation::Ccw, 7800);
  for (int k = 0; k < 64; ++k) {
    CHECK(m.segments[k].design == k % 2);
    CHECK(m.segments[k].lifter_height_m == Approx(k % 2 ? 0.15 : 0.25).margin(1e-9));
    CHECK(m.segments[k].top_width_m == Approx(k % 2 ? 0.10 : 0.15).margin(1e-6));
  }
  d.segments = 63;
  CHECK_THROWS_AS(build_liner_surface(qiu_mill(), d), InputError);
}

TEST_CASE("filleted top corners remove the analytic fillet area", "[geometry][build]") {
  LinerDesign sharp = qiu_liner(0.002);
  LinerDesign round = sharp;
  round.design.corner_radius_m = 0.03;
  const LinerSurface a = build_liner_surface(qiu_mill(), sharp), b = build_liner_surface(qiu_mill(), round);
  // interior angle at each top corner between the top chord and the face
  const auto chain = segment_chain(a, 0);
  double removed = 0;
  int corners = 0;
  const double r = 0.03;
  for (size_t i = 1; i + 1 < chain.size(); ++i) {
    const V u = (chain[i - 1] - chain[i]).normalized(), w = (chain[i + 1] - chain[i]).normalized();
    const double gamma = std::acos(u.dot(w));
    // the two top corners: sharp turns above mid-height of the lifter
    if (gamma < 2.5 && chain[i].norm() < 5.105 - 0.125) {
      ++corners;
      // the fillet r^2 (cot(gamma/2) - (pi - gamma)/2), plus the sagittas of
      // the n chords that sample its arc: r^2 / 2 (beta - n sin(beta / n))
      const double beta = M_PI - gamma;
      const int n = static_cast<int>(std::ceil(beta * r / 0.002));
      removed += r * r * (1 / std::tan(gamma / 2) - beta / 2) + 0.5 * r * r * (beta - n * std::sin(beta / n));
    }
  }
  REQUIRE(corners == 2);
  CHECK(segment_area(a, 0) - segment_area(b, 0) == Approx(removed).epsilon(1e-9));
  CHECK(segment_metrics(b, 0, Rotation::Ccw, 7800).face_angle_leading_deg == Approx(20).margin(2e-3));
}

TEST_CASE("impossible lifters are refused naming the key", "[geometry][build][input]") {
  auto refuse = [](LinerDesign d, const std::string& key, const std::string& words) {
    try {
      build_liner_surface(qiu_mill(), d);
      FAIL("accepted a design that should be refused: " << key);
    } catch (const InputError& e) {
      CHECK(e.key() == key);
      CHECK_THAT(e.what(), Catch::Contains(words));
    }
  };
  LinerDesign d = qiu_liner();
  d.design.lifter_height_m = 1.4;  // R/4 = 1.295
  refuse(d, "liner.lifter_height_m", "quarter of the shell radius");
  d = qiu_liner();
  d.design.top_width_m = 0.6;  // wider than the 0.5 m segment
  refuse(d, "liner.lifter_top_width_m", "narrower than the segment");
  d = qiu_liner();
  d.design.face_angle_leading_deg = 80;
  refuse(d, "liner.face_angle_leading_deg", "< 80");
  d = qiu_liner();
  d.design.face_angle_trailing_deg = -5;
  refuse(d, "liner.face_angle_trailing_deg", "undercut");
  d = qiu_liner();
  d.design.face_angle_leading_deg = 40;
  d.design.face_angle_trailing_deg = 40;  // base 0.15 + 2 * 0.25 tan 40 = 0.57 > 0.5
  refuse(d, "liner.face_angle_leading_deg", "does not fit");
  d = qiu_liner();
  d.design.corner_radius_m = 0.2;
  refuse(d, "liner.corner_radius_m", "does not fit");
  d = qiu_liner(0.05);
  refuse(d, "liner.element_size_m", "too coarse");
  // a top or a lifter under four of the finest elements (1 mm) is the
  // lifter's fault, not the element size's: the message asked for
  // element_size_m <= 0.00075 m, below its floor
  d = qiu_liner(kMinElementSizeM);
  d.design.top_width_m = 0.003;
  refuse(d, "liner.lifter_top_width_m", "lifter_top_width_m = 0.003 m is under four of the finest surface elements");
  refuse(d, "liner.lifter_top_width_m", "allowed lifter_top_width_m >= 0.004 m");
  d.design.top_width_m = 0.004;
  CHECK(build_liner_surface(qiu_mill(), d).n_elements() > 0);
  d = qiu_liner(kMinElementSizeM);
  d.design.lifter_height_m = 0.002;
  refuse(d, "liner.lifter_height_m", "allowed lifter_height_m >= 0.004 m, or lifter_height_m = 0 for no lifter");
  d = qiu_liner();
  d.design.plate_thickness_m = 0;
  refuse(d, "liner.plate_thickness_m", "must be > 0");
}
