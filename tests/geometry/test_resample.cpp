#include <cmath>
#include <list>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "fixtures.h"
#include "geometry/resample.h"

using namespace linerlife;
using namespace linerlife::test;
using V = Eigen::Vector2d;

namespace {
/// area between an open polyline and the chord joining its ends
double area_under(const std::vector<V>& p) { return polygon_area(p); }

/// resample_polyline as it was before 2026-12-04 (with that day's degenerate-element rule: any element
/// shorter than 1e-6 h goes): a scan of every vertex for
/// each one removed, O(n^2); the new one must give exactly its result.
std::vector<V> resample_by_scan(const std::vector<V>& pts, double h) {
  std::vector<V> p;
  // drop exact duplicates first
  for (const V& q : pts)
    if (p.empty() || (q - p.back()).norm() > 1e-12 * h) p.push_back(q);
  if (p.size() >= 2 && (pts.back() - p.back()).norm() > 0) p.back() = pts.back();

  // A vertex is removed only if that takes material away or changes nothing:
  // the polyline runs anticlockwise with the charge on its left, so removing a
  // vertex that lies left of the chord joining its neighbours cuts off a
  // triangle of liner; one to the right would add liner material, which wear
  // never does.
  const double min_len = 0.3 * h, max_tri = 0.01 * h * h;
  const double collinear = std::sin(0.5 * 3.14159265358979323846 / 180.0);
  bool changed = true;
  while (changed && p.size() > 2) {
    changed = false;
    int best = -1;
    double best_tri = 1e300;
    for (size_t i = 1; i + 1 < p.size(); ++i) {
      const V a = p[i] - p[i - 1], b = p[i + 1] - p[i];
      const double la = a.norm(), lb = b.norm();
      const double merged = (p[i + 1] - p[i - 1]).norm();
      const double signed_tri = 0.5 * (a.x() * b.y() - a.y() * b.x());  // > 0: vertex right of the chord
      // a degenerate element (shorter than 1e-6 h) always goes: the area it
      // can change, below 1e-6 h^2 / 2, is round-off against the liner's
      if (std::min(la, lb) < 1e-6 * h) {
        best = static_cast<int>(i);
        break;
      }
      if (signed_tri > 0) continue;
      const double tri = -signed_tri;
      const bool nearly_straight = la > 0 && lb > 0 && tri / (la * lb) * 2 < collinear && a.dot(b) > 0 && merged <= h;
      const bool short_and_small = std::min(la, lb) < min_len && tri < max_tri && merged <= h;
      if ((nearly_straight || short_and_small) && tri < best_tri) {
        best_tri = tri;
        best = static_cast<int>(i);
      }
    }
    if (best > 0) {
      p.erase(p.begin() + best);
      changed = true;
    }
  }
  std::vector<V> out{p.front()};
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    // elements may stretch to 1.25 h under wear before they are split, so a
    // plate that recedes does not double its node count
    const double len = (p[i + 1] - p[i]).norm();
    const int n = len > 1.25 * h ? static_cast<int>(std::ceil(len / h - 1e-9)) : 1;
    for (int j = 1; j < n; ++j) out.push_back(p[i] + (p[i + 1] - p[i]) * (static_cast<double>(j) / n));
    out.push_back(p[i + 1]);
  }
  return out;
}
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

// A remesh's Boolean difference can give two vertices a few 1e-15 m apart
// (distinct exact points rounded to doubles) between elements of about h.
// The degenerate element went only where the merged one stayed within h, so
// here it stayed; it ran back on itself, and the next remesh refused the
// ring as crossing itself: every forecast of the bundled mill with
// element_size_m = 0.002 or 0.0015 ended with exit 3 after about 68 h.
TEST_CASE("a degenerate element between two elements longer than h is removed", "[geometry][resample]") {
  const double h = 0.002;
  const V b(1.003 * h, 0);
  const std::vector<V> p{{0, 0}, b, b + V(-2.4e-15, 1e-16), {2.006 * h, 0.0001 * h}};
  const auto q = resample_polyline(p, h);
  double shortest = 1;
  for (size_t i = 0; i + 1 < q.size(); ++i) shortest = std::min(shortest, (q[i + 1] - q[i]).norm());
  CHECK(shortest > 1e-6 * h);
  CHECK(q.front() == p.front());
  CHECK(q.back() == p.back());
  CHECK(std::abs(area_under(q) - area_under(p)) < 1e-6 * h * h);
}

TEST_CASE("resampling removes the vertices a scan of them all would, one by one", "[geometry][resample]") {
  // noisy and exact lines, arcs both ways, slivers, repeated points; and a
  // dense profile of 20,000 points (a measured profile as a scanner gives
  // it), which took seconds per segment when every removal rescanned them all
  std::mt19937 rng(20261204);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const double h = 0.01;
    const int n = 3 + static_cast<int>(rng() % 300);
    std::vector<V> p;
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      switch (trial % 4) {
        case 0: p.emplace_back(0.3 * t, 0.0); break;                                          // exactly straight
        case 1: p.emplace_back(0.3 * t, 1e-5 * noise(rng)); break;                            // a noisy scan
        case 2: p.emplace_back(0.5 * std::cos(t), (trial % 8 < 4 ? 1 : -1) * 0.5 * std::sin(t)); break;  // arcs
        default: p.push_back(i == 0 ? V(0, 0) : V(p.back() + V(0.004 * std::abs(noise(rng)), 0.003 * noise(rng))));
      }
      if (trial % 5 == 0 && i % 7 == 3) p.push_back(p.back());  // repeated points
    }
    INFO("trial " << trial);
    CHECK(resample_polyline(p, h) == resample_by_scan(p, h));
  }
  std::vector<V> dense;
  for (int i = 0; i < 20000; ++i) {
    const double t = i / 20000.0;
    dense.emplace_back(0.5 * t + 1e-6 * noise(rng), 0.075 + 0.25 * std::exp(-std::pow((t - 0.5) / 0.1, 2)));
  }
  const auto q = resample_polyline(dense, 0.01);
  CHECK(q.size() < dense.size());
  CHECK(q.front() == dense.front());
  CHECK(q.back() == dense.back());
}
