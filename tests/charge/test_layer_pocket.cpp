// The layer model's pocket loads (ModelSpec::pocket_loads, docs/models/layer.md
// §7, "Pocket loads"): the lifter faces that hold the pockets take the
// tangential weight of the charge over them. Checked against force balance on
// a lifter of known face angle, on a plain shell (no face: nothing moves), and
// against the run without them (the charge itself must not change).
#include <algorithm>
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "bench/worn_profiles.h"
#include "fixtures.h"
#include "geometry/measured_profile.h"

using namespace linerlife;
using namespace linerlife::test;

namespace {

/// Sums of the time-averaged loads over the plate (normal within 2 deg of the
/// radial, at the shell's largest radius: not the lifter tops), over the
/// faces (normal turned more than 30 deg towards the tangent), split into
/// the leading faces (facing the rotation) and the trailing ones, per metre
/// of mill.
struct Parts {
  double plate_n = 0, plate_s = 0, face_n = 0, lead_n = 0, trail_n = 0, all_n = 0;
};

Parts parts(const LinerSurface& s, const LinerLoads& L, Rotation rot) {
  double r_max = 0;
  for (int e = 0; e < s.n_elements(); ++e) r_max = std::max(r_max, s.midpoint[e].norm());
  const double turn = rot == Rotation::Ccw ? 1.0 : -1.0;
  Parts p;
  for (int e = 0; e < s.n_elements(); ++e) {
    const Eigen::Vector2d m = s.midpoint[e];
    const Eigen::Vector2d er = m.normalized(), et = turn * Eigen::Vector2d(-er.y(), er.x());
    const double radial = -s.normal[e].dot(er);  // the normal points into the mill
    p.all_n += L.normal_force_n_per_m[e];
    if (radial > std::cos(2.0 * kPi / 180.0) && m.norm() > r_max - 0.002) {
      p.plate_n += L.normal_force_n_per_m[e];
      p.plate_s += L.shear_force_n_per_m[e];
    } else if (radial < std::cos(30.0 * kPi / 180.0)) {
      p.face_n += L.normal_force_n_per_m[e];
      (s.normal[e].dot(et) > 0 ? p.lead_n : p.trail_n) += L.normal_force_n_per_m[e];
    }
  }
  return p;
}

}  // namespace

TEST_CASE("pocket loads put the charge's tangential weight on the lifter faces, not the plate", "[charge][layer]") {
  // The bundled ball mill: straight 30 deg faces, sharp corners, 0.12 m
  // lifters (2.4 media diameters: up to three layers in a pocket).
  Config c = mill_config("ball_mill_5m.toml");
  REQUIRE(c.liner.design.face_angle_leading_deg == 30.0);
  REQUIRE(c.liner.design.face_angle_trailing_deg == 30.0);
  REQUIRE(c.liner.design.corner_radius_m == 0.0);
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2, 1);
  REQUIRE(!in.model.pocket_loads);  // off by default: the thesis' loads
  const ChargeResult off = run_model("layer", in);
  in.model.pocket_loads = true;
  const ChargeResult on = run_model("layer", in);
  // the loads are an output: the charge, its power and its flights are the same
  CHECK(on.indicators.net_power_kw == off.indicators.net_power_kw);
  CHECK(on.indicators.toe_deg == off.indicators.toe_deg);
  CHECK(on.indicators.shoulder_deg == off.indicators.shoulder_deg);
  CHECK(on.loads.impacts.size() == off.loads.impacts.size());
  const Parts a = parts(s, off.loads, c.mill.rotation), b = parts(s, on.loads, c.mill.rotation);
  INFO("plate N " << a.plate_n << " -> " << b.plate_n << ", plate S " << a.plate_s << " -> " << b.plate_s
                  << ", leading faces N " << a.lead_n << " -> " << b.lead_n << ", trailing " << a.trail_n << " -> "
                  << b.trail_n << " N/m");
  REQUIRE(a.plate_s > 0);
  // the plate keeps its radial load (its normal is radial: the tangential
  // force never pressed on it) and loses shear: the pocket layers' own
  // tangential weight and the layers' above up to mu N (0.43 of it is left
  // when written: what the layers above cannot pass on)
  CHECK(b.plate_n == Approx(a.plate_n).epsilon(1e-3));
  CHECK(b.plate_s < 0.7 * a.plate_s);
  // force balance: a tangential force T taken off the plate presses on a 30
  // deg face with T cos 30 deg; the faces also take the pushes of the columns
  // standing on them, so at least that much arrives; of what the liner gains
  // in normal load the faces take nearly all, the crest corners touched by a
  // disc above a face the rest (93 % on the faces when written)
  const double taken = a.plate_s - b.plate_s;
  CHECK(b.face_n - a.face_n >= 0.99 * std::cos(30.0 * kPi / 180.0) * taken);
  CHECK(b.face_n - a.face_n > 0.9 * (b.all_n - a.all_n));
  // which face: the bed lies on the rising side, where the leading face of
  // the lifter behind pushes the pocket; the trailing faces hold the pockets
  // of the falling side, the toe's few (1.45 times as much to the leading
  // faces since the bed's support rule of 2026-12-06 brought the bed down
  // the rising side to the DEM's, 2.8 times before; a push sent the wrong way
  // round gives the reverse)
  CHECK(b.lead_n - a.lead_n > 1.2 * (b.trail_n - a.trail_n));
  CHECK(b.trail_n > a.trail_n);
}

TEST_CASE("pocket loads reach the corner of a bar lifter lower than a ball", "[charge][layer]") {
  // Pilot test 6: 25 mm square bars (5 deg faces, sharp corners) and 50 mm
  // balls, a clockwise mill. The ball in a pocket touches the bar's crest
  // corner, where the ride table names the crest's element or the face's:
  // the push is judged by the contact's direction, so both sides of the
  // mill load the bars (the rising side, which holds most of the bed, takes
  // 76 % of the plate's shear off when written; judged by the element's
  // normal, the rising side found no face at all).
  const Config c = mill_config("pilot_test_06.toml");
  REQUIRE(c.mill.rotation == Rotation::Cw);
  REQUIRE(c.liner.design.lifter_height_m < c.charge.ball_diameter_m);
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 2, 1);
  const ChargeResult off = run_model("layer", in);
  in.model.pocket_loads = true;
  const ChargeResult on = run_model("layer", in);
  const Parts a = parts(s, off.loads, c.mill.rotation), b = parts(s, on.loads, c.mill.rotation);
  INFO("plate S " << a.plate_s << " -> " << b.plate_s << ", all N " << a.all_n << " -> " << b.all_n << " N/m");
  REQUIRE(a.plate_s > 0);
  CHECK(b.plate_s < 0.5 * a.plate_s);
  CHECK(b.all_n > a.all_n);
}

TEST_CASE("pocket loads change nothing on a plain shell", "[charge][layer]") {
  Config c = mill_config("ball_mill_5m.toml");
  c.liner.design.lifter_height_m = 0.0;  // no lifter, no face, no pocket
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in = charge_input(c, s, 1, 1);
  const ChargeResult off = run_model("layer", in);
  in.model.pocket_loads = true;
  const ChargeResult on = run_model("layer", in);
  REQUIRE(off.loads.normal_force_n_per_m.size() == on.loads.normal_force_n_per_m.size());
  double total = 0;
  for (size_t e = 0; e < off.loads.normal_force_n_per_m.size(); ++e) {
    total += off.loads.normal_force_n_per_m[e];
    CHECK(on.loads.normal_force_n_per_m[e] == off.loads.normal_force_n_per_m[e]);
    CHECK(on.loads.shear_force_n_per_m[e] == off.loads.shear_force_n_per_m[e]);
  }
  CHECK(total > 0);
}

TEST_CASE("pocket loads find the faces of a worn lifter", "[charge][layer][worn]") {
  // The Qiu mill's lifter after 8,659 h of the forecast (a measured-profile
  // CSV: curved faces, laid back to about 55 deg, remeshed): the pockets come
  // from the ride table of the profile itself.
  const Config c = load_default_config();
  const MeasuredProfile p = load_profile_csv(std::string(LINERLIFE_SOURCE_DIR) + "/tests/charge/data/qiu_worn_8659h.csv");
  const LinerSurface s = bench::ring_of(c.mill.shell_radius_m(), c.liner.segments,
                                        measured_profile_to_segment(p, c.mill.shell_radius_m(), c.liner.segments,
                                                                    c.liner.element_size_m));
  ChargeInput in = charge_input(c, s, 2, 1);
  const ChargeResult off = run_model("layer", in);
  in.model.pocket_loads = true;
  const ChargeResult on = run_model("layer", in);
  CHECK(on.indicators.net_power_kw == off.indicators.net_power_kw);
  const Parts a = parts(s, off.loads, c.mill.rotation), b = parts(s, on.loads, c.mill.rotation);
  INFO("faces N " << a.face_n << " -> " << b.face_n << ", all N " << a.all_n << " -> " << b.all_n << " N/m");
  // the worn faces take the push: their normal load rises (by 20 % when
  // written; their own columns' load is most of it), and most of what is
  // added lands where the face stands less than 60 deg from the radial (63 %
  // when written; the rest where the worn face lies flatter, and on the
  // crest corners)
  CHECK(b.face_n > 1.1 * a.face_n);
  CHECK(b.face_n - a.face_n > 0.5 * (b.all_n - a.all_n));
}

namespace {

/// What the pocket loads add on the faces of a parametric surface: the
/// normal load [N/m], its mean height above the plate [m] (weighted by the
/// added load), and the share of the face places (an element's place in its
/// segment) between the lowest and the highest loaded one that take some of
/// it. Every segment is meshed alike and the ride table has a whole number of
/// bins per segment, so the segments' pushes are summed by place: the places
/// that take none are the comb a load rule leaves.
struct FacePush {
  double added_n = 0, mean_height_m = 0, covered = 0;
};

FacePush face_push(const Config& c, const LinerSurface& s, double contact_spacing_m) {
  ChargeInput in = charge_input(c, s, 6, 1);
  in.model.load_contact_spacing_m = contact_spacing_m;
  const ChargeResult off = run_model("layer", in);
  in.model.pocket_loads = true;
  const ChargeResult on = run_model("layer", in);
  const double plate_r = s.shell_radius_m - c.liner.design.plate_thickness_m;
  const int per_seg = s.segment_size(0);
  std::vector<double> by_place(static_cast<size_t>(per_seg), 0.0);
  std::vector<char> is_face(static_cast<size_t>(per_seg), 0);
  FacePush f;
  double h = 0;
  for (int e = 0; e < s.n_elements(); ++e) {
    const Eigen::Vector2d m = s.midpoint[e];
    if (-s.normal[e].dot(m.normalized()) >= std::cos(30.0 * kPi / 180.0)) continue;  // not a face
    const double dn = on.loads.normal_force_n_per_m[e] - off.loads.normal_force_n_per_m[e];
    f.added_n += dn;
    h += dn * (plate_r - m.norm());
    const int k = e - s.segment_begin[s.element_segment[e]];
    is_face[k] = 1;
    by_place[k] += dn;
  }
  f.mean_height_m = h / f.added_n;
  int first = -1, last = -1;
  for (int k = 0; k < per_seg; ++k)
    if (is_face[k] && by_place[k] > 0) last = k, first = first < 0 ? k : first;
  int in_range = 0, loaded = 0;
  for (int k = std::max(first, 0); k <= last; ++k)
    if (is_face[k]) ++in_range, loaded += by_place[k] > 0;
  f.covered = in_range > 0 ? static_cast<double>(loaded) / in_range : 0.0;
  return f;
}

}  // namespace

TEST_CASE("pocket loads land where the disc touches, whatever the contact rays and the element size",
          "[charge][layer][loads]") {
  // docs/models/layer.md §7, "Pocket loads". A bin's push is spread over
  // its contact rays, each loading the element a disc on it touches, as
  // every other load lands since 2026-12-05. Until then each bin loaded one
  // element, its smaller edge's, and on the Qiu mill's 20 deg faces most
  // elements took no push (this test's measures on that code: 0.24 of the
  // face places at 10 mm elements and 0.06 at 2.5 mm took some; with one ray
  // at each bin's centre 0.28 and 0.07, and the push at 2.5 mm elements
  // 3.7 % short).
  const Config c = load_default_config();
  const LinerSurface s10 = build_liner_surface(c.mill, c.liner);
  const LinerSurface s25 = surface_with_elements(c, 0.0025);
  const FacePush def = face_push(c, s10, 0), ref = face_push(c, s10, 0.00025), mesh = face_push(c, s25, 0);
  INFO("added on the faces: " << def.added_n << ", " << ref.added_n << ", " << mesh.added_n
                              << " N/m; its mean height above the plate " << def.mean_height_m << ", "
                              << ref.mean_height_m << ", " << mesh.mean_height_m << " m; face places loaded "
                              << def.covered << ", " << ref.covered << ", " << mesh.covered
                              << " (default; rays 0.25 mm apart; elements 2.5 mm)");
  REQUIRE(def.added_n > 0);
  // no comb: the face places between the lowest and the highest loaded one
  // take some of the push (all of them at 10 mm elements, 0.875 at 2.5 mm
  // when written, where the default rays, 1.9 mm apart on the shell, touch
  // the face about 5 mm apart)
  CHECK(def.covered > 0.95);
  CHECK(mesh.covered > 0.8);
  // the same push at the same height, whatever the rays and the elements
  CHECK(ref.added_n == Approx(def.added_n).epsilon(0.01));
  CHECK(mesh.added_n == Approx(def.added_n).epsilon(0.01));
  CHECK(std::abs(def.mean_height_m - ref.mean_height_m) < 0.0015);
  CHECK(std::abs(mesh.mean_height_m - def.mean_height_m) < 0.0015);
}
