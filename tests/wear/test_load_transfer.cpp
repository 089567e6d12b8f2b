// Carrying loads between surfaces and onto representative liners (Table B.1
// LinerComputation).
#include <catch2/catch.hpp>
#include <cmath>

#include "geometry/build_liner_surface.h"
#include "geometry/remesh.h"
#include "wear/load_transfer.h"

using namespace linerlife;

namespace {

LinerSurface ring(bool hi_lo = false) {
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
  if (hi_lo) {
    d.hi_lo = true;
    d.low = d.design;
    d.low.lifter_height_m = 0.15;
  }
  return build_liner_surface(mill, d);
}

/// Loads depending on the position within the segment only (every liner alike).
LinerLoads periodic_loads(const LinerSurface& s) {
  LinerLoads l;
  l.reset(s.n_elements(), 5.0);
  l.has_impacts = true;
  for (int i = 0; i < s.n_elements(); ++i) {
    const int q = i - s.segment_begin[s.element_segment[i]];
    l.normal_force_n_per_m[i] = 100.0 + q;
    l.centrifugal_force_n_per_m[i] = 40.0;
    l.gravitational_force_n_per_m[i] = 60.0 + q;
    l.normal_slip_power_w_per_m[i] = 0.1 * (100.0 + q);
    l.slip_speed_m_s[i] = 0.1;
  }
  for (int k = 0; k < s.segments; ++k) {
    ImpactEvent e;
    e.element = s.segment_begin[k] + 3;
    e.normal_speed_m_s = 4;
    e.mass_kg = 1;
    e.rate_per_s = 0.25;
    l.impacts.push_back(e);
  }
  return l;
}

double segment_sum(const LinerSurface& s, const std::vector<double>& v, int k) {
  double a = 0;
  for (int i = s.segment_begin[k]; i < s.segment_begin[k + 1]; ++i) a += v[i];
  return a;
}

}  // namespace

TEST_CASE("carrying loads onto the same surface changes nothing", "[wear][transfer]") {
  const LinerSurface s = ring();
  const LinerLoads l = periodic_loads(s);
  const LinerLoads t = transfer_loads(l, s, s);
  for (int i = 0; i < s.n_elements(); ++i) {
    CHECK(t.normal_force_n_per_m[i] == Approx(l.normal_force_n_per_m[i]).epsilon(1e-12));
    CHECK(t.slip_speed_m_s[i] == Approx(0.1).epsilon(1e-12));
  }
  REQUIRE(t.impacts.size() == l.impacts.size());
  for (size_t j = 0; j < l.impacts.size(); ++j) CHECK(t.impacts[j].element == l.impacts[j].element);
}

TEST_CASE("carrying loads onto a remeshed surface keeps every segment's totals", "[wear][transfer]") {
  const LinerSurface s = ring();
  // wear lifter 0 and its neighbours unevenly so the elements change
  std::vector<double> d(s.n_nodes(), 0.0);
  for (int i = 0; i < s.n_nodes(); ++i) {
    const double th = std::atan2(s.nodes[i].y(), s.nodes[i].x());
    if (std::abs(th) < 0.08) d[i] = 0.01 * (1 + std::sin(40 * th));
  }
  const LinerSurface w = remesh(s, d, RemeshOptions{0.01}).surface;
  const LinerLoads l = periodic_loads(s);
  const LinerLoads t = transfer_loads(l, s, w);
  REQUIRE(t.n_elements == w.n_elements());
  for (int k : {63, 0, 1, 2}) {
    CHECK(segment_sum(w, t.normal_force_n_per_m, k) ==
          Approx(segment_sum(s, l.normal_force_n_per_m, k)).epsilon(1e-12));
    CHECK(segment_sum(w, t.normal_slip_power_w_per_m, k) ==
          Approx(segment_sum(s, l.normal_slip_power_w_per_m, k)).epsilon(1e-12));
  }
  // impacts stay in their segment, near where they hit, with their rates shared out (split, never lost)
  std::vector<double> rate_before(s.segments, 0.0), rate_after(s.segments, 0.0);
  for (const ImpactEvent& e : l.impacts) rate_before[s.element_segment[e.element]] += e.rate_per_s;
  for (const ImpactEvent& e : t.impacts) {
    rate_after[w.element_segment[e.element]] += e.rate_per_s;
    const Eigen::Vector2d hit = s.midpoint[s.segment_begin[w.element_segment[e.element]] + 3];
    CHECK((w.midpoint[e.element] - hit).norm() < 0.03);
  }
  for (int k = 0; k < s.segments; ++k) CHECK(rate_after[k] == Approx(rate_before[k]).epsilon(1e-12));
  CHECK(t.impacts.size() <= 2 * l.impacts.size());
}

TEST_CASE("averaging onto the representative liner of each design", "[wear][transfer]") {
  for (bool hi_lo : {false, true}) {
    const LinerSurface s = ring(hi_lo);
    const LinerLoads l = periodic_loads(s);
    const std::vector<int> rep = representative_segments(s);
    REQUIRE(rep.size() == (hi_lo ? 2u : 1u));
    CHECK(rep[0] == 0);
    if (hi_lo) CHECK(rep[1] == 1);
    const LinerLoads a = average_onto_representatives(l, s);
    // every liner of a design carries the same loads, so the average is the representative's own
    for (int r : rep)
      for (int i = s.segment_begin[r]; i < s.segment_begin[r + 1]; ++i)
        CHECK(a.normal_force_n_per_m[i] == Approx(l.normal_force_n_per_m[i]).epsilon(1e-9));
    // and nothing anywhere else
    for (int i = s.segment_begin[rep.size()]; i < s.n_elements(); ++i) CHECK(a.normal_force_n_per_m[i] == 0.0);
    // impacts: all on the representatives, total rate per representative as one liner's
    double rate = 0;
    for (const ImpactEvent& e : a.impacts) {
      CHECK(s.element_segment[e.element] < static_cast<int>(rep.size()));
      rate += e.rate_per_s;
    }
    CHECK(rate == Approx(0.25 * rep.size()).epsilon(1e-12));
  }
}

TEST_CASE("replicating the representatives rebuilds a fresh ring", "[wear][transfer]") {
  for (bool hi_lo : {false, true}) {
    const LinerSurface s = ring(hi_lo);
    const LinerSurface r = replicate_representatives(s);
    REQUIRE(r.n_nodes() == s.n_nodes());
    double worst = 0;
    for (int i = 0; i < s.n_nodes(); ++i) worst = std::max(worst, (r.nodes[i] - s.nodes[i]).norm());
    CHECK(worst < 1e-9);
  }
}
