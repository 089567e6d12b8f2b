#include "charge/particle_indicators.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linerlife {

namespace {

constexpr double kPiI = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPiI;

double wrap_deg(double a) {
  a = std::fmod(a, 360.0);
  return a < 0 ? a + 360.0 : a;
}

double angle_rad(double x, double y) {
  const double a = std::atan2(y, x);
  return a < 0 ? a + 2 * kPiI : a;
}

int wrap_index(int k, int n) { return ((k % n) + n) % n; }

}  // namespace

ParticleIndicators::ParticleIndicators(const ParticleIndicatorGeometry& g, const ParticleIndicatorOptions& o)
    : g_(g), o_(o) {
  // band bins at least one mean diameter long, so the time average sees discs in each
  const double min_band_deg = g_.mean_diameter / g_.r_crest * kDeg;
  nb_ = std::max(8, static_cast<int>(std::lround(360.0 / std::max(o_.band_bin_deg, min_band_deg))));
  band_area_.assign(nb_, 0);
  ns_ = std::max(8, static_cast<int>(std::lround(360.0 / o_.grid_bin_deg)));
  nr_ = std::max(1, static_cast<int>(std::ceil(g_.r_crest / g_.mean_diameter)));
  ring_off_.resize(nr_ + 1), ring_ns_.resize(nr_), ring_bin_area_.resize(nr_);
  ring_off_[0] = 0;
  for (int ring = 0; ring < nr_; ++ring) {
    const double ro = g_.r_crest - ring * g_.mean_diameter, ri = std::max(0.0, ro - g_.mean_diameter);
    ring_ns_[ring] = std::max(1, static_cast<int>(std::lround(ns_ * 0.5 * (ro + ri) / g_.r_crest)));
    ring_bin_area_[ring] = kPiI * (ro * ro - ri * ri) / ring_ns_[ring];
    ring_off_[ring + 1] = ring_off_[ring] + ring_ns_[ring];
  }
  const size_t ng = static_cast<size_t>(ring_off_[nr_]);
  for (auto* v : {&grid_area_, &grid_flight_area_, &grid_mass_, &grid_mx_, &grid_my_, &grid_mvx_, &grid_mvy_,
                  &grid_mw_})
    v->assign(ng, 0);
  for (auto* v : {&pocket_mass_, &pocket_mx_, &pocket_my_}) v->assign(ns_, 0);
  nl_ = std::max(8, static_cast<int>(std::lround(360.0 / o_.lifter_bin_deg)));
  lift_n_.assign(nl_, 0), lift_t_.assign(nl_, 0), lift_count_.assign(nl_, 0);
}

int ParticleIndicators::ring_of(double r) const {
  if (r > g_.r_crest) return -1;
  return std::min(nr_ - 1, static_cast<int>((g_.r_crest - r) / g_.mean_diameter));
}

int ParticleIndicators::bin_of(int ring, double a) const {
  a = std::fmod(a, 2 * kPiI);
  if (a < 0) a += 2 * kPiI;
  const int n = ring_ns_[ring];
  return ring_off_[ring] + std::min(n - 1, static_cast<int>(a / (2 * kPiI) * n));
}

void ParticleIndicators::add_sample(const ParticleFrame& f) {
  ++samples_;
  const double band_in = g_.r_crest - o_.band_depth_diameters * g_.mean_diameter;
  for (int i = 0; i < f.n; ++i) {
    const double x = f.x[i], y = f.y[i], r = std::hypot(x, y);
    const double a = angle_rad(x, y);
    const double area = kPiI * f.radius[i] * f.radius[i], m = f.mass[i];
    if (r >= band_in) band_area_[std::min(nb_ - 1, static_cast<int>(a / (2 * kPiI) * nb_))] += area;
    const int ring = ring_of(r);
    if (ring < 0) {
      const int s = std::min(ns_ - 1, static_cast<int>(a / (2 * kPiI) * ns_));
      pocket_mass_[s] += m, pocket_mx_[s] += m * x, pocket_my_[s] += m * y;
      continue;
    }
    const size_t k = static_cast<size_t>(bin_of(ring, a));
    grid_area_[k] += area;
    if (f.contacts[i] == 0) grid_flight_area_[k] += area;
    grid_mass_[k] += m, grid_mx_[k] += m * x, grid_my_[k] += m * y;
    grid_mvx_[k] += m * f.vx[i], grid_mvy_[k] += m * f.vy[i];
    if (r > 0) grid_mw_[k] += m * (x * f.vy[i] - y * f.vx[i]) / (r * r);
  }
}

std::vector<std::pair<double, double>> ParticleIndicators::band_profile() const {
  std::vector<std::pair<double, double>> out;
  const double band_in = g_.r_crest - o_.band_depth_diameters * g_.mean_diameter;
  const double bin_area = kPiI * (g_.r_shell * g_.r_shell - band_in * band_in) / nb_;
  for (int k = 0; k < nb_; ++k)
    out.emplace_back((k + 0.5) * 360.0 / nb_, samples_ ? band_area_[k] / (bin_area * samples_) : 0.0);
  return out;
}

void ParticleIndicators::add_lifter_force(double angle, double fn, double ft) {
  double a = std::fmod(angle, 2 * kPiI);
  if (a < 0) a += 2 * kPiI;
  const int b = std::min(nl_ - 1, static_cast<int>(a / (2 * kPiI) * nl_));
  lift_n_[b] += fn, lift_t_[b] += ft, ++lift_count_[b];
}

void ParticleIndicators::finish(Indicators& out) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double sense = g_.sense >= 0 ? 1.0 : -1.0;
  const int sgn = sense > 0 ? 1 : -1;
  out.toe_deg = out.shoulder_deg = out.com_angle_deg = out.com_radius_m = out.charge_area_m2 = nan;
  // a particle model has no inner surface radius of Morrell's eq. 4.14: not
  // given (null in --json), not 0 m (a review, 2026-12-06)
  out.inner_radius_m = nan;
  out.n_layers = out.n_trajectories = 0;
  out.layer_speed_rpm.clear();
  out.lifter_force_angle_deg.clear();
  out.lifter_normal_force_n_per_m.clear();
  out.lifter_tangential_force_n_per_m.clear();
  for (int b = 0; b < nl_; ++b) {
    if (!lift_count_[b]) continue;
    out.lifter_force_angle_deg.push_back((b + 0.5) * 360.0 / nl_);
    out.lifter_normal_force_n_per_m.push_back(lift_n_[b] / lift_count_[b]);
    out.lifter_tangential_force_n_per_m.push_back(lift_t_[b] / lift_count_[b]);
  }
  if (samples_ == 0) return;

  // --- toe and shoulder: where the liner band's occupancy crosses the threshold share of its peak ---
  std::vector<double> occ(nb_);
  for (int k = 0; k < nb_; ++k)
    occ[k] = (band_area_[wrap_index(k - 1, nb_)] + band_area_[k] + band_area_[wrap_index(k + 1, nb_)]) / 3.0;
  const int kmax = static_cast<int>(std::max_element(occ.begin(), occ.end()) - occ.begin());
  const double thr = o_.en_masse_threshold * occ[kmax];
  const double bw = 360.0 / nb_;
  auto crossing = [&](int dir) {  // walk from the peak in direction dir until the occupancy drops below thr
    int k = kmax;
    for (int step = 0; step < nb_; ++step) {
      const int kn = wrap_index(k + dir, nb_);
      if (occ[kn] < thr) {
        const double frac = (occ[k] - thr) / (occ[k] - occ[kn]);
        return wrap_deg((k + 0.5) * bw + dir * frac * bw);
      }
      k = kn;
    }
    return nan;  // charge all round: centrifuged
  };
  const double toe = crossing(-sgn), shoulder = crossing(sgn);
  out.toe_deg = toe, out.shoulder_deg = shoulder;
  // arc from toe to shoulder in the direction of rotation [deg]
  const double arc = std::isnan(toe) ? 360.0 : wrap_deg(sense * (shoulder - toe));
  auto in_arc = [&](double a_deg) { return std::isnan(toe) || wrap_deg(sense * (a_deg - toe)) <= arc; };

  // --- polar grid: occupancy, the bed's packing fraction, en-masse bins ---
  const size_t ng = grid_area_.size();
  std::vector<double> gocc(ng);
  std::vector<int> ring_of_bin(ng);
  for (int ring = 0; ring < nr_; ++ring)
    for (int k = ring_off_[ring]; k < ring_off_[ring + 1]; ++k) {
      gocc[k] = grid_area_[k] / (ring_bin_area_[ring] * samples_);
      ring_of_bin[k] = ring;
    }
  const double gmax = *std::max_element(gocc.begin(), gocc.end());
  double sum = 0;
  int cnt = 0;
  for (double v : gocc)
    if (v >= 0.5 * gmax) sum += v, ++cnt;
  const double phi_bed = cnt ? sum / cnt : 0;  // packing fraction of the bed
  std::vector<char> em(ng, 0);
  double area = 0, M = 0, MX = 0, MY = 0;
  for (size_t k = 0; k < ng; ++k)
    if (phi_bed > 0 && gocc[k] >= o_.en_masse_threshold * phi_bed) {
      em[k] = 1;
      area += ring_bin_area_[ring_of_bin[k]];
      M += grid_mass_[k], MX += grid_mx_[k], MY += grid_my_[k];
    }
  for (int s = 0; s < ns_; ++s)
    if (in_arc((s + 0.5) * 360.0 / ns_)) M += pocket_mass_[s], MX += pocket_mx_[s], MY += pocket_my_[s];
  out.charge_area_m2 = area + g_.pocket_area * arc / 360.0;
  if (M > 0) {
    out.com_angle_deg = wrap_deg(std::atan2(MY, MX) * kDeg);
    out.com_radius_m = std::hypot(MX, MY) / M;
  }

  // --- centre of circulation: the interior en-masse bin with the slowest mean velocity ---
  auto centre_angle = [&](int ring, int k) { return (k - ring_off_[ring] + 0.5) * 2 * kPiI / ring_ns_[ring]; };
  int best = -1;
  double best_v = std::numeric_limits<double>::max();
  for (int ring = 1; ring + 1 < nr_; ++ring)
    for (int k = ring_off_[ring]; k < ring_off_[ring + 1]; ++k) {
      if (!em[k] || grid_mass_[k] <= 0) continue;
      const double a = centre_angle(ring, k), da = 2 * kPiI / ring_ns_[ring];
      const bool interior = em[bin_of(ring - 1, a)] && em[bin_of(ring + 1, a)] && em[bin_of(ring, a - da)] &&
                            em[bin_of(ring, a + da)];
      if (!interior) continue;
      const double v = std::hypot(grid_mvx_[k], grid_mvy_[k]) / grid_mass_[k];
      if (v < best_v) best_v = v, best = k;
    }
  if (best < 0) return;
  const int coc_ring = ring_of_bin[best];
  const double coc_a = angle_rad(grid_mx_[best], grid_my_[best]);
  out.n_layers = coc_ring;  // rings of one mean diameter between the lifter crests and the centre of circulation

  // --- layer speeds: rings within +-layer_window of the centre of circulation's angle ---
  const double win = o_.layer_window_deg / kDeg;
  for (int ring = 0; ring < coc_ring; ++ring) {
    double m = 0, mw = 0;
    for (int k = ring_off_[ring]; k < ring_off_[ring + 1]; ++k) {
      double da = std::fmod(centre_angle(ring, k) - coc_a + 3 * kPiI, 2 * kPiI) - kPiI;
      if (std::abs(da) <= win) m += grid_mass_[k], mw += grid_mw_[k];
    }
    out.layer_speed_rpm.push_back(m > 0 ? sense * mw / m * 60.0 / (2 * kPiI) : nan);
  }

  // --- trajectories: rings where airborne discs are dense just past the shoulder ---
  if (!std::isnan(shoulder)) {
    const double sh = shoulder / kDeg, fw = o_.flight_window_deg / kDeg;
    for (int ring = 0; ring < nr_; ++ring) {
      double fa = 0, ba = 0;
      for (int k = ring_off_[ring]; k < ring_off_[ring + 1]; ++k) {
        const double past = std::fmod(sense * (centre_angle(ring, k) - sh) + 4 * kPiI, 2 * kPiI);  // past the shoulder
        if (past > fw) continue;
        fa += grid_flight_area_[k];
        ba += ring_bin_area_[ring] * samples_;
      }
      if (ba > 0 && fa / ba >= o_.flight_threshold * phi_bed) ++out.n_trajectories;
    }
  }
}

}  // namespace linerlife
