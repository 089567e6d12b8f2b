#include "charge/dem/dem_system.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <omp.h>

#include "geometry/errors.h"

namespace linerlife {

/// Contact force, torque and contact count on one disc from one partition
/// (half a cache line: the pair loop touches a partner once).
struct DemSystem::ForceAcc {
  double fx = 0, fy = 0;  // [N/m]
  double tq = 0;          // [N m/m]
  double nc = 0;          // contacts
};

/// One wall element packed in one cache line for the contact loop.
struct alignas(64) DemSystem::PackedElement {
  double ax, ay;  // [m] start node, body frame
  double ux, uy;  // unit tangent
  double nx, ny;  // unit normal into the particle side
  double len;     // [m]
  int convex_start, convex_end;
};

/// Everything one partition writes during a step, padded against false sharing.
struct alignas(64) DemSystem::ThreadData {
  std::vector<ForceAcc> f;         // contact forces on every disc from this thread's contacts
  std::vector<int> row_count;      // list rebuild: partners of each row in this thread's particle range
  std::vector<int> loc_j;
  std::vector<double> loc_xi;
  double maxd2 = 0, maxd2b = 0;    // [m2] the two largest squared displacements since the last build
  std::vector<double> ld_n, ld_s, ld_ns, ld_ss;  // per element load sums
  double drive_work = 0;           // [J/m]
  double wall_fx = 0, wall_fy = 0;  // [N/m] sum of the wall forces this thread computed at the last evaluation
  double wimp_x = 0, wimp_y = 0;   // [N s/m] wall impulse, kick by kick
  std::vector<ImpactRecord> impacts;
  std::vector<WallContactRecord> records;
  long long pair_contacts = 0, wall_contacts = 0;
  double max_ratio = 0;       // largest particle-particle overlap / smaller radius
  double max_wall_ratio = 0;  // largest wall overlap / radius
  long long wall_hits_dropped = 0;     // disc-liner contacts beyond kMaxWallHits of one disc (the shallowest)
  long long wall_springs_dropped = 0;  // contacts beyond kWallSlots of one disc: their tangential spring restarts
  double max_v2 = 0;  // [m2/s2] largest speed squared at the last check
  int worst = -1;     // disc with max_v2
  bool nonfinite = false;
  bool checked = false;  // the last gather checked its range
  int escaped = -1;      // a disc found outside escape_radius at the last check
  std::vector<int> wall_part;          // discs this thread checks against the wall until the next build
  std::vector<int> wc_start, wc_elem;  // their candidate elements (CSR)
  double elastic_pair = 0, elastic_wall = 0;  // [J/m] energy in the contact springs at the last evaluation
  long long steps_done = 0;  // steps completed in this advance()
  int fail = 0;  // this thread has reported a failure
};

namespace {

inline int range_begin(int n, int t, int nt) { return static_cast<int>(static_cast<long long>(n) * t / nt); }

}  // namespace

DemSystem::DemSystem(const DemSettings& settings, WallMesh walls, const DemParticles& p)
    : set_(settings), walls_(std::move(walls)) {
  n_ = p.size();
  for (const auto* v : {&p.y, &p.vx, &p.vy, &p.w, &p.radius, &p.mass})
    if (static_cast<int>(v->size()) != n_) throw std::invalid_argument("DemParticles: vectors of different sizes");
  if (!(set_.dt > 0)) throw std::invalid_argument("DemSettings: dt must be > 0");
  nt_ = std::max(1, set_.threads);
  np_ = kPartitions;
  x_ = p.x, y_ = p.y, vx_ = p.vx, vy_ = p.vy, w_ = p.w, r_ = p.radius, m_ = p.mass;
  invm_.resize(n_), invI_.resize(n_);
  rmax_ = 0, rmin_ = std::numeric_limits<double>::max();
  for (int i = 0; i < n_; ++i) {
    if (!(r_[i] > 0 && m_[i] > 0)) throw std::invalid_argument("DemParticles: radius and mass must be > 0");
    invm_[i] = 1 / m_[i];
    invI_[i] = 2 / (m_[i] * r_[i] * r_[i]);  // uniform disc: I = m r^2 / 2
    rmax_ = std::max(rmax_, r_[i]), rmin_ = std::min(rmin_, r_[i]);
  }
  if (n_ == 0) rmax_ = rmin_ = 1;
  double rmean = 0;
  for (int i = 0; i < n_; ++i) rmean += r_[i] / n_;
  // 3/4 of the mean radius: a larger skin means fewer list builds but more
  // list entries to test every step; in the mills of data/mills the list is
  // rebuilt every 5 to 15 steps with it
  skin_ = set_.skin > 0 ? set_.skin : 0.75 * (n_ > 0 ? rmean : 1.0);
  fx_.assign(n_, 0), fy_.assign(n_, 0), tq_.assign(n_, 0);
  xref_ = x_, yref_ = y_;
  ncontact_.assign(n_, 0);
  free_steps_.assign(n_, 0);
  id_.resize(n_);
  for (int i = 0; i < n_; ++i) id_[i] = i;
  wslot_elem_.assign(static_cast<size_t>(n_) * kWallSlots, -1);
  wslot_xi_.assign(static_cast<size_t>(n_) * kWallSlots, 0.0);
  nb_start_.assign(n_ + 1, 0);
  for (auto& v : shadow_d_) v.resize(n_);
  shadow_id_.resize(n_), shadow_free_.resize(n_);
  shadow_slot_e_.resize(wslot_elem_.size()), shadow_slot_xi_.resize(wslot_xi_.size());
  td_.resize(np_);
  wacc_.assign(n_, ForceAcc{});
  part_lo_.assign(np_, 0), part_hi_.assign(np_, -1);
  for (auto& t : td_) {
    t.f.assign(n_, ForceAcc{});
  }
  if (walls_.n_elements() > 0 && (walls_.cell_start.empty() || walls_.reach < rmax_ + skin_))
    build_wall_grid(walls_, rmax_ + skin_, std::max(0.5 * (rmax_ + skin_), 1e-3 * (walls_.max_radius + rmax_)));
  packed_.resize(walls_.n_elements());
  for (int e = 0; e < walls_.n_elements(); ++e)
    packed_[e] = {walls_.ax[e], walls_.ay[e], walls_.ux[e], walls_.uy[e], walls_.nx[e],
                  walls_.ny[e], walls_.len[e], walls_.convex_start[e], walls_.convex_end[e]};
  angle_ = set_.wall_angle0;
  cos_a_ = std::cos(angle_), sin_a_ = std::sin(angle_);
}

DemSystem::~DemSystem() = default;
DemSystem::DemSystem(DemSystem&&) noexcept = default;
DemSystem& DemSystem::operator=(DemSystem&&) noexcept = default;

void DemSystem::set_velocity(int i, double vx, double vy, double w) {
  vx_[i] = vx, vy_[i] = vy, w_[i] = w;
}

int DemSystem::index_of(int id) const {
  for (int i = 0; i < n_; ++i)
    if (id_[i] == id) return i;
  return -1;
}

void DemSystem::fail(const std::string& message) {
#pragma omp critical(dem_fail)
  {
    if (!failed_) failure_ = message;
    failed_ = 1;
  }
}

// ---------------------------------------------------------------- neighbours

void DemSystem::rebuild_prepare(double time) {
  ++builds_;
  std::swap(nb_start_, old_start_);
  std::swap(nb_j_, old_j_);
  std::swap(nb_xi_, old_xi_);
  if (old_start_.size() != static_cast<size_t>(n_) + 1) old_start_.assign(n_ + 1, 0);
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (int i = 0; i < n_; ++i) {
    x0 = std::min(x0, x_[i]), x1 = std::max(x1, x_[i]);
    y0 = std::min(y0, y_[i]), y1 = std::max(y1, y_[i]);
  }
  cell_ = 2 * rmax_ + skin_;
  cx0_ = x0 - 0.5 * cell_, cy0_ = y0 - 0.5 * cell_;
  const double nxd = std::floor((x1 - cx0_) / cell_) + 1, nyd = std::floor((y1 - cy0_) / cell_) + 1;
  if (!(nxd * nyd < 2e7)) {
    fail(fmt::format("at t = {:.4f} s the discs spread over {:.3g} x {:.3g} m ({} cells): a disc has flown off "
                     "(a blow-up); reduce the time step or check the contact parameters",
                     time, x1 - x0, y1 - y0, nxd * nyd));
    cnx_ = cny_ = 1;
  } else {
    cnx_ = std::max(3, static_cast<int>(nxd)), cny_ = static_cast<int>(nyd);
  }
  // Counting sort by cell (stable, so the order is deterministic).
  const int nc = cnx_ * cny_;
  cell_start_.assign(nc + 1, 0);
  cell_of_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    int cx = static_cast<int>((x_[i] - cx0_) / cell_), cy = static_cast<int>((y_[i] - cy0_) / cell_);
    cx = std::clamp(cx, 0, cnx_ - 1), cy = std::clamp(cy, 0, cny_ - 1);
    cell_of_[i] = cy * cnx_ + cx;
    ++cell_start_[cell_of_[i] + 1];
  }
  for (int c = 0; c < nc; ++c) cell_start_[c + 1] += cell_start_[c];
  order_.resize(n_);
  {
    std::vector<int>& fill = scratch_i_;
    fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (int i = 0; i < n_; ++i) order_[fill[cell_of_[i]]++] = i;
  }
}

void DemSystem::rebuild_permute(int t) {
  // Reorder every per-disc array into its shadow (the particles of a cell
  // become contiguous); each thread does one slice. The accelerations and
  // contact counts are rewritten by the next gather before anyone reads them.
  const int p0 = range_begin(n_, t, np_), p1 = range_begin(n_, t + 1, np_);
  const int* __restrict order = order_.data();
  std::vector<double>* const dv[] = {&x_, &y_, &vx_, &vy_, &w_, &r_, &m_, &invm_, &invI_};
  for (int a = 0; a < 9; ++a) {
    const double* __restrict src = dv[a]->data();
    double* __restrict dst = shadow_d_[a].data();
    for (int k = p0; k < p1; ++k) dst[k] = src[order[k]];
  }
  for (int k = p0; k < p1; ++k) {
    shadow_id_[k] = id_[order[k]];
    shadow_free_[k] = free_steps_[order[k]];
    for (int s = 0; s < kWallSlots; ++s) {
      shadow_slot_e_[static_cast<size_t>(k) * kWallSlots + s] = wslot_elem_[static_cast<size_t>(order[k]) * kWallSlots + s];
      shadow_slot_xi_[static_cast<size_t>(k) * kWallSlots + s] = wslot_xi_[static_cast<size_t>(order[k]) * kWallSlots + s];
    }
  }
}

void DemSystem::rebuild_swap() {
  std::vector<double>* const dv[] = {&x_, &y_, &vx_, &vy_, &w_, &r_, &m_, &invm_, &invI_};
  for (int a = 0; a < 9; ++a) dv[a]->swap(shadow_d_[a]);
  id_.swap(shadow_id_);
  free_steps_.swap(shadow_free_);
  wslot_elem_.swap(shadow_slot_e_);
  wslot_xi_.swap(shadow_slot_xi_);
  const int nc = cnx_ * cny_;
  for (int c = 0; c < nc; ++c)
    for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) cell_of_[k] = c;
}

void DemSystem::rebuild_rows(int t, const StepClock& clk) {
  ThreadData& d = td_[t];
  const int p0 = range_begin(n_, t, np_), p1 = range_begin(n_, t + 1, np_);
  d.row_count.assign(p1 - p0, 0);
  d.loc_j.clear();
  d.loc_xi.clear();
  const double skin = skin_;
  const double* x = x_.data();
  const double* y = y_.data();
  const double* r = r_.data();
  for (int i = p0; i < p1; ++i) {
    const double xi = x[i], yi = y[i], ri = r[i];
    const int c = cell_of_[i], cx = c % cnx_, cy = c / cnx_;
    const int before = static_cast<int>(d.loc_j.size());
    // Half stencil in cell order: the rest of i's cell, the cell to the right, the three above.
    // Every partner has a larger index, and they come out in ascending order.
    auto scan = [&](int j0, int j1) {
      for (int j = j0; j < j1; ++j) {
        const double dx = x[j] - xi, dy = y[j] - yi, cut = ri + r[j] + skin;
        if (dx * dx + dy * dy < cut * cut) d.loc_j.push_back(j);
      }
    };
    scan(i + 1, cell_start_[c + 1]);
    if (cx + 1 < cnx_) scan(cell_start_[c + 1], cell_start_[c + 2]);
    if (cy + 1 < cny_) {
      const int ca = c + cnx_;
      scan(cell_start_[cx > 0 ? ca - 1 : ca], cell_start_[cx + 1 < cnx_ ? ca + 2 : ca + 1]);
    }
    // Tangential springs of pairs already listed (old indices through order_).
    const int oi = order_[i];
    for (int k = before; k < static_cast<int>(d.loc_j.size()); ++k) {
      const int oj = order_[d.loc_j[k]];
      const int a = std::min(oi, oj), b = std::max(oi, oj);
      double xi_t = 0;
      for (int o = old_start_[a]; o < old_start_[a + 1]; ++o)
        if (old_j_[o] == b) {
          xi_t = old_xi_[o];
          break;
        }
      d.loc_xi.push_back(xi_t);
    }
    d.row_count[i - p0] = static_cast<int>(d.loc_j.size()) - before;
  }
  // Wall candidates of this partition's discs, its particle range (the one its
  // gather reads): the elements within radius + skin of the disc in the wall's
  // frame. (Dealt round the partitions instead, i = t, t + 8, ..., the discs on
  // the liner were spread evenly, but the two threads wrote neighbouring discs'
  // liner forces and read each other's in the gather: with the lanes of
  // PhaseQueue, the Qiu slice on 2 threads ran 0.89 x real time that way and
  // 1.08 x this way, docs/benchmarks.md, "Thread lanes".) They stay complete
  // until the next build: advance() rebuilds before a disc's displacement and
  // the wall's turn at its outermost node add up to the skin.
  d.wall_part.clear();
  d.wc_elem.clear();
  d.wc_start.assign(1, 0);
  if (walls_.n_elements() > 0) {
    const WallMesh& W = walls_;
    const double rc = W.min_radius - rmax_ - skin_;
    const double rc2 = rc > 0 ? rc * rc : -1;
    for (int i = p0; i < p1; ++i) {
      const double px = x[i], py = y[i];
      if (px * px + py * py < rc2) continue;
      const double qx = clk.c * px + clk.s * py, qy = -clk.s * px + clk.c * py;
      const int c = W.cell_of(qx, qy);
      if (c < 0) continue;
      const double lim = r[i] + skin;
      const size_t before = d.wc_elem.size();
      for (int k = W.cell_start[c]; k < W.cell_start[c + 1]; ++k) {
        const int e = W.cell_elems[k];
        const PackedElement& E = packed_[e];
        const double dx = qx - E.ax, dy = qy - E.ay;
        const double tt = std::clamp(dx * E.ux + dy * E.uy, 0.0, E.len);
        const double ex = dx - tt * E.ux, ey = dy - tt * E.uy;
        if (ex * ex + ey * ey <= lim * lim) d.wc_elem.push_back(e);
      }
      if (d.wc_elem.size() > before) {
        d.wall_part.push_back(i);
        d.wc_start.push_back(static_cast<int>(d.wc_elem.size()));
      }
    }
  }
}

void DemSystem::rebuild_finish() {
  nb_start_.assign(n_ + 1, 0);
  for (int t = 0; t < np_; ++t) {
    const int p0 = range_begin(n_, t, np_);
    for (size_t k = 0; k < td_[t].row_count.size(); ++k) nb_start_[p0 + k + 1] = td_[t].row_count[k];
  }
  for (int i = 0; i < n_; ++i) nb_start_[i + 1] += nb_start_[i];
  nb_j_.resize(nb_start_[n_]);
  nb_xi_.resize(nb_start_[n_]);
  for (int t = 0; t < np_; ++t) {
    const int off = nb_start_[range_begin(n_, t, np_)];
    std::copy(td_[t].loc_j.begin(), td_[t].loc_j.end(), nb_j_.begin() + off);
    std::copy(td_[t].loc_xi.begin(), td_[t].loc_xi.end(), nb_xi_.begin() + off);
  }
  // Rows split so every thread gets about the same work: a list entry costs one
  // distance test, a contact (counted at the last step, before the reorder) about
  // three more; the counts are deterministic, so the split is too.
  row_split_.assign(np_ + 1, n_);
  row_split_[0] = 0;
  if (np_ > 1) {
    std::vector<double>& wsum = row_weight_;
    wsum.assign(n_ + 1, 0.0);
    for (int i = 0; i < n_; ++i)
      wsum[i + 1] = wsum[i] + (nb_start_[i + 1] - nb_start_[i]) + 2.0 + 1.5 * ncontact_[order_[i]];
    int t = 1;
    for (int i = 0; i < n_ && t < np_; ++i)
      if (wsum[i + 1] >= wsum[n_] * t / np_) row_split_[t++] = i + 1;
  }
  // The discs each partition's contacts can write to: its rows and their partners.
  for (int k = 0; k < np_; ++k) {
    part_lo_[k] = row_split_[k];
    int hi = row_split_[k + 1] - 1;
    for (int e = nb_start_[row_split_[k]]; e < nb_start_[row_split_[k + 1]]; ++e) hi = std::max(hi, nb_j_[e]);
    part_hi_[k] = hi;
  }
  xref_ = x_, yref_ = y_;
  rebuild_needed_ = false;
  build_angle_ = build_angle_next_;
}

// ---------------------------------------------------------------- contacts

namespace {

/// Normal force [N/m] of a contact with overlap delta [m], approach speed vn
/// [m/s] and effective mass meff [kg/m] (contact_law.h); also the incremental
/// normal stiffness and the normal damping coefficient the tangential spring
/// and dashpot are scaled from.
template <bool Hertz>
inline double normal_force(const ContactParams& p, double sqrt_kpm, double delta, double vn, double meff,
                           double& kn_inc, double& cn) {
  const double k = p.k_fixed + p.k_per_mass * meff;
  const double sk_m = p.k_fixed > 0 ? std::sqrt(k * meff) : meff * sqrt_kpm;  // sqrt(k m*)
  if constexpr (Hertz) {
    const double sd = std::sqrt(delta);
    kn_inc = 1.5 * k * sd;                          // dF/d delta of k delta^1.5
    cn = p.gamma * sk_m * std::sqrt(sd);            // alpha sqrt(k m*) delta^0.25 (Tsuji et al. 1992)
    return k * delta * sd + cn * vn;
  } else {
    kn_inc = k;
    cn = p.gamma * sk_m;                            // 2 zeta sqrt(k m*)
    return k * delta + cn * vn;
  }
}

/// Coulomb-capped tangential spring-dashpot (Cundall & Strack 1979). xi [m] is
/// the spring stretch, updated in place; vt [m/s] the slip velocity of the
/// contact point; returns the tangential force [N/m] along t.
inline double tangential_force(double& xi, double vt, double dt, double kt, double ct, double fmax) {
  xi += vt * dt;
  double ft = -(kt * xi + ct * vt);
  if (std::abs(ft) > fmax) {
    ft = std::copysign(fmax, ft);
    xi = kt > 0 ? -(ft + ct * vt) / kt : 0.0;  // the spring that gives the capped force (LAMMPS gran/history)
  }
  return ft;
}

/// Constant directional rolling torque [N m/m] on body i (Ai et al. 2011, model
/// A): mu_r max(F_n, 0) R* against the relative rotation wrel [rad/s], no
/// larger than what stops wrel within the step (so it never reverses it).
inline double rolling_torque(double mu_r, double fn, double rstar, double wrel, double inv_i_sum, double dt) {
  if (mu_r <= 0 || fn <= 0 || wrel == 0) return 0;
  double m = mu_r * fn * rstar;
  const double aw = std::abs(wrel);
  if (m * dt * inv_i_sum > aw) m = aw / (dt * inv_i_sum);  // would reverse the relative rotation
  return -std::copysign(m, wrel);
}

}  // namespace

template <bool Hertz>
void DemSystem::pair_forces(int t) {
  ThreadData& d = td_[t];
  const ContactParams& p = set_.particle;
  const double sqrt_kpm = std::sqrt(p.k_per_mass);
  const double dt = set_.dt, mu = p.friction, mu_r = p.rolling_resistance;
  const double* __restrict x = x_.data();
  const double* __restrict y = y_.data();
  const double* __restrict vx = vx_.data();
  const double* __restrict vy = vy_.data();
  const double* __restrict w = w_.data();
  const double* __restrict r = r_.data();
  const double* __restrict invm = invm_.data();
  const double* __restrict invI = invI_.data();
  const int* __restrict nbj = nb_j_.data();
  const int* __restrict nbs = nb_start_.data();
  double* __restrict nbxi = nb_xi_.data();
  ForceAcc* __restrict acc = d.f.data();
  long long contacts = 0;
  double max_ratio = d.max_ratio;
  double elastic = 0;
  for (int i = row_split_[t]; i < row_split_[t + 1]; ++i) {
    const double xi = x[i], yi = y[i], vxi = vx[i], vyi = vy[i], wi = w[i], ri = r[i], invmi = invm[i],
                 invIi = invI[i];
    double fxi = 0, fyi = 0, tqi = 0;
    int nci = 0;
    for (int k = nbs[i], kend = nbs[i + 1]; k < kend; ++k) {
      const int j = nbj[k];
      const double dx = x[j] - xi, dy = y[j] - yi, rsum = ri + r[j];
      const double d2 = dx * dx + dy * dy;
      if (d2 >= rsum * rsum) {
        if (nbxi[k] != 0) nbxi[k] = 0;  // a read is cheaper than a store on every step
        continue;
      }
      const double dist = std::sqrt(d2), inv_d = 1 / dist;
      const double nx = dx * inv_d, ny = dy * inv_d;  // unit normal from i to j
      const double delta = rsum - dist;
      const double dvx = vxi - vx[j], dvy = vyi - vy[j];
      const double vn = dvx * nx + dvy * ny;                     // approach speed, d delta / dt
      const double vt = -dvx * ny + dvy * nx + wi * ri + w[j] * r[j];  // slip along t = (-ny, nx)
      const double meff = 1 / (invmi + invm[j]);
      double kn_inc, cn;
      const double fn = normal_force<Hertz>(p, sqrt_kpm, delta, vn, meff, kn_inc, cn);
      const double fnp = fn > 0 ? fn : 0.0;
      double xi_t = nbxi[k];
      const double kt = p.kt_ratio * kn_inc;
      const double ft = tangential_force(xi_t, vt, dt, kt, p.ct_ratio * cn, mu * fnp);
      nbxi[k] = xi_t;
      // stored energy: int F d delta = k delta^2 / 2 (linear), 2/5 k delta^2.5 = kn_inc delta^2 / 3.75 (hertz)
      elastic += (Hertz ? kn_inc * delta * delta / 3.75 : 0.5 * kn_inc * delta * delta) + 0.5 * kt * xi_t * xi_t;
      const double rj = r[j];
      const double mr =
          rolling_torque(mu_r, fnp, ri * rj / rsum, wi - w[j], invIi + invI[j], dt);  // R* = ri rj / (ri + rj)
      // force on i: -fn n + ft t; torque on i: ri ft + mr; on j the opposite force, torque rj ft - mr.
      const double Fx = -fn * nx - ft * ny, Fy = -fn * ny + ft * nx;
      fxi += Fx, fyi += Fy, tqi += ri * ft + mr;
      ForceAcc& aj = acc[j];
      aj.fx -= Fx, aj.fy -= Fy, aj.tq += rj * ft - mr, aj.nc += 1;
      ++nci;
      const double rmin = ri < rj ? ri : rj;
      if (delta > max_ratio * rmin) max_ratio = delta / rmin;
    }
    ForceAcc& ai = acc[i];
    ai.fx += fxi, ai.fy += fyi, ai.tq += tqi, ai.nc += nci;
    contacts += nci;
  }
  d.pair_contacts += contacts;
  d.max_ratio = max_ratio;
  d.elastic_pair = elastic;
}

namespace {

struct WallHit {
  int element;    // face element, or the element starting at the touched node
  int share;      // second element sharing a node contact's load (-1: none)
  double delta;   // [m] overlap
  double nbx, nby;  // body-frame unit normal, wall -> disc centre
  double cbx, cby;  // body-frame contact point on the wall
  bool face;
};

}  // namespace

template <bool Hertz>
void DemSystem::wall_forces(int t, bool first, const StepClock& clk) {
  ThreadData& d = td_[t];
  const WallMesh& W = walls_;
  const ContactParams& p = set_.wall;
  const double sqrt_kpm = std::sqrt(p.k_per_mass);
  const double dt = set_.dt, mu = p.friction, mu_r = p.rolling_resistance, Om = set_.wall_omega;
  const double ca = clk.c, sa = clk.s;
  const bool acc = accumulate_ && !first;
  const bool rec = clk.record;
  const bool cross_check = !first;  // the first evaluation of a run follows no drift
  double wsum_x = 0, wsum_y = 0, elastic = 0;
  const PackedElement* __restrict pel = packed_.data();
  const int* __restrict cstart = d.wc_start.data();
  const int* __restrict celems = d.wc_elem.data();
  const double* __restrict x = x_.data();
  const double* __restrict y = y_.data();
  const double* __restrict r = r_.data();
  const int nw = static_cast<int>(d.wall_part.size());
  for (int idx = 0; idx < nw; ++idx) {
    const int i = d.wall_part[idx];
    const double px = x[i], py = y[i], ri = r[i];
    // Body frame: q = R(-angle) p.
    const double qx = ca * px + sa * py, qy = -sa * px + ca * py;
    // The centre's body-frame move over this step, q - q(n-1): the drift was
    // x(n) = x(n-1) + dt v(n-1/2) and vx_, vy_ still hold v(n-1/2).
    double mx = 0, my = 0;
    if (cross_check) {
      const double ox = px - dt * vx_[i], oy = py - dt * vy_[i];
      mx = qx - (clk.cp * ox + clk.sp * oy), my = qy - (-clk.sp * ox + clk.cp * oy);
    }
    // The contacts of this disc. More than kMaxWallHits at once (a disc in a
    // concave pocket of many short elements) keeps the deepest and counts the
    // rest, which the run reports (docs/models/dem.md §4).
    WallHit hits[kMaxWallHits];
    int nh = 0;
    auto add_hit = [&](const WallHit& h) {
      if (nh < kMaxWallHits) {
        hits[nh++] = h;
        return;
      }
      ++d.wall_hits_dropped;
      int lo = 0;
      for (int a = 1; a < nh; ++a)
        if (hits[a].delta < hits[lo].delta) lo = a;
      if (h.delta > hits[lo].delta) hits[lo] = h;
    };
    for (int k = cstart[idx], kend = cstart[idx + 1]; k < kend; ++k) {
      const int e = celems[k];
      const PackedElement& E = pel[e];
      const double dx = qx - E.ax, dy = qy - E.ay;
      const double sd = dx * E.nx + dy * E.ny;  // signed distance from the element's line
      const double tt = dx * E.ux + dy * E.uy;
      if (sd <= 0 && cross_check) {
        // Passed through: the centre crossed the element, from its particle side
        // to its back, during this step. Being behind the element's line within
        // a radius is not enough: beside a fold of the liner thinner than the
        // overlap (a worn crest corner) a disc in contact with the near face is
        // that close behind the far face (docs/models/dem.md §4).
        const double sd0 = sd - (mx * E.nx + my * E.ny);  // at the start of the step
        if (sd0 >= 0 && sd0 > sd) {
          const double f = sd0 / (sd0 - sd);                          // where the path meets the line,
          const double tx = tt - (1 - f) * (mx * E.ux + my * E.uy);  // and how far along the element
          if (tx >= 0 && tx <= E.len) {
            if (!d.fail)
              fail(fmt::format("disc {} (radius {:.4g} m) passed through liner element {} at t = {:.4f} s (overlap "
                               "larger than its radius): the contacts are too soft or the time step too large; give "
                               "a shorter [dem] collision_time_s (or a larger stiffness) or more steps_per_collision",
                               id_[i], ri, e, clk.time));
            d.fail = 1;
            continue;
          }
        }
      }
      if (sd >= ri || sd <= -ri) continue;
      if (tt > 0 && tt < E.len) {
        if (sd <= 0) continue;  // the element turns its back to the centre: no face contact
        add_hit({e, -1, ri - sd, E.nx, E.ny, E.ax + tt * E.ux, E.ay + tt * E.uy, true});
      } else if (tt <= 0 && E.convex_start) {
        const int pe = W.prev[e];
        if (pe >= 0 && dx * pel[pe].ux + dy * pel[pe].uy < 0) continue;  // not in the node's wedge
        const double dist2 = dx * dx + dy * dy;
        if (dist2 >= ri * ri || dist2 <= 0) continue;
        const double dist = std::sqrt(dist2);
        add_hit({e, pe, ri - dist, dx / dist, dy / dist, E.ax, E.ay, false});
      } else if (tt >= E.len && E.convex_end) {
        const double ex = qx - (E.ax + E.len * E.ux), ey = qy - (E.ay + E.len * E.uy);
        const double dist2 = ex * ex + ey * ey;
        if (dist2 >= ri * ri || dist2 <= 0) continue;
        const double dist = std::sqrt(dist2);
        add_hit({e, -1, ri - dist, ex / dist, ey / dist, qx - ex, qy - ey, false});
      }
    }
    // Two faces meeting at a shallow concave node touch one disc once: keep the deeper.
    for (int a = 0; a < nh; ++a)
      for (int b = 0; b < nh; ++b) {
        if (a == b || !hits[a].face || !hits[b].face || hits[a].delta < 0 || hits[b].delta < 0) continue;
        if (W.next[hits[a].element] == hits[b].element && W.merge_next[hits[a].element]) {
          if (hits[a].delta >= hits[b].delta) hits[b].delta = -1;
          else hits[a].delta = -1;
        }
      }
    // Contacts of this step against the springs of the last (matched by element, or a neighbour
    // within two elements: a disc rolling over element joints keeps its spring).
    int* slot_e = &wslot_elem_[static_cast<size_t>(i) * kWallSlots];
    double* slot_xi = &wslot_xi_[static_cast<size_t>(i) * kWallSlots];
    int old_e[kWallSlots];
    double old_xi[kWallSlots];
    for (int s = 0; s < kWallSlots; ++s) old_e[s] = slot_e[s], old_xi[s] = slot_xi[s], slot_e[s] = -1, slot_xi[s] = 0;
    int nslot = 0;
    double fxs = 0, fys = 0, tqs = 0;
    int ncont = 0;
    const double vxi = vx_[i], vyi = vy_[i], wi = w_[i], mi = m_[i], invIi = invI_[i];
    for (int h = 0; h < nh; ++h) {
      const WallHit& H = hits[h];
      if (H.delta <= 0) continue;
      // lab frame: n = R(angle) nb, c = R(angle) cb
      const double nx = ca * H.nbx - sa * H.nby, ny = sa * H.nbx + ca * H.nby;
      const double cx = ca * H.cbx - sa * H.cby, cy = sa * H.cbx + ca * H.cby;
      const double wvx = -Om * cy, wvy = Om * cx;  // wall velocity at the contact point
      const double rvx = vxi - wvx, rvy = vyi - wvy;  // centre velocity relative to the wall
      const double vn = -(rvx * nx + rvy * ny);       // approach speed, d delta / dt
      const double vt_body = -rvx * ny + rvy * nx;    // along t = (-ny, nx)
      const double vt = vt_body - wi * ri;            // slip of the disc's contact point
      double xi_t = 0;
      bool continuing = false;
      for (int s = 0; s < kWallSlots; ++s)
        if (old_e[s] >= 0 && W.chain_distance(old_e[s], H.element) <= 2) {
          xi_t = old_xi[s];
          old_e[s] = -1;  // one spring continues one contact
          continuing = true;
          break;
        }
      double kn_inc, cn;
      const double fn = normal_force<Hertz>(p, sqrt_kpm, H.delta, vn, mi, kn_inc, cn);
      const double fnp = fn > 0 ? fn : 0.0;
      const double kt = p.kt_ratio * kn_inc;
      const double ft = tangential_force(xi_t, vt, dt, kt, p.ct_ratio * cn, mu * fnp);
      elastic += (Hertz ? kn_inc * H.delta * H.delta / 3.75 : 0.5 * kn_inc * H.delta * H.delta) + 0.5 * kt * xi_t * xi_t;
      const double mr = rolling_torque(mu_r, fnp, ri, wi - Om, invIi, dt);
      const double Fx = fn * nx - ft * ny, Fy = fn * ny + ft * nx;  // on the disc
      fxs += Fx, fys += Fy;
      tqs += -ri * ft + mr;  // contact point at -ri n: (-ri n) x (ft t) = -ri ft
      ++ncont;
      if (nslot < kWallSlots) slot_e[nslot] = H.element, slot_xi[nslot] = xi_t, ++nslot;
      else ++d.wall_springs_dropped;
      if (H.delta > d.max_wall_ratio * ri) d.max_wall_ratio = H.delta / ri;
      if (acc) {
        const double aft = std::abs(ft), slip = std::abs(vt);
        const double wgt = H.share >= 0 ? 0.5 * dt : dt;
        for (int e : {H.element, H.share}) {
          if (e < 0) continue;
          d.ld_n[e] += fnp * wgt;
          d.ld_s[e] += aft * wgt;
          d.ld_ns[e] += fnp * slip * wgt;
          d.ld_ss[e] += aft * slip * wgt;
        }
        d.drive_work += Om * (cx * Fy - cy * Fx) * dt;  // P = Omega x torque of the contact forces on the discs
        if (!continuing && vn >= set_.impact_min_speed)
          d.impacts.push_back({clk.step, id_[i], H.element, vn, std::abs(vt_body), free_steps_[i]});
      }
      if (rec) d.records.push_back({id_[i], H.element, -Fx, -Fy, cx, cy});
    }
    wacc_[i] = {fxs, fys, tqs, static_cast<double>(ncont)};  // this disc's liner contacts, one partition writes it
    wsum_x += fxs, wsum_y += fys;
    d.wall_contacts += ncont;
  }
  d.wall_fx = wsum_x, d.wall_fy = wsum_y;  // wall force this thread computed, for the impulse bookkeeping
  d.elastic_wall = elastic;
}

// ---------------------------------------------------------------- integration

void DemSystem::kick_drift(int t) {
  ThreadData& d = td_[t];
  const double dt = set_.dt, h = 0.5 * dt;
  const int p0 = range_begin(n_, t, np_), p1 = range_begin(n_, t + 1, np_);
  double maxd2 = 0, maxd2b = 0;
  for (int i = p0; i < p1; ++i) {
    vx_[i] += h * fx_[i];  // fx_, fy_, tq_ hold the accelerations of the last gather
    vy_[i] += h * fy_[i];
    w_[i] += h * tq_[i];
    x_[i] += dt * vx_[i];
    y_[i] += dt * vy_[i];
    const double dx = x_[i] - xref_[i], dy = y_[i] - yref_[i];
    const double d2 = dx * dx + dy * dy;
    if (d2 > maxd2b) {
      if (d2 > maxd2) maxd2b = maxd2, maxd2 = d2;
      else maxd2b = d2;
    }
  }
  d.maxd2 = maxd2, d.maxd2b = maxd2b;
  d.wimp_x += h * d.wall_fx, d.wimp_y += h * d.wall_fy;
}

void DemSystem::gather(int t, bool kick, bool do_check, bool drift_next) {
  ThreadData& d = td_[t];
  if (kick) ++d.steps_done;
  double max_v2 = 0, maxd2 = 0, maxd2b = 0;
  int worst = -1, escaped = -1;
  bool nonfinite = false;
  const double esc2 = set_.escape_radius > 0 ? set_.escape_radius * set_.escape_radius : 1e300;
  const double dt = set_.dt, h = 0.5 * dt, gx = set_.gravity_x, gy = set_.gravity_y;
  const int p0 = range_begin(n_, t, np_), p1 = range_begin(n_, t + 1, np_);
  double* __restrict x = x_.data();
  double* __restrict y = y_.data();
  double* __restrict vx = vx_.data();
  double* __restrict vy = vy_.data();
  double* __restrict w = w_.data();
  const double* __restrict invm = invm_.data();
  const double* __restrict invI = invI_.data();
  const double* __restrict xref = xref_.data();
  const double* __restrict yref = yref_.data();
  double* __restrict ax_out = fx_.data();
  double* __restrict ay_out = fy_.data();
  double* __restrict aw_out = tq_.data();
  int* __restrict nc_out = ncontact_.data();
  long long* __restrict free_steps = free_steps_.data();
  // The partitions whose contacts can reach this range, in partition order.
  ForceAcc* bufs[kPartitions];
  int lo[kPartitions], hi[kPartitions], nb = 0;
  for (int u = 0; u < np_; ++u)
    if (part_lo_[u] < p1 && part_hi_[u] >= p0) bufs[nb] = td_[u].f.data(), lo[nb] = part_lo_[u], hi[nb] = part_hi_[u], ++nb;
  ForceAcc* __restrict wacc = wacc_.data();
  for (int i = p0; i < p1; ++i) {
    ForceAcc a = wacc[i];
    wacc[i] = ForceAcc{};
    for (int u = 0; u < nb; ++u) {
      if (i < lo[u] || i > hi[u]) continue;
      ForceAcc& b = bufs[u][i];
      a.fx += b.fx, a.fy += b.fy, a.tq += b.tq, a.nc += b.nc;
      b = ForceAcc{};
    }
    const double ax = a.fx * invm[i] + gx, ay = a.fy * invm[i] + gy, aw = a.tq * invI[i];  // [m/s2], [rad/s2]
    const int nc = static_cast<int>(a.nc);
    nc_out[i] = nc;
    if (!drift_next) ax_out[i] = ax, ay_out[i] = ay, aw_out[i] = aw;  // for the first kick of the next call
    if (kick) {
      // end of this step: v(n+1) = v(n+1/2) + dt/2 a(n+1)
      vx[i] += h * ax, vy[i] += h * ay, w[i] += h * aw;
      free_steps[i] = nc ? 0 : free_steps[i] + 1;
      if (do_check) {
        const double v2 = vx[i] * vx[i] + vy[i] * vy[i];
        if (!std::isfinite(v2 + x[i] + y[i] + w[i])) nonfinite = true, worst = i;
        if (v2 > max_v2 && !nonfinite) max_v2 = v2, worst = i;
        if (x[i] * x[i] + y[i] * y[i] > esc2) escaped = i;
      }
    }
    if (drift_next) {
      // start of the next step: v(n+3/2) = v(n+1) + dt/2 a(n+1), x(n+2) = x(n+1) + dt v(n+3/2)
      vx[i] += h * ax, vy[i] += h * ay, w[i] += h * aw;
      x[i] += dt * vx[i], y[i] += dt * vy[i];
      const double dx = x[i] - xref[i], dy = y[i] - yref[i];
      const double d2 = dx * dx + dy * dy;
      if (d2 > maxd2b) {  // the two largest
        if (d2 > maxd2) maxd2b = maxd2, maxd2 = d2;
        else maxd2b = d2;
      }
    }
  }
  if (do_check) d.max_v2 = max_v2, d.worst = worst, d.nonfinite = nonfinite, d.escaped = escaped;
  d.checked = do_check;
  if (kick) d.wimp_x += h * d.wall_fx, d.wimp_y += h * d.wall_fy;
  if (drift_next) {
    d.maxd2 = maxd2, d.maxd2b = maxd2b;
    d.wimp_x += h * d.wall_fx, d.wimp_y += h * d.wall_fy;
  }
}

std::string DemSystem::check_failure(long long step, double time) const {
  double v2 = 0;
  int worst = -1;
  for (const auto& d : td_) {
    if (d.escaped >= 0) {
      const int i = d.escaped;
      return fmt::format("disc {} (radius {:.4g} m) left the mill at t = {:.4f} s: its centre is {:.4g} m from the "
                         "axis, outside the shell ({:.4g} m): the time step ({:.3g} s) is too large for the contact "
                         "stiffness; raise [dem] steps_per_collision (or lower time_step_s)",
                         id_[i], r_[i], time, std::hypot(x_[i], y_[i]), set_.escape_radius, set_.dt);
    }
    if (d.nonfinite)
      return fmt::format("disc {} has a non-finite position or velocity at t = {:.4f} s (step {}): the run blew up; "
                         "reduce the time step (more [dem] steps_per_collision)",
                         id_[d.worst], time, step);
    if (d.max_v2 > v2) v2 = d.max_v2, worst = d.worst;
  }
  if (set_.speed_limit > 0 && v2 > set_.speed_limit * set_.speed_limit)
    return fmt::format(
        "energy growth: disc {} moves at {:.3g} m/s at t = {:.4f} s (step {}), more than the {:.3g} m/s the mill "
        "can give a disc (liner speed plus a fall across the mill, doubled): the run blew up. Reduce the time step "
        "(more [dem] steps_per_collision, or a smaller time_step_s) or lengthen collision_time_s",
        id_[worst], std::sqrt(v2), time, step, set_.speed_limit);
  return {};
}

namespace {

/// Work published by the control thread in numbered phases of `items` items
/// and claimed by whichever threads are running. Item k of a phase always does
/// the same work into the same buffers, whoever runs it, so the results do not
/// depend on the schedule; a thread the system has descheduled never holds up
/// the others (they take its items), which a barrier would.
///
/// Each thread of the team has a lane, a contiguous block of each phase's items
/// (thread t of T: items [t n / T, (t + 1) n / T)), which it works through first
/// before it takes what is left in the other lanes. Item k of every phase covers
/// about the same discs (the partitions of dem_system.h), so a thread keeps
/// finding in its cache what it wrote in the phase before; with one shared
/// counter the two threads took alternate items and the gather of a step read
/// the other core's force buffers.
class PhaseQueue {
 public:
  explicit PhaseQueue(int items) : items_(items), lane_(static_cast<size_t>(std::max(1, items))) {}
  /// Control thread, before its first phase: the lanes (threads in the team; at most one per item).
  void set_lanes(int lanes) { lanes_ = std::clamp(lanes, 1, static_cast<int>(lane_.size())); }
  /// Control thread: opens the next phase.
  unsigned publish(int kind) {
    const unsigned s = ++seq_;
    kind_[s & 1].store(kind, std::memory_order_relaxed);
    done_[s & 1].store(0, std::memory_order_relaxed);
    for (int l = 0; l < lanes_; ++l) lane_[l].next.store(pack(s, lane_begin(l)), std::memory_order_release);
    phase_.store(s, std::memory_order_release);
    return s;
  }
  /// Claims an item of the current phase, from lane `own` first; false when
  /// all are taken.
  bool claim(int own, unsigned& s, int& kind, int& item) {
    s = phase_.load(std::memory_order_acquire);  // also makes lanes_ visible (set before the first publish)
    if (s == 0) return false;
    for (int q = 0; q < lanes_; ++q) {
      const int l = (own + q) % lanes_;
      const int end = lane_begin(l + 1);
      std::atomic<unsigned long long>& next = lane_[l].next;
      unsigned long long c = next.load(std::memory_order_acquire);
      // a counter of another phase (the control thread moved on meanwhile) is never exchanged
      while (static_cast<unsigned>(c >> 32) == s && static_cast<int>(c & 0xffffffffULL) < end) {
        if (next.compare_exchange_weak(c, c + 1, std::memory_order_acq_rel, std::memory_order_acquire)) {
          // kind_ of phase s stays put while it has unclaimed items
          kind = kind_[s & 1].load(std::memory_order_relaxed);
          item = static_cast<int>(c & 0xffffffffULL);
          return true;
        }
      }
    }
    return false;
  }
  void complete(unsigned s) { done_[s & 1].fetch_add(1, std::memory_order_acq_rel); }
  bool finished(unsigned s) const { return done_[s & 1].load(std::memory_order_acquire) == items_; }
  std::atomic<bool> stop{false};

 private:
  static unsigned long long pack(unsigned s, int item) {
    return (static_cast<unsigned long long>(s) << 32) | static_cast<unsigned>(item);
  }
  int lane_begin(int l) const { return range_begin(items_, l, lanes_); }
  struct alignas(64) Lane {
    std::atomic<unsigned long long> next{0};  // phase number << 32 | next item of the lane
  };
  const int items_;
  int lanes_ = 1;
  std::vector<Lane> lane_;
  std::atomic<unsigned> phase_{0};
  std::atomic<int> kind_[2] = {}, done_[2] = {};
  unsigned seq_ = 0;
};

/// Waits briefly by spinning, then by giving the core away.
inline void relax(int& spins) {
  if (++spins > 2000) std::this_thread::yield();
}

enum PhaseKind { kKickDrift, kPermute, kRows, kForces, kGather };

}  // namespace

void DemSystem::advance(long long steps) {
  failed_ = 0;
  failure_.clear();
  for (auto& d : td_) d.fail = 0, d.checked = false;
  const bool hertz = set_.particle.law == ContactLaw::Hertz;
  const double turn_radius = walls_.n_elements() > 0 ? walls_.max_radius : 0.0;  // [m]
  const int check_every = std::max(1, set_.check_interval);
  const long long step0 = step_;
  const bool record = record_next_;
  record_next_ = false;

  // The step's parameters, written by the control thread before it opens a
  // phase and read by the items of that phase.
  struct Args {
    StepClock clk;
    bool first = false, do_check = false, drift_next = false;
  } args;
  PhaseQueue queue(np_);
  auto execute = [&](int kind, int k) {
    switch (kind) {
      case kKickDrift: kick_drift(k); break;
      case kPermute: rebuild_permute(k); break;
      case kRows: rebuild_rows(k, args.clk); break;
      case kForces:
        if (hertz) {
          pair_forces<true>(k);
          wall_forces<true>(k, args.first, args.clk);
        } else {
          pair_forces<false>(k);
          wall_forces<false>(k, args.first, args.clk);
        }
        break;
      case kGather: gather(k, !args.first, args.do_check, args.drift_next); break;
    }
  };
  // Control thread: open a phase of np_ items (the partitions), work on it, wait for the rest.
  auto run = [&](int kind) {
    const unsigned s = queue.publish(kind);
    unsigned cs;
    int ck, item;
    while (queue.claim(0, cs, ck, item)) {
      execute(ck, item);
      queue.complete(cs);
    }
    for (int spins = 0; !queue.finished(s);) relax(spins);
  };

  // Threads for this call. With adapt_threads, 1 or nt_, whichever cost less
  // per particle-step lately, trying the other one every 32nd call: on a machine
  // shared with other jobs a second thread can cost more than it brings.
  int use = nt_;
  int slot = 1;
  if (set_.adapt_threads && nt_ > 1) {
    ++calls_;
    const bool explore = calls_ % 32 == 0;
    int best = 1;
    if (cost_ema_[1] == 0) best = 1;                   // not tried yet: try nt_
    else if (cost_ema_[0] == 0) best = 0;              // then 1
    else best = cost_ema_[0] < cost_ema_[1] ? 0 : 1;
    slot = explore && cost_ema_[0] > 0 && cost_ema_[1] > 0 ? 1 - best : best;
    use = slot == 0 ? 1 : nt_;
  }
  last_threads_ = use;
  const auto t_call = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(use)
  {
    if (omp_get_thread_num() != 0) {
      // helper: take items until the control thread stops, from its own lane first
      const int own = omp_get_thread_num();
      unsigned cs;
      int ck, item;
      for (int spins = 0; !queue.stop.load(std::memory_order_acquire);) {
        if (queue.claim(own, cs, ck, item)) {
          execute(ck, item);
          queue.complete(cs);
          spins = 0;
        } else {
          relax(spins);
        }
      }
    } else {
      queue.set_lanes(omp_get_num_threads());
      const long long s_begin = forces_valid_ ? 0 : -1;
      for (long long s = s_begin; s < steps; ++s) {
        const bool first = s < 0;
        if (s == 0 && s_begin == 0) run(kKickDrift);  // later steps were started by the last gather
        // checks of the last gather
        if (!first && td_[0].checked) {
          bool bad = false;
          for (const auto& d : td_)
            bad |= d.nonfinite || d.escaped >= 0 ||
                   (set_.speed_limit > 0 && d.max_v2 > set_.speed_limit * set_.speed_limit);
          if (bad) {
            failed_ = 1;
            break;
          }
        }
        StepClock& clk = args.clk;
        clk.step = step0 + (first ? 0 : s + 1);
        clk.time = clk.step * set_.dt;
        const double angle = set_.wall_angle0 + set_.wall_omega * clk.time;
        clk.c = std::cos(angle), clk.s = std::sin(angle);
        clk.cp = std::cos(angle - set_.wall_omega * set_.dt), clk.sp = std::sin(angle - set_.wall_omega * set_.dt);
        clk.record = record && s == 0;
        args.first = first;
        // A pair can close the skin only if its two discs moved skin in all; a disc
        // can reach a liner element it was not listed with only if its own
        // displacement and the liner's turn at its outermost node add up to skin.
        double m1 = 0, m2 = 0;  // the two largest displacements [m]
        for (const auto& d : td_) {
          for (double v : {d.maxd2, d.maxd2b}) {
            if (v > m2 * m2) {
              if (v > m1 * m1) m2 = m1, m1 = std::sqrt(v);
              else m2 = std::sqrt(v);
            }
          }
        }
        const bool rebuild = rebuild_needed_ || m1 + m2 > skin_ || m1 + std::abs(angle - build_angle_) * turn_radius > skin_;
        if (rebuild) {
          rebuild_prepare(clk.time);
          build_angle_next_ = angle;
          run(kPermute);
          rebuild_swap();
          run(kRows);
          rebuild_finish();
        }
        run(kForces);
        if (failed_) break;
        args.do_check = !first && (clk.step % check_every == 0 || s == steps - 1);
        args.drift_next = s + 1 < steps;
        run(kGather);
      }
      queue.stop.store(true, std::memory_order_release);
    }
  }
  // the clock of the last completed step
  long long done = 0;
  for (const auto& d : td_) done = std::max(done, d.steps_done);
  if (set_.adapt_threads && nt_ > 1 && done >= 20 && n_ > 0) {
    const double c = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_call).count() / (done * n_);
    cost_ema_[slot] = cost_ema_[slot] == 0 ? c : 0.7 * cost_ema_[slot] + 0.3 * c;
  }
  step_ = step0 + done;
  time_ = step_ * set_.dt;
  angle_ = set_.wall_angle0 + set_.wall_omega * time_;
  cos_a_ = std::cos(angle_), sin_a_ = std::sin(angle_);
  for (auto& d : td_) {
    pair_contact_steps_ += d.pair_contacts, wall_contact_steps_ += d.wall_contacts;
    d.pair_contacts = d.wall_contacts = 0;
    max_overlap_ratio_ = std::max(max_overlap_ratio_, d.max_ratio);
    max_wall_overlap_ratio_ = std::max(max_wall_overlap_ratio_, d.max_wall_ratio);
    wall_hits_dropped_ += d.wall_hits_dropped, wall_springs_dropped_ += d.wall_springs_dropped;
    d.wall_hits_dropped = d.wall_springs_dropped = 0;
    d.steps_done = 0;
  }
  if (!failed_ && td_[0].checked) {
    const std::string f = check_failure(step_, time_);
    if (!f.empty()) failed_ = 1, failure_ = f;
  } else if (failed_ && failure_.empty()) {
    failure_ = check_failure(step_, time_);
  }
  if (failed_) throw SimulationError(failure_);
  forces_valid_ = true;
  if (accumulate_) accum_duration_ = (step_ - accum_start_step_) * set_.dt;
}

// ---------------------------------------------------------------- loads and diagnostics

void DemSystem::set_accumulate(bool on) {
  accumulate_ = on;
  if (!on) return;
  const int ne = walls_.n_elements();
  for (auto& d : td_) {
    d.ld_n.assign(ne, 0), d.ld_s.assign(ne, 0), d.ld_ns.assign(ne, 0), d.ld_ss.assign(ne, 0);
    d.drive_work = 0;
    d.impacts.clear();
  }
  accum_start_step_ = step_;
  accum_duration_ = 0;
}

WallLoadSums DemSystem::load_sums() const {
  WallLoadSums s;
  const int ne = walls_.n_elements();
  s.duration = accum_duration_;
  s.normal.assign(ne, 0), s.shear.assign(ne, 0), s.normal_slip.assign(ne, 0), s.shear_slip.assign(ne, 0);
  for (const auto& d : td_) {
    if (d.ld_n.empty()) continue;
    for (int e = 0; e < ne; ++e) {
      s.normal[e] += d.ld_n[e], s.shear[e] += d.ld_s[e];
      s.normal_slip[e] += d.ld_ns[e], s.shear_slip[e] += d.ld_ss[e];
    }
    s.drive_work += d.drive_work;
  }
  return s;
}

std::vector<ImpactRecord> DemSystem::take_impacts() {
  std::vector<ImpactRecord> all;
  for (auto& d : td_) {
    all.insert(all.end(), d.impacts.begin(), d.impacts.end());
    d.impacts.clear();
  }
  std::sort(all.begin(), all.end(), [](const ImpactRecord& a, const ImpactRecord& b) {
    if (a.step != b.step) return a.step < b.step;
    if (a.particle != b.particle) return a.particle < b.particle;
    return a.element < b.element;
  });
  return all;
}

std::vector<WallContactRecord> DemSystem::take_contact_records() {
  std::vector<WallContactRecord> all;
  for (auto& d : td_) {
    all.insert(all.end(), d.records.begin(), d.records.end());
    d.records.clear();
  }
  std::sort(all.begin(), all.end(), [](const WallContactRecord& a, const WallContactRecord& b) {
    return a.particle != b.particle ? a.particle < b.particle : a.element < b.element;
  });
  return all;
}

double DemSystem::kinetic_energy() const {
  double e = 0;
  for (int i = 0; i < n_; ++i)
    e += 0.5 * m_[i] * (vx_[i] * vx_[i] + vy_[i] * vy_[i]) + 0.5 * w_[i] * w_[i] / invI_[i];
  return e;
}

double DemSystem::elastic_energy() const {
  double e = 0;
  for (const auto& d : td_) e += d.elastic_pair + d.elastic_wall;
  return e;
}

double DemSystem::potential_energy() const {
  double e = 0;
  for (int i = 0; i < n_; ++i) e -= m_[i] * (set_.gravity_x * x_[i] + set_.gravity_y * y_[i]);
  return e;
}

double DemSystem::momentum_x() const {
  double p = 0;
  for (int i = 0; i < n_; ++i) p += m_[i] * vx_[i];
  return p;
}

double DemSystem::momentum_y() const {
  double p = 0;
  for (int i = 0; i < n_; ++i) p += m_[i] * vy_[i];
  return p;
}

double DemSystem::wall_impulse_x() const {
  double s = 0;
  for (const auto& d : td_) s += d.wimp_x;
  return s;
}

double DemSystem::wall_impulse_y() const {
  double s = 0;
  for (const auto& d : td_) s += d.wimp_y;
  return s;
}

}  // namespace linerlife
