// wear_results.h - the summary and the results file of a coupled wear run
// (`linerlife wear`; layout in docs/models/wear.md §7). Shared by the command
// and bench/, which draws the same charts from a test-double charge model.
#pragma once

#include <string>

#include "app/config.h"
#include "app/json.h"
#include "wear/wear_run.h"

namespace linerlife {

/// The --json summary of a run: at least mass_loss_kg_per_m,
/// liner_mass_kg_per_m (after), max_recession_m, impact_fraction,
/// lifter_height_m and face_angle_leading_deg (after), simulated_s, wall_s,
/// realtime_ratio. `mill` is the mill as run (its rotation decides which face leads).
Json wear_summary(const Config& c, const WearRunResult& r, const Mill& mill, const std::string& model_name);

/// Writes wear.h5 at `path` (truncating): run header, summary, the initial,
/// final and snapshot profiles, the wear history per liner and contribution,
/// the last recession rates, and the final profiles of the abrasion-only and
/// impact-only companion runs when given (thesis Figs. 5-16, 5-17).
void write_wear_h5(const std::string& path, const Config& c, const Json& summary, const WearRunResult& r,
                   const WearRunResult* abrasion_only, const WearRunResult* impact_only);

}  // namespace linerlife
