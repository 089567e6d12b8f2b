// liner_loads.h - what the charge does to the liner, per surface element,
// time-averaged over a run (DESIGN.md §2). Every charge model fills it; every
// wear law reads it.
//
// All forces and rates are per metre of mill length (the models are 2D
// slices, DESIGN.md §3). Element index i refers to LinerSurface element i of
// the surface the run was made on.
#pragma once

#include <cstddef>
#include <vector>

namespace linerlife {

/// One class of impacts on the liner: identical impacts arriving at a rate.
/// A model may report every impact as its own event (rate = 1 / duration) or
/// lump identical ones.
struct ImpactEvent {
  int element = 0;                    // surface element hit
  double normal_speed_m_s = 0;        // [m/s] relative speed along the inward normal at contact onset, > 0
  double tangential_speed_m_s = 0;    // [m/s] relative speed along the element (magnitude)
  double mass_kg = 0;                 // [kg] impacting mass (a ball, or an agglomerated element per metre of length)
  double diameter_m = 0;              // [m] size of the impacting body (for crater / contact-time models)
  double rate_per_s = 0;              // [1/s] how often this impact happens, per metre of mill length
  bool direct = false;                // thrown from the shoulder straight onto the liner (not through the charge)
  // impact angle from the surface: atan2(normal_speed, tangential_speed)
};

struct LinerLoads {
  double duration_s = 0;  // [s] simulated time the averages cover
  int n_elements = 0;
  // Per element, time averages over duration_s:
  std::vector<double> normal_force_n_per_m;         // [N/m] compressive, >= 0
  std::vector<double> centrifugal_force_n_per_m;    // [N/m] the centrifugal part of normal_force (thesis eq. 5.1); 0 if not split
  std::vector<double> gravitational_force_n_per_m;  // [N/m] the gravitational part (thesis eq. 5.2); 0 if not split
  std::vector<double> shear_force_n_per_m;          // [N/m] tangential force magnitude
  std::vector<double> slip_speed_m_s;               // [m/s] load-weighted relative sliding speed: <N v> / <N>, 0 where unloaded
  std::vector<double> normal_slip_power_w_per_m;    // [W/m] <N v_slip>, for laws of the form N x v (thesis eq. 5.4)
  std::vector<double> shear_work_rate_w_per_m;      // [W/m] <F_t v_slip>, for Archard on shear work (Qiu 2001)
  std::vector<ImpactEvent> impacts;
  bool has_impacts = false;  // the model resolves impacts (a law that needs them refuses a model that does not)

  /// Sized for n elements, all zero.
  void reset(int n, double duration);
};

inline void LinerLoads::reset(int n, double duration) {
  n_elements = n;
  duration_s = duration;
  for (auto* v : {&normal_force_n_per_m, &centrifugal_force_n_per_m, &gravitational_force_n_per_m,
                  &shear_force_n_per_m, &slip_speed_m_s, &normal_slip_power_w_per_m, &shear_work_rate_w_per_m})
    v->assign(static_cast<size_t>(n), 0.0);
  impacts.clear();
}

}  // namespace linerlife
