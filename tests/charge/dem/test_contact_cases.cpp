// 2D analogues of the MFiX DEM verification cases (Garg et al. 2012, MFiX DEM
// verification manual DEM-01..06), each against its analytic result with a
// stated tolerance; plus the balances of a closed box (issue 6 §2).
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "charge/dem/contact_law.h"
#include "charge/dem/dem_system.h"
#include "geometry/errors.h"

using namespace linerlife;

namespace {

constexpr double kPiT = 3.14159265358979323846;

/// A floor along y = 0 (particles above it) from x = -10 to 10 m.
WallMesh floor_wall() { return make_wall_mesh({{-10, 0}, {10, 0}}, false); }

/// A closed square box [0, L]^2, anticlockwise so the particles are inside.
WallMesh box_wall(double L) { return make_wall_mesh({{0, 0}, {L, 0}, {L, L}, {0, L}}, true); }

DemParticles one_disc(double x, double y, double vx, double vy, double w, double r, double m) {
  DemParticles p;
  p.x = {x}, p.y = {y}, p.vx = {vx}, p.vy = {vy}, p.w = {w}, p.radius = {r}, p.mass = {m};
  return p;
}

ContactParams params(ContactLaw law, double e, double mu, double tc, double v_ref, double mu_r = 0) {
  return make_contact_params(law, e, mu, mu_r, tc, 0, v_ref);
}

const char* law_name(ContactLaw l) { return l == ContactLaw::Linear ? "linear" : "hertz"; }

}  // namespace

TEST_CASE("DEM-01 free fall: velocity Verlet is exact under constant gravity", "[dem][verification]") {
  DemSettings s;
  s.particle = s.wall = params(ContactLaw::Linear, 0.9, 0.3, 1e-3, 1);
  s.dt = 1e-4;
  DemSystem sys(s, WallMesh{}, one_disc(0.3, 10.0, 0.5, 0.0, 0.0, 0.05, 2.0));
  sys.advance(10000);  // 1 s
  const double T = sys.time();
  CHECK(T == Approx(1.0).epsilon(1e-12));
  // y = y0 - g T^2 / 2, v = -g T, x = x0 + u T (tolerance: round-off, 1e-10 relative)
  CHECK(sys.y()[0] == Approx(10.0 - 0.5 * 9.81 * T * T).epsilon(1e-10));
  CHECK(sys.vy()[0] == Approx(-9.81 * T).epsilon(1e-10));
  CHECK(sys.x()[0] == Approx(0.3 + 0.5 * T).epsilon(1e-10));
}

TEST_CASE("DEM-02 bounce: the measured restitution equals the input within 1e-3", "[dem][verification]") {
  // Normal impact at 2 m/s without gravity, 2000 steps per contact: the error of the
  // half-step damping velocity is first order in dt (about 0.35 / steps).
  for (ContactLaw law : {ContactLaw::Linear, ContactLaw::Hertz})
    for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
      const double v = 2.0, r = 0.05, m = 10.0, tc = 1e-3;
      const ContactParams cp = params(law, e, 0.0, tc, v);
      DemSettings s;
      s.particle = s.wall = cp;
      s.gravity_y = 0;
      const double tcw = collision_time(cp, m, v);
      s.dt = tcw / 2000;
      INFO(law_name(law) << " e = " << e);
      {  // disc on a wall
        DemSystem sys(s, floor_wall(), one_disc(0, r + 5 * v * s.dt, 0, -v, 0, r, m));
        sys.advance(static_cast<long long>((5 * s.dt + 1.5 * tcw) / s.dt));
        CHECK(sys.contacts()[0] == 0);
        CHECK(sys.vy()[0] / v == Approx(e).margin(1e-3));
      }
      {  // two discs
        // unequal discs head on: e = -(v1' - v2') / (v1 - v2)
        DemParticles p;
        const double m2 = 3.0, r2 = 0.03;
        p.x = {0, r + r2 + 5 * v * s.dt}, p.y = {0, 0}, p.vx = {0.5 * v, -0.5 * v}, p.vy = {0, 0}, p.w = {0, 0};
        p.radius = {r, r2}, p.mass = {m, m2};
        const double meff = m * m2 / (m + m2);
        const double tcp = collision_time(cp, meff, v);
        s.dt = tcp / 2000;
        DemSystem sys(s, WallMesh{}, p);
        sys.advance(static_cast<long long>((10 * tcp / 2000 + 1.5 * tcp) / s.dt));
        const int a = sys.index_of(0), b = sys.index_of(1);
        CHECK(-(sys.vx()[a] - sys.vx()[b]) / v == Approx(e).margin(1e-3));
        // momentum is conserved exactly (round-off)
        CHECK(m * sys.vx()[a] + m2 * sys.vx()[b] == Approx(m * 0.5 * v - m2 * 0.5 * v).margin(1e-12));
      }
    }
}

TEST_CASE("DEM-03 normal overlap: the largest overlap equals the analytic maximum", "[dem][verification]") {
  const double v = 1.5, r = 0.04, m = 5.0, tc = 2e-3;
  struct Case {
    ContactLaw law;
    double e;
    double analytic;  // [m]; < 0: from max_overlap()
  };
  // Undamped Hertz: delta_max = (5 m v^2 / (4 k))^(2/5) (Johnson 1985 §11.4); linear:
  // (v / wn) exp(-zeta / sqrt(1 - zeta^2) atan2(sqrt(1 - zeta^2), zeta)).
  for (Case c : {Case{ContactLaw::Linear, 1.0, -1}, Case{ContactLaw::Linear, 0.9, -1}, Case{ContactLaw::Linear, 0.5, -1},
                 Case{ContactLaw::Linear, 0.2, -1}, Case{ContactLaw::Hertz, 1.0, 0}}) {
    const ContactParams cp = params(c.law, c.e, 0.0, tc, v);
    double expect = max_overlap(cp, m, v);
    if (c.law == ContactLaw::Linear) {
      const double zeta = 0.5 * cp.gamma, wn = std::sqrt(cp.stiffness(m) / m), sq = std::sqrt(1 - zeta * zeta);
      CHECK(expect == Approx(v / wn * std::exp(-zeta / sq * std::atan2(sq, zeta))).epsilon(1e-12));
    } else {
      const double hertz = std::pow(5 * m * v * v / (4 * cp.stiffness(m)), 0.4);
      CHECK(expect == Approx(hertz).epsilon(1e-5));  // the nondimensional RK4 integration
      expect = hertz;
    }
    DemSettings s;
    s.particle = s.wall = cp;
    s.gravity_y = 0;
    s.dt = collision_time(cp, m, v) / 2000;
    DemSystem sys(s, floor_wall(), one_disc(0, r + 2 * v * s.dt, 0, -v, 0, r, m));
    double ymin = 1e9;
    for (int k = 0; k < 3000; ++k) {
      sys.advance(1);
      ymin = std::min(ymin, sys.y()[0]);
    }
    INFO(law_name(c.law) << " e = " << c.e);
    // tolerance 2e-3: the step resolves the peak within (pi / 2000)^2 / 2 and the onset within one step
    CHECK(r - ymin == Approx(expect).epsilon(2e-3));
  }
}

TEST_CASE("DEM-04 slide to roll: a sliding disc ends rolling at v = 2 v0 / 3", "[dem][verification]") {
  // Disc (I = m r^2 / 2) sliding with v0 and no spin on a floor with Coulomb mu:
  // friction -mu m g until v = omega r at t = v0 / (3 mu g), then v = 2 v0 / 3.
  for (ContactLaw law : {ContactLaw::Linear, ContactLaw::Hertz}) {
    const double v0 = 2.0, r = 0.05, m = 4.0, mu = 0.3, g = 9.81;
    const ContactParams cp = params(law, 0.5, mu, 1e-3, 1.0);
    DemSettings s;
    s.particle = s.wall = cp;
    s.dt = 2e-5;
    // start at rest on the floor: static overlap m g / k (linear) or (m g / k)^(2/3) (hertz)
    const double k = cp.stiffness(m);
    const double d0 = law == ContactLaw::Linear ? m * g / k : std::pow(m * g / k, 2.0 / 3.0);
    DemSystem sys(s, floor_wall(), one_disc(0, r - d0, v0, 0, 0, r, m));
    const double t_roll = v0 / (3 * mu * g);
    double t_seen = -1;
    while (sys.time() < 2 * t_roll + 0.2) {
      sys.advance(10);
      if (t_seen < 0 && std::abs(sys.vx()[0] - (-sys.w()[0] * r)) < 1e-3 * v0) t_seen = sys.time();
    }
    INFO(law_name(law));
    CHECK(sys.vx()[0] / v0 == Approx(2.0 / 3.0).epsilon(1e-3));
    CHECK(-sys.w()[0] * r / v0 == Approx(2.0 / 3.0).epsilon(1e-3));
    CHECK(t_seen == Approx(t_roll).epsilon(0.02));  // the tangential spring takes a few microseconds to load
  }
}

TEST_CASE("DEM-05 oblique impact: a disc sliding through the contact loses mu times the compressive impulse",
          "[dem][verification]") {
  // Gross sliding (v_t / v_n > 3 mu (1 + e) for a disc): the Coulomb impulse is
  // mu J_c with J_c the compressive normal impulse, so v_t' = v_t - mu J_c / m and
  // omega' = -2 mu J_c / (m r) (I = m r^2 / 2); v_n' = e v_n.
  struct Case {
    ContactLaw law;
    double e;
  };
  for (Case c : {Case{ContactLaw::Linear, 0.8}, Case{ContactLaw::Linear, 0.5}, Case{ContactLaw::Hertz, 1.0}}) {
    for (double angle_deg : {60.0, 75.0}) {  // incidence from the normal
      const double V = 2.0, r = 0.05, m = 3.0, mu = 0.1;
      const double vn = V * std::cos(angle_deg * kPiT / 180), vt = V * std::sin(angle_deg * kPiT / 180);
      REQUIRE(vt / vn > 3 * mu * (1 + c.e));
      const ContactParams cp = params(c.law, c.e, mu, 1e-3, vn);
      DemSettings s;
      s.particle = s.wall = cp;
      s.gravity_y = 0;
      const double tcw = collision_time(cp, m, vn);
      s.dt = tcw / 2000;
      DemSystem sys(s, floor_wall(), one_disc(0, r + 5 * vn * s.dt, vt, -vn, 0, r, m));
      sys.advance(static_cast<long long>((5 * s.dt + 1.5 * tcw) / s.dt));
      const double share = c.law == ContactLaw::Linear ? linear_compressive_impulse_share(c.e) : 1.0;
      const double Jc = share * m * vn * (1 + c.e);
      INFO(law_name(c.law) << " e = " << c.e << ", " << angle_deg << " deg");
      CHECK(sys.vy()[0] / vn == Approx(c.e).margin(1e-3));
      CHECK((vt - sys.vx()[0]) / (mu * Jc / m) == Approx(1.0).epsilon(2e-3));
      CHECK(sys.w()[0] / (-2 * mu * Jc / (m * r)) == Approx(1.0).epsilon(2e-3));
    }
  }
  // the compressive share is 1 without damping and above 1 with it (the dashpot pulls at the end)
  CHECK(linear_compressive_impulse_share(1.0) == Approx(1.0).epsilon(1e-12));
  CHECK(linear_compressive_impulse_share(0.5) > 1.0);
}

TEST_CASE("closed box: mass stays, momentum changes only by the wall impulse and gravity", "[dem][verification]") {
  const double L = 1.0;
  DemParticles p;
  int id = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j, ++id) {
      const double r = 0.02 + 0.01 * ((id * 7) % 5) / 4.0;
      p.x.push_back(0.08 + 0.093 * i), p.y.push_back(0.08 + 0.093 * j);
      p.vx.push_back(std::sin(1.3 * id)), p.vy.push_back(std::cos(0.7 * id)), p.w.push_back(3 * std::sin(id));
      p.radius.push_back(r), p.mass.push_back(7800 * kPiT * r * r);
    }
  DemSettings s;
  s.particle = params(ContactLaw::Linear, 0.7, 0.3, 1e-3, 1, 0.02);
  s.wall = params(ContactLaw::Linear, 0.8, 0.3, 1e-3, 1, 0.02);
  s.dt = 1e-3 / 20;
  s.threads = 2;
  DemSystem sys(s, box_wall(L), p);
  double M = 0;
  for (double m : sys.mass()) M += m;
  const double px0 = sys.momentum_x(), py0 = sys.momentum_y();
  sys.advance(40000);  // 2 s
  const double T = sys.time();
  REQUIRE(sys.size() == 100);
  double M1 = 0;
  for (double m : sys.mass()) M1 += m;
  CHECK(M1 == Approx(M).epsilon(1e-14));
  for (int i = 0; i < sys.size(); ++i) {
    CHECK(sys.x()[i] > 0);
    CHECK(sys.x()[i] < L);
    CHECK(sys.y()[i] > 0);
    CHECK(sys.y()[i] < L);
  }
  // momentum balance: the particle forces cancel pairwise (Newton's third law),
  // so P(T) - P(0) = J_wall + M g T to round-off (1e-9 of M g T)
  const double scale = M * 9.81 * T;
  CHECK(sys.momentum_x() - px0 - sys.wall_impulse_x() == Approx(0).margin(1e-9 * scale));
  CHECK(sys.momentum_y() - py0 - sys.wall_impulse_y() - (-9.81 * M * T) == Approx(0).margin(1e-9 * scale));
  CHECK(std::abs(sys.wall_impulse_y()) > 0.5 * scale);  // the floor carried the weight
}

TEST_CASE("closed box with e = 1 and no friction conserves energy", "[dem][verification]") {
  const double L = 1.0;
  DemParticles p;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const int id = 8 * i + j;
      const double r = 0.03 + 0.01 * (id % 3) / 2.0;
      p.x.push_back(0.1 + 0.11 * i), p.y.push_back(0.1 + 0.11 * j);
      p.vx.push_back(2 * std::sin(1.7 * id)), p.vy.push_back(2 * std::cos(0.9 * id)), p.w.push_back(0);
      p.radius.push_back(r), p.mass.push_back(1000 * kPiT * r * r);
    }
  DemSettings s;
  s.particle = s.wall = params(ContactLaw::Linear, 1.0, 0.0, 1e-3, 1);
  s.dt = 1e-3 / 50;
  DemSystem sys(s, box_wall(L), p);
  sys.advance(0);
  auto energy = [&] { return sys.kinetic_energy() + sys.potential_energy() + sys.elastic_energy(); };
  const double e0 = energy();
  double worst = 0;
  for (int k = 0; k < 400; ++k) {
    sys.advance(250);  // 2 s in all, thousands of collisions
    worst = std::max(worst, std::abs(energy() - e0) / e0);
  }
  // Verlet is symplectic for the conservative contact: the energy error stays bounded,
  // O((dt / t_c)^2) per contact in progress; measured about 1e-4 here.
  CHECK(worst < 1e-3);
  CHECK(sys.pair_contact_steps() > 1000);
}

TEST_CASE("a blow-up stops the run with a diagnostic", "[dem][verification]") {
  // A time step as long as the contact is far beyond the stable range: the discs
  // gain energy at every contact until the speed limit trips.
  DemParticles p;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      p.x.push_back(0.2 + 0.099 * i), p.y.push_back(0.06 + 0.099 * j);
      p.vx.push_back(0), p.vy.push_back(0), p.w.push_back(0), p.radius.push_back(0.05), p.mass.push_back(10);
    }
  DemSettings s;
  s.particle = s.wall = params(ContactLaw::Linear, 0.9, 0.3, 1e-3, 1);
  s.dt = 1.2e-3;
  s.speed_limit = 20;
  s.escape_radius = 10;
  DemSystem sys(s, box_wall(1.0), p);
  try {
    sys.advance(20000);
    FAIL("the unstable run was not stopped");
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK((what.find("energy growth") != std::string::npos || what.find("passed through") != std::string::npos ||
           what.find("left the mill") != std::string::npos || what.find("non-finite") != std::string::npos));
    CHECK(what.find("t = ") != std::string::npos);
  }
}
