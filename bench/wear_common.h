// wear_common.h - the Qiu mill as a wear-run input, for the wear benchmarks.
#pragma once

#include "app/config.h"
#include "geometry/build_liner_surface.h"
#include "wear/wear_run.h"

namespace linerlife::bench {

/// The wear run of configuration `c` as `linerlife wear` sets it up.
inline WearRunInput wear_input(const Config& c) {
  WearRunInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.surface = build_liner_surface(c.mill, c.liner);
  in.material = c.material;
  in.wear = c.wear;
  in.remesh.element_size_m = c.liner.element_size_m;
  return in;
}

}  // namespace linerlife::bench
