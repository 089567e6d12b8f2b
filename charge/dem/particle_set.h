// particle_set.h - the discs that stand for a mill charge in the 2D slice:
// balls and a rock size distribution, optionally coarse-grained, with the
// documented mass scaling (docs/models/dem.md §3).
#pragma once

#include <string>
#include <vector>

#include "charge/charge_spec.h"
#include "charge/dem/dem_spec.h"

namespace linerlife {

enum class Material : unsigned char { Ball = 0, Rock = 1 };

/// The discs of one charge, before placement.
struct ParticleSet {
  std::vector<double> radius_m;       // [m] simulated disc radius (coarse-grained)
  std::vector<double> mass_kg_per_m;  // [kg/m] disc mass per metre of length
  std::vector<double> real_diameter_m;  // [m] the ball or rock a disc stands for (radius * 2 / coarse_grain)
  std::vector<double> real_mass_kg;     // [kg] mass of that 3D ball or rock, rho pi d^3 / 6
  std::vector<Material> material;
  double coarse_grain = 1;            // [-] s
  double density_scale = 1;           // [-] (1 - E) / phi_2D: disc mass = this x rho x disc area
  int n_balls = 0, n_rocks = 0;
  double ball_mass_kg_per_m = 0;      // [kg/m] all balls
  double rock_mass_kg_per_m = 0;      // [kg/m] all rocks
  int size() const { return static_cast<int>(radius_m.size()); }
};

/// The largest real (not coarse-grained) disc diameter make_particle_set()
/// draws for this charge: the ball diameter, or the largest rock where the
/// charge has rocks (filling > ball_filling).
double largest_real_diameter_m(const ChargeSpec& charge, const DemSpec& spec);

/// How many discs make_particle_set() draws for this charge (below), balls
/// and rocks, without drawing them: a run can refuse a charge of millions of
/// discs before it allocates them.
struct DiscCount {
  double balls = 0, rocks = 0;
  double total() const { return balls + rocks; }
};
DiscCount count_discs(const ChargeSpec& charge, const DemSpec& spec, double free_area_m2);

/// Discs for `charge` in a mill whose free area (inside the liner) is
/// free_area_m2 [m2]:
///  - the balls fill J_B free_area and the rocks (J - J_B) free_area as bulk
///    area, at the 2D packing fraction phi_2D of spec.packing_fraction_2d:
///    count = phi_2D x bulk area / mean disc area;
///  - each disc of diameter d has mass rho (1 - E) / phi_2D x pi d^2 / 4 per
///    metre, so the slice holds the 3D charge mass per metre, rho (1 - E) J A;
///  - ball diameters are uniform in [d_B (1 - spread), d_B]; rocks follow the
///    Gates-Gaudin-Schuhmann distribution P(d) = (d / d_max)^m truncated to
///    [d_min, d_max] (area share = mass share by Delesse's principle), in 6
///    geometric classes with uniform diameters inside each;
///  - coarse-graining by s multiplies every diameter by s and divides the
///    count by s^2 (Bierwisch et al. 2009).
/// The order is shuffled with `seed` (a splitmix64/xorshift generator whose
/// output is the same on every platform).
ParticleSet make_particle_set(const ChargeSpec& charge, const DemSpec& spec, double free_area_m2,
                              unsigned long long seed);

/// A small portable random generator (xoshiro256** seeded by splitmix64;
/// Blackman & Vigna 2018): the same sequence on every compiler, unlike the
/// std:: distributions.
class DemRandom {
 public:
  explicit DemRandom(unsigned long long seed);
  unsigned long long next();
  double uniform();  // [0, 1)
 private:
  unsigned long long s_[4];
};

}  // namespace linerlife
