// plots.h - charts are drawn by matplotlib (DESIGN.md §4) from the results
// file, by app/plots/linerlife_plot.py run with Debian's /usr/bin/python3.
#pragma once

#include <string>

namespace linerlife {

/// Runs the plotting script: `kind` names the chart set ("geometry", ...),
/// `results_h5` the file to read, `out_dir` where the PNGs go (each written
/// atomically by the script). Returns false, after a warning on stderr, when
/// the charts could not be drawn; the results file is unaffected.
bool draw_charts(const std::string& kind, const std::string& results_h5, const std::string& out_dir);

}  // namespace linerlife
