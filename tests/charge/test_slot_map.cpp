// SlotMap: the incremental map between two rings of cells of the layer
// model. Its queries must never miss a cell whose relation changes (the
// layer model's column map and support sweep rely on it), checked against
// brute force over many offsets and ring sizes.
#include <cmath>
#include <random>
#include <set>

#include <catch2/catch.hpp>

#include "charge/slot_map.h"

using namespace linerlife;

TEST_CASE("SlotMap::changed returns every cell whose lower cell changes", "[charge][slot_map]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const int sizes[][2] = {{250, 246}, {246, 250}, {60, 41}, {41, 60}, {97, 97}, {13, 7}};
  for (const auto& sz : sizes) {
    const int Sa = sz[0], Sb = sz[1];
    const double ratio = (2 * M_PI / Sa) * (Sb / (2 * M_PI));  // delta_a / delta_b
    const SlotMap map(Sa, Sb, ratio);
    for (int trial = 0; trial < 400; ++trial) {
      const double b0 = 0.5 + U(rng) * Sb;
      const double D = (U(rng) - 0.5) * 0.98;  // |D| < 0.49
      double b1 = b0 + D;
      if (b1 >= Sb + 0.5) b1 -= Sb;  // the offset is kept wrapped, as the model does
      if (b1 < 0.5) b1 += Sb;
      std::set<int> got;
      REQUIRE(map.changed(b0, D, [&](int s) { got.insert(s); }));
      int n_changed = 0;
      for (int s = 0; s < Sa; ++s)
        if (map.cell(s, b0) != map.cell(s, b1)) {
          ++n_changed;
          INFO("Sa " << Sa << " Sb " << Sb << " b0 " << b0 << " D " << D << " s " << s);
          CHECK(got.count(s) == 1);
        }
      // and not much more than that (a superset by the rounding slack only)
      CHECK(static_cast<int>(got.size()) <= n_changed + 2);
    }
  }
}

TEST_CASE("SlotMap::changed refuses a step too large to be reliable", "[charge][slot_map]") {
  const SlotMap map(100, 90, 0.9);
  int calls = 0;
  CHECK_FALSE(map.changed(3.0, 0.7, [&](int) { ++calls; }));
  CHECK(calls == 0);
}

TEST_CASE("SlotMap::over returns every upper cell over a lower cell", "[charge][slot_map]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  // the last two: a partial inner layer of a few wide cells under the outer
  // ring (ratio < 1/2), where b + s ratio wraps twice for b > S_b
  for (const auto& sz : {std::pair<int, int>{250, 246}, {41, 60}, {60, 41}, {232, 4}, {232, 46}}) {
    const int Sa = sz.first, Sb = sz.second;
    const SlotMap map(Sa, Sb, static_cast<double>(Sb) / Sa);
    for (int trial = 0; trial < 200; ++trial) {
      const double b = trial < 20 ? Sb + 0.5 * U(rng) : 0.5 + U(rng) * Sb;
      for (int k = 0; k < Sb; ++k) {
        std::set<int> got;
        map.over(k, b, [&](int s) { got.insert(s); });
        for (int s = 0; s < Sa; ++s)
          if (map.cell(s, b) == k) CHECK(got.count(s) == 1);
        CHECK(got.size() <= 2 * (static_cast<size_t>(std::ceil(1.0 / map.ratio())) + 2));
      }
    }
  }
}

TEST_CASE("SlotMap::across returns every cell that changes across a boundary", "[charge][slot_map]") {
  // the column map (LayerSim::update_columns()) finds the outer cells whose
  // lower cell changes between two cells of different occupancy from the
  // boundaries of the lower ring's occupancy: every cell whose lower cell
  // changes crosses the boundary between its old and new cell
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const auto& sz : {std::pair<int, int>{250, 246}, {41, 60}, {60, 41}, {232, 4}, {232, 46}, {97, 97}}) {
    const int Sa = sz.first, Sb = sz.second;
    const SlotMap map(Sa, Sb, static_cast<double>(Sb) / Sa);
    for (int trial = 0; trial < 300; ++trial) {
      const double b0 = trial < 30 ? Sb + 0.5 * U(rng) : 0.5 + U(rng) * Sb;
      const double D = (U(rng) - 0.5) * 0.98;  // |D| < 0.49
      double b1 = b0 + D;
      if (b1 >= Sb + 0.5) b1 -= Sb;  // kept wrapped, as the model does
      if (b1 < 0.5) b1 += Sb;
      const double lo = std::min(0.0, D), hi = std::max(0.0, D);
      for (int K = 0; K < Sb; ++K) {
        std::set<int> got;
        map.across(K, b0, lo, hi, [&](int s) { got.insert(s); });
        int n = 0;
        for (int s = 0; s < Sa; ++s) {
          const int c0 = map.cell(s, b0), c1 = map.cell(s, b1);
          if (c0 == c1) continue;
          // the boundary between c0 and c1 (adjacent, mod Sb): K is the upper one
          const int upper = (c1 == (c0 + 1) % Sb) ? c1 : c0;
          if (upper != K) continue;
          ++n;
          INFO("Sa " << Sa << " Sb " << Sb << " b0 " << b0 << " D " << D << " K " << K << " s " << s);
          CHECK(got.count(s) == 1);
        }
        CHECK(static_cast<int>(got.size()) <= n + 2 * (static_cast<int>(std::ceil(1.0 / map.ratio())) + 1));
      }
    }
  }
}
