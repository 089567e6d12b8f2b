// The layer model's pocket loads (ModelSpec::pocket_loads, docs/models/layer.md
// §7, "Pocket loads"): the lifter faces that hold the pockets take the
// tangential weight of the charge over them. Checked against force balance on
// a lifter of known face angle, on a plain shell (no face: nothing moves), and
// against the run without them (the charge itself must not change).
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
/// radial, at the largest radius) and over the faces (normal turned more
/// than 30 deg towards the tangent), per metre of mill.
struct Parts {
  double plate_n = 0, plate_s = 0, face_n = 0, all_n = 0;
};

Parts parts(const LinerSurface& s, const LinerLoads& L) {
  double r_max = 0;
  for (int e = 0; e < s.n_elements(); ++e) r_max = std::max(r_max, s.midpoint[e].norm());
  Parts p;
  for (int e = 0; e < s.n_elements(); ++e) {
    const Eigen::Vector2d m = s.midpoint[e];
    const Eigen::Vector2d er = m.normalized();
    const double radial = -s.normal[e].dot(er);  // the normal points into the mill
    p.all_n += L.normal_force_n_per_m[e];
    if (radial > std::cos(2.0 * kPi / 180.0) && m.norm() > r_max - 0.002) {
      p.plate_n += L.normal_force_n_per_m[e];
      p.plate_s += L.shear_force_n_per_m[e];
    } else if (radial < std::cos(30.0 * kPi / 180.0)) {
      p.face_n += L.normal_force_n_per_m[e];
    }
  }
  return p;
}

}  // namespace

TEST_CASE("pocket loads put the charge's tangential weight on the lifter faces, not the plate", "[charge][layer]") {
  // The bundled ball mill: straight 30 deg faces, sharp corners, 0.12 m
  // lifters (2.4 media diameters: two layers in each pocket).
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
  const Parts a = parts(s, off.loads), b = parts(s, on.loads);
  INFO("plate N " << a.plate_n << " -> " << b.plate_n << ", plate S " << a.plate_s << " -> " << b.plate_s
                  << ", faces N " << a.face_n << " -> " << b.face_n << " N/m");
  REQUIRE(a.plate_s > 0);
  // the plate keeps its radial load (its normal is radial: the tangential
  // force never pressed on it) and loses shear: the pocket layers' own
  // tangential weight, and the layers' above up to mu N
  CHECK(b.plate_n == Approx(a.plate_n).epsilon(1e-3));
  CHECK(b.plate_s < 0.7 * a.plate_s);
  // force balance: a tangential force T taken off the plate presses on a 30
  // deg face with T cos 30 deg; the faces also take the pushes of the columns
  // standing on them, so at least that much arrives
  const double taken = a.plate_s - b.plate_s;
  CHECK(b.face_n - a.face_n >= 0.99 * std::cos(30.0 * kPi / 180.0) * taken);
  // ... and no more than every column's tangential weight (the shear of all
  // the liner without pocket loads bounds it)
  double all_s = 0;
  for (const double x : off.loads.shear_force_n_per_m) all_s += x;
  CHECK(b.face_n - a.face_n <= all_s);
  CHECK(b.all_n - a.all_n == Approx(b.face_n - a.face_n).epsilon(0.01));
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
  const Parts a = parts(s, off.loads), b = parts(s, on.loads);
  INFO("faces N " << a.face_n << " -> " << b.face_n << ", all N " << a.all_n << " -> " << b.all_n << " N/m");
  // the worn faces take the push: their normal load rises, and most of what
  // is added lands on the steep part of the face (more than 30 deg from the
  // radial; the rest on its flatter foot and crest: 75 % when written)
  CHECK(b.face_n > 1.2 * a.face_n);
  CHECK(b.face_n - a.face_n > 0.6 * (b.all_n - a.all_n));
}
