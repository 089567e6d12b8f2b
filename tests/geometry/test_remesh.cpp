// Remeshing: what is removed, what is kept, and the states at the ends of a
// liner's life.
#include <random>

#include <catch2/catch.hpp>

#include "fixtures.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"

using namespace linerlife;
using namespace linerlife::test;
using V = Eigen::Vector2d;

namespace {

double total_area(const LinerSurface& s) {
  double a = 0;
  for (int k = 0; k < s.segments; ++k) a += segment_area(s, k);
  return a;
}

/// sum over elements of (mean node depth) x length: what a recession field should remove
double depth_times_length(const LinerSurface& s, const std::vector<double>& d) {
  double a = 0;
  for (int i = 0; i < s.n_elements(); ++i) a += 0.5 * (d[i] + d[s.next(i)]) * s.length[i];
  return a;
}

/// A random smooth field of arc length: a few random Fourier modes, >= 0.
std::vector<double> random_smooth_field(const LinerSurface& s, std::mt19937& rng, double mean, double amp) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> arc(s.n_nodes(), 0.0);
  for (int i = 1; i < s.n_nodes(); ++i) arc[i] = arc[i - 1] + s.length[i - 1];
  const double L = arc.back() + s.length.back();
  std::vector<double> d(s.n_nodes(), mean);
  for (int mode = 1; mode <= 4; ++mode) {
    // wavelengths from a fraction of a segment up: kept long against elements
    const double k = 2 * M_PI * (s.segments * (0.5 + 2 * u(rng))) / L, ph = 2 * M_PI * u(rng), a = amp * u(rng) / 4;
    for (int i = 0; i < s.n_nodes(); ++i) d[i] += a * std::sin(k * arc[i] + ph);
  }
  for (double& x : d) x = std::max(0.0, x);
  return d;
}

bool ring_is_simple(const LinerSurface& s) {
  for (int k = 0; k < s.segments; ++k)
    if (polyline_self_intersects(segment_chain(s, k))) return false;
  return true;
}

}  // namespace

TEST_CASE("uniform recession of a plate lowers it by the depth", "[geometry][remesh]") {
  LinerDesign d = qiu_liner();
  d.design.lifter_height_m = 0;
  const LinerSurface s = build_liner_surface(qiu_mill(), d);
  for (double depth : {0.001, 0.02}) {
    const RemeshResult r = remesh(s, std::vector<double>(s.n_nodes(), depth), RemeshOptions{0.01});
    REQUIRE(r.status == RemeshStatus::Ok);
    double tmin = 1, tmax = 0;
    for (const V& p : r.surface.nodes) {
      tmin = std::min(tmin, 5.18 - p.norm());
      tmax = std::max(tmax, 5.18 - p.norm());
    }
    // chords of a circle: nodes move by depth / cos(half the chord angle)
    CHECK(tmin == Approx(0.075 - depth).margin(1e-7));
    CHECK(tmax == Approx(0.075 - depth).margin(1e-5));  // nodes placed on chords lie off the circle by the sagitta
    CHECK(r.removed_area_m2 == Approx(M_PI * (5.105 + depth) * (5.105 + depth) - M_PI * 5.105 * 5.105).epsilon(1e-5));
  }
}

TEST_CASE("removed area equals the sum of depth x length for random smooth fields", "[geometry][remesh]") {
  std::mt19937 rng(20261122);
  const LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  for (int trial = 0; trial < 3; ++trial) {
    const std::vector<double> d = random_smooth_field(s, rng, 0.002, 0.004);
    const RemeshResult r = remesh(s, d, RemeshOptions{0.01});
    const double expected = depth_times_length(s, d);
    INFO("trial " << trial << ": removed " << r.removed_area_m2 << " m2, sum depth x length " << expected);
    CHECK(r.removed_area_m2 == Approx(expected).epsilon(0.005));
    CHECK(r.removed_area_m2 == Approx(total_area(s) - total_area(r.surface)).epsilon(1e-9));
    CHECK(ring_is_simple(r.surface));
  }
  // and with one depth per element
  std::vector<double> de(s.n_elements());
  for (int i = 0; i < s.n_elements(); ++i) de[i] = 0.003 * (1 + std::sin(s.midpoint[i].x() * 3 + s.midpoint[i].y()));
  double expected = 0;
  for (int i = 0; i < s.n_elements(); ++i) expected += de[i] * s.length[i];
  CHECK(remesh_elements(s, de, RemeshOptions{0.01}).removed_area_m2 == Approx(expected).epsilon(0.005));
}

TEST_CASE("1000 random wear steps keep the profile simple and its area falling", "[geometry][remesh]") {
  // random smooth wear on lifter 0 of the Qiu liner and the plates beside it,
  // 10 to 50 microns a step: about 30 mm in all, well inside the liner
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  const RemeshOptions opt{0.01};
  double area = total_area(s);
  int simple_failures = 0, growth = 0, worn_through = 0;
  for (int step = 0; step < 1000; ++step) {
    std::vector<double> d(s.n_nodes(), 0.0);
    const double a = u(rng), b = 20 + 60 * u(rng), c = 2 * M_PI * u(rng);
    for (int i = 0; i < s.n_nodes(); ++i) {
      const double th = std::atan2(s.nodes[i].y(), s.nodes[i].x());
      if (std::abs(th) < 0.06) d[i] = 3e-5 * (1 + a * std::sin(b * th + c)) + 1e-5 * u(rng);
    }
    const RemeshResult r = remesh(s, d, opt);
    const double next = total_area(r.surface);
    if (!(next < area)) ++growth;
    if (!ring_is_simple(r.surface)) ++simple_failures;
    if (r.status != RemeshStatus::Ok) ++worn_through;
    area = next;
    s = r.surface;
  }
  CHECK(worn_through == 0);
  CHECK(simple_failures == 0);
  CHECK(growth == 0);
  // the element count stays bounded (no accumulation of slivers)
  const LinerSurface fresh = build_liner_surface(qiu_mill(), qiu_liner());
  CHECK(s.segment_size(0) < 1.3 * fresh.segment_size(0));
  for (int i = 0; i < s.n_elements(); ++i) CHECK(s.length[i] <= 1.25 * 0.01 + 1e-12);
  // about 30 mm over the 1 m of profile in the window
  CHECK(segment_area(fresh, 0) - segment_area(s, 0) > 0.02);
}

TEST_CASE("a lifter worn down to the plate leaves a valid plate-only profile", "[geometry][remesh]") {
  LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  const RemeshOptions opt{0.01};
  // wear only what stands above the plate, 20 mm a step, until it is gone
  for (int step = 0; step < 30; ++step) {
    std::vector<double> d(s.n_nodes(), 0.0);
    for (int i = 0; i < s.n_nodes(); ++i) d[i] = std::min(0.02, std::max(0.0, (5.18 - s.nodes[i].norm()) - 0.075));
    const RemeshResult r = remesh(s, d, opt);
    REQUIRE(r.status == RemeshStatus::Ok);
    s = r.surface;
  }
  const LinerMetrics m = metrics(s, Rotation::Ccw, 7800);
  for (const SegmentMetrics& sm : m.segments) {
    CHECK_FALSE(sm.has_lifter);
    CHECK(std::isnan(sm.face_angle_leading_deg));
    CHECK(sm.lifter_height_m < 0.002);
    // the last thin spike's faces recede sideways, so its tip is cut a little
    // below the plate (by d / sin of its half-angle); the plate elsewhere stays
    CHECK(sm.min_thickness_m <= 0.075 + 1e-9);
    CHECK(sm.min_thickness_m > 0.06);
    CHECK(sm.plate_ref_thickness_m == Approx(0.075).margin(1e-9));
  }
  CHECK(ring_is_simple(s));
  CHECK(m.area_m2 == Approx(M_PI * (5.18 * 5.18 - 5.105 * 5.105)).epsilon(5e-3));
}

TEST_CASE("a plate worn to the shell is reported as worn through, with where", "[geometry][remesh]") {
  LinerDesign d = qiu_liner();
  d.design.lifter_height_m = 0;
  const LinerSurface s = build_liner_surface(qiu_mill(), d);
  std::vector<double> depth(s.n_nodes(), 0.01);
  // a deep gouge at 90 deg (segment 16)
  for (int i = 0; i < s.n_nodes(); ++i) {
    const double th = std::atan2(s.nodes[i].y(), s.nodes[i].x());
    if (std::abs(th - M_PI / 2) < 0.02) depth[i] = 0.2;
  }
  RemeshOptions opt{0.01};
  opt.min_thickness_m = 1e-4;
  const RemeshResult r = remesh(s, depth, opt);
  CHECK(r.status == RemeshStatus::WornThrough);
  CHECK(r.worn_through_segment == 16);
  CHECK(std::abs(r.worn_through_angle_rad - M_PI / 2) < 0.021);
  CHECK_THAT(r.message, Catch::Contains("worn through"));
  // the surface stays valid: held min_thickness_m short of the shell
  CHECK(ring_is_simple(r.surface));
  CHECK(metrics(r.surface, Rotation::Ccw, 7800).min_thickness_m == Approx(1e-4).margin(1e-9));
}

TEST_CASE("a lifter top cut loose by face wear is counted as removed", "[geometry][remesh]") {
  LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  // deep wear on both faces of lifter 0 below its top, none on the top itself
  std::vector<double> d(s.n_nodes(), 0.0);
  for (int i = s.segment_begin[0]; i < s.segment_begin[1]; ++i) {
    const double t = 5.18 - s.nodes[i].norm();
    if (t > 0.08 && t < 0.30) d[i] = 0.12;
  }
  const RemeshResult r = remesh(s, d, RemeshOptions{0.01});
  CHECK(r.detached_area_m2 > 0);
  CHECK(ring_is_simple(r.surface));
  const double before = segment_area(s, 0), after = segment_area(r.surface, 0);
  CHECK(before - after == Approx(r.removed_area_m2).epsilon(1e-9));
  // both faces swept past the centreline above the height where the lifter
  // is 2 x 0.12 m wide (about 0.12 m above the plate): only a stub is left
  CHECK(segment_metrics(r.surface, 0, Rotation::Ccw, 7800).lifter_height_m < 0.14);
}

TEST_CASE("zero depth leaves the surface as it is, and bad depths are programming errors", "[geometry][remesh]") {
  const LinerSurface s = build_liner_surface(pilot_mill(), pilot_liner());
  const RemeshResult r = remesh(s, std::vector<double>(s.n_nodes(), 0.0), RemeshOptions{0.002});
  REQUIRE(r.surface.n_nodes() == s.n_nodes());
  for (int i = 0; i < s.n_nodes(); ++i) CHECK((r.surface.nodes[i] - s.nodes[i]).norm() == 0);
  CHECK(r.removed_area_m2 == 0);
  CHECK_THROWS_AS(remesh(s, std::vector<double>(3, 0.0), RemeshOptions{}), std::invalid_argument);
  std::vector<double> neg(s.n_nodes(), 0.0);
  neg[5] = -1e-3;
  CHECK_THROWS_AS(remesh(s, neg, RemeshOptions{}), std::invalid_argument);
}

TEST_CASE("displace_nodes moves every node along its recession direction", "[geometry][remesh]") {
  const LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  const std::vector<double> d(s.n_nodes(), 0.001);
  const LinerSurface t = displace_nodes(s, d);
  // straight elements keep their direction and move by exactly d
  for (int i = 0; i < s.n_elements(); i += 11) {
    const double shift = (t.midpoint[i] - s.midpoint[i]).dot(-s.normal[i]);
    CHECK(shift == Approx(0.001).epsilon(1e-3));
  }
}

TEST_CASE("remeshing one segment and replicating it equals remeshing the ring", "[geometry][remesh]") {
  const LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  // the same depth pattern on every segment (a function of the local position)
  std::vector<double> d(s.n_nodes());
  for (int k = 0; k < s.segments; ++k)
    for (int i = s.segment_begin[k]; i < s.segment_begin[k + 1]; ++i) {
      const int j = i - s.segment_begin[k];
      d[i] = 0.002 + 0.003 * std::sin(0.2 * j) * std::sin(0.2 * j);
    }
  const RemeshResult full = remesh(s, d, RemeshOptions{0.01});
  const SegmentRemesh one = remesh_segment(s, d, 0, RemeshOptions{0.01});
  const LinerSurface ring = assemble_ring(5.18, 64, {one.nodes}, std::vector<int>(64, 0));
  REQUIRE(ring.n_nodes() == full.surface.n_nodes());
  double worst = 0;
  for (int i = 0; i < ring.n_nodes(); ++i) worst = std::max(worst, (ring.nodes[i] - full.surface.nodes[i]).norm());
  CHECK(worst < 1e-9);
  CHECK(64 * one.removed_area_m2 == Approx(full.removed_area_m2).epsilon(1e-9));
}
