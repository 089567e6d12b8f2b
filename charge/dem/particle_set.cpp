#include "charge/dem/particle_set.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace linerlife {

namespace {

constexpr double kPiP = 3.14159265358979323846;

unsigned long long splitmix64(unsigned long long& x) {
  unsigned long long z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

unsigned long long rotl(unsigned long long x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

DemRandom::DemRandom(unsigned long long seed) {
  unsigned long long x = seed;
  for (auto& s : s_) s = splitmix64(x);
}

unsigned long long DemRandom::next() {
  const unsigned long long result = rotl(s_[1] * 5, 7) * 9;
  const unsigned long long t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double DemRandom::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

double largest_real_diameter_m(const ChargeSpec& charge, const DemSpec& spec) {
  double d = charge.ball_filling > 0 ? charge.ball_diameter_m : 0.0;
  if (charge.filling > charge.ball_filling)
    d = std::max(d, spec.rock_diameter_max_m > 0 ? spec.rock_diameter_max_m : charge.ball_diameter_m);
  return d;
}

namespace {

/// One size class of discs: n discs of real diameters uniform in [d0, d1].
struct DiscClass {
  double d0, d1, rho;
  Material material;
  long long n;
};

/// The classes make_particle_set() draws, in its order (balls, then the rock
/// classes from the finest up).
std::vector<DiscClass> disc_classes(const ChargeSpec& charge, const DemSpec& spec, double free_area_m2) {
  std::vector<DiscClass> out;
  const double s = spec.coarse_grain;
  const double phi = spec.packing_fraction_2d;
  // Balls: diameters uniform in [a, b]; mean disc area pi/4 (a^2 + ab + b^2)/3.
  const double solid_balls = phi * charge.ball_filling * free_area_m2;  // [m2]
  if (solid_balls > 0) {
    const double b = charge.ball_diameter_m, a = b * (1 - spec.ball_size_spread);
    const double mean_area = s * s * kPiP / 4 * (a * a + a * b + b * b) / 3;
    out.push_back({a, b, charge.ball_density_kg_m3, Material::Ball,
                   std::max(1LL, static_cast<long long>(std::llround(solid_balls / mean_area)))});
  }
  // Rocks: Gates-Gaudin-Schuhmann, area (= mass) share of class [d0, d1] is
  // (d1^m - d0^m) / (dmax^m - dmin^m).
  const double solid_rocks = phi * (charge.filling - charge.ball_filling) * free_area_m2;
  if (solid_rocks > 1e-12 * free_area_m2) {
    const double dmax = spec.rock_diameter_max_m > 0 ? spec.rock_diameter_max_m : charge.ball_diameter_m;
    const double dmin = spec.rock_diameter_min_m > 0 ? spec.rock_diameter_min_m : 0.25 * charge.ball_diameter_m;
    const double m = spec.rock_size_exponent;
    const int classes = dmax > dmin * 1.0001 ? 6 : 1;
    const double total = std::pow(dmax, m) - std::pow(dmin, m);
    for (int c = 0; c < classes; ++c) {
      const double d0 = dmin * std::pow(dmax / dmin, static_cast<double>(c) / classes);
      const double d1 = dmin * std::pow(dmax / dmin, static_cast<double>(c + 1) / classes);
      const double share = classes == 1 ? 1.0 : (std::pow(d1, m) - std::pow(d0, m)) / total;
      const double mean_area = s * s * kPiP / 4 * (d0 * d0 + d0 * d1 + d1 * d1) / 3;
      out.push_back({d0, d1, charge.ore_density_kg_m3, Material::Rock,
                     static_cast<long long>(std::llround(solid_rocks * share / mean_area))});
    }
  }
  return out;
}

}  // namespace

DiscCount count_discs(const ChargeSpec& charge, const DemSpec& spec, double free_area_m2) {
  DiscCount n;
  for (const DiscClass& c : disc_classes(charge, spec, free_area_m2))
    (c.material == Material::Ball ? n.balls : n.rocks) += static_cast<double>(c.n);
  return n;
}

ParticleSet make_particle_set(const ChargeSpec& charge, const DemSpec& spec, double free_area_m2,
                              unsigned long long seed) {
  ParticleSet ps;
  DemRandom rng(seed);
  const double s = spec.coarse_grain;
  const double phi = spec.packing_fraction_2d;
  ps.coarse_grain = s;
  ps.density_scale = (1 - charge.porosity) / phi;

  auto add = [&](double d_real, double rho, Material mat) {
    const double d = s * d_real;
    ps.radius_m.push_back(0.5 * d);
    const double m = ps.density_scale * rho * kPiP * d * d / 4;
    ps.mass_kg_per_m.push_back(m);
    ps.real_diameter_m.push_back(d_real);
    ps.real_mass_kg.push_back(rho * kPiP * d_real * d_real * d_real / 6);
    ps.material.push_back(mat);
    (mat == Material::Ball ? ps.ball_mass_kg_per_m : ps.rock_mass_kg_per_m) += m;
  };

  for (const DiscClass& c : disc_classes(charge, spec, free_area_m2)) {
    for (long long i = 0; i < c.n; ++i) add(c.d0 + (c.d1 - c.d0) * rng.uniform(), c.rho, c.material);
    (c.material == Material::Ball ? ps.n_balls : ps.n_rocks) += static_cast<int>(c.n);
  }

  // Shuffle (Fisher-Yates with the portable generator) so sizes mix in the placement.
  const int n = ps.size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  for (int i = n - 1; i > 0; --i) std::swap(order[i], order[static_cast<int>(rng.next() % (i + 1))]);
  auto permute = [&](auto& v) {
    auto copy = v;
    for (int i = 0; i < n; ++i) v[i] = copy[order[i]];
  };
  permute(ps.radius_m);
  permute(ps.mass_kg_per_m);
  permute(ps.real_diameter_m);
  permute(ps.real_mass_kg);
  permute(ps.material);
  return ps;
}

}  // namespace linerlife
