// Checks that two charge-model runs are the same run, bit for bit: the
// indicators, the liner loads and every impact. Shared by the tests that
// compare two ways of computing one run (incremental against full sweeps in
// the layer model, thread counts in the DEM).
#pragma once

#include <cmath>

#include <catch2/catch.hpp>

#include "charge/charge_model.h"

namespace linerlife::test {

/// x and y are the same value (both NaN counts: a figure a model does not give).
inline bool same_value(double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); }

inline void check_same_run(const ChargeResult& a, const ChargeResult& b) {
  CHECK(same_value(a.indicators.toe_deg, b.indicators.toe_deg));
  CHECK(same_value(a.indicators.shoulder_deg, b.indicators.shoulder_deg));
  CHECK(same_value(a.indicators.net_power_w_per_m, b.indicators.net_power_w_per_m));
  CHECK(same_value(a.indicators.net_power_kw, b.indicators.net_power_kw));
  CHECK(same_value(a.indicators.alt_net_power_kw, b.indicators.alt_net_power_kw));
  CHECK(same_value(a.indicators.com_radius_m, b.indicators.com_radius_m));
  CHECK(a.indicators.lifter_normal_force_n_per_m == b.indicators.lifter_normal_force_n_per_m);
  CHECK(a.stats.flights == b.stats.flights);
  CHECK(a.loads.normal_force_n_per_m == b.loads.normal_force_n_per_m);
  CHECK(a.loads.shear_work_rate_w_per_m == b.loads.shear_work_rate_w_per_m);
  REQUIRE(a.loads.impacts.size() == b.loads.impacts.size());
  for (size_t i = 0; i < a.loads.impacts.size(); ++i) {
    CHECK(a.loads.impacts[i].element == b.loads.impacts[i].element);
    CHECK(a.loads.impacts[i].normal_speed_m_s == b.loads.impacts[i].normal_speed_m_s);
  }
}

}  // namespace linerlife::test
