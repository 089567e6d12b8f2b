// SlotMap: which cell of a lower ring lies under each cell of an upper ring of
// the layer model, and which of those relations can change when the two
// rings turn against each other. Internal to the layer model
// (docs/models/layer.md §Incremental maps); header-only so that it can be
// unit-tested.
//
// The upper ring has S_a cells, the lower S_b; cell s of the upper ring lies
// over cell floor(b + s ratio) mod S_b of the lower one, where
// ratio = delta_a / delta_b (cell angles) and the offset b = (phase_a -
// phase_b) / delta_b + 1/2 changes as the rings slip. Between two offsets
// only the cells whose fractional part frac(b + s ratio) crosses an integer
// change; with the fractional parts frac(s ratio) sorted once, they form one
// or two contiguous runs found by binary search, so keeping a map up to date
// costs O(changes + log S) instead of O(S).
#pragma once

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "charge/exact_math.h"

namespace linerlife {

class SlotMap {
 public:
  /// Slack [cells] added to every query so that rounding never hides a change.
  static constexpr double kEps = 1e-6;

  SlotMap() = default;
  SlotMap(int S_a, int S_b, double ratio) : S_a_(S_a), S_b_(S_b), ratio_(ratio), inv_ratio_(1.0 / ratio) {
    frac_.resize(S_a);
    order_.resize(S_a);
    std::iota(order_.begin(), order_.end(), 0);
    std::vector<double> f(S_a);
    for (int s = 0; s < S_a; ++s) {
      const double x = s * ratio;
      f[s] = x - std::floor(x);
    }
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return f[a] != f[b] ? f[a] < f[b] : a < b; });
    for (int i = 0; i < S_a; ++i) frac_[i] = f[order_[i]];
  }

  int upper_cells() const { return S_a_; }
  int lower_cells() const { return S_b_; }
  double ratio() const { return ratio_; }

  /// The lower cell under upper cell s at offset b, 0 <= b < S_b + 1.
  int cell(int s, double b) const {
    int k = static_cast<int>(b + s * ratio_);
    while (k >= S_b_) k -= S_b_;
    return k;
  }

  /// Calls f(s) for every upper cell s whose lower cell may differ between
  /// the offsets b0 and b0 + D (D: the unwrapped change of the offset). A
  /// superset: cells within kEps of a boundary are included. Returns false
  /// (and calls nothing) when |D| is too large for the runs to be reliable;
  /// the caller then treats every cell as changed.
  template <class F>
  bool changed(double b0, double D, F&& f) const {
    if (!(std::abs(D) < 0.5)) return false;
    if (D == 0) return true;
    // frac(b0 + s ratio) = frac(fb + frac(s ratio)) must lie in [lo, lo + len) (mod 1)
    const double fb = b0 - floor_exact(b0);
    const double lo = D > 0 ? 1.0 - D - kEps : -kEps;
    const double len = std::abs(D) + 2 * kEps;
    double a = lo - fb;  // the same interval for frac(s ratio)
    a -= floor_exact(a);
    visit(a, std::min(1.0, a + len), f);
    if (a + len > 1.0) visit(0.0, a + len - 1.0, f);
    return true;
  }

  /// Calls f(s) for every upper cell s whose lower cell may be on one side
  /// of the lower ring's boundary K (between cells K - 1 and K, mod S_b) at
  /// offset b0 and on the other at b0 + x, for some x in [lo, hi] (lo <= 0 <=
  /// hi, both of magnitude below 1/2): b0 + s ratio + x crosses K, K + S_b or
  /// K + 2 S_b (b0 + s ratio < 2 S_b + 1/2, as in over()). A superset: the
  /// span is widened by kEps each side, so that rounding never hides a cell.
  template <class F>
  void across(int K, double b0, double lo, double hi, F&& f) const {
    const int last = S_a_ - 1;
    // b0 + s ratio + x spans [x_lo, x_hi] (s in 0 .. last, x in [lo, hi]):
    // only the Kp in it are worked out
    const double x_lo = b0 + lo - kEps, x_hi = b0 + last * ratio_ + hi + kEps;
    int Kp = K;
    while (Kp < x_lo) Kp += S_b_;
    for (; Kp <= x_hi; Kp += S_b_) {
      // s ratio in [Kp - b0 - hi, Kp - b0 - lo]
      const int s0 = ceil_int((Kp - b0 - hi - kEps) * inv_ratio_);
      const int s1 = floor_int((Kp - b0 - lo + kEps) * inv_ratio_);
      for (int s = std::max(s0, 0); s <= std::min(s1, last); ++s) f(s);
    }
  }

  /// Calls f(s) for every upper cell s that may lie over lower cell k at
  /// offset b (a superset: one extra cell each side). b + s ratio runs up to
  /// b + S_b - ratio < 2 S_b + 1/2, so cell k is reached at k, k + S_b and
  /// (for b > S_b, when the lower ring's cells are more than twice as wide)
  /// k + 2 S_b.
  template <class F>
  void over(int k, double b, F&& f) const {
    const int last = S_a_ - 1;
    // the K whose range of cells is sure to be empty are passed over without
    // the divisions: hi < 0 when K + 1 - b < -ratio, lo > last when K - b >
    // (last + 1) ratio (with a margin for the rounding)
    const double skip_below = b - 1 - ratio_ - kEps, stop_above = b + (last + 1) * ratio_ + kEps;
    for (int K : {k, k + S_b_, k + 2 * S_b_}) {
      if (K < skip_below) continue;
      if (K > stop_above) break;  // K grows: no later K reaches a cell either
      const int lo = ceil_int((K - b) / ratio_) - 1;
      if (lo > last) break;  // lo grows with K: no later K reaches a cell either
      const int hi = floor_int((K + 1 - b) / ratio_) + 1;
      for (int s = std::max(lo, 0); s <= std::min(hi, last); ++s) f(s);
    }
  }

 private:
  template <class F>
  void visit(double x0, double x1, F&& f) const {
    // local pointers: f() may store anywhere, and the vectors' data would be
    // reloaded on every cell otherwise
    const double* fr = frac_.data();
    const int* ord = order_.data();
    const long n = static_cast<long>(frac_.size());
    // lower bound of x0: the fractional parts are spread evenly over [0, 1)
    // (those of s S_b / S_a), so x0 n is within a few places of it; the two
    // scans end on the first place not below x0 from wherever they start
    long i = std::min(n, std::max(0L, static_cast<long>(x0 * static_cast<double>(n))));
    while (i > 0 && fr[i - 1] >= x0) --i;
    while (i < n && fr[i] < x0) ++i;
    for (; i < n && fr[i] < x1; ++i) f(ord[i]);
  }

  int S_a_ = 0, S_b_ = 0;
  double ratio_ = 1, inv_ratio_ = 1;
  std::vector<double> frac_;  // frac(s ratio), ascending
  std::vector<int> order_;    // the s of each
};

}  // namespace linerlife
