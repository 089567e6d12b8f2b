#include "wear/smoothing.h"

#include <fmt/format.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/errors.h"

namespace linerlife {

SmoothingMethod smoothing_method_from_name(const std::string& n) {
  if (n == "none") return SmoothingMethod::None;
  if (n == "moving_average") return SmoothingMethod::MovingAverage;
  if (n == "csaps") return SmoothingMethod::Csaps;
  if (n == "tukey") return SmoothingMethod::Tukey;
  if (n == "tukey_csaps") return SmoothingMethod::TukeyCsaps;
  throw InputError("wear.smoothing", fmt::format("smoothing = \"{}\": allowed one of \"none\", \"moving_average\", "
                                                 "\"csaps\", \"tukey\", \"tukey_csaps\"",
                                                 n));
}

const char* smoothing_method_name(SmoothingMethod m) {
  switch (m) {
    case SmoothingMethod::None:
      return "none";
    case SmoothingMethod::MovingAverage:
      return "moving_average";
    case SmoothingMethod::Csaps:
      return "csaps";
    case SmoothingMethod::Tukey:
      return "tukey";
    case SmoothingMethod::TukeyCsaps:
      return "tukey_csaps";
  }
  return "";
}

// ---------------------------------------------------------------- moving average

std::vector<double> moving_average(const std::vector<double>& y, int window, bool periodic) {
  const int n = static_cast<int>(y.size());
  if (window <= 1 || n < 3) return y;
  const bool even = window % 2 == 0;
  const int k = even ? window / 2 : (window - 1) / 2;
  std::vector<double> out(n);
  for (int i = 0; i < n; ++i) {
    const int m = periodic ? std::min(k, (n - 1) / 2) : std::min({k, i, n - 1 - i});
    const bool half_ends = even && m == k;
    double sum = 0, wsum = 0;
    for (int j = -m; j <= m; ++j) {
      const double w = (half_ends && (j == -m || j == m)) ? 0.5 : 1.0;
      const int idx = periodic ? ((i + j) % n + n) % n : i + j;
      sum += w * y[idx];
      wsum += w;
    }
    out[i] = sum / wsum;
  }
  return out;
}

// ---------------------------------------------------------------- csaps

std::vector<double> csaps(const std::vector<double>& y, const std::vector<double>& h, const std::vector<double>& w,
                          double p, bool periodic) {
  const int n = static_cast<int>(y.size());
  if (!(p > 0) || p > 1) throw std::invalid_argument("csaps: p must be in (0, 1]");
  if (p == 1.0 || n < 3) return y;
  if (static_cast<int>(h.size()) != (periodic ? n : n - 1) || static_cast<int>(w.size()) != n)
    throw std::invalid_argument("csaps: spacing and weights of the wrong size");
  using Sp = Eigen::SparseMatrix<double>;
  using T = Eigen::Triplet<double>;
  // unknowns: the second derivatives gamma at the interior sites (open) or at all sites (periodic)
  const int m = periodic ? n : n - 2;
  auto col_site = [&](int j) { return periodic ? j : j + 1; };  // site of unknown j
  std::vector<T> tq, tr;
  for (int j = 0; j < m; ++j) {
    const int s = col_site(j);
    const int sm = periodic ? (s - 1 + n) % n : s - 1, sp = periodic ? (s + 1) % n : s + 1;
    const double hm = h[periodic ? sm : s - 1], hp = h[s];  // h_{s-1}, h_s
    tq.emplace_back(sm, j, 1.0 / hm);
    tq.emplace_back(s, j, -1.0 / hm - 1.0 / hp);
    tq.emplace_back(sp, j, 1.0 / hp);
    tr.emplace_back(j, j, (hm + hp) / 3.0);
    if (periodic || j + 1 < m) {
      const int jn = (j + 1) % m;
      tr.emplace_back(j, jn, hp / 6.0);
      tr.emplace_back(jn, j, hp / 6.0);
    }
  }
  Sp Q(n, m), R(m, m), Dinv(n, n);
  Q.setFromTriplets(tq.begin(), tq.end());
  R.setFromTriplets(tr.begin(), tr.end());
  double wmean = 0;
  for (double v : w) wmean += v / n;
  std::vector<T> td;
  for (int i = 0; i < n; ++i) td.emplace_back(i, i, wmean / w[i]);  // W^-1 with the weights scaled to mean 1
  Dinv.setFromTriplets(td.begin(), td.end());
  const Sp QtDQ = Sp(Q.transpose()) * Dinv * Q;
  const Sp A = p * R + (1.0 - p) * QtDQ;
  Eigen::Map<const Eigen::VectorXd> yv(y.data(), n);
  const Eigen::VectorXd rhs = p * (Q.transpose() * yv);
  // natural ordering: the matrix is (cyclic) pentadiagonal, so the fill stays in a border of two rows
  Eigen::SimplicialLDLT<Sp, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt(A);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("csaps: factorisation failed");
  const Eigen::VectorXd gamma = ldlt.solve(rhs);
  const Eigen::VectorXd f = yv - ((1.0 - p) / p) * (Dinv * (Q * gamma));
  return std::vector<double>(f.data(), f.data() + n);
}

// ---------------------------------------------------------------- Tukey

namespace {

double med3(double a, double b, double c) { return std::max(std::min(a, b), std::min(std::max(a, b), c)); }

/// Tukey's end-point rule: y0 <- med(y0, z1, 3 z1 - 2 z2).
void end_rule(std::vector<double>& z, const std::vector<double>& y) {
  const int n = static_cast<int>(z.size());
  if (n < 3) return;
  z[0] = med3(y[0], z[1], 3 * z[1] - 2 * z[2]);
  z[n - 1] = med3(y[n - 1], z[n - 2], 3 * z[n - 2] - 2 * z[n - 3]);
}

std::vector<double> running_median(const std::vector<double>& y, int span, bool periodic) {
  const int n = static_cast<int>(y.size());
  if (n < 3) return y;
  std::vector<double> z(y);
  const int k = span / 2;
  double buf[5];
  for (int i = 0; i < n; ++i) {
    int m = periodic ? k : std::min({k, i, n - 1 - i});
    if (m == 0) continue;
    int c = 0;
    for (int j = -m; j <= m; ++j) buf[c++] = y[periodic ? ((i + j) % n + n) % n : i + j];
    std::nth_element(buf, buf + c / 2, buf + c);
    z[i] = buf[c / 2];
  }
  if (!periodic) end_rule(z, y);
  return z;
}

std::vector<double> repeat_median(const std::vector<double>& y, int span, bool periodic) {
  std::vector<double> z = running_median(y, span, periodic);
  for (int it = 0; it < 200; ++it) {
    std::vector<double> next = running_median(z, span, periodic);
    if (next == z) break;
    z.swap(next);
  }
  return z;
}

std::vector<double> hanning(const std::vector<double>& y, bool periodic) {
  const int n = static_cast<int>(y.size());
  if (n < 3) return y;
  std::vector<double> z(y);
  for (int i = 0; i < n; ++i) {
    if (!periodic && (i == 0 || i == n - 1)) continue;
    const double a = y[(i - 1 + n) % n], b = y[(i + 1) % n];
    z[i] = 0.25 * a + 0.5 * y[i] + 0.25 * b;
  }
  return z;
}

/// One splitting pass: every two-point plateau that is a local peak or valley
/// is split and each half re-estimated by the end-point rule; then 3R.
std::vector<double> split(const std::vector<double>& y, bool periodic) {
  const int n = static_cast<int>(y.size());
  if (n < 6) return y;
  std::vector<double> z(y);
  auto at = [&](int i) { return y[(i % n + n) % n]; };
  for (int i = 0; i < n; ++i) {
    if (!periodic && (i < 2 || i + 3 >= n)) continue;
    const double a = at(i), b = at(i + 1);
    if (a != b) continue;
    const double l = at(i - 1), r = at(i + 2);
    if (!((l - a) * (r - b) > 0)) continue;  // not a peak or valley plateau
    z[i] = med3(a, l, 3 * l - 2 * at(i - 2));
    z[(i + 1) % n] = med3(b, r, 3 * r - 2 * at(i + 3));
  }
  return repeat_median(z, 3, periodic);
}

struct TukeyOp {
  char kind;  // '3', '5', 'S', 'H'
  bool repeat = false;
};

std::vector<TukeyOp> parse_tukey(const std::string& seq, bool& twice) {
  std::vector<TukeyOp> ops;
  twice = false;
  std::string s;
  for (char c : seq)
    if (!std::isspace(static_cast<unsigned char>(c)))
      s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const auto comma = s.find(',');
  if (comma != std::string::npos) {
    if (s.substr(comma) != ",TWICE")
      throw InputError("wear.smoothing_tukey",
                       fmt::format("smoothing_tukey = \"{}\": only \",twice\" may follow the sequence", seq));
    twice = true;
    s = s.substr(0, comma);
  }
  if (s.empty()) throw InputError("wear.smoothing_tukey", "smoothing_tukey is empty; e.g. \"3RSSH,twice\"");
  bool last_r = false;
  for (char c : s) {
    if (c == '3' || c == '5' || c == 'S' || c == 'H') {
      ops.push_back({c, false});
      last_r = false;
    } else if (c == 'R') {
      if (last_r) continue;  // R after R: already converged
      if (!ops.empty() && ops.back().kind != 'H' && !ops.back().repeat) {
        ops.back().repeat = true;
      } else {
        ops.push_back({'3', true});  // R after H (or leading): repeated running medians
      }
      last_r = true;
    } else {
      throw InputError(
          "wear.smoothing_tukey",
          fmt::format("smoothing_tukey = \"{}\": unknown letter '{}'; allowed 3, 5, R, S, H and \",twice\"", seq, c));
    }
  }
  return ops;
}

std::vector<double> apply_ops(const std::vector<double>& y, const std::vector<TukeyOp>& ops, bool periodic) {
  std::vector<double> z(y);
  for (const TukeyOp& op : ops) {
    switch (op.kind) {
      case '3':
      case '5': {
        const int span = op.kind - '0';
        z = op.repeat ? repeat_median(z, span, periodic) : running_median(z, span, periodic);
        break;
      }
      case 'S': {
        std::vector<double> next = split(z, periodic);
        for (int it = 0; op.repeat && it < 100 && next != z; ++it) {
          z.swap(next);
          next = split(z, periodic);
        }
        z.swap(next);
        break;
      }
      case 'H':
        z = hanning(z, periodic);
        break;
    }
  }
  return z;
}

}  // namespace

std::vector<double> tukey_smooth(const std::vector<double>& y, const std::string& sequence, bool periodic) {
  bool twice = false;
  const std::vector<TukeyOp> ops = parse_tukey(sequence, twice);
  std::vector<double> z = apply_ops(y, ops, periodic);
  if (twice) {
    std::vector<double> r(y.size());
    for (size_t i = 0; i < y.size(); ++i) r[i] = y[i] - z[i];
    const std::vector<double> zr = apply_ops(r, ops, periodic);
    for (size_t i = 0; i < y.size(); ++i) z[i] += zr[i];
  }
  return z;
}

// ---------------------------------------------------------------- depth fields

SmoothingResult smooth_depth(const std::vector<double>& y, const std::vector<double>& spacing,
                             const std::vector<double>& w, const SmoothingSpec& spec, bool periodic) {
  SmoothingResult r;
  const size_t n = y.size();
  for (size_t i = 0; i < n; ++i) r.raw_mass += w[i] * y[i];
  switch (spec.method) {
    case SmoothingMethod::None:
      r.values = y;
      break;
    case SmoothingMethod::MovingAverage:
      r.values = moving_average(y, spec.window, periodic);
      break;
    case SmoothingMethod::Csaps:
      r.values = csaps(y, spacing, w, spec.csaps_p, periodic);
      break;
    case SmoothingMethod::Tukey:
      r.values = tukey_smooth(y, spec.tukey, periodic);
      break;
    case SmoothingMethod::TukeyCsaps:
      r.values = csaps(tukey_smooth(y, spec.tukey, periodic), spacing, w, spec.csaps_p, periodic);
      break;
  }
  auto mass = [&](const std::vector<double>& v) {
    double m = 0;
    for (size_t i = 0; i < n; ++i) m += w[i] * v[i];
    return m;
  };
  if (!(r.raw_mass > 0)) {
    r.values = y;
    return r;
  }
  r.relative_change = mass(r.values) / r.raw_mass - 1.0;
  for (double& v : r.values) v = std::max(0.0, v);
  const double clipped = mass(r.values);
  r.relative_change_clipped = clipped / r.raw_mass - 1.0;
  if (!(clipped > 0)) {  // the smoother removed everything (an isolated spike): keep the raw field
    r.values = y;
    return r;
  }
  const double scale = r.raw_mass / clipped;
  for (double& v : r.values) v *= scale;
  return r;
}

}  // namespace linerlife
