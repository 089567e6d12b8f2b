// checkpoint_file.h - a forecast's checkpoint in DIR/checkpoint.h5 (issue 7
// §1): written atomically, read back bit for bit, tied to the configuration
// it was made with.
#pragma once

#include <string>

#include "app/output_dir.h"
#include "forecast/forecast.h"

namespace linerlife {

/// Writes `c` with the resolved configuration text to dir/checkpoint.h5
/// (temporary name, then rename).
void write_checkpoint(const OutputDir& dir, const std::string& config_text, const ForecastCheckpoint& c);

/// Reads the checkpoint at `path` for a run of `in` with `spec`; throws
/// InputError naming the file (and the dataset) if it was made with another
/// configuration or program version, cannot be read, or is damaged: its
/// arrays inconsistent with each other or with the run
/// (checkpoint_problem(), forecast/forecast.h).
ForecastCheckpoint read_checkpoint(const std::string& path, const std::string& config_text, const ForecastInput& in,
                                   const ForecastSpec& spec);

}  // namespace linerlife
