// bench_main.h - what the bench programs share: a [dem] key set from a
// command-line `key=value`, and main()'s exit codes for input (2) and
// simulation (3) failures, as the linerlife command uses them.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/config.h"
#include "geometry/errors.h"

namespace linerlife::bench {

/// Sets the [dem] key `k` of `c` from its text `v`; InputError if `k` is not one.
inline void set_dem_key(Config& c, const std::string& k, const std::string& v) {
  const KeySpec* spec = config_schema().find("dem", k);
  if (!spec) throw InputError(k, "not a [dem] key: " + k);
  const ConfigValue cv = spec->kind == ConfigValue::Kind::String ? ConfigValue::String(v)
                         : spec->kind == ConfigValue::Kind::Int  ? ConfigValue::Int(std::atoll(v.c_str()))
                                                                 : ConfigValue::Real(std::atof(v.c_str()));
  spec->set(c, cv);
}

/// The median of `v` (the mean of the middle two for an even count).
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Runs `body` and maps the failures to exit codes: input 2, simulation 3.
template <class F>
int guarded_main(F&& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::fprintf(stderr, "input error: %s\n", e.what());
    return 2;
  } catch (const SimulationError& e) {
    std::fprintf(stderr, "simulation failed: %s\n", e.what());
    return 3;
  }
}

}  // namespace linerlife::bench
