// wear_spec.h - how wear is computed: which laws, their parameters, the
// calibration and amplification factors of thesis Table B.1, and the
// settings of the coupled wear run. The [wear] section of the input file
// (app/config_schema_wear.cpp) fills it; docs/models/wear.md describes it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "wear/smoothing.h"

namespace linerlife {

struct WearSpec {
  /// Laws by name from the table wear_laws() (e.g. "abrasion/radziszewski",
  /// "impact/sheldon_kanhere"); their wear adds up. Empty: no wear.
  /// Default: abrasion and Sheldon-Kanhere impact wear (thesis Table B.1
  /// Method 0, the one the thesis used).
  std::vector<std::string> laws = {"abrasion/radziszewski", "impact/sheldon_kanhere"};
  /// Law parameters by their [wear] key (WearLawEntry::parameters); a key
  /// not given takes the table's default.
  std::map<std::string, double> parameters;
  std::map<std::string, std::string> choices;  // parameters that are names (e.g. radziszewski_slip)

  // Thesis Table B.1 (CalifCF, CalifGF, CalifImp): multiply the wear from
  // the centrifugal and gravitational parts of the normal force and from
  // impacts. 1: no calibration.
  double calibration_centrifugal = 1;    // [-] > 0
  double calibration_gravitational = 1;  // [-] > 0
  double calibration_impact = 1;         // [-] > 0
  // Table B.1 (AbrWear / ImpWear Amplification): time acceleration of the
  // coupled wear run (Qiu 2001 and the thesis: 1e7 over about 1.5
  // revolutions). recession_rates() does not apply them; the wear run does.
  double amplification_abrasion = 1;  // [-] > 0
  double amplification_impact = 1;    // [-] > 0

  // The coupled wear run (`linerlife wear`, thesis chapter 5).
  std::string liner_computation = "one";  // Table B.1 LinerComputation: "one" liner (copied to its like) | "all"
  bool feedback = false;                  // Table B.1 FeedBack: re-drive the charge on the worn profile
  double revolutions = 1.5;               // [-] mill revolutions simulated (Qiu 2001: about 1.5)
  int remesh_every_steps = 10;            // [-] charge time steps between two remeshes
  int feedback_every_steps = 0;           // [-] steps between two charge drives with feedback; 0: at every remesh
  double drive_revolutions = 1.0;         // [-] revolutions each charge drive averages its loads over
  int snapshots = 5;                      // [-] profiles stored between the initial and the final one
  SmoothingSpec smoothing;                // applied to the depth of each remesh
};

}  // namespace linerlife
