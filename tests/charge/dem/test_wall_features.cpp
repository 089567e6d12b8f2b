// The wall contact on features of a worn liner thinner than a disc's overlap:
// a disc beside such a feature is behind the line of its far face, within one
// radius, without having crossed the liner; only a centre that crosses an
// element has passed through it (docs/models/dem.md §4).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "charge/dem/contact_law.h"
#include "charge/dem/dem_system.h"
#include "geometry/errors.h"

using namespace linerlife;

namespace {

DemParticles one_disc(double x, double y, double vx, double vy, double w, double r, double m) {
  DemParticles p;
  p.x = {x}, p.y = {y}, p.vx = {vx}, p.vy = {vy}, p.w = {w}, p.radius = {r}, p.mass = {m};
  return p;
}

/// Nodes 2478 to 2500 of the Qiu liner the DEM forecast at calibration 0.13445
/// drove at 8,053 h (body frame [m], the displaced ring as the drive gave it to
/// the DEM): the trailing face up to the crest corner (node 2487), 3.9 mm
/// along the crest to node 2488, back 0.54 mm (element 2488, a 162 deg turn: a
/// fold 0.17 mm thick at its root) and on along a ragged crest.
std::vector<Eigen::Vector2d> worn_crest_corner() {
  return {{-4.91439595706, 1.10605172738}, {-4.90615477998, 1.1007407781}, {-4.89771298198, 1.09552010959},
          {-4.88916924151, 1.090366678},   {-4.88066654145, 1.08525756926}, {-4.87218663829, 1.08016145557},
          {-4.8636396112, 1.07512550005},  {-4.85513700581, 1.07013568305}, {-4.84714934339, 1.06463903424},
          {-4.84119877387, 1.05782169914}, {-4.84118360677, 1.05393384983}, {-4.8413524327, 1.05444912752},
          {-4.84462732079, 1.04807982959}, {-4.85049784065, 1.04025939804}, {-4.847096796, 1.03589049716},
          {-4.84898571291, 1.03417504569}, {-4.85250789519, 1.03352918721}, {-4.85645918948, 1.02821419306},
          {-4.85860628928, 1.02319969511}, {-4.86063103563, 1.01785017059}, {-4.86394027179, 1.01142179499},
          {-4.86867745699, 1.0068913056},  {-4.87286155053, 1.00338993503}};
}

/// A floor along y = 0 with a fold 0.2 mm thick standing 50 mm up from it at
/// x = 0 (particles above): up its left face, across its top, down its right face.
std::vector<Eigen::Vector2d> thin_fold() {
  return {{-1, 0}, {0, 0}, {0, 0.05}, {0.0002, 0.05}, {0.0002, 0}, {1, 0}};
}

/// Shortest distance [m] from point q to the open polyline.
double distance_to(const std::vector<Eigen::Vector2d>& nodes, const Eigen::Vector2d& q) {
  double best = 1e300;
  for (size_t k = 0; k + 1 < nodes.size(); ++k) {
    const Eigen::Vector2d a = nodes[k], d = nodes[k + 1] - a;
    const double t = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (q - a - t * d).norm());
  }
  return best;
}

}  // namespace

TEST_CASE("dem wall: a disc thrown at a worn crest corner with a fold thinner than its overlap bounces off",
          "[dem][walls]") {
  // The contact of the failed forecast drive (disc 3106, t = 1.4719 s): a rock
  // of radius 19.4 mm flying at 9.3 m/s (body frame) onto the crest corner,
  // the Qiu drive's linear contact (t_c = 8 steps, e = 0.8, mu = 0.3), the wall
  // at rest and no gravity (the drive turns the liner 1.3e-4 rad a step). Its
  // overlap with the corner reaches 1.4 mm, more than the fold is thick, so its
  // centre is within a radius behind the fold's far face (element 10 here,
  // 2488 in the liner) and projects onto it: the old check called that
  // passing through. The start is swept across the corner, 1 mm apart.
  const std::vector<Eigen::Vector2d> nodes = worn_crest_corner();
  const double r = 0.0194324026, m = 2.35, dt = 1.193e-4;
  const Eigen::Vector2d v(-5.64, 7.35);  // [m/s] relative to the liner, from the drive's trace
  const Eigen::Vector2d q0(-4.806264, 1.037583);
  const Eigen::Vector2d across = Eigen::Vector2d(-v.y(), v.x()).normalized();
  DemSettings s;
  s.particle = s.wall = make_contact_params(ContactLaw::Linear, 0.8, 0.3, 0.02, 8 * dt, 0, 9.3);
  s.dt = dt;
  s.gravity_x = s.gravity_y = 0;
  int touched = 0;
  for (int k = -15; k <= 15; ++k) {
    const Eigen::Vector2d q = q0 + 1e-3 * k * across;
    DemSystem sys(s, make_wall_mesh(nodes, false), one_disc(q.x(), q.y(), v.x(), v.y(), -28.7, r, m));
    INFO("start offset " << k << " mm across the path");
    double closest = 1e300;
    for (int step = 0; step < 60; ++step) {
      REQUIRE_NOTHROW(sys.advance(1));
      closest = std::min(closest, distance_to(nodes, {sys.x()[0], sys.y()[0]}));
    }
    if (closest >= r) continue;  // passed the corner without touching
    ++touched;
    // it touched and came away: the largest overlap is the soft contact's (a few
    // per cent of the radius), and the disc has left the liner
    CHECK(r - closest < 0.2 * r);
    CHECK(distance_to(nodes, {sys.x()[0], sys.y()[0]}) > r);
  }
  CHECK(touched >= 20);
}

TEST_CASE("dem wall: a disc driven through a fold or a wall still stops the run", "[dem][walls]") {
  // Contacts far too soft for the speed: the disc's centre reaches the wall. A
  // floor, and a fold 0.2 mm thick standing 50 mm up from it, must both stop
  // the run with the diagnostic (exit 3 in the app).
  const double r = 0.02, m = 2.0;
  DemSettings s;
  s.particle = s.wall = make_contact_params(ContactLaw::Linear, 0.8, 0.0, 0.0, 10e-3, 0, 10.0);
  s.dt = 10e-3 / 8;
  s.gravity_x = s.gravity_y = 0;
  SECTION("a floor") {
    DemSystem sys(s, make_wall_mesh({{-1, 0}, {1, 0}}, false), one_disc(0, 0.1, 0, -10, 0, r, m));
    REQUIRE_THROWS_WITH(sys.advance(200), Catch::Contains("passed through liner element"));
  }
  SECTION("a fold, hit on its face") {
    DemSystem sys(s, make_wall_mesh(thin_fold(), false), one_disc(-0.1, 0.025, 10, 0, 0, r, m));
    REQUIRE_THROWS_WITH(sys.advance(200), Catch::Contains("passed through liner element"));
  }
}

TEST_CASE("dem wall: a disc pressed on a fold thinner than its overlap stays on its side", "[dem][walls]") {
  // The fold 0.2 mm thick and a disc dropped against its face by a steady
  // force (gravity along +x) that overlaps it 1 mm at rest, five times the
  // fold's thickness: it must come to rest there, not pass.
  const double r = 0.02, m = 2.0;
  DemSettings s;
  s.particle = s.wall = make_contact_params(ContactLaw::Linear, 0.5, 0.3, 0.0, 1e-3, 0, 1.0);
  s.dt = 1e-3 / 20;
  s.gravity_y = 0;
  const double k = s.wall.k_per_mass * m;  // [N/m per m]
  s.gravity_x = 1e-3 * k / m;              // steady overlap 1 mm
  DemSystem sys(s, make_wall_mesh(thin_fold(), false), one_disc(-r - 0.001, 0.025, 0, 0, 0, r, m));
  REQUIRE_NOTHROW(sys.advance(4000));  // 0.2 s, 200 collision times
  CHECK(sys.x()[0] == Approx(-(r - 0.001)).margin(1e-6));
  CHECK(sys.y()[0] == Approx(0.025).margin(1e-6));
  CHECK(std::abs(sys.vx()[0]) < 1e-3);
}

TEST_CASE("dem wall: a disc touching more liner elements than its contact list holds is counted, not silent",
          "[dem][walls]") {
  // A disc of radius 20 mm held at the centre of a lower half-circle pocket of
  // radius 19.9 mm: it overlaps every element of the pocket by 0.1 mm. With
  // 62 elements of 1 mm it touches more than DemSystem::kMaxWallHits (16) at
  // once, with 10 elements of 6.2 mm fewer. No gravity: the disc stays put.
  const double r = 0.02, m = 2.0, R = 0.0199;
  DemSettings s;
  s.particle = s.wall = make_contact_params(ContactLaw::Linear, 0.5, 0.3, 0.0, 1e-3, 0, 1.0);
  s.dt = 1e-3 / 20;
  s.gravity_x = s.gravity_y = 0;
  auto pocket = [&](int n) {
    std::vector<Eigen::Vector2d> nodes;
    for (int k = 0; k <= n; ++k) {
      const double a = -M_PI + M_PI * k / n;  // from (-R, 0) down and round to (R, 0)
      nodes.push_back({R * std::cos(a), R * std::sin(a)});
    }
    return nodes;
  };
  for (int n : {10, 62}) {
    DemSystem sys(s, make_wall_mesh(pocket(n), false), one_disc(0, 0, 0, 0, 0, r, m));
    REQUIRE_NOTHROW(sys.advance(3));
    INFO(n << " elements: " << sys.wall_hits_dropped() << " dropped, " << sys.wall_springs_dropped()
           << " without a spring, " << sys.wall_contact_steps() << " contact evaluations");
    if (n <= DemSystem::kMaxWallHits) {
      CHECK(sys.wall_hits_dropped() == 0);
    } else {
      // every step finds n contacts and keeps 16 (the merge of shallow concave
      // nodes may then drop some of those, not the count of the dropped)
      CHECK(sys.wall_hits_dropped() >= (n - DemSystem::kMaxWallHits) * 3);
      CHECK(sys.wall_springs_dropped() > 0);
    }
  }
}
