#include "charge/charge_occupancy.h"

#include <algorithm>
#include <cmath>

#include "geometry/mill.h"

namespace linerlife {
namespace {

double deg(double rad) {
  double d = rad * 180.0 / kPi;
  d = std::fmod(d, 360.0);
  return d < 0 ? d + 360.0 : d;
}

/// The q-quantile of the positive values of v (0 if none).
double positive_quantile(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !(x > 0.05); }), v.end());
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return v[k];
}

}  // namespace

ChargeOccupancy::ChargeOccupancy(double R, double d, double sense) : R_(R), d_(d), sense_(sense) {
  nr_ = std::max(1, static_cast<int>(std::floor(R / d)));
  nt_.resize(nr_);
  off_.resize(nr_ + 1);
  inv_dth_.resize(nr_);
  area_.resize(nr_);
  off_[0] = 0;
  for (int j = 0; j < nr_; ++j) {
    const double ro = R - j * d, ri = j + 1 == nr_ ? 0.0 : R - (j + 1) * d;
    nt_[j] = std::max(1, static_cast<int>(std::lround(2.0 * kPi * ring_mid_radius(j) / d)));
    inv_dth_[j] = nt_[j] / (2.0 * kPi);
    area_[j] = kPi * (ro * ro - ri * ri) / nt_[j];
    off_[j + 1] = off_[j] + nt_[j];
  }
  const size_t n = static_cast<size_t>(off_[nr_]);
  acc_area_.assign(n, 0);
  acc_m_.assign(n, 0);
  inv_d_ = 1.0 / d;
}

void ChargeOccupancy::add_polar(const Eigen::Vector2d&, double th, double r, double area, double m, double w) {
  const int j = ring(r);
  add_to_bin(j, angular_bin(j, th), w * area, w * m);
}

// Most of add_arc's time is the run of whole bins below (about 350
// instructions a call on media size -25 %): with AVX2 where the CPU has it (a
// second copy, picked at load time) the loop adds four bins an instruction
// instead of two. Additions and products as before, no FMA (avx2 does not
// enable it), so the sums are the same to the bit.
#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void ChargeOccupancy::add_arc(int j, double th0, double th1, double spr, double area, double m) {
  if (!(th1 > th0)) return;
  const int n = nt_[j];
  const double u0 = th0 * inv_dth_[j], u1 = th1 * inv_dth_[j];  // in bins
  const double per_bin = spr / inv_dth_[j];                     // [s] to cross one bin
  const long long b0 = floor_ll(u0), b1 = floor_ll(u1);
  int i = static_cast<int>(b0 % n);
  if (i < 0) i += n;
  const size_t base = static_cast<size_t>(off_[j]);
  if (b0 == b1) {
    const double t = (u1 - u0) * per_bin;
    acc_area_[base + i] += t * area;
    acc_m_[base + i] += t * m;
    return;
  }
  double t = (static_cast<double>(b0 + 1) - u0) * per_bin;  // first, partial bin
  acc_area_[base + i] += t * area;
  acc_m_[base + i] += t * m;
  const double fa = per_bin * area, fm = per_bin * m;
  // the whole bins between, in runs that do not wrap round the ring (each
  // bin gets the same additions in the same order as one bin at a time, so
  // the sums are the same to the bit; the runs vectorise)
  double* __restrict ar = acc_area_.data() + base;
  double* __restrict ms = acc_m_.data() + base;
  long long left = b1 - b0 - 1;
  if (++i == n) i = 0;
  while (left > 0) {
    const int run = static_cast<int>(std::min<long long>(left, n - i));
    for (int q = i; q < i + run; ++q) {
      ar[q] += fa;
      ms[q] += fm;
    }
    left -= run;
    i += run;
    if (i == n) i = 0;
  }
  t = (u1 - static_cast<double>(b1)) * per_bin;  // last, partial bin
  acc_area_[base + i] += t * area;
  acc_m_[base + i] += t * m;
}

double ChargeOccupancy::occupancy(int j, int i) const {
  return time_s_ > 0 ? acc_area_[index(j, i)] / (time_s_ * area_[j]) : 0.0;
}

OccupancyIndicators ChargeOccupancy::evaluate() const {
  OccupancyIndicators o;
  if (!(time_s_ > 0)) return o;
  std::vector<double> occ(acc_area_.size());
  for (int j = 0; j < nr_; ++j)
    for (int i = 0; i < nt_[j]; ++i) occ[index(j, i)] = occupancy(j, i);
  // En masse: at least half the occupancy of a packed bin. "Packed" is the
  // 75th percentile of the occupied bins: most occupied bins lie in the bed,
  // and a few over-full bins (streams of flights) do not move it.
  o.threshold = 0.5 * positive_quantile(occ, 0.75);
  if (!(o.threshold > 0)) return o;
  double m = 0, mx = 0, my = 0;
  for (int j = 0; j < nr_; ++j)
    for (int i = 0; i < nt_[j]; ++i) {
      const size_t k = index(j, i);
      if (occ[k] < o.threshold) continue;
      o.charge_area_m2 += area_[j];
      const double rc = ring_mid_radius(j), tc = (i + 0.5) * 2.0 * kPi / nt_[j];
      m += acc_m_[k];
      mx += acc_m_[k] * rc * std::cos(tc);
      my += acc_m_[k] * rc * std::sin(tc);
    }
  if (m > 0) {
    o.com_angle_deg = deg(std::atan2(my, mx));
    o.com_radius_m = std::hypot(mx, my) / m;
  }
  // Toe and shoulder: the band of the two rings next to the liner, on the
  // angular bins of ring 0.
  const int nt = nt_[0];
  const double dth = 2.0 * kPi / nt;
  std::vector<double> band(nt, 0.0);
  for (int i = 0; i < nt; ++i) {
    double a = occ[index(0, i)] * area_[0], at = area_[0];
    if (nr_ > 1) {
      a += occ[index(1, angular_bin(1, (i + 0.5) * dth))] * area_[1] * nt_[0] / nt_[1];
      at += area_[1] * nt_[0] / nt_[1];
    }
    band[i] = a / at;
  }
  const double thr = 0.5 * positive_quantile(band, 0.75);
  if (!(thr > 0)) return o;
  // longest circular run of bins at or above thr
  int best_len = 0, best_start = -1;
  bool all = true;
  for (int i = 0; i < nt; ++i) all = all && band[i] >= thr;
  if (all) {
    o.toe_deg = o.shoulder_deg = 90.0;  // a ring all round: centrifuged
  } else {
    int start = 0;
    while (band[start] >= thr) ++start;  // begin after a gap
    int len = 0, run_start = -1;
    for (int k = 1; k <= nt; ++k) {
      const int i = (start + k) % nt;
      if (band[i] >= thr) {
        if (len == 0) run_start = i;
        ++len;
        if (len > best_len) best_len = len, best_start = run_start;
      } else {
        len = 0;
      }
    }
    if (best_start < 0) return o;
    // sub-bin crossings, linear between bin centres
    auto cross = [&](int below, int above) {
      const double f = (thr - band[below]) / (band[above] - band[below]);
      double step = (above - below) * dth;
      if (std::abs(step) > kPi) step -= std::copysign(2.0 * kPi, step);
      return (below + 0.5) * dth + f * step;
    };
    const int first = best_start, last = (best_start + best_len - 1) % nt;
    const double lo = cross((first - 1 + nt) % nt, first);  // start of the run (increasing angle)
    const double hi = cross((last + 1) % nt, last);
    // anticlockwise mill: the charge enters at the low end (toe); clockwise: the high end
    o.toe_deg = deg(sense_ > 0 ? lo : hi);
    o.shoulder_deg = deg(sense_ > 0 ? hi : lo);
  }
  // Number of layers: the en-masse depth along the radius through the centre
  // of mass, in media diameters: the occupancy of the rings from the liner to
  // the innermost en-masse ring on that radius, each relative to a packed bin
  // (lifters take part of the rings next to the liner, so those are counted
  // by what they hold, not by the threshold).
  const double thc = o.com_angle_deg * kPi / 180.0;
  const double packed = 2.0 * o.threshold;
  int last = -1;
  for (int j = 0; j < nr_; ++j)
    if (occ[index(j, angular_bin(j, thc))] >= o.threshold) last = j;
  double depth = 0;
  for (int j = 0; j <= last; ++j) depth += std::min(1.0, occ[index(j, angular_bin(j, thc))] / packed);
  o.n_layers = static_cast<int>(std::lround(depth));
  o.valid = true;
  return o;
}

}  // namespace linerlife
