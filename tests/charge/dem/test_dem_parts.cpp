// The pieces of the DEM model: the particle set (counts, mass scaling,
// coarse-graining), the wall mesh (convex nodes, candidate grid) and the
// indicator extraction from particle data on a charge of known shape.
#include <algorithm>
#include <cmath>
#include <numeric>

#include <catch2/catch.hpp>

#include "charge/dem/particle_set.h"
#include "charge/dem/wall_mesh.h"
#include "charge/particle_indicators.h"

using namespace linerlife;

namespace {
constexpr double kPiT = 3.14159265358979323846;
}

TEST_CASE("the particle set holds the 3D charge mass per metre", "[dem][particles]") {
  ChargeSpec c;
  c.filling = 0.24, c.ball_filling = 0.12, c.ball_diameter_m = 0.1333;
  c.ball_density_kg_m3 = 7800, c.ore_density_kg_m3 = 2700, c.porosity = 0.4;
  DemSpec d;
  const double A = 80.0;  // [m2] free area
  const ParticleSet ps = make_particle_set(c, d, A, 1);
  REQUIRE(ps.n_balls + ps.n_rocks == ps.size());
  // mass per metre = rho (1 - E) x bulk area, balls and rocks (counts are rounded: 1 %)
  CHECK(ps.ball_mass_kg_per_m == Approx(7800 * 0.6 * 0.12 * A).epsilon(0.01));
  CHECK(ps.rock_mass_kg_per_m == Approx(2700 * 0.6 * 0.12 * A).epsilon(0.01));
  double solid = 0;
  for (double r : ps.radius_m) solid += kPiT * r * r;
  CHECK(solid == Approx(d.packing_fraction_2d * 0.24 * A).epsilon(0.01));
  for (int i = 0; i < ps.size(); ++i) {
    const double dd = 2 * ps.radius_m[i];
    if (ps.material[i] == Material::Ball) {
      CHECK(dd <= 0.1333 + 1e-12);
      CHECK(dd >= 0.1333 * 0.9 - 1e-12);
    } else {
      CHECK(dd <= 0.1333 + 1e-12);
      CHECK(dd >= 0.25 * 0.1333 - 1e-12);
    }
    CHECK(ps.real_diameter_m[i] == Approx(dd).epsilon(1e-12));
  }
  // Gates-Gaudin-Schuhmann with m = 0.5: the rocks below the geometric middle of
  // [dmin, dmax] carry (dmid^m - dmin^m) / (dmax^m - dmin^m) of the rock mass
  const double dmin = 0.25 * 0.1333, dmax = 0.1333, dmid = std::sqrt(dmin * dmax), m = 0.5;
  double below = 0, all = 0;
  for (int i = 0; i < ps.size(); ++i)
    if (ps.material[i] == Material::Rock) {
      all += ps.mass_kg_per_m[i];
      if (2 * ps.radius_m[i] < dmid) below += ps.mass_kg_per_m[i];
    }
  CHECK(below / all == Approx((std::pow(dmid, m) - std::pow(dmin, m)) / (std::pow(dmax, m) - std::pow(dmin, m))).epsilon(0.02));
  // the Qiu slice with the defaults: at least 3000 discs
  CHECK(make_particle_set(c, d, 77.9, 1).size() >= 3000);
}

TEST_CASE("coarse-graining by s: s times larger discs, s^2 fewer, the same mass", "[dem][particles]") {
  ChargeSpec c;
  c.filling = 0.3, c.ball_filling = 0.3, c.ball_diameter_m = 0.02, c.ball_density_kg_m3 = 7800;
  DemSpec d;
  const ParticleSet a = make_particle_set(c, d, 0.45, 3);
  d.coarse_grain = 2;
  const ParticleSet b = make_particle_set(c, d, 0.45, 3);
  CHECK(static_cast<double>(b.size()) == Approx(a.size() / 4.0).epsilon(0.01));
  CHECK(b.ball_mass_kg_per_m == Approx(a.ball_mass_kg_per_m).epsilon(0.01));
  for (int i = 0; i < b.size(); ++i) {
    CHECK(b.real_diameter_m[i] == Approx(b.radius_m[i]).epsilon(1e-12));  // 2 r / s
    CHECK(b.real_mass_kg[i] == Approx(7800 * kPiT * std::pow(b.real_diameter_m[i], 3) / 6).epsilon(1e-12));
  }
  // the same seed gives the same set
  const ParticleSet b2 = make_particle_set(c, d, 0.45, 3);
  CHECK(b2.radius_m == b.radius_m);
}

TEST_CASE("the largest real disc is the one the particle set draws", "[dem][particles]") {
  const auto largest_drawn = [](const ChargeSpec& c, const DemSpec& d) {
    const ParticleSet ps = make_particle_set(c, d, 2.0, 5);
    return *std::max_element(ps.real_diameter_m.begin(), ps.real_diameter_m.end());
  };
  ChargeSpec c;
  c.filling = 0.3, c.ball_filling = 0.3, c.ball_diameter_m = 0.05, c.ball_density_kg_m3 = 7800;
  c.ore_density_kg_m3 = 2700;
  DemSpec d;
  CHECK(largest_real_diameter_m(c, d) == 0.05);  // balls only
  CHECK(largest_drawn(c, d) <= 0.05);
  CHECK(largest_drawn(c, d) > 0.05 * (1 - d.ball_size_spread));
  c.ball_filling = 0.1;  // a SAG charge: rocks up to the ball size by default
  CHECK(largest_real_diameter_m(c, d) == 0.05);
  d.rock_diameter_max_m = 0.08;
  CHECK(largest_real_diameter_m(c, d) == 0.08);
  CHECK(largest_drawn(c, d) <= 0.08);
  CHECK(largest_drawn(c, d) > 0.06);  // the coarsest rock class runs up to it
}

TEST_CASE("wall mesh: convex nodes, merged shallow concave nodes, a complete candidate grid", "[dem][walls]") {
  // A lifter on a floor, particles above: floor, up the face, across the top, down, floor.
  const std::vector<Eigen::Vector2d> nodes = {{-1, 0}, {-0.1, 0}, {-0.1, 0.2}, {0.1, 0.2}, {0.1, 0}, {1, 0}, {1.5, 0.05}};
  // travelling left to right with the particles on the left (above) needs the
  // polyline in that order: +x along the floor has +y on the left.
  WallMesh w = make_wall_mesh(nodes, false);
  REQUIRE(w.n_elements() == 6);
  CHECK(w.convex_start[0]);   // free end
  CHECK(!w.convex_start[1]);  // foot of the lifter: concave
  CHECK(w.convex_start[2]);   // top corners: convex
  CHECK(w.convex_start[3]);
  CHECK(!w.convex_start[4]);
  CHECK(!w.convex_start[5]);  // 5.7 deg upward bend: concave
  CHECK(w.merge_next[4]);     // shallow: one contact
  CHECK(!w.merge_next[0]);    // 90 deg: two contacts
  CHECK(w.convex_end[5]);
  CHECK(w.ny[0] == Approx(1.0));
  build_wall_grid(w, 0.05, 0.03);
  // every element within reach of a point is listed in the point's cell
  for (int k = 0; k < 2000; ++k) {
    const double qx = -1.05 + 2.6 * std::fmod(0.6180339887 * k, 1.0), qy = -0.05 + 0.35 * std::fmod(0.7548776662 * k, 1.0);
    const int c = w.cell_of(qx, qy);
    REQUIRE(c >= 0);
    for (int e = 0; e < w.n_elements(); ++e) {
      const double t = std::clamp((qx - w.ax[e]) * w.ux[e] + (qy - w.ay[e]) * w.uy[e], 0.0, w.len[e]);
      const double dist = std::hypot(qx - w.ax[e] - t * w.ux[e], qy - w.ay[e] - t * w.uy[e]);
      if (dist > 0.05) continue;
      bool listed = false;
      for (int j = w.cell_start[c]; j < w.cell_start[c + 1]; ++j) listed |= w.cell_elems[j] == e;
      CHECK(listed);
    }
  }
}

TEST_CASE("indicators from particles: toe, shoulder, area and centre of mass of a known charge",
          "[dem][indicators]") {
  // A charge filling the circle of radius 1 m between toe 225 deg and shoulder
  // 45 deg (anticlockwise mill): the segment below the chord through them,
  // discs of 0.02 m on a square lattice, at rest.
  ParticleIndicatorGeometry g;
  g.sense = 1, g.omega = 1, g.r_eff = 1.0, g.r_crest = 1.0, g.r_shell = 1.0, g.pocket_area = 0, g.mean_diameter = 0.04;
  ParticleIndicators ind(g);
  // discs of 0.02 m in a jittered lattice (0.04 m), a new jitter each sample as time would give
  const double h = 0.04, rr = 0.02;
  double M = 0, MX = 0, MY = 0;
  DemRandom rng(5);
  for (int sample = 0; sample < 40; ++sample) {
    std::vector<double> x, y, vx, vy, r, m;
    std::vector<int> nc;
    for (double px0 = -1; px0 <= 1; px0 += h)
      for (double py0 = -1; py0 <= 1; py0 += h) {
        const double px = px0 + h * (rng.uniform() - 0.5), py = py0 + h * (rng.uniform() - 0.5);
        if (px * px + py * py > (1 - rr) * (1 - rr)) continue;
        if (py > px) continue;  // below the chord y = x through 225 and 45 deg
        x.push_back(px), y.push_back(py), vx.push_back(-py), vy.push_back(px), r.push_back(rr), m.push_back(1);
        nc.push_back(2);
        M += 1, MX += px, MY += py;
      }
    ParticleFrame f;
    f.n = static_cast<int>(x.size());
    f.x = x.data(), f.y = y.data(), f.vx = vx.data(), f.vy = vy.data(), f.radius = r.data(), f.mass = m.data();
    f.contacts = nc.data();
    ind.add_sample(f);
  }
  Indicators out;
  ind.finish(out);
  // the band is 2 diameters deep, so its occupancy halves where the chord is one diameter
  // inside the circle: about 1.5 deg from the ends, plus the 2 deg bins
  CHECK(out.toe_deg == Approx(225).margin(4));
  CHECK(out.shoulder_deg == Approx(45).margin(4));
  CHECK(out.charge_area_m2 == Approx(kPiT / 2).epsilon(0.05));  // half the circle
  CHECK(out.n_layers > 10);
  CHECK(out.com_angle_deg == Approx(360 + std::atan2(MY, MX) * 180 / kPiT).margin(1));  // 315 deg
  CHECK(out.com_radius_m == Approx(std::hypot(MX, MY) / M).epsilon(0.02));
  // centroid of a half disc: 4 R / (3 pi) from the centre
  CHECK(std::hypot(MX, MY) / M == Approx(4 / (3 * kPiT)).epsilon(0.03));
  // the lattice turns rigidly with the mill: every layer at the mill speed
  for (double v : out.layer_speed_rpm) CHECK(v == Approx(60 / (2 * kPiT)).epsilon(1e-9));
}
