// Metrics of parametric designs against their definitions, and convergence of
// the metrics of a worn profile with the element size.
#include <catch2/catch.hpp>

#include "fixtures.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"

using namespace linerlife;
using namespace linerlife::test;
using V = Eigen::Vector2d;

TEST_CASE("metrics of a parametric lifter equal its design", "[geometry][metrics]") {
  struct Case {
    Mill mill;
    LinerDesign liner;
  };
  LinerDesign asym = qiu_liner();
  asym.design.face_angle_leading_deg = 30;
  asym.design.face_angle_trailing_deg = 12;
  asym.design.top_width_m = 0.12;
  for (const Case& c : {Case{qiu_mill(), qiu_liner()}, Case{qiu_mill(Rotation::Cw), asym}, Case{pilot_mill(), pilot_liner()}}) {
    const LinerSurface s = build_liner_surface(c.mill, c.liner);
    const LinerMetrics lm = metrics(s, c.mill.rotation, c.liner.density_kg_m3);
    const LifterDesign& d = c.liner.design;
    for (int k : {0, 1, c.liner.segments - 1}) {
      const SegmentMetrics& m = lm.segments[k];
      CHECK(m.has_lifter);
      CHECK(m.lifter_height_m == Approx(d.lifter_height_m).margin(1e-12));
      CHECK(m.plate_ref_thickness_m == Approx(d.plate_thickness_m).margin(1e-12));
      CHECK(m.min_thickness_m == Approx(d.plate_thickness_m).margin(1e-12));
      // face angles: the fit band's centroid sits within a fraction of a mm of
      // the mid-height point that defines the design angle
      CHECK(m.face_angle_leading_deg == Approx(d.face_angle_leading_deg).margin(3e-3));
      CHECK(m.face_angle_trailing_deg == Approx(d.face_angle_trailing_deg).margin(3e-3));
      CHECK(m.top_width_m == Approx(d.top_width_m).margin(1e-9));
      CHECK(m.mass_kg_per_m == Approx(m.area_m2 * c.liner.density_kg_m3));
      CHECK(std::abs(std::remainder(m.crest_angle_rad - s.segment_centre_rad(k), 2 * M_PI)) < 1e-9);
    }
    // free area + liner area = shell disc
    const double R = c.mill.shell_radius_m();
    CHECK(lm.free_area_m2 + lm.area_m2 == Approx(M_PI * R * R).epsilon(1e-12));
    CHECK(lm.effective_diameter_m == Approx(2 * std::sqrt(lm.free_area_m2 / M_PI)));
  }
}

TEST_CASE("a worn lifter lays its leading face back and loses height", "[geometry][metrics]") {
  // wear concentrated on the leading face: the face recedes more at its top
  const Mill mill = qiu_mill();
  LinerSurface s = build_liner_surface(mill, qiu_liner());
  const SegmentMetrics before = segment_metrics(s, 0, Rotation::Ccw, 7800);
  std::vector<double> depth(s.n_nodes(), 0.0);
  for (int i = s.segment_begin[0]; i < s.segment_begin[1]; ++i) {
    const V& p = s.nodes[i];
    const double th = std::atan2(p.y(), p.x()), t = 5.18 - p.norm();
    if (th > 0) depth[i] = 0.04 * std::max(0.0, (t - 0.075) / 0.25);  // 0 at the plate, 40 mm at the top
  }
  const RemeshResult r = remesh(s, depth, RemeshOptions{0.01});
  const SegmentMetrics after = segment_metrics(r.surface, 0, Rotation::Ccw, 7800);
  CHECK(after.face_angle_leading_deg > before.face_angle_leading_deg + 5);
  CHECK(after.face_angle_trailing_deg == Approx(before.face_angle_trailing_deg).margin(0.5));
  CHECK(after.lifter_height_m < before.lifter_height_m);
  CHECK(after.mass_kg_per_m < before.mass_kg_per_m);
}

TEST_CASE("a top worn into a groove between two horns is not taken for a face", "[geometry][metrics]") {
  // A V-groove 60 mm deep in the 0.14 m flat top of the Qiu lifter (0.25 m
  // high), the horns at the top's corners untouched: deeper than the 20 % of
  // the height above the face-fit band's upper end (50 mm), so a walk from the
  // higher horn down towards the other side meets the groove's wall first (it
  // read 33 deg for the 19.3 deg faces). The faces, the height and the top
  // width are the new lifter's.
  const Mill mill = qiu_mill();
  for (const Rotation rot : {Rotation::Ccw, Rotation::Cw}) {
    const LinerSurface s = build_liner_surface(mill, qiu_liner());
    const SegmentMetrics before = segment_metrics(s, 0, rot, 7800);
    std::vector<double> depth(s.n_nodes(), 0.0);
    double half = 0;  // half the top's arc length at the crest radius
    for (int i = s.segment_begin[0]; i < s.segment_begin[1]; ++i)
      if (5.18 - s.nodes[i].norm() > 0.075 + 0.25 - 2e-3) half = std::max(half, std::abs(std::atan2(s.nodes[i].y(), s.nodes[i].x())));
    REQUIRE(half > 0);
    for (int i = s.segment_begin[0]; i < s.segment_begin[1]; ++i) {
      const V& p = s.nodes[i];
      if (5.18 - p.norm() < 0.075 + 0.25 - 2e-3) continue;  // the top only (a chord: 0.5 mm lower at its ends)
      // slightly off centre, so one horn stays the higher
      depth[i] = 0.06 * std::max(0.0, 1.0 - std::abs(std::atan2(p.y(), p.x()) - 0.1 * half) / (0.9 * half));
    }
    const RemeshResult r = remesh(s, depth, RemeshOptions{0.01});
    const SegmentMetrics after = segment_metrics(r.surface, 0, rot, 7800);
    // the groove is there, deeper than the band's upper end
    double floor_t = 1e9;
    for (int i = r.surface.segment_begin[0]; i < r.surface.segment_begin[1]; ++i) {
      const V& p = r.surface.nodes[i];
      if (std::abs(std::atan2(p.y(), p.x())) < 0.5 * half) floor_t = std::min(floor_t, 5.18 - p.norm());
    }
    REQUIRE(floor_t < 0.075 + 0.8 * 0.25 - 0.005);
    CHECK(after.lifter_height_m == Approx(before.lifter_height_m).margin(1e-3));
    CHECK(after.face_angle_leading_deg == Approx(before.face_angle_leading_deg).margin(0.2));
    CHECK(after.face_angle_trailing_deg == Approx(before.face_angle_trailing_deg).margin(0.2));
    CHECK(after.top_width_m == Approx(before.top_width_m).margin(0.005));
  }
}

namespace {

/// A smooth recession field in space [m]: deeper at the lifter top and on the
/// leading side, the shape the layer model gives.
double wear_field(const V& p) {
  const double th = std::atan2(p.y(), p.x()), t = 5.18 - p.norm();
  return 0.004 * (1.0 + 0.6 * std::tanh(th / 0.02)) * (0.3 + (t - 0.075) / 0.25);
}

SegmentMetrics worn_metrics(double h, int steps) {
  LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner(h));
  RemeshOptions opt;
  opt.element_size_m = h;
  for (int k = 0; k < steps; ++k) {
    // wear on the lifter of segment 0 and the plates beside it
    std::vector<double> depth(s.n_nodes(), 0.0);
    for (int i = 0; i < s.n_nodes(); ++i)
      if (std::abs(std::atan2(s.nodes[i].y(), s.nodes[i].x())) < 1.5 * s.segment_angle_rad())
        depth[i] = wear_field(s.nodes[i]);
    s = remesh(s, depth, opt).surface;
  }
  return segment_metrics(s, 0, Rotation::Ccw, 7800);
}

}  // namespace

TEST_CASE("metrics of a worn profile change by under 1 % when the element size is halved", "[geometry][metrics][convergence]") {
  // 10 steps of the same spatial wear field at the default 10 mm and at 5 mm
  const SegmentMetrics a = worn_metrics(0.01, 10), b = worn_metrics(0.005, 10);
  INFO("height " << a.lifter_height_m << " vs " << b.lifter_height_m << ", lead " << a.face_angle_leading_deg << " vs "
                 << b.face_angle_leading_deg << ", area " << a.area_m2 << " vs " << b.area_m2);
  CHECK(a.lifter_height_m == Approx(b.lifter_height_m).epsilon(0.01));
  CHECK(a.face_angle_leading_deg == Approx(b.face_angle_leading_deg).epsilon(0.01));
  CHECK(a.face_angle_trailing_deg == Approx(b.face_angle_trailing_deg).epsilon(0.01));
  CHECK(a.top_width_m == Approx(b.top_width_m).epsilon(0.01));
  CHECK(a.area_m2 == Approx(b.area_m2).epsilon(0.01));
  // and the wear did something measurable
  CHECK(a.lifter_height_m < 0.25 - 0.02);
}

namespace {

/// Segment 0 of a Qiu-sized ring (R = 5.18 m, 64 segments, 0.075 m plate)
/// whose lifter, H high with an 0.08 m top, falls to the plate over 0.09 m of
/// arc on its trailing side and, on its leading side, has a shelf: the crest
/// drops by `drop`, then the thickness changes linearly by `rise` over `shelf`
/// metres of arc away from the crest before the flank falls steeply to the
/// plate. Thickness is given against the arc length s at the shell radius from
/// the segment's centre.
LinerSurface shelf_ring(double H, double drop, double shelf, double rise) {
  const double R = 5.18, P = 0.075, top = P + H;
  const int S = 64;
  const double half = R * M_PI / S;
  const double s1 = 0.04, s2 = s1 + 0.005, s3 = s2 + shelf, s4 = s3 + 0.01;
  const double t_shelf = top - drop;
  auto thickness = [&](double s) {
    if (s < -s1) return std::max(P, top - (-s1 - s) * (top - P) / 0.09);
    if (s <= s1) return top;
    if (s <= s2) return top + (s - s1) / (s2 - s1) * (t_shelf - top);
    if (s <= s3) return t_shelf + (s - s2) / shelf * rise;
    if (s <= s4) return t_shelf + rise + (s - s3) / (s4 - s3) * (P - t_shelf - rise);
    return P;
  };
  std::vector<V> prof;
  const int n = 2000;
  for (int i = 0; i <= n; ++i) {
    const double s = -half + 2.0 * half * i / n, th = s / R, r = R - thickness(s);
    prof.push_back(r * V(std::cos(th), std::sin(th)));
  }
  return assemble_ring(R, S, {prof}, std::vector<int>(S, 0));
}

}  // namespace

TEST_CASE("a face worn almost flat reads near +90 deg whichever way its fitted line tilts", "[geometry][metrics]") {
  // A lifter worn down to 30 mm whose leading side is a ledge 0.17 m long in
  // the middle of the face-fit band: as the ledge tilts from level to rising
  // away from the crest (by up to 40 % of the height), the fitted line turns
  // through the tangential, from about 89 to 92 deg. The reading must turn
  // with it, continuously: it jumped from +90.0 to -89.9 deg where the line's
  // radial part changed sign, so a face-angle criterion of 60 deg saw a face
  // flat on the shell as undercut (docs/validation/forecast.md).
  const double H = 0.03;
  double prev = 0;
  int beyond_90 = 0;
  for (int i = 0; i <= 40; ++i) {
    const double rise = 0.01 * H * i;
    const LinerSurface s = shelf_ring(H, 0.65 * H, 0.17, rise);
    const SegmentMetrics m = segment_metrics(s, 0, Rotation::Ccw, 7800);
    INFO("ledge rise " << rise << " m: leading face " << m.face_angle_leading_deg << " deg");
    REQUIRE(m.has_lifter);
    CHECK(m.lifter_height_m == Approx(H).margin(1e-9));
    CHECK(m.face_angle_leading_deg > 85.0);
    CHECK(m.face_angle_leading_deg < 95.0);
    if (i > 0) {
      // the line turns a little with each 0.3 mm of rise, always the same way
      CHECK(m.face_angle_leading_deg > prev);
      CHECK(m.face_angle_leading_deg < prev + 0.5);
    }
    prev = m.face_angle_leading_deg;
    beyond_90 += m.face_angle_leading_deg > 90.0;
    // the other flank, 30 mm over 90 mm of arc, is untouched: atan(3) = 71.6 deg
    CHECK(m.face_angle_trailing_deg == Approx(71.6).margin(1.0));
    // a clockwise mill leads with the same face of the mirrored profile
    std::vector<V> mirrored;
    const std::vector<V> own(s.nodes.begin() + s.segment_begin[0], s.nodes.begin() + s.segment_begin[1] + 1);
    for (auto it = own.rbegin(); it != own.rend(); ++it) mirrored.push_back(V(it->x(), -it->y()));
    const LinerSurface sm = assemble_ring(s.shell_radius_m, s.segments, {mirrored}, std::vector<int>(s.segments, 0));
    CHECK(segment_metrics(sm, 0, Rotation::Cw, 7800).face_angle_leading_deg ==
          Approx(m.face_angle_leading_deg).margin(1e-6));
  }
  // the sweep does cross the tangential (else it tests nothing)
  CHECK(beyond_90 > 5);
  CHECK(beyond_90 < 41);
}
