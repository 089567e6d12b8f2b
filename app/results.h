// results.h - pieces of the HDF5 results files shared by the commands
// (layout: docs/output.md).
#pragma once

#include <string>

#include "app/config.h"
#include "app/h5_writer.h"
#include "geometry/lifter_grid.h"
#include "geometry/liner_surface.h"
#include "forecast/forecast.h"
#include "geometry/metrics.h"

namespace linerlife {

/// Root attributes (program, version, command, created, config source) and
/// /config (the resolved configuration as TOML).
void write_run_header(H5Writer& h5, const Config& c, const std::string& command);

/// group/nodes, normal, length, segment_begin, segment_design (+ attributes).
void write_surface(H5Writer& h5, const std::string& group, const LinerSurface& s);

/// group/ring attributes and per-segment arrays.
void write_metrics(H5Writer& h5, const std::string& group, const LinerMetrics& m);

/// group/fraction (ny x nx) and the grid's placement.
void write_lifter_grid(H5Writer& h5, const std::string& group, const LifterGrid& g, double density_kg_m3,
                       double length_m);

/// group/summary attrs, group/history/* (one dataset per LifeRecord field),
/// group/profiles (all profile snapshots: nodes concatenated, with offsets
/// and hours), group/stats attrs.
void write_forecast(H5Writer& h5, const std::string& group, const ForecastResult& f, const ForecastSpec& spec);

}  // namespace linerlife
