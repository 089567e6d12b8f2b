// charge_spec.h - what is in the mill and which charge model moves it.
#pragma once

#include <string>

#include "charge/dem/dem_spec.h"

namespace linerlife {

/// How the mill discharges (Morrell 1996): a grate keeps the slurry level at
/// the toe; an overflow mill holds a slurry pool up to the trunnion.
enum class Discharge { Grate, Overflow };

/// The mill charge (reference/charge-models.md §1 symbols in brackets).
struct ChargeSpec {
  double filling = 0;               // [-] J, total charge as a fraction of the volume inside the liners
  double ball_filling = 0;          // [-] J_B, balls as a fraction of that volume
  double ball_diameter_m = 0;       // [m] grinding media (the largest ball)
  double ball_density_kg_m3 = 0;    // [kg/m3] rho_b
  double ore_density_kg_m3 = 0;     // [kg/m3] rho_o
  double porosity = 0.4;            // [-] E, voids in the charge bed (Morrell 1996)
  // Added by the charge-motion issue (Morrell's C-model needs them):
  double slurry_void_fill = 0;      // [-] U, fraction of the bed voids filled with slurry (0: dry charge)
  double slurry_solids_mass_fraction = 0.7;  // [-] mass fraction of solids in the slurry
  Discharge discharge = Discharge::Grate;
  double trunnion_radius_m = 0;     // [m] r_t; sets the slurry pool of an overflow mill and the cone power
  double cone_length_m = 0;         // [m] L_d, length of one cone end (0: flat ends)
};

/// The charge model chosen by name (DESIGN.md §2).
struct ModelSpec {
  std::string charge = "layer";   // "empirical" | "layer" | "dem"
  std::string variant = "1.2";    // layer model version of thesis §4.6: "1.0" | "1.1" | "1.2"
  double time_step_s = 0.005;     // [s] time step of the layer model (default from the study in docs/models/layer.md)
  // Added by the charge-motion issue (layer model, docs/models/layer.md):
  std::string slip_model = "morrell";   // layer speeds: "morrell" (thesis eq. 4.16) | "radziszewski" (eqs. 5.5-5.7)
  double slip_parameter = 0.005;        // [-] delta of the Radziszewski slip law (eq. 5.7)
  double friction_coefficient = 0.5;    // [-] mu of McIvor's flight angle (thesis eq. 4.5), ball on lifter face
  double repose_angle_deg = 35.0;       // [deg] dynamic angle of repose: foot stability and V-1.1 clipping
  bool slurry_drag = false;             // drag of the slurry pool on flights (overflow mills only)
  bool lifter_slide = false;            // balls slide out along the lifter face before flying (Powell 1991)
  bool pocket_loads = false;            // layer model: the lifter faces carry the tangential weight of the charge
                                        //     in the pockets (docs/models/layer.md §7, "Pocket loads")
  double settle_revolutions = 1.0;      // [-] revolutions run before averaging starts (docs/models/layer.md §Settling)
  std::string initial_phases = "staggered";  // layer model at t = 0: "staggered" (each layer turned by a different
                                             //     fraction of its slot) | "aligned" (slot 0 of every layer at angle 0)
  double hf_lift_angle_deg = 45.0;      // [deg] lift angle alpha of the Hogg-Fuerstenau power figure
  double element_size_diameters = 1.0;  // [-] studies only: layer model's element edge in media diameters
                                        //     (agglomerated elements, thesis §4.4.5; docs/models/layer.md §1)
  double load_contact_spacing_m = 0;    // [m] studies only: layer model's contact rays for the liner loads, at
                                        //     most this far apart (0: load_contact_spacing_m() of the surface,
                                        //     2 mm or finer; docs/models/layer.md §Liner loads)
  double unheld_friction_coefficient = -1;  // [-] studies only: mu of McIvor's angle with beta = 0 for the
                                           //     layers no lifter holds (< 0: friction_coefficient;
                                           //     0: Davis' angle; docs/models/layer.md §3, "The release study")
  double held_pocket_balls = -1;        // [-] studies only: < 0, every element of a lifter-held layer leaves at its
                                        //     lifter's angle (the thesis); >= 0, only those within this many
                                        //     element widths of the foot of the leading face, the rest as unheld
                                        //     (docs/models/layer.md §3, "The release study")
  double inner_radius_beta = -1;        // [-] studies only: the en-masse share beta in eq. 4.14 (< 0: Morrell's,
                                        //     from his flight time; docs/models/layer-worn.md, "The en-masse share
                                        //     of eq. 4.14"); sets r_i, so version 1.2's band and every version's slip
  double relaxation_interval_cells = 0.5;  // [-] layer model: support sweep and surface relaxation every this many
                                         //     outer cells of shell travel (docs/models/layer.md §9)
  double max_courant = 0;               // [-] studies only: shell travel per step / media diameter allowed
                                        //     before sub-stepping (0: the model's own limit)
  bool incremental_maps = true;         // tests only: false makes every column map, support sweep and
                                        //     relaxation pass of the layer model a full one, and sample()
                                        //     take every slot's liner angle by atan2 (the references its
                                        //     incremental bookkeeping and shortcuts must reproduce exactly)
  DemSpec dem;                    // the [dem] section: parameters of the DEM model
};

}  // namespace linerlife
