// recede(): the fast path gives remesh()'s surface, and hands over to it
// where it does not apply.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "geometry/build_liner_surface.h"
#include "geometry/metrics.h"
#include "wear/recede.h"

using namespace linerlife;

namespace {

LinerSurface qiu() {
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
  return build_liner_surface(mill, d);
}

}  // namespace

TEST_CASE("recede: small smooth steps take the fast path and match remesh()", "[wear][recede]") {
  const LinerSurface s = qiu();
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 5; ++trial) {
    // a smooth field on liners 0 and 1 (and the edge nodes they share), up to 1 mm
    std::vector<double> d(s.n_nodes(), 0.0);
    const double a = u(rng), b = 10 + 40 * u(rng), c = 2 * M_PI * u(rng);
    for (int i = s.segment_begin[0]; i <= s.segment_begin[2]; ++i) {
      const double th = std::atan2(s.nodes[i].y(), s.nodes[i].x());
      d[i] = 5e-4 * (1 + a * std::sin(b * th + c));
    }
    bool fast = false;
    const RemeshResult f = recede(s, d, RemeshOptions{0.01}, &fast);
    const RemeshResult r = remesh(s, d, RemeshOptions{0.01});
    REQUIRE(fast);
    CHECK(f.removed_area_m2 == Approx(r.removed_area_m2).epsilon(1e-9));
    REQUIRE(f.surface.n_nodes() == r.surface.n_nodes());
    double worst = 0;
    for (int i = 0; i < r.surface.n_nodes(); ++i)
      worst = std::max(worst, (f.surface.nodes[i] - r.surface.nodes[i]).norm());
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("recede: loops and wear through go to remesh()", "[wear][recede]") {
  const LinerSurface s = qiu();
  // 4 cm at once on the lifter top: its corners move 4 / cos 35 deg = 4.9 cm along their bisectors, past
  // the next nodes of the 1 cm top elements, which turn over; remesh() cuts the loops away
  std::vector<double> d(s.n_nodes(), 0.0);
  for (int i = s.segment_begin[0]; i < s.segment_begin[1]; ++i) {
    const double t = s.shell_radius_m - s.nodes[i].norm();
    if (t > 0.2) d[i] = 0.04;
  }
  bool fast = true;
  const RemeshResult f = recede(s, d, RemeshOptions{0.01}, &fast);
  CHECK_FALSE(fast);
  CHECK(f.removed_area_m2 == Approx(remesh(s, d, RemeshOptions{0.01}).removed_area_m2).epsilon(1e-12));
  // through the plate: remesh() reports where
  std::vector<double> through(s.n_nodes(), 0.0);
  for (int i = s.segment_begin[3]; i <= s.segment_begin[4]; ++i) through[i] = 0.2;
  const RemeshResult w = recede(s, through, RemeshOptions{0.01}, &fast);
  CHECK_FALSE(fast);
  CHECK(w.status == RemeshStatus::WornThrough);
  // no depth: the same surface, by the fast path
  const RemeshResult z = recede(s, std::vector<double>(s.n_nodes(), 0.0), RemeshOptions{0.01}, &fast);
  CHECK(fast);
  CHECK(z.removed_area_m2 == 0.0);
  CHECK(z.surface.nodes == s.nodes);
}
