// charge_spec.h - what is in the mill and which charge model moves it.
#pragma once

#include <string>

#include "charge/dem/dem_spec.h"

namespace linerlife {

/// The mill charge (reference/charge-models.md §1 symbols in brackets).
struct ChargeSpec {
  double filling = 0;               // [-] J, total charge as a fraction of the volume inside the liners
  double ball_filling = 0;          // [-] J_B, balls as a fraction of that volume
  double ball_diameter_m = 0;       // [m] grinding media (the largest ball)
  double ball_density_kg_m3 = 0;    // [kg/m3] rho_b
  double ore_density_kg_m3 = 0;     // [kg/m3] rho_o
  double porosity = 0.4;            // [-] E, voids in the charge bed (Morrell 1996)
};

/// The charge model chosen by name (DESIGN.md §2).
struct ModelSpec {
  std::string charge = "layer";   // "empirical" | "layer" | "dem"
  std::string variant = "1.2";    // layer model version of thesis §4.6: "1.0" | "1.1" | "1.2"
  double time_step_s = 0.01;      // [s] time step of the layer model
  DemSpec dem;                    // the [dem] section: parameters of the DEM model
};

}  // namespace linerlife
