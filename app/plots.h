// plots.h - charts are drawn by matplotlib (DESIGN.md §4) from the results
// file, by app/plots/linerlife_plot.py run with Debian's /usr/bin/python3.
#pragma once

#include <string>
#include <vector>

namespace linerlife {

/// Runs the plotting script: `kind` names the chart set ("geometry", ...),
/// `results_h5` the file to read, `out_dir` where the PNGs go (each written
/// atomically by the script). Returns false, after a warning on stderr, when
/// the charts could not be drawn; the results file is unaffected.
bool draw_charts(const std::string& kind, const std::string& results_h5, const std::string& out_dir);

/// The exit status of the plotting script (linerlife_plot.py: 0 drawn, 3 the
/// file lacks what its kind has, 4 a dataset it draws holds a NaN or an
/// infinite value, other the environment), -1 if the script is not found; no
/// warning printed. `report`, when given, gets what the script printed on its
/// standard output (with 4: "DATASET: what is wrong"), without the last newline.
int run_plot_script(const std::string& kind, const std::string& results_h5, const std::string& out_dir,
                    std::string* report = nullptr);

/// The charts plot_forecast.py draws (its CHARTS). A failed forecast removes
/// them beside its partial forecast.h5 without running Python (they would be
/// read as its own), so the names are written here too; a test checks the two
/// lists agree ("the forecast charts a partial run removes are the ones
/// plot_forecast.py draws").
inline constexpr const char* kForecastCharts[] = {"forecast_profiles.png", "forecast_lifter.png",
                                                  "forecast_charge.png"};

/// The kinds of results file that have charts (a plot_KIND.py next to the
/// plotting script), sorted.
std::vector<std::string> chart_kinds();

}  // namespace linerlife
