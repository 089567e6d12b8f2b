// liner_ride_table.h - the liner as a disc of the media size sees it, looked
// up by angle: for every polar angle psi of the liner frame, the largest radius
// at which the centre of a disc of radius a can sit without overlapping the
// liner polyline ("ride radius"), and the surface element it then touches.
//
// Built once per run (per surface); every lookup afterwards is O(1), which is
// what lets the layer model place elements on the real (worn) profile and find
// where flights land at real-time speed (docs/models/layer.md §Geometry).
//
// Frame: the liner frame of the surface (mill frame at t = 0), angles
// anticlockwise from +x. Bin b covers [b h, (b + 1) h), h = 2 pi / n_bins.
// The ride radius is computed exactly at the bin edges; a bin stores the
// smaller of its two edges (so a disc placed anywhere in the bin at that
// radius does not overlap the liner where the profile is monotone over the
// bin), and the ride polyline used for crossings joins the edge points.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "charge/exact_math.h"
#include "geometry/liner_surface.h"

namespace linerlife {

struct LinerRideTable {
  double disc_radius_m = 0;          // [m] a
  int n_bins = 0;
  double bin_rad = 0;                // [rad] h
  double inv_bin = 0;                // [1/rad]
  std::vector<double> ride_radius_m; // [m] per bin: the smaller of its edges
  std::vector<int> support_element;  // surface element touched, per bin
  std::vector<double> edge_radius_m; // [m] exact ride radius at the edge angle b h
  std::vector<double> cos_e, sin_e;  // direction of each edge
  double min_ride_m = 0;             // [m] smallest ride radius (over lifter tops)
  double max_ride_m = 0;             // [m] largest ride radius (deepest pocket)
  static constexpr int kBlock = 16;  // bins per block of block_min_ride_m
  std::vector<double> block_min_ride_m;  // [m] smallest ride radius of each block of kBlock bins
  // Where the loads go (docs/models/layer.md §Liner loads, "Where a load
  // lands"): the element the disc touches on contact rays, m per bin (ray j
  // at angle j h / m; ray b m is edge b). A load at angle psi goes to the
  // nearest ray's element, so its position is off by at most half a ray
  // spacing either way, not biased towards the crest as the bin's
  // smaller-edge element is.
  int contact_rays_per_bin = 1;          // m, a power of two
  double inv_contact_ray = 0;            // [1/rad] m / h
  std::vector<int> contact_element;      // n_bins m entries
  std::vector<Eigen::Vector2d> ride_normal;  // per bin: unit normal of the ride polyline from edge b to b + 1,
                                             // into the mill (the direction a disc riding there is pushed)

  /// Bin of angle psi [rad] (any value). Inline, and floor(x) without the
  /// libm call: the flights and the liner loads ask for bins all the time.
  /// The count of bins is a power of two, so the mask wraps negative ones too.
  int bin(double psi) const {
    return floor_int(psi * inv_bin) & (n_bins - 1);
  }
  double ride(double psi) const { return ride_radius_m[bin(psi)]; }
  int support(double psi) const { return support_element[bin(psi)]; }
  /// Element the disc touches at the contact ray nearest psi [rad] (any value).
  int contact(double psi) const {
    // nearest ray: floor(x + 1/2) without the libm call; the count of rays is
    // a power of two, so the mask wraps negative ones too
    const int j = floor_int(psi * inv_contact_ray + 0.5);
    return contact_element[static_cast<size_t>(j & (static_cast<int>(contact_element.size()) - 1))];
  }
  /// bin() and contact() of an angle psi >= 0 from its half-ray index
  /// iz = floor(psi / (h / 2 m)), for a psi strictly between two half-ray
  /// points iz h / 2 m: the bin edges and the midpoints between rays are all
  /// such points, so the whole interval has one bin and one nearest ray.
  /// (n_bins and 2 m are powers of two: the shift and the masks wrap psi
  /// beyond 2 pi too.) A copy of the layout, taken once before a loop, so
  /// that the loop keeps it in registers (LayerSim::sample()).
  struct HalfRays {
    int shift, bin_mask, ray_mask;  // log2(2 m), n_bins - 1, n_bins m - 1
    const int* contact_element;
    int bin(int iz) const { return (iz >> shift) & bin_mask; }
    int contact(int iz) const { return contact_element[((iz + 1) >> 1) & ray_mask]; }
  };
  HalfRays half_rays() const {
    return {__builtin_ctz(2u * static_cast<unsigned>(contact_rays_per_bin)), n_bins - 1,
            static_cast<int>(contact_element.size()) - 1, contact_element.data()};
  }
  /// Arc [m] along the shell between contact rays.
  double contact_spacing_m(double shell_radius_m) const { return shell_radius_m * bin_rad / contact_rays_per_bin; }
  /// Ride point at edge b (liner frame) [m].
  Eigen::Vector2d point(int b) const { return edge_radius_m[b] * Eigen::Vector2d(cos_e[b], sin_e[b]); }
};

/// Builds the table for discs of radius `disc_radius_m` with about
/// `bins_per_disc_radius` bins per disc radius along the shell (at least 1024,
/// a power of two). Exact disc-segment geometry: each element is a capsule of
/// radius a and the ray from the axis enters the first capsule at the ride radius.
/// The contact rays are at most `contact_spacing_m` apart along the shell
/// (0: one per bin edge), at most 64 per bin.
LinerRideTable build_liner_ride_table(const LinerSurface& s, double disc_radius_m, int bins_per_disc_radius = 8,
                                      double contact_spacing_m = 0);

/// The contact spacing the layer model asks for on a surface [m]: 2 mm, or
/// three quarters of the median element where that is shorter, so that every
/// element is touched by some ray (docs/models/layer.md §Liner loads).
double load_contact_spacing_m(const LinerSurface& s);

/// First crossing, within (t_a, t_b], of the parabola p(t) = p0 + v0 t + 1/2 acc t^2
/// (fixed frame, t from the parabola's origin) outward through the ride polyline
/// rotated by `rotation_rad` (liner frame -> fixed frame), searched over the
/// bins between the polar angles of p(t_a) and p(t_b) (plus one on each side).
/// Returns false if there is none; otherwise the crossing time and the bin.
/// Exact: each ride segment is a straight line and the crossing a quadratic root.
/// `reach_m`: the caller's bound on the arc, if it has one: the segments of
/// the bins whose ride radius exceeds it are not searched (the caller knows
/// the arc stays inside them; LayerSim::liner_crossing()).
bool first_ride_crossing(const LinerRideTable& t, double rotation_rad, const Eigen::Vector2d& p0,
                         const Eigen::Vector2d& v0, const Eigen::Vector2d& acc, double t_a, double t_b, double& t_hit,
                         int& bin_hit, double reach_m = std::numeric_limits<double>::infinity());

}  // namespace linerlife
