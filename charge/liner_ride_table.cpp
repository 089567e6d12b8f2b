#include "charge/liner_ride_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "charge/exact_math.h"
#include "geometry/errors.h"
#include "geometry/mill.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();

double wrap_2pi(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

/// atan2 to about 1e-5 rad, enough to pick the bins to search.
inline double fast_atan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double mx = std::max(ax, ay), mn = std::min(ax, ay);
  if (mx == 0) return 0;
  const double a = mn / mx, s = a * a;
  double r = ((((((-0.0040540580 * s + 0.0218612288) * s - 0.0559098861) * s + 0.0964200441) * s - 0.1390853351) * s +
               0.1994653599) * s - 0.3332985605) * s * a + a;
  if (ay > ax) r = 0.5 * kPi - r;
  if (x < 0) r = kPi - r;
  return y < 0 ? -r : r;
}

/// The capsule of radius a round segment AB, with the terms of
/// capsule_entry() that do not depend on the ray.
struct Capsule {
  double ax, ay, bx, by;  // A, B
  double abx, aby, l2;    // B - A, |B - A|^2
  double nx, ny, an;      // unit normal of AB, A . n
  double a2n, b2n, aa;    // |A|^2, |B|^2, a^2
  double a;
  Capsule(const V& A, const V& B, double a_) : ax(A.x()), ay(A.y()), bx(B.x()), by(B.y()), a(a_) {
    abx = bx - ax;
    aby = by - ay;
    l2 = abx * abx + aby * aby;
    nx = ny = an = 0;
    if (l2 > 0) {
      const double sl = std::sqrt(l2);
      nx = -aby / sl;
      ny = abx / sl;
      an = ax * nx + ay * ny;
    }
    a2n = ax * ax + ay * ay;
    b2n = bx * bx + by * by;
    aa = a * a;
  }
};

/// Radius at which the ray r u (r >= 0) first enters the capsule of radius a
/// round segment AB; +inf if it does not. The origin must lie outside.
/// (Scalar, each term in the order of the vector form it replaced, so the
/// table is the same to the bit.)
inline __attribute__((always_inline)) double capsule_entry(double ux, double uy, const Capsule& c) {
  double best = std::numeric_limits<double>::infinity();
  if (c.l2 > 0) {
    const double un = ux * c.nx + uy * c.ny;
    if (std::abs(un) > 1e-14) {
      for (double side : {-1.0, 1.0}) {
        const double r = (c.an + side * c.a) / un;
        if (r <= 0 || r >= best) continue;
        const double t = ((r * ux - c.ax) * c.abx + (r * uy - c.ay) * c.aby) / c.l2;
        if (t >= 0 && t <= 1) best = r;
      }
    }
  }
  {
    const double uc = ux * c.ax + uy * c.ay;
    const double disc = uc * uc - c.a2n + c.aa;
    if (disc >= 0) {
      const double r = uc - std::sqrt(disc);
      if (r > 0 && r < best) best = r;
    }
  }
  {
    const double uc = ux * c.bx + uy * c.by;
    const double disc = uc * uc - c.b2n + c.aa;
    if (disc >= 0) {
      const double r = uc - std::sqrt(disc);
      if (r > 0 && r < best) best = r;
    }
  }
  return best;
}

}  // namespace

double load_contact_spacing_m(const LinerSurface& s) {
  std::vector<double> len(s.length.begin(), s.length.end());
  if (len.empty()) return 0.002;
  std::nth_element(len.begin(), len.begin() + len.size() / 2, len.end());
  return std::min(0.002, 0.75 * len[len.size() / 2]);
}

LinerRideTable build_liner_ride_table(const LinerSurface& s, double a, int bins_per_disc_radius,
                                      double contact_spacing_m) {
  if (!(a > 0)) throw InputError("charge.ball_diameter_m", "the media diameter must be positive");
  LinerRideTable t;
  t.disc_radius_m = a;
  const double R = s.shell_radius_m;
  const double want = kTwoPi * R / (a / bins_per_disc_radius);
  int n = 1024;
  while (n < want && n < (1 << 16)) n <<= 1;
  t.n_bins = n;
  t.bin_rad = kTwoPi / n;
  t.inv_bin = n / kTwoPi;
  t.edge_radius_m.assign(n, std::numeric_limits<double>::infinity());
  std::vector<int> edge_element(n, -1);
  t.cos_e.resize(n);
  t.sin_e.resize(n);
  for (int b = 0; b < n; ++b) {
    const double c = b * t.bin_rad;
    t.cos_e[b] = std::cos(c);
    t.sin_e[b] = std::sin(c);
  }
  // Each element's capsule covers a short arc of angles: its endpoints' angles
  // widened by the angle the disc subtends at its nearest point. The ride
  // radius at an edge is the smallest entry radius over the elements whose
  // arc holds it, and its element the first (lowest index) of equals: what a
  // scan of the elements in order keeping strict improvements gives.
  //
  // Most of those entries are far from the smallest (the arc is wide, the
  // nearest element is hit straight on), so they are bounded from below and
  // computed only where the bound does not rule them out. With the
  // endpoints' arc [L, H] in bins, a ray at bin B < L is at least
  // j = floor(L - 1e-6) - B whole bins from every point of the segment, one
  // at B > H at least j = B - ceil(H + 1e-6) (the 1e-6 bin covers the
  // rounding of the angles):
  //  1. the rays with j <= 0 (inside the arc or within a bin of it: the
  //     element straight ahead and its neighbours, usually the smallest),
  //     for every element in order, with the bound of 2. at delta = 0;
  //  2. the rays with j >= 1: a ray at angle delta (< pi/2) from every point
  //     of a segment at distance >= rho (> a') from the axis can only meet
  //     the capsule of radius a' round it at a radius of at least
  //     rho cos(delta) - sqrt(a'^2 - rho^2 sin^2(delta)) (law of cosines:
  //     the near intersection with the disc round any point q of the segment
  //     grows with |q| and with the angle to q), and not at all where
  //     rho sin(delta) > a'. A computed entry is a point within a' = a + tol
  //     of the segment (the roots' rounding moves it by far less than tol
  //     where |u . n| is not tiny; rays nearly parallel to the segment are
  //     never skipped), so an entry whose bound (at delta = j bins) exceeds
  //     the best so far by tol cannot change the table.
  // Same table to the bit (checked against the scan of every element on the
  // fingerprint mills, the forecast's worn surfaces and the unit tests).
  const int ne_all = s.n_elements();
  const int mask = n - 1;  // n is a power of two
  std::vector<double> node_angle(ne_all);
  for (int i = 0; i < ne_all; ++i) node_angle[i] = std::atan2(s.nodes[i].y(), s.nodes[i].x());
  struct Reach {
    Capsule cap;
    double rho;   // [m] distance of the segment from the axis (a lower bound)
    int b0, b1;   // the bins of the arc (unwrapped: b & mask), b0..b1
    int JL, JR;   // j = JL - B before the arc, B - JR after it
  };
  std::vector<Reach> reach;
  reach.reserve(ne_all);
  const double tol = 1e-6 * (R + a);  // [m] see a' above
  const double a1 = a + tol;
  auto offer = [&](int b, int e, double r) {
    if (r < t.edge_radius_m[b] || (r == t.edge_radius_m[b] && e < edge_element[b])) {
      t.edge_radius_m[b] = r;
      edge_element[b] = e;
    }
  };
  for (int e = 0; e < ne_all; ++e) {
    const V& A = s.nodes[e];
    const V& B = s.nodes[s.next(e)];
    const Capsule cap(A, B, a);  // its own terms once for all its rays
    const double ra = A.norm(), rb = B.norm();
    const double rmin = std::max(1e-9, std::min(ra, rb) - a);
    const double widen = rmin > a ? std::asin(a / rmin) : kPi;
    const double pa = node_angle[e];
    const double dp = remainder_2pi(node_angle[s.next(e)] - pa);
    const double lo_e = dp >= 0 ? pa : pa + dp;
    const double lo = lo_e - widen;
    const double span = std::abs(dp) + 2.0 * widen;
    const int b0 = floor_int(lo * t.inv_bin) - 1;
    const int nb = ceil_int(span * t.inv_bin) + 2;
    const double tc = cap.l2 > 0 ? std::clamp(-(A.x() * cap.abx + A.y() * cap.aby) / cap.l2, 0.0, 1.0) : 0.0;
    const double rho = V(A.x() + tc * cap.abx, A.y() + tc * cap.aby).norm() * (1 - 1e-12);
    const Reach rc{cap, rho, b0, b0 + nb, floor_int(lo_e * t.inv_bin - 1e-6),
                   ceil_int((lo_e + std::abs(dp)) * t.inv_bin + 1e-6)};
    // 1. j <= 0, with the bound at delta = 0, rho - a' (in a pocket the
    // lifter before it may have ruled out the plate)
    const double bound0 = rho > a1 ? rho - a1 - tol : -kInf;
    for (int q = std::max(b0, rc.JL), q1 = std::min(rc.b1, rc.JR); q <= q1; ++q) {
      const int b = q & mask;
      const double ux = t.cos_e[b], uy = t.sin_e[b];
      if (bound0 > t.edge_radius_m[b]) {
        const double un = std::abs(ux * cap.nx + uy * cap.ny);
        if (!(un > 1e-14 && un < 1e-6)) continue;
      }
      offer(b, e, capsule_entry(ux, uy, cap));
    }
    reach.push_back(rc);
  }
  // 2. j >= 1, where the bound does not rule it out. The bound depends on j
  // only: one per j and element (bound[j]).
  const double a12 = a1 * a1;
  std::vector<double> bound;
  for (int e = 0; e < ne_all; ++e) {
    const Reach& rc = reach[e];
    const int jmax = std::max(rc.JL - rc.b0, rc.b1 - rc.JR);
    if (jmax < 1) continue;
    if (!(rc.rho > a1) || 4 * jmax >= n) {  // no bound: every ray
      for (int B = rc.b0; B <= rc.b1; ++B) {
        if (B >= rc.JL && B <= rc.JR) continue;  // done in 1.
        const int b = B & mask;
        offer(b, e, capsule_entry(t.cos_e[b], t.sin_e[b], rc.cap));
      }
      continue;
    }
    // +inf: the ray passes the capsule (so do those further out: rho sin(delta) grows)
    bound.resize(static_cast<size_t>(jmax) + 1);
    int jpass = jmax + 1;
    for (int j = 1; j <= jmax; ++j) {
      const double rs = rc.rho * t.sin_e[j];
      if (rs > a1) {
        jpass = j;
        break;
      }
      bound[j] = rc.rho * t.cos_e[j] - std::sqrt(a12 - rs * rs) - tol;
    }
    // The bound holds for computed entries where |u . n| is not within
    // (1e-14, 1e-6): everywhere over the arc if it is well beyond at its
    // middle (u . n turns by at most the angle turned), else tested per ray.
    const int Bm = (rc.b0 + rc.b1) / 2;
    const double un_mid = std::abs(t.cos_e[Bm & mask] * rc.cap.nx + t.sin_e[Bm & mask] * rc.cap.ny);
    const bool un_clear = un_mid > 1e-6 + (rc.b1 - Bm + 2) * t.bin_rad;
    auto ray = [&](int B, int j) {
      const int b = B & mask;
      const double ux = t.cos_e[b], uy = t.sin_e[b];
      if (j >= jpass || bound[j] > t.edge_radius_m[b]) {
        if (un_clear) return;
        const double un = std::abs(ux * rc.cap.nx + uy * rc.cap.ny);
        if (!(un > 1e-14 && un < 1e-6)) return;
      }
      offer(b, e, capsule_entry(ux, uy, rc.cap));
    };
    // before the arc, then after it; where |u . n| is clear of the band the
    // rays from jpass on pass the capsule and are not visited
    const int jend = un_clear ? jpass - 1 : jmax;
    for (int B = std::min(rc.JL - 1, rc.b1); B >= rc.b0 && rc.JL - B <= jend; --B) ray(B, rc.JL - B);
    for (int B = std::max(rc.JR + 1, rc.b0); B <= rc.b1 && B - rc.JR <= jend; ++B) ray(B, B - rc.JR);
  }
  // a bin keeps the smaller of its edges, and the element touched there
  t.ride_radius_m.resize(n);
  t.support_element.resize(n);
  for (int b = 0; b < n; ++b) {
    const int b1 = b + 1 == n ? 0 : b + 1;
    const bool left = t.edge_radius_m[b] <= t.edge_radius_m[b1];
    t.ride_radius_m[b] = left ? t.edge_radius_m[b] : t.edge_radius_m[b1];
    t.support_element[b] = left ? edge_element[b] : edge_element[b1];
  }
  // Contact rays between the edges (LinerRideTable::contact_element). The
  // disc touches edge_element[b] at edge b and edge_element[b + 1] at edge
  // b + 1; the surface between those two contact points is the elements
  // between them along the ring, so only they can be touched by a ray
  // between, each tested exactly as above. Along the rays the touched element
  // moves forward along the ring (on a profile every ray from the axis
  // crosses once), so the bin is bisected: a ray halfway between two rays is
  // searched among the elements from the one's to the other's, and rays
  // between two that touch the same element touch it too. Tested
  // against every element, on new and worn lifters
  // (tests/charge/test_liner_ride_table.cpp).
  int rays = 1;
  if (contact_spacing_m > 0)
    while (rays < 64 && R * t.bin_rad / rays > contact_spacing_m) rays <<= 1;
  t.contact_rays_per_bin = rays;
  t.inv_contact_ray = t.inv_bin * rays;
  t.contact_element.resize(static_cast<size_t>(n) * rays);
  const int ne = s.n_elements();
  std::vector<double> ck(rays), sk(rays);
  for (int k = 0; k < rays; ++k) {
    ck[k] = std::cos(k * t.bin_rad / rays);
    sk[k] = std::sin(k * t.bin_rad / rays);
  }
  // the element among `count` from `first` on along the ring whose capsule
  // ray k of bin b enters first (the first of equals; `none` if none)
  auto touched = [&](int b, int k, int first, int count, int none) {
    const V u(t.cos_e[b] * ck[k] - t.sin_e[b] * sk[k], t.sin_e[b] * ck[k] + t.cos_e[b] * sk[k]);
    double best = std::numeric_limits<double>::infinity();
    int be = none;
    for (int i = 0, e = first; i < count; ++i, e = e + 1 == ne ? 0 : e + 1) {
      const double r = capsule_entry(u.x(), u.y(), reach[e].cap);  // (Capsule(nodes e, e + 1, a), made once)
      if (r < best) {
        best = r;
        be = e;
      }
    }
    return be;
  };
  for (int b = 0; b < n; ++b) {
    const int b1 = b + 1 == n ? 0 : b + 1;
    const int e0 = edge_element[b], e1 = edge_element[b1];
    int* out = &t.contact_element[static_cast<size_t>(b) * rays];
    out[0] = e0;
    if (rays == 1) continue;
    if (e0 == e1 || e0 < 0 || e1 < 0) {  // (no element at an edge: refused below)
      std::fill(out + 1, out + rays, e0);
      continue;
    }
    const int fwd = ((e1 - e0) % ne + ne) % ne;
    if (fwd > ne - fwd) {  // the surface runs back here (an overhang): every element between, every ray
      for (int k = 1; k < rays; ++k) out[k] = touched(b, k, e1, ne - fwd + 1, 2 * k < rays ? e0 : e1);
      continue;
    }
    // the touched element moves forward along the ring from ray to ray: a ray
    // halfway between two rays touches one of the elements from the first's
    // to the second's, and where both touch the same element so do all rays
    // between them
    auto fill = [&](auto&& self, int klo, int khi, int elo, int ehi) -> void {
      if (khi - klo < 2) return;
      if (elo == ehi) {
        std::fill(out + klo + 1, out + khi, elo);
        return;
      }
      const int km = (klo + khi) / 2;
      out[km] = touched(b, km, elo, ((ehi - elo) % ne + ne) % ne + 1, elo);
      self(self, klo, km, elo, out[km]);
      self(self, km, khi, out[km], ehi);
    };
    fill(fill, 0, rays, e0, e1);
  }
  t.ride_normal.resize(n);
  for (int b = 0; b < n; ++b) {
    const V e = t.point(b + 1 == n ? 0 : b + 1) - t.point(b);
    const double l = e.norm();
    t.ride_normal[b] = l > 0 && std::isfinite(l) ? V(-e.y() / l, e.x() / l) : V(-t.cos_e[b], -t.sin_e[b]);
  }
  t.block_min_ride_m.assign((n + LinerRideTable::kBlock - 1) / LinerRideTable::kBlock,
                            std::numeric_limits<double>::infinity());
  for (int b = 0; b < n; ++b) {
    double& m = t.block_min_ride_m[b / LinerRideTable::kBlock];
    m = std::min(m, t.ride_radius_m[b]);
  }
  t.min_ride_m = std::numeric_limits<double>::infinity();
  t.max_ride_m = 0;
  for (int b = 0; b < n; ++b) {
    if (!std::isfinite(t.ride_radius_m[b]))
      throw SimulationError("liner ride table: a ray from the mill axis meets no liner element; the surface is not a closed ring");
    t.min_ride_m = std::min(t.min_ride_m, t.ride_radius_m[b]);
    t.max_ride_m = std::max(t.max_ride_m, t.ride_radius_m[b]);
  }
  return t;
}

bool first_ride_crossing(const LinerRideTable& t, double rot, const V& p0, const V& v0, const V& acc, double ta,
                         double tb, double& t_hit, int& bin_hit, double reach_m) {
  const V pa = p0 + v0 * ta + 0.5 * acc * ta * ta;
  const V pb = p0 + v0 * tb + 0.5 * acc * tb * tb;
  const double psa = fast_atan2(pa.y(), pa.x()) - rot, psb = fast_atan2(pb.y(), pb.x()) - rot;
  double d = remainder_2pi(psb - psa);
  // the polar angle of a parabola arc can turn by more than the chord says
  // when it passes close to the axis; such arcs are far from the liner, and
  // the caller only asks near it.
  const double lo = d >= 0 ? psa : psa + d;
  double lw = lo < 0 ? lo + kTwoPi : lo;
  if (lw >= kTwoPi) lw -= kTwoPi;
  if (lw < 0 || lw >= kTwoPi) lw = wrap_2pi(lw);
  const int b0 = static_cast<int>(lw * t.inv_bin) - 1;
  const int nb = static_cast<int>(std::ceil(std::abs(d) * t.inv_bin)) + 3;
  // (the layer model passes the path in the liner frame: rot = 0, no rotation)
  const bool turned = rot != 0;
  const double c = turned ? std::cos(rot) : 1.0, s = turned ? std::sin(rot) : 0.0;
  // quick reject: the arc stays inside the smallest ride radius of the bins it spans
  {
    const double rmax2 = std::max(pa.squaredNorm(), pb.squaredNorm());
    const double tm = 0.5 * (ta + tb);
    const Eigen::Vector2d pm = p0 + v0 * tm + 0.5 * acc * tm * tm;
    const double rmax = std::sqrt(std::max(rmax2, pm.squaredNorm())) + 0.125 * (pb - pa).norm();
    if (rmax < t.min_ride_m) return false;
    const int B = LinerRideTable::kBlock;
    const int nblk = static_cast<int>(t.block_min_ride_m.size());
    const int k0 = (b0 < 0 ? b0 + t.n_bins : b0) / B, k1 = ((b0 + nb + 1) % t.n_bins + t.n_bins) % t.n_bins / B;
    double mn = std::numeric_limits<double>::infinity();
    for (int k = k0;; k = (k + 1) % nblk) {
      mn = std::min(mn, t.block_min_ride_m[k]);
      if (k == k1) break;
    }
    if (rmax < mn) return false;
  }
  bool found = false;
  double best = tb;
  // ride point at edge b in the fixed frame; the rotation by 0 returns a point
  // unchanged where its radius is positive and finite (no coordinate is -0 or
  // infinite)
  auto placed = [&](int b) {
    const V q = t.point(b);
    const double r = t.edge_radius_m[b];
    return !turned && r > 0 && r < kInf ? q : V(c * q.x() - s * q.y(), s * q.x() + c * q.y());
  };
  int b = b0 % t.n_bins;
  if (b < 0) b += t.n_bins;
  for (int k = 0; k <= nb; ++k) {
    const int b1 = b + 1 == t.n_bins ? 0 : b + 1;
    if (t.ride_radius_m[b] > reach_m) {  // not reached (the caller's bound)
      b = b1;
      continue;
    }
    const V q1 = placed(b);
    const V q2 = placed(b1);
    const V e = q2 - q1;
    const V m(-e.y(), e.x());  // points into the mill (polyline runs anticlockwise)
    // f(t) = (p(t) - q1) . m: > 0 inside, crossing outward where f falls through 0.
    const double A2 = 0.5 * acc.dot(m), A1 = v0.dot(m), A0 = (p0 - q1).dot(m);
    double roots[2];
    int nr = 0;
    if (std::abs(A2) < 1e-300) {
      if (std::abs(A1) > 0) roots[nr++] = -A0 / A1;
    } else {
      const double disc = A1 * A1 - 4 * A2 * A0;
      if (disc >= 0) {
        const double sq = std::sqrt(disc);
        const double qq = -0.5 * (A1 + (A1 >= 0 ? sq : -sq));
        roots[nr++] = qq / A2;
        if (qq != 0) roots[nr++] = A0 / qq;
      }
    }
    for (int i = 0; i < nr; ++i) {
      const double r = roots[i];
      if (!(r > ta) || r > best) continue;
      const double slope = 2 * A2 * r + A1;  // df/dt
      if (slope >= 0) continue;               // moving inward: not an entry into the liner
      const V p = p0 + v0 * r + 0.5 * acc * r * r;
      const double l2 = e.squaredNorm();
      const double u = l2 > 0 ? (p - q1).dot(e) / l2 : 0;
      if (u < -1e-9 || u > 1 + 1e-9) continue;
      best = r;
      bin_hit = b;
      found = true;
    }
    b = b1;
  }
  if (found) t_hit = best;
  return found;
}

}  // namespace linerlife
