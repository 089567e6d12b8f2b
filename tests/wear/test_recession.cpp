// From loads to recession rates: hand-computed rates, the split into
// centrifugal, gravitational and impact parts, calibration, and the inputs
// refused at setup.
#include <catch2/catch.hpp>
#include <cmath>

#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "wear/impact_laws.h"
#include "wear/recession.h"
#include "wear/wear_laws.h"

using namespace linerlife;

namespace {

const ChargeModelEntry kFull{"fake", "abrasion and impacts", true, true, nullptr};
const ChargeModelEntry kNoImpacts{"noimpacts", "abrasion only", false, true, nullptr};
const ChargeModelEntry kNoAbrasion{"noabrasion", "impacts only", true, false, nullptr};

const LinerSurface& qiu() {
  static const LinerSurface s = [] {
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
  }();
  return s;
}

WearSpec spec_of(std::vector<std::string> laws) {
  WearSpec w;
  w.laws = std::move(laws);
  return w;
}

template <class F>
std::string input_error_key(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.key();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("zero loads give zero recession", "[wear][recession]") {
  const LinerSurface& s = qiu();
  const WearModel m = make_wear_model(WearSpec{}, kFull);
  LinerLoads loads;
  loads.reset(s.n_elements(), 10.0);
  loads.has_impacts = true;
  const RecessionRates r = recession_rates(m, loads, s, LinerMaterial{});
  for (int i = 0; i < s.n_elements(); ++i) CHECK(r.total[i] == 0.0);
  CHECK(r.mass_rate_kg_s_per_m == 0.0);
}

TEST_CASE("Radziszewski and Archard abrasion by hand, split and calibrated", "[wear][recession]") {
  const LinerSurface& s = qiu();
  const LinerMaterial mat;  // 350 BHN = 3.432328e9 Pa, 7800 kg/m3
  LinerLoads loads;
  loads.reset(s.n_elements(), 10.0);
  const int i = 40;
  loads.normal_force_n_per_m[i] = 1000;
  loads.centrifugal_force_n_per_m[i] = 300;
  loads.gravitational_force_n_per_m[i] = 700;
  loads.normal_slip_power_w_per_m[i] = 100;
  loads.shear_work_rate_w_per_m[i] = 30;
  const double L = s.length[i];

  SECTION("Radziszewski with the charge model's slip") {
    // thesis eq. 5.4: V = tan(theta) / (pi H) <N v> = 0.02 x 100 / (pi x 3.432328e9) = 1.854776e-10 m2/s
    WearSpec w = spec_of({"abrasion/radziszewski"});
    w.calibration_centrifugal = 2;
    w.calibration_gravitational = 3;
    const RecessionRates r = recession_rates(make_wear_model(w, kFull), loads, s, mat);
    CHECK(r.centrifugal[i] == Approx(2 * 0.3 * 1.854776e-10 / L).epsilon(1e-6));
    CHECK(r.gravitational[i] == Approx(3 * 0.7 * 1.854776e-10 / L).epsilon(1e-6));
    CHECK(r.impact[i] == 0.0);
    CHECK(r.total[i] == Approx(r.centrifugal[i] + r.gravitational[i]).epsilon(1e-15));
    CHECK(r.mass_rate_kg_s_per_m == Approx(7800 * (0.6 + 2.1) * 1.854776e-10).epsilon(1e-6));
    CHECK(r.centrifugal_mass_rate_kg_s_per_m == Approx(7800 * 0.6 * 1.854776e-10).epsilon(1e-6));
    for (int j = 0; j < s.n_elements(); ++j)
      if (j != i) CHECK(r.total[j] == 0.0);
  }
  SECTION("Archard on the shear work rate (Qiu 2001)") {
    // V = K P S / H per unit time = 0.02 x 30 / 3.432328e9 = 1.748085e-10 m2/s
    const RecessionRates r = recession_rates(make_wear_model(spec_of({"abrasion/archard"}), kFull), loads, s, mat);
    CHECK(r.total[i] * L == Approx(1.748085e-10).epsilon(1e-6));
  }
  SECTION("both abrasion laws add up") {
    const RecessionRates a = recession_rates(make_wear_model(spec_of({"abrasion/radziszewski"}), kFull), loads, s, mat);
    const RecessionRates b = recession_rates(make_wear_model(spec_of({"abrasion/archard"}), kFull), loads, s, mat);
    const RecessionRates ab =
        recession_rates(make_wear_model(spec_of({"abrasion/radziszewski", "abrasion/archard"}), kFull), loads, s, mat);
    CHECK(ab.total[i] == Approx(a.total[i] + b.total[i]).epsilon(1e-14));
  }
  SECTION("a model that does not split its normal force counts the abrasion as gravitational") {
    loads.centrifugal_force_n_per_m[i] = 0;
    loads.gravitational_force_n_per_m[i] = 0;
    const RecessionRates r = recession_rates(make_wear_model(spec_of({"abrasion/radziszewski"}), kFull), loads, s, mat);
    CHECK(r.centrifugal[i] == 0.0);
    CHECK(r.gravitational[i] * L == Approx(1.854776e-10).epsilon(1e-6));
  }
  SECTION("Morrell slip replaces the charge model's <N v> by N x V_Morrell") {
    WearSpec w = spec_of({"abrasion/radziszewski"});
    w.choices["radziszewski_slip"] = "morrell";
    WearModel m = make_wear_model(w, kFull);
    CHECK_THROWS_AS(recession_rates(m, loads, s, mat), std::logic_error);  // no operating point yet
    OperatingPoint op;
    op.valid = true;
    op.omega_rad_s = 1;
    op.radius_m = 5;
    op.inner_radius_m = 3;
    op.filling = 0.3;
    op.ball_diameter_m = 0.1;
    set_operating_point(m, op);
    const RecessionRates r = recession_rates(m, loads, s, mat);
    // V_Morrell = 0.05213375 m/s (test_abrasion): V = 0.02 / (pi H) x 1000 x 0.05213375
    CHECK(r.slip_speed_m_s == Approx(0.05213375).epsilon(1e-6));
    CHECK(r.total[i] * L == Approx(0.02 / (M_PI * 3.432328e9) * 1000 * 0.05213375).epsilon(1e-6));
  }
}

TEST_CASE("impact wear per element: rate x volume per impact, over the element length", "[wear][recession]") {
  const LinerSurface& s = qiu();
  const LinerMaterial mat;
  LinerLoads loads;
  loads.reset(s.n_elements(), 10.0);
  loads.has_impacts = true;
  ImpactEvent e;
  e.element = 77;
  e.normal_speed_m_s = 5;
  e.tangential_speed_m_s = 0;
  e.mass_kg = 1;
  e.diameter_m = 0.1333;
  e.rate_per_s = 2;
  loads.impacts = {e, e};
  loads.impacts[1].rate_per_s = 0.5;
  WearSpec w;  // radziszewski + sheldon_kanhere
  w.calibration_impact = 4;
  const RecessionRates r = recession_rates(make_wear_model(w, kFull), loads, s, mat);
  // Sheldon-Kanhere of this impact: 1.661810e-10 m3 (test_impact_laws); 2.5 impacts per second; calibration 4
  CHECK(r.impact[77] * s.length[77] == Approx(4 * 2.5 * 1.661810e-10).epsilon(1e-6));
  CHECK(r.impact_mass_rate_kg_s_per_m == Approx(7800 * 4 * 2.5 * 1.661810e-10).epsilon(1e-6));
  CHECK(r.mass_rate_kg_s_per_m == Approx(r.impact_mass_rate_kg_s_per_m).epsilon(1e-12));
  // amplification is not in the rates; amplified_rate applies it per contribution
  WearSpec wa = w;
  wa.amplification_impact = 1e7;
  const WearModel ma = make_wear_model(wa, kFull);
  CHECK(amplified_rate(ma, r, 77) == Approx(1e7 * r.impact[77]).epsilon(1e-15));
  // two impact laws add up
  const WearModel both = make_wear_model(spec_of({"impact/sheldon_kanhere", "impact/bitter"}), kFull);
  CHECK(impact_volume(both, e, mat) == Approx(sheldon_kanhere_volume(1, 5, 0, SheldonKanhereParams{}, mat) +
                                              bitter_volume(1, 5, 0, BitterParams{}, mat).total())
                                           .epsilon(1e-12));
}

TEST_CASE("bad wear input is refused at setup naming the key", "[wear][recession][input]") {
  CHECK(input_error_key([] { make_wear_model(spec_of({"impact/bogus"}), kFull); }) == "wear.laws");
  CHECK(input_error_key([] { make_wear_model(spec_of({"impact/finnie", "impact/finnie"}), kFull); }) == "wear.laws");
  // incompatible combinations: impact laws need impact spectra, abrasion laws sliding loads
  CHECK(input_error_key([] { make_wear_model(spec_of({"impact/bitter"}), kNoImpacts); }) == "wear.laws");
  CHECK(input_error_key([] { make_wear_model(spec_of({"abrasion/archard"}), kNoAbrasion); }) == "wear.laws");
  CHECK_NOTHROW(make_wear_model(spec_of({"abrasion/archard"}), kNoImpacts));
  WearSpec w;
  w.amplification_abrasion = 0;
  CHECK(input_error_key([&] { make_wear_model(w, kFull); }) == "wear.amplification_abrasion");
  w = WearSpec{};
  w.amplification_impact = -1e7;
  CHECK(input_error_key([&] { make_wear_model(w, kFull); }) == "wear.amplification_impact");
  w = WearSpec{};
  w.calibration_impact = 0;
  CHECK(input_error_key([&] { make_wear_model(w, kFull); }) == "wear.calibration_impact");
  w = WearSpec{};
  w.parameters["finnie_cutting_fraction"] = 1.5;  // a law not chosen: still checked
  CHECK(input_error_key([&] { make_wear_model(w, kFull); }) == "wear.finnie_cutting_fraction");
  w = WearSpec{};
  w.choices["radziszewski_slip"] = "psychic";
  CHECK(input_error_key([&] { make_wear_model(w, kFull); }) == "wear.radziszewski_slip");
  w = WearSpec{};
  w.smoothing.tukey = "3RX";
  CHECK(input_error_key([&] { make_wear_model(w, kFull); }) == "wear.smoothing_tukey");
  // materials
  LinerMaterial m;
  m.hardness_bhn = -350;
  CHECK(input_error_key([&] { validate_liner_material(m); }) == "liner.hardness_bhn");
  m = LinerMaterial{};
  m.poisson_ratio = 0.6;
  CHECK(input_error_key([&] { validate_liner_material(m); }) == "wear.liner_poisson_ratio");
  CHECK_NOTHROW(validate_liner_material(LinerMaterial{}));
  // every message names the value and the range
  m = LinerMaterial{};
  m.hardness_bhn = -350;
  try {
    validate_liner_material(m);
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("-350") && Catch::Contains("allowed"));
  }
}

TEST_CASE("every law declares its parameters with unit, range and a default inside it", "[wear][laws]") {
  for (const WearLawEntry& e : wear_laws()) {
    CHECK_FALSE(e.source.empty());
    CHECK((e.name.rfind("abrasion/", 0) == 0) == (e.kind == WearKind::Abrasion));
    CHECK_NOTHROW(find_wear_law(e.name));
    for (const LawParameter& p : e.parameters) {
      CHECK_FALSE(p.unit.empty());
      CHECK_FALSE(p.help.empty());
      if (p.choices.empty())
        CHECK_NOTHROW(law_parameter(WearSpec{}, p));
      else
        CHECK(law_choice(WearSpec{}, p) == p.default_choice);
    }
  }
  CHECK(parse_law_list("abrasion/archard, impact/finnie") ==
        std::vector<std::string>{"abrasion/archard", "impact/finnie"});
  CHECK(parse_law_list("none").empty());
}
