// particle_indicators.h - the mill indicators of thesis §4.4 (Arekar 2004)
// from particle data: time-averaged occupancy in polar bins gives the toe,
// shoulder, en-masse area, centre of mass, centre of circulation, layers and
// trajectories; lifter forces come binned by the lifter's angle.
// Definitions and thresholds: docs/models/dem.md §5.
//
// Angles are in the physical frame (DESIGN.md §3): the particles are given in
// the mill frame, which for a clockwise mill is already the physical picture,
// so nothing is mirrored; `sense` only says which way the charge moves.
#pragma once

#include <utility>
#include <vector>

#include "charge/indicators.h"

namespace linerlife {

/// The documented parameters of the extraction (docs/models/dem.md §5).
struct ParticleIndicatorOptions {
  double band_bin_deg = 2.0;         // [deg] angular bins of the liner band (toe, shoulder)
  double band_depth_diameters = 2.0; // [-] the band reaches this many mean diameters inside the lifter crests
  double grid_bin_deg = 5.0;         // [deg] angular bins of the polar occupancy grid
  double en_masse_threshold = 0.5;   // [-] a bin is en masse at this share of the bed's packing fraction
  double flight_threshold = 0.1;     // [-] a layer is a trajectory where airborne discs fill this share of the bed packing
  double flight_window_deg = 30.0;   // [deg] trajectories are counted this far past the shoulder
  double layer_window_deg = 15.0;    // [deg] layer speeds: half-width of the sector through the centre of circulation
  double lifter_bin_deg = 5.0;       // [deg] lifter force bins
};

/// One instant of the charge (arrays of n discs).
struct ParticleFrame {
  int n = 0;
  const double* x = nullptr;   // [m] mill frame
  const double* y = nullptr;
  const double* vx = nullptr;  // [m/s]
  const double* vy = nullptr;
  const double* radius = nullptr;  // [m]
  const double* mass = nullptr;    // [kg/m]
  const int* contacts = nullptr;   // contacts of each disc (0: airborne)
};

/// The geometry the extraction needs.
struct ParticleIndicatorGeometry {
  double sense = 1;             // +1 anticlockwise mill, -1 clockwise
  double omega = 0;             // [rad/s] mill speed (magnitude)
  double r_eff = 0;             // [m] radius of the circle with the free area (metrics().effective_diameter_m / 2)
  double r_crest = 0;           // [m] nearest liner point to the axis (the lifter crests)
  double r_shell = 0;           // [m] shell radius
  double pocket_area = 0;       // [m2] free area outside the crest circle (between the lifters)
  double mean_diameter = 0;     // [m] number-mean disc diameter: the layer thickness
};

class ParticleIndicators {
 public:
  ParticleIndicators(const ParticleIndicatorGeometry& g, const ParticleIndicatorOptions& o = {});

  /// Adds one instant to the time averages.
  void add_sample(const ParticleFrame& f);

  /// Adds the force [N/m] one lifter row takes at one instant: its angular
  /// position [rad, mill frame], the force's component along the outward radial
  /// through the lifter (normal) and against the rotation (tangential).
  void add_lifter_force(double angle_rad, double normal_n_per_m, double tangential_n_per_m);

  /// Fills toe, shoulder, com, layers, trajectories, charge area, layer speeds
  /// and the lifter force curve of `out` (the other fields are left alone).
  void finish(Indicators& out) const;

  int samples() const { return samples_; }

  /// Time-averaged occupancy of the liner band (disc area over band area) at
  /// the centre angle [deg] of each band bin: the profile toe and shoulder are
  /// read from (for charts and the documentation).
  std::vector<std::pair<double, double>> band_profile() const;

 private:
  int ring_of(double r) const;
  int bin_of(int ring, double angle_rad) const;  // flat index of the bin of `ring` holding the angle
  ParticleIndicatorGeometry g_;
  ParticleIndicatorOptions o_;
  int samples_ = 0;
  // liner band
  int nb_ = 0;
  std::vector<double> band_area_;        // [m2 x samples] disc area with centres in each band bin
  // polar grid: rings of one mean diameter inside the crest circle; the outer
  // ring has sectors of grid_bin_deg, inner rings proportionally fewer, so every
  // bin has about the same arc length and area
  int nr_ = 0, ns_ = 0;
  std::vector<int> ring_off_, ring_ns_;  // flat index of each ring's first bin, its sector count
  std::vector<double> ring_bin_area_;    // [m2] area of one bin of each ring
  std::vector<double> grid_area_, grid_flight_area_;   // [m2 x samples]
  std::vector<double> grid_mass_, grid_mx_, grid_my_;  // [kg/m x samples], mass-weighted positions
  std::vector<double> grid_mvx_, grid_mvy_;            // momentum sums
  std::vector<double> grid_mw_;                        // mass-weighted angular velocity about the axis
  // pockets (outside the crest circle), per grid sector
  std::vector<double> pocket_mass_, pocket_mx_, pocket_my_;
  // lifter forces
  int nl_ = 0;
  std::vector<double> lift_n_, lift_t_;
  std::vector<int> lift_count_;
};

}  // namespace linerlife
