// The thesis' n x n lifter grid (§5.6) as bookkeeping behind the surface.
#include <catch2/catch.hpp>

#include "fixtures.h"
#include "geometry/lifter_grid.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"

using namespace linerlife;
using namespace linerlife::test;

TEST_CASE("the lifter grid holds the lifter and balances with the segment", "[geometry][grid]") {
  const LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  const LifterGridSpec spec = lifter_grid_spec(s, 0, 60);
  const LifterGrid g = fill_lifter_grid(spec, s);
  REQUIRE(g.fraction.size() == 3600u);
  // eq. 5.30: cell size = extent / n
  CHECK(spec.dy * 60 == Approx(0.075 + 0.25).epsilon(1e-9));
  // material bookkeeping: grid + plate = the segment
  CHECK(g.grid_area_m2 + g.plate_area_m2 == Approx(segment_area(s, 0)).epsilon(1e-12));
  CHECK(g.plate_area_m2 > 0);
  // the middle column is solid up to the top (the bottom cell loses the sliver
  // under the curved shell), the corners above the feet are empty
  for (int j = 1; j < 60; ++j) CHECK(g.fraction_at(30, j) == Approx(1.0).margin(1e-9));
  CHECK(g.fraction_at(30, 0) == Approx(1.0).margin(1e-3));
  CHECK(g.fraction_at(0, 59) == 0.0);
  CHECK(g.fraction_at(59, 59) == 0.0);
  for (double f : g.fraction) {
    CHECK(f >= 0.0);
    CHECK(f <= 1.0);
  }
  // eq. 5.29
  CHECK(g.cell_mass_kg(30, 10, 7800, 5.0) == Approx(7800 * spec.dx * spec.dy * 5.0));
  // the grid area is the lifter plus the plate under it: close to the trapezoid
  // (0.15 + 0.345) / 2 x 0.25 plus 0.075 x its base width
  CHECK(g.grid_area_m2 > 0.06);
  CHECK(g.grid_area_m2 < 0.11);
}

TEST_CASE("wear empties the top rows of the grid and mass follows the surface", "[geometry][grid]") {
  LinerSurface s = build_liner_surface(qiu_mill(), qiu_liner());
  const LifterGridSpec spec = lifter_grid_spec(s, 0, 40);
  const LifterGrid g0 = fill_lifter_grid(spec, s);
  std::vector<double> d(s.n_nodes(), 0.0);
  for (int i = 0; i < s.n_nodes(); ++i)
    if (5.18 - s.nodes[i].norm() > 0.2) d[i] = 0.05;
  const RemeshResult r = remesh(s, d, RemeshOptions{0.01});
  const LifterGrid g1 = fill_lifter_grid(spec, r.surface);
  // the top row (0.317-0.325 m) is gone; the bottom rows are untouched
  double top = 0, bottom0 = 0, bottom1 = 0;
  for (int i = 0; i < 40; ++i) {
    top += g1.fraction_at(i, 39);
    bottom0 += g0.fraction_at(i, 3);
    bottom1 += g1.fraction_at(i, 3);
  }
  CHECK(top == 0.0);
  CHECK(bottom1 == Approx(bottom0).epsilon(1e-12));
  // the mass the grid lost is what the surface lost in this segment
  const double lost_grid = (g0.grid_area_m2 + g0.plate_area_m2) - (g1.grid_area_m2 + g1.plate_area_m2);
  CHECK(lost_grid == Approx(segment_area(s, 0) - segment_area(r.surface, 0)).epsilon(1e-9));
  CHECK(g0.grid_area_m2 - g1.grid_area_m2 > 0.9 * lost_grid);
}
