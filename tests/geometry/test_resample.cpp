#include <catch2/catch.hpp>

#include "fixtures.h"
#include "geometry/resample.h"

using namespace linerlife;
using namespace linerlife::test;
using V = Eigen::Vector2d;

namespace {
/// area between an open polyline and the chord joining its ends
double area_under(const std::vector<V>& p) { return polygon_area(p); }
}  // namespace

TEST_CASE("long elements are split into equal parts without changing the area", "[geometry][resample]") {
  const std::vector<V> p{{0, 0}, {1, 0}, {1, 0.3}, {0.2, 0.5}};
  const auto q = resample_polyline(p, 0.1);
  CHECK(q.front() == p.front());
  CHECK(q.back() == p.back());
  for (size_t i = 0; i + 1 < q.size(); ++i) CHECK((q[i + 1] - q[i]).norm() <= 0.1 + 1e-12);
  CHECK(area_under(q) == Approx(area_under(p)).epsilon(1e-12));
}

TEST_CASE("slivers and collinear points are merged with a negligible area change", "[geometry][resample]") {
  const double h = 0.01;
  std::vector<V> p{{0, 0}, {0.009, 0}, {0.0091, 0.00001}, {0.018, 0.0000}, {0.027, 0.00005}, {0.03, 0.008}};
  const auto q = resample_polyline(p, h);
  CHECK(q.size() < p.size());
  for (size_t i = 0; i + 1 < q.size(); ++i) CHECK((q[i + 1] - q[i]).norm() >= 0.15 * h);
  CHECK(std::abs(area_under(q) - area_under(p)) < 0.01 * h * h);
  // removing vertices only takes material away: for a polyline running
  // anticlockwise with the charge on its left (here +y, where area_under
  // measures), the charge side never shrinks
  CHECK(area_under(q) >= area_under(p) - 1e-18);
  // a corner is kept even next to a short element
  const std::vector<V> corner{{0, 0}, {0.01, 0}, {0.0101, 0.01}, {0.0101, 0.02}};
  const auto c = resample_polyline(corner, h);
  CHECK(std::abs(area_under(c) - area_under(corner)) < 0.01 * h * h);
}
