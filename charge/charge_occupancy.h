// charge_occupancy.h - the mill indicators that every charge model shares,
// defined on the time-averaged occupancy of the cross-section in polar bins
// (docs/models/indicators.md). Model-independent on purpose: the layer model
// feeds its elements, a particle model (DEM) feeds its particles, and both get
// the same toe, shoulder, centre of mass, charge area and number of layers.
//
// Bins: rings of width d (the media diameter) counted inwards from the liner
// radius R (radius of the circle with the free area; anything outside R, i.e.
// between lifters, falls in ring 0), each cut into angular bins about d long
// at its mid-radius, so that every bin holds about one media-sized body.
// Angles in degrees in the physical mill frame (DESIGN.md §3).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "charge/exact_math.h"

namespace linerlife {

struct OccupancyIndicators {
  double toe_deg = 0;          // [deg] start of the occupied arc next to the liner, in the direction of rotation
  double shoulder_deg = 0;     // [deg] its end
  double com_angle_deg = 0;    // [deg] centre of mass of the en-masse region
  double com_radius_m = 0;     // [m]
  double charge_area_m2 = 0;   // [m2] area of the en-masse region
  int n_layers = 0;            // en-masse depth along the radius through the centre of mass, in media diameters
  double threshold = 0;        // [-] occupancy above which a bin is en masse
  bool valid = false;          // false when nothing was sampled or no occupied arc was found
};

class ChargeOccupancy {
 public:
  /// liner_radius_m: R; media_diameter_m: d; sense: +1 anticlockwise mill,
  /// -1 clockwise. Positions passed to add() are in the physical frame.
  ChargeOccupancy(double liner_radius_m, double media_diameter_m, double sense);

  /// One body (element or particle) in one sample: centre p [m], area [m2 per
  /// m of length], mass [kg per m], weighted by the sample duration w [s].
  /// The centre of mass is that of the time-averaged mass of the en-masse
  /// bins, each bin's mass placed at the bin centre.
  void add(const Eigen::Vector2d& p, double area_m2, double mass_kg, double w_s) {
    add_polar(p, std::atan2(p.y(), p.x()), p.norm(), area_m2, mass_kg, w_s);
  }
  void add_polar(const Eigen::Vector2d& p, double theta_rad, double r_m, double area_m2, double mass_kg, double w_s);
  /// Low-level: adds w * area and w * mass to bin (j, i) directly (for models
  /// whose bodies sit on the rings, like the layer model's elements).
  void add_to_bin(int j, int i, double area_w, double mass_w) {
    const size_t k = index(j, i);
    acc_area_[k] += area_w;
    acc_m_[k] += mass_w;
  }
  /// Low-level: a body moving round ring j at constant angular speed from
  /// angle theta0 to theta1 >= theta0 [rad] (unwrapped), spending
  /// `seconds_per_rad` [s/rad]: each bin it crosses gets area and mass times
  /// the time it spent there. Exact time integration for bodies that move
  /// rigidly round the axis (the layer model's en-masse elements).
  void add_arc(int j, double theta0, double theta1, double seconds_per_rad, double area_m2, double mass_kg);
  /// Ring j holding radius r [m].
  int ring(double r_m) const {
    const int j = static_cast<int>((R_ - r_m) * inv_d_);
    return r_m >= R_ ? 0 : (j >= nr_ ? nr_ - 1 : j);
  }
  /// Adds w [s] to the sampled time (call once per sample).
  void add_time(double w_s) { time_s_ += w_s; }

  OccupancyIndicators evaluate() const;

  int n_rings() const { return nr_; }
  int n_angular(int j) const { return nt_[j]; }
  double media_diameter() const { return d_; }
  double liner_radius() const { return R_; }
  /// Time-averaged occupied fraction of bin (j, i): ring j from the liner,
  /// angular bin i from 0 rad (bin width 2 pi / n_angular(j)).
  double occupancy(int j, int i) const;
  double bin_area(int j) const { return area_[j]; }
  double ring_mid_radius(int j) const { return R_ - (j + 0.5) * d_; }
  /// Angular bin of ring j holding angle theta [rad] (inline, floor without
  /// the libm call: sample() asks for one per flight).
  int angular_bin(int j, double theta_rad) const {
    int i = floor_int(theta_rad * inv_dth_[j]);
    const int n = nt_[j];
    if (i >= 0 && i < n) return i;
    i %= n;
    return i < 0 ? i + n : i;
  }
  double sampled_time() const { return time_s_; }

 private:
  size_t index(int j, int i) const { return static_cast<size_t>(off_[j] + i); }
  double R_, d_, sense_;
  int nr_ = 0;
  std::vector<int> nt_, off_;            // angular bins and first bin of each ring
  std::vector<double> inv_dth_;         // [1/rad] per ring
  double time_s_ = 0;
  std::vector<double> area_;            // per ring, one angular bin
  std::vector<double> acc_area_;        // sum w * area, per bin
  std::vector<double> acc_m_;           // sum w * m
  double inv_d_ = 0;
};

}  // namespace linerlife
