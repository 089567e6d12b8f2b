// The layer model (docs/models/layer.md). Everything is computed for an
// anticlockwise mill (the canonical frame); a clockwise mill is mirrored in
// and out (canonical_surface.h).
#include "charge/layer_model.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <functional>
#include <limits>
#include <numeric>
#include <random>

#include <fmt/format.h>

#include "charge/canonical_surface.h"
#include "charge/charge_occupancy.h"
#include "charge/checked_range.h"
#include "charge/exact_math.h"
#include "charge/lifter_launch.h"
#include "charge/liner_ride_table.h"
#include "charge/morrell_c_model.h"
#include "charge/settling_note.h"
#include "charge/slip_model.h"
#include "charge/slot_map.h"
#include "charge/slurry_drag.h"
#include "geometry/errors.h"
#include "geometry/metrics.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kInf = std::numeric_limits<double>::infinity();
// [rad] per-segment angles closer than this are one angle (rounding between the
// segments of a ring of identical lifters: about 5e-12 rad)
constexpr double kAlikeRad = 1e-9;
// Pocket loads: the liner takes a share of a pocket's push where the disc's
// contact faces it, the face at most this far from the radial
// (docs/models/layer.md §7, "Pocket loads"; lifter faces of 0-60 deg and their corners)
constexpr double kPocketFaceDeg = 80.0;

constexpr double kInvTwoPi = 1.0 / kTwoPi;

inline double wrap2pi(double a) {
  if (a >= 0 && a < kTwoPi) return a;
  // One turn out (most of the rest: slot_of() of an atan2 angle in (-pi,
  // pi]): there a * kInvTwoPi lies in (-0.9995, 0) (no underflow to -0
  // above -1e-300) or in (1.001, 1.99), so its floor is -1 or 1 and the
  // line below gives a - 2 pi (-1) = a + 2 pi or a - 2 pi: the same bits
  // without the floor.
  if (a < -1e-300 && a > -6.28) return a + kTwoPi;
  if (a > 6.29 && a < 12.5) return a - kTwoPi;
  return a - kTwoPi * floor_exact(a * kInvTwoPi);
}

/// std::nextafter(x, +inf) without the libm call: the next
/// representable double above x (one step of the bit pattern).
inline double next_up(double x) {
  if (!(x < std::numeric_limits<double>::infinity())) return x;  // +inf, NaN
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b += x > 0 ? 1 : -1;  // two's complement: -1 on the magnitude of a negative x
  std::memcpy(&x, &b, sizeof x);
  return x;
}

/// atan2 to about 1e-5 rad (enough to find bins and slots; polynomial of
/// Abramowitz & Stegun 4.4.49 type on [0, 1] with octant reduction).
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

/// Share of a held layer's lifter launches the relaxation may take (the
/// two-flight-angle window, LayerSim::run()) from which a run says so.
constexpr double kHeldWindowNoteShare = 0.05;

/// Lifters lower than this many media diameters, and rows further apart than
/// this many, get a note (LayerSim::note_unchecked_lifters()). From the
/// bundled Qiu mill against the 2D DEM (docs/models/layer.md, "Lifters the
/// layer model is not checked on"): net power +71 % at 0.15 d (20 mm), within
/// 8 % from 0.5 d up; +14 % at 30 d between rows (8 rows), +3.7 % at 15 d.
constexpr double kLowLifterDiameters = 0.5;
constexpr double kWideRowsDiameters = 20.0;

/// Pulp density [kg/m3] of a slurry with solids mass fraction w.
double pulp_density(double w, double rho_solid, double rho_water) { return 1.0 / (w / rho_solid + (1.0 - w) / rho_water); }

/// One concentric layer: a rigid ring of S slots of one media diameter.
struct Layer {
  double r = 0;          // [m] radius of the slot centres
  int S = 0;             // slots
  double delta = 0;      // [rad] slot angle 2 pi / S
  double inv_delta = 0;  // [1/rad]
  double omega = 0;      // [rad/s] angular speed (slip model)
  double phase = 0;      // [rad] angle of slot 0 at the start of the current step, in [0, 2 pi)
  int offset = 0;        // first slot in the occupancy array
  bool held = false;     // held by the lifters of at least one segment
  double release = kInf; // [rad] flight angle of an unheld layer (+inf: never leaves); of a held
                         // layer the smallest over the segments of its own angle (rel_seg_)
  double release_max = -kInf;  // [rad] the largest finite of those (departures()' scan)
  double rel_min = kInf, rel_max = -kInf;  // [rad] range of the per-segment flight angles of a held layer
};

/// How an element of a held layer leaves the lifter of one segment.
struct HeldLaunch {
  bool held = false;       // this layer is held by this segment's lifter
  bool released = false;   // false: carried round
  double release = kInf;   // [rad] polar angle where it leaves its slot
  double slide_s = 0;      // [s] sliding time along the face
  double dtheta = 0;       // [rad] launch angle - release angle
  double radius = 0;       // [m] launch radius
  double vr = 0, vt = 0;   // [m/s] launch velocity, polar components
  double r0 = 0;           // [m] radius of the ball's centre in the pocket
};

/// An element no lifter holds (the release study's plate elements, departures()).
const HeldLaunch kUnheldLaunch{};

struct Landing {
  double t = 0;        // [s]
  int flight = 0;      // index in the flight list
  int bin = -1;        // ride-table bin of a liner impact, -1 for a landing on the charge
  V p = V::Zero(), v = V::Zero();  // [m], [m/s] state at landing
};

/// A slot reaching its flight angle within the current step.
struct DepartureEvent {
  double t;  // [s]
  int j, s;  // layer, slot
  int seg;   // segment of the lifter holding it, -1 if unheld
};

struct Flight {
  int id = 0, from_layer = 0;
  double t_rel = 0;   // [s] leaves its slot (start of the slide along a lifter face)
  double t0 = 0;      // [s] origin of the parabola (the launch)
  V p0, v0;           // [m], [m/s] state at t0
  V p_rel;            // [m] where it left its slot
  double t_check = 0; // [s] path checked up to here
  double t_next = 0;  // [s] end of the next interval to check
  V p_next;           // [m] flight_position(t_next), kept by check_flight() (no drag) for its next call
  double r_next = 0;  // [m] |p_next|
  bool landed = false;  // a landing has been found, at `landing` (it happens when the steps get there)
  Landing landing;
  bool drag = false;  // in the slurry pool: p0, v0 are advanced numerically
  double grace = 0;   // [s] no contact with the charge counts before this time (a relaunched element
                      //     first clears the cell it rolled off)
};



class LayerSim {
 public:
  explicit LayerSim(const ChargeInput& in);
  ChargeResult run();

 private:
  // ---- setup
  void setup_geometry();
  void setup_layers();
  /// The layers' cell angles and offsets, and with `tables` the slot
  /// direction tables (left out before the cell counts are final).
  void layout_slots(bool tables);
  void setup_flight_angles();
  /// Layer j's balls a lifter lets go where they cannot be thrown, caught by
  /// the lifter behind it (setup_flight_angles(); a hi-lo ring's low lifters).
  void caught_behind(int j);
  /// Notes for lifters lower than kLowLifterDiameters media diameters and
  /// rows further apart than kWideRowsDiameters (docs/models/layer.md).
  void note_unchecked_lifters();
  void setup_initial_fill();
  // ---- state queries
  double slot_angle(int j, int s, double tau) const {
    return L_[j].phase + L_[j].omega * (tau - t_step0_) + s * L_[j].delta;
  }
  int slot_of(int j, double theta, double tau) const {
    const Layer& l = L_[j];
    const double u = wrap2pi(theta - l.phase - l.omega * (tau - t_step0_) + 0.5 * l.delta);
    int s = static_cast<int>(u * l.inv_delta);
    return s >= l.S ? s - l.S : (s < 0 ? 0 : s);
  }
  /// Direction (cos, sin) of slot s of layer j at time tau, from per-layer
  /// tables and a cached direction of the layer's phase (no trig per call).
  void slot_dir(int j, int s, double tau, double& c, double& sn) const {
    if (dir_tau_[j] != tau) {
      const double ph = L_[j].phase + L_[j].omega * (tau - t_step0_);
      dir_c_[j] = std::cos(ph);
      dir_s_[j] = std::sin(ph);
      dir_tau_[j] = tau;
    }
    const double cs = slot_cos_[L_[j].offset + s], ss = slot_sin_[L_[j].offset + s];
    c = dir_c_[j] * cs - dir_s_[j] * ss;
    sn = dir_s_[j] * cs + dir_c_[j] * ss;
  }
  int& occ(int j, int s) { return occ_[L_[j].offset + s]; }
  int occ(int j, int s) const { return occ_[L_[j].offset + s]; }
  /// Top of the charge column at angle theta at time tau: the layer just
  /// above the highest element of the stack there (so a landing element sits
  /// on top, never in a hole under other elements). Starts from the column
  /// map and walks up or down to the current top.
  int ncol(double theta, double tau) const {
    const Layer& l0 = L_[0];
    const double ph = l0.phase + l0.omega * (t_map_ - t_step0_);
    int s0 = static_cast<int>(wrap2pi(theta - ph + 0.5 * l0.delta) * l0.inv_delta);
    if (s0 >= l0.S) s0 -= l0.S;
    int h = std::min(col_[s0], n_open_);
    while (h < n_open_ && occ(h, slot_of(h, theta, tau)) >= 0) ++h;
    while (h > 0 && occ(h - 1, slot_of(h - 1, theta, tau)) < 0) --h;
    return h;
  }
  double mill_angle(double tau) const { return omega_ * tau + canon_.initial_angle_rad; }
  /// Where an en-masse element of layer j at polar angle theta is drawn: the
  /// outer layer rides on the liner; inner layers keep their radius unless a
  /// lifter below pushes them in.
  double drawn_radius(int j, double theta, double tau) const {
    const double ride = ride_.ride(theta - mill_angle(tau));
    return j == 0 ? ride : std::min(L_[j].r, ride - j * d_);
  }
  V flight_position(const Flight& f, double tau) const;
  V flight_velocity(const Flight& f, double tau) const;
  // ---- the step
  void departures(double t0, double t1);
  void launch(int j, int s, double tau, int seg, bool relaunch = false);
  /// Polar angle beyond which layer j cannot carry an element (its flight angle).
  double flight_angle(int j) const { return std::min(L_[j].release, L_[j].rel_min); }
  /// The release study's pocket (ModelSpec::held_pocket_balls >= 0): the
  /// segment of the lifter whose leading face pushes an element of layer j at
  /// liner-frame angle psi in segment seg, if the element is within
  /// held_pocket_balls element widths of the face's foot (along layer j's
  /// arc); -1 if it rests on the plate further ahead.
  int pocket_lifter(int j, int seg, double psi) const;
  void check_flights(double t1);
  /// The events of a step, ordered by time (then departures, landings,
  /// checks; then index: deterministic). events_ is kept sorted latest first,
  /// so that the next event is at its back: most events are known at the
  /// start of the step and sorted once; the few that arise during it
  /// (landings found, launches) are inserted in order.
  enum EventKind { kDepart = 0, kLand = 1, kCheck = 2 };
  /// (t, kind, index) as one 128-bit unsigned key, compared in one go: the
  /// high word t's bits mapped to an unsigned order (sign bit flipped for
  /// t >= 0, all bits for t < 0: the order of the doubles, and reversible, so
  /// t() gives t back), the low word kind and index. The same order as
  /// comparing t, then kind, then index: -0 is taken as +0 (t + 0.0), equal as
  /// the doubles compare (no event time is -0 or NaN: they are sums with the
  /// step's start t0 >= +0).
  struct StepEvent {
    std::uint64_t tkey, tie;
    StepEvent(double t_, int kind_, int index_)
        : tie((static_cast<std::uint64_t>(kind_) << 32) | static_cast<std::uint32_t>(index_)) {
      const double t0 = t_ + 0.0;  // -0 -> +0, every other value unchanged
      std::uint64_t b;
      std::memcpy(&b, &t0, sizeof b);
      tkey = b ^ (b >> 63 ? ~std::uint64_t{0} : std::uint64_t{1} << 63);
    }
    double t() const {
      const std::uint64_t b = tkey ^ (tkey >> 63 ? std::uint64_t{1} << 63 : ~std::uint64_t{0});
      double x;
      std::memcpy(&x, &b, sizeof x);
      return x;
    }
    int kind() const { return static_cast<int>(tie >> 32); }
    int index() const { return static_cast<int>(static_cast<std::uint32_t>(tie)); }
  };
  __extension__ typedef unsigned __int128 EventKey;
  static bool event_after(const StepEvent& x, const StepEvent& y) {
    return ((static_cast<EventKey>(x.tkey) << 64) | x.tie) > ((static_cast<EventKey>(y.tkey) << 64) | y.tie);
  }
  void push_event(const StepEvent& e) {
    events_.insert(std::lower_bound(events_.begin(), events_.end(), e, event_after), e);
  }
  /// Flight i's next event in the current step (its landing, or the check of
  /// its next interval) if it has one there, else the flight waits for the
  /// first step that has (wait_flight()).
  void schedule_flight(int i);
  /// Files flight i under the first step from step k_min on that has its next
  /// event: the steps take their flights from there (check_flights()), not
  /// from a scan of every flight.
  void wait_flight(int i, long long k_min);
  __attribute__((noinline)) void wait_far(long long k, int id);
  /// Where the flight's unchecked path starts.
  static double next_check(const Flight& f) { return std::max({f.t_next, f.t_check, f.t0}); }
  bool check_flight(Flight& f, double t1, Landing& out);
  bool check_flight_drag(Flight& f, double t1, Landing& out);
  /// First crossing into the liner over (tau, tb] of the path through pa with
  /// velocity va and acceleration acc at tau.
  bool liner_crossing(const V& pa, const V& va, const V& acc, double tau, double tb, double& t_hit, int& bin) const;
  /// The point q (radius r, angle theta) lies in an occupied cell at time tq.
  bool inside_charge(const V& q, double r, double theta, double tq) const;
  /// The same, the angle of q computed only where it matters (not inside the
  /// innermost open layer, where the flights spend much of their time).
  bool inside_charge(const V& q, double r, double tq) const {
    return r >= r_open_min_ && inside_charge(q, r, fast_atan2(q.y(), q.x()), tq);
  }
  void drag_advance(Flight& f, double h) const;
  void deposit(int id, double theta, double tau, const V& v_land);
  /// Puts element `id`, which is in no slot, at (k, s) at time tau and lets
  /// it settle by the foot-stability rules.
  void place(int id, int k, int s, double tau);
  /// From theta, steps against the rotation (one outer cell at a time) to
  /// the first column with room below n_open (and, with `holdable`, whose
  /// top cell its layer can hold), passing over the columns the column map
  /// shows full; theta and k_out are that column's angle and top, s_out =
  /// slot_of(k_out, theta, tau). False if there is none.
  bool toe_ward_room(double& theta, double tau, bool holdable, int& k_out, int& s_out) const;
  /// The slot is on the rising side beyond the flight angle of its layer.
  bool past_flight_angle(int k, int s, double tau) const;
  /// The same from the slot's direction (c, sn) = slot_dir(k, s, tau), where
  /// the caller has it. The flight angle is that of the segment the direction
  /// lies over at tau (the lifter holding the element; sin_fa_seg_), which is
  /// the layer's own (sin_fa_, their smallest) unless the segments differ.
  bool past_flight_dir(int k, double c, double sn, double tau) const {
    if (!(c > 0 && sn > sin_fa_[k])) return false;
    if (!fa_by_segment_[static_cast<size_t>(k)]) return true;
    return sn > sin_fa_seg_[static_cast<size_t>(k) * seg_.size() + segment_at(c, sn, tau)];
  }
  /// The segment under direction (c, sn) at time tau.
  int segment_at(double c, double sn, double tau) const {
    return canon_.surface.segment_of_angle(std::atan2(sn, c) - mill_angle(tau));
  }
  /// An element just placed in slot s of layer j at time tau: if it is past
  /// where the layer lets go, it leaves now; if it gets there before the end
  /// of the current step, it leaves then (departures() has already run).
  /// sn: the sine of slot_dir(j, s, tau), which the caller has at hand.
  void check_departure(int j, int s, double tau, double sn);
  void support_sweep(double tau);
  /// Element `id` leaves slot s of layer j at tau: the arc it swept since it
  /// came there is added to the occupancy (exact time integration).
  void leave_slot(int id, int j, int s, double tau);
  /// Element `id` comes to slot s of layer j at tau.
  void enter_slot(int id, int j, int s, double tau);
  /// Foot stability of the whole surface: the top element of every column
  /// rolls to a neighbouring column where the surface is steeper than the
  /// angle of repose (or where its layer cannot hold it), a sandpile rule.
  void relax_surface(double tau);
  /// Whether the element at (k, s) at tau would roll, and where: the top
  /// cell (kn, sn) of the steepest-descent neighbouring column. (c, sn_th)
  /// is slot_dir(k, s, tau) on entry and, where it rolls, slot_dir(kn, sn,
  /// tau) on return (the values roll_target() computed for the target).
  bool roll_target(int k, int s, double tau, int& kn_out, int& sn_out, double& c, double& sn_th);
  /// The top that the roll rules compare the top (k, s) with in the column
  /// at angle thn (a neighbour's centre): its cell (kn, sn), direction (cn,
  /// snn) = slot_dir(kn, sn, tau) and position (xn, yn). False where there is
  /// none: the column is full, or its top is (k, s) itself, or, unless
  /// `onto_liner`, it is the liner (k = kn = 0: there the lifters hold it).
  /// One place for roll_target() and repose_exact().
  bool neighbour_top(int k, int s, double thn, double tau, bool onto_liner, int& kn, int& sn, double& cn,
                     double& snn, double& xn, double& yn) const {
    int sb;
    kn = ncol_at(thn, tau, sb, sn);
    if (kn >= n_open_) return false;
    if (kn == 0 && k == 0 && !onto_liner) return false;
    if (kn == k && sn == s) return false;
    slot_dir(kn, sn, tau, cn, snn);
    xn = L_[kn].r * cn;
    yn = L_[kn].r * snn;
    return true;
  }
  /// ncol(theta, tau), which also hands back the slots it found on the way:
  /// at = slot_of(h, theta, tau) if h < n_open, below = slot_of(h - 1, theta,
  /// tau) if h > 0 (the same values; the foot-stability rules need them).
  int ncol_at(double theta, double tau, int& below, int& at) const {
    // ncol()'s walks, in the same order over the same cells
    const Layer& l0 = L_[0];
    const double ph = l0.phase + l0.omega * (t_map_ - t_step0_);
    int s0 = static_cast<int>(wrap2pi(theta - ph + 0.5 * l0.delta) * l0.inv_delta);
    if (s0 >= l0.S) s0 -= l0.S;
    return ncol_from(s0, theta, tau, below, at);
  }
  /// ncol_at() once the outer cell s0 of the column map at theta is known.
  int ncol_from(int s0, double theta, double tau, int& below, int& at) const {
    int h = std::min(col_[s0], n_open_);
    below = at = -1;
    while (h < n_open_) {
      const int q = slot_of(h, theta, tau);
      if (occ(h, q) < 0) {
        at = q;
        break;
      }
      below = q;
      ++h;
    }
    while (h > 0) {
      const int q = below >= 0 ? below : slot_of(h - 1, theta, tau);
      if (occ(h - 1, q) >= 0) {
        below = q;
        break;
      }
      at = q;
      below = -1;
      --h;
    }
    return h;
  }
  /// Marks in relax_cur_ the outer cells whose column's top may roll at tau
  /// (a conservative filter for relax_surface(), from the column map).
  void relax_candidates(double tau);
  /// Whether the top of the column above outer cell s, h = col_[s] > 0 high,
  /// may roll at tau, once the cheap first look of relax_candidates() let it
  /// through (h_min: the smallest column within relax_min_reach_, at most n_open).
  bool relax_candidate_exact(int s, int h, int h_min, double tau) const;
  /// For relax_candidate_exact(): the top of the column above outer cell s
  /// (h high) is (k, st) at (x, y) and cannot roll by the repose rule at tau.
  bool repose_exact(int s, int h, int k, int st, double x, double y, double tau) const;
  /// Bit sets of outer cells (relax_cur_, relax_next_): sets bits lo .. hi;
  /// the first set bit at or after q (below n), the last at or before q; -1
  /// if none.
  static void bits_set(std::vector<std::uint64_t>& b, int lo, int hi);
  static int bits_next(const std::vector<std::uint64_t>& b, int q, int n);
  static int bits_prev(const std::vector<std::uint64_t>& b, int q);
  /// Column heights round the outer layer at tau, and with `window` their
  /// window maxima for the flights' clearance (bed_clearance()).
  void update_columns(double tau, bool window);
  /// Cell k of layer j was entered (or left) at tau: marks the columns of
  /// the map and the slots of the support sweep that may change.
  void note_cell(int j, int k, double tau, bool entered);
  /// Column s may have changed from layer j up (update_columns()).
  void mark_col(int s, int j) {
    if (!col_dirty_[s]) {
      col_dirty_[s] = 1;
      col_dirty_list_.push_back(s);
      col_from_[s] = j;
    } else if (j < col_from_[s]) {
      col_from_[s] = j;
    }
  }
  void mark_sup(int j, int s) { sup_bits_[occ_bits_off_[j] + (s >> 6)] |= std::uint64_t{1} << (s & 63); }
  /// Offset b of the SlotMap from the outer layer to layer j at tau.
  /// Remembered per layer: the maps and note_cell() (on every move of a
  /// sweep or relaxation) ask for the same offset at one time many times.
  /// The phases change only together with t_step0_, so (tau, t_step0_)
  /// names the value.
  double colmap_offset(int j, double tau) const {
    MapOffset& c = colmap_off_[j];
    if (c.tau != tau || c.t0 != t_step0_) {
      c.tau = tau;
      c.t0 = t_step0_;
      c.b = wrap2pi(slot_angle(0, 0, tau) - slot_angle(j, 0, tau)) * L_[j].inv_delta + 0.5;
    }
    return c.b;
  }
  /// Offset b of the SlotMap from layer j to layer j - 1 at tau (remembered likewise).
  double supmap_offset(int j, double tau) const {
    MapOffset& c = supmap_off_[j];
    if (c.tau != tau || c.t0 != t_step0_) {
      c.tau = tau;
      c.t0 = t_step0_;
      c.b = wrap2pi(slot_angle(j, 0, tau) - slot_angle(j - 1, 0, tau)) * L_[j - 1].inv_delta + 0.5;
    }
    return c.b;
  }
  /// out[s] = max (or min) of v over s - m .. s + m, circularly.
  void window_extreme(const std::vector<int>& v, int m, bool max, std::vector<int>& out);
  /// A lower bound [m] on the distance from (r, theta) at time tau to any cell
  /// the charge can occupy before tau + skip_H_ (from the column map).
  double bed_clearance(double r, double theta, double tau) const;
  void sample(double tau, double w);
  void snapshot(double tau);

  // ---- inputs
  const ChargeInput& in_;
  CanonicalSurface canon_;
  LinerMetrics metrics_;
  std::vector<SegmentMetrics> seg_;
  LinerRideTable ride_;
  double ride_reject_ = 0;  // cos(h/2) (1 - 1e-7), h the bin; 0: no quick reject (see liner_crossing())
  double inv_d_ = 0;
  // d_: edge of an element (a cell of the lattice), element_size_diameters
  // media diameters (1: one ball); a_ = d_ / 2. d_ball_: the media diameter,
  // for what concerns one ball (its mass and size in impacts, slurry drag,
  // the trajectory threshold).
  double R_eff_ = 0, d_ = 0, a_ = 0, omega_ = 0, J_ = 0, phi_ = 0, d_ball_ = 0;
  double rho_c_ = 0;           // [kg/m3] charge bulk density (Morrell)
  double m_ = 0;               // [kg/m] mass of one element
  double m_sphere_ = 0;        // [kg] one media sphere of the element's mean solid density
  double rho_solid_ = 0, rho_pulp_ = 0;
  double mu_ = 0, gamma_ = 0;  // friction coefficient, repose angle [rad]
  double beta_ = 0;            // en-masse share in eq. 4.14 (Morrell's, or the study's)
  double airborne_w_ = 0, airborne_t_ = 0;  // time integral of the flights in progress, and of the time, while averaging
  double mu_unheld_ = 0;       // friction coefficient of the unheld layers' flight angle
  double pocket_balls_ = -1;   // < 0: a held layer leaves at its lifter's angle everywhere; else see pocket_lifter()
  double r_i_ = 0, z_ = 0;     // Morrell's inner radius and z
  double toe_morrell_ = 0;     // [rad] eq. 4.15
  int variant_ = 12;           // 10, 11, 12
  bool drag_on_ = false;
  double y_pool_ = -kInf;      // [m] slurry level of an overflow mill
  int N_ = 0;
  // ---- layers and state
  std::vector<Layer> L_;
  int n_open_ = 0;                          // layers that may hold elements (0 .. n_open_-1)
  int partial_layer_ = -1;                  // version 1.2: the layer cut by r_i, open with a share of its cells
  int partial_S_full_ = 0;                  // its cell count when whole
  std::vector<std::vector<HeldLaunch>> held_;  // [held layer][segment]
  int n_held_layers_ = 0;
  std::vector<int> occ_;                    // element id per slot, -1 empty
  std::vector<double> slot_cos_, slot_sin_; // cos, sin of s delta_j per slot
  mutable std::vector<double> dir_tau_, dir_c_, dir_s_;  // cache of slot_dir(): the phase direction at dir_tau_
  std::vector<double> sin_fa_;              // sin of each layer's flight angle (+inf: never)
  // sin of the flight angle of layer j over segment k, [j * segments + k]:
  // min(layer's, that segment's lifter release); fa_by_segment_[j] where they
  // differ (a hi-lo ring), else sin_fa_ alone is used
  std::vector<double> sin_fa_seg_;
  std::vector<double> rel_seg_;  // [rad] layer j's own flight angle over segment k, [j * segments + k] (setup_flight_angles())
  double rel_seg(int j, int k) const { return rel_seg_[static_cast<size_t>(j) * seg_.size() + static_cast<size_t>(k)]; }
  /// Where a ball that came into layer j over lifter seg after the lifter's
  /// release leaves (the layer's own angle there, docs/models/layer.md §3
  /// "Per segment"), or +inf where that is not later than the release.
  double late_ball_angle(int j, int seg) const {
    const HeldLaunch& h = held_[static_cast<size_t>(j)][static_cast<size_t>(seg)];
    const double rb = rel_seg(j, seg);
    return h.held && h.released && std::isfinite(rb) && rb > h.release ? rb : kInf;
  }
  std::vector<char> fa_by_segment_;
  std::vector<int> holder_;  // per segment: the lifter that pushes what rides over it, -1 on a ring without (setup_flight_angles())
  double tan_g_ = 0;                        // tan of the angle of repose
  std::vector<int> elem_layer_, elem_slot_; // -1 when flying
  std::vector<double> elem_y_entry_;        // [m] height where it last entered the charge
  std::vector<double> elem_t_slot_;         // [s] since when it sits in its slot
  std::vector<double> elem_sin_slot_;       // sin of its slot's angle then (while averaging; leave_slot())
  std::vector<double> phase0_;              // [rad] phase of each layer at t = 0 (the phase is phase0 + omega t)
  std::vector<Flight> flights_;
  std::vector<StepEvent> events_;
  // The waiting flights, by element id, filed under the step of their next
  // event (wait_flight()): a ring of kWakeRing steps from the current one,
  // and the flights further ahead.
  static constexpr int kWakeRing = 512;
  std::vector<std::vector<int>> wake_ring_ = std::vector<std::vector<int>>(kWakeRing);
  std::vector<std::pair<long long, int>> wake_far_;  // (step, element id)
  std::vector<int> wake_due_;               // scratch of check_flights()
  std::vector<int> flight_pos_;             // [element id] index in flights_ of its latest flight
  long long step_k_ = 0;                    // index of the step check_flights() runs next (or is running)
  double step_t1_ = 0;
  bool in_step_ = false;  // inside check_flights(): a launch schedules its flight
  std::vector<DepartureEvent> dep_events_;
  std::vector<int> gone_;
  std::vector<int> moved_;                  // scratch of support_sweep
  double t_step0_ = 0;
  double t_step1_ = 0;                      // end of the current step
  double dt_ = 0;
  int substeps_ = 1;
  double relax_dt_ = 0;  // [s] interval of the support sweep and surface relaxation
  int deepest_ = 0;                         // deepest layer holding an element (for the flight skip)
  // ---- averaging window
  double t_avg0_ = 0, t_end_ = 0;
  bool averaging_ = false;
  double avg_time_ = 0;
  double energy_ = 0;                       // [J/m] work done on departing elements
  double arm_time_ = 0;                     // [kg m s / m] time integral of sum m x over the elements in slots (power)
  double arm_fly_time_ = 0;                 // [kg m s / m] the same over the flying ones, sampled (sample())
  std::vector<double> layer_count_acc_;     // element-seconds per layer
  std::vector<long long> traj_count_;       // trajectory flights per launch layer
  long long n_traj_flights_ = 0;
  long long n_flights_ = 0;
  long long n_avg_landings_ = 0;  // landings in the averaging window (direct_impact_fraction's denominator)
  // loads, canonical element index
  std::vector<double> acc_N_, acc_Nc_, acc_Ng_, acc_S_, acc_NV_, acc_SV_;
  // pocket loads (ModelSpec::pocket_loads; docs/models/layer.md §7, "Pocket
  // loads"): per direction (0: the column pushes against the rotation, onto
  // the face behind it; 1: with the rotation, onto the face ahead) and ride
  // bin, how many layers a face holds there, and for each of those layers the
  // face elements that take its tangential force per newton of it
  struct PocketShare {
    int element;
    double kn, ks;    // normal and shear force on the element per N of tangential force
    double r;         // [m] ride radius there (the slip speed's radius)
    V lifter;         // force on segment 0's elements per N (liner frame; lifter forces)
  };
  void setup_pocket_loads();
  /// The pocket loads of the column of n layers over ride bin b (sample()):
  /// accumulates the faces' share, returns the force left under the column.
  __attribute__((noinline)) V pocket_push(int b, int n, double c, double sn, double C, double Fr_g, const V& er,
                                          const V& et, double w, double vslip_w, double cr, double sr, V& f_lifter);
  std::vector<int> pocket_depth_[2];          // [dir][bin]
  std::vector<int> pocket_begin_[2];          // [dir][bin * pocket_layers_ + q], one past the end at the back
  std::vector<PocketShare> pocket_share_[2];  // [dir][...]
  int pocket_layers_ = 0;                     // most layers a face holds anywhere
  std::vector<ImpactEvent> impacts_;
  std::vector<double> lifter_n_, lifter_t_;  // per 2-degree bin of lifter 0's angle
  std::vector<int> lifter_cnt_;
  std::unique_ptr<ChargeOccupancy> occupancy_;
  bool ring_is_layer_ = false;              // occupancy rings coincide with the layers, bins with slots
  std::vector<int> col_;                    // column height above each outer slot, at t_map_
  std::vector<int> colwin_;                 // max column height over outer slots s-m .. s+m
  std::vector<int> win_pre_, win_val_;      // scratch of the window extremes
  std::vector<std::int16_t> win16_val_, win16_tmp_;  // the same, for values that fit 16 bits
  std::vector<int> active_;                 // scratch: outer slots whose column is still growing
  std::vector<std::uint64_t> relax_cur_, relax_next_;  // scratch of relax_surface(): columns to visit (bits)
  std::vector<double> relax_tol_, relax_past_sn_, relax_ovh_sn_;  // [layer] the first look's bounds (relax_candidates())
  // incremental maps (docs/models/layer.md §Incremental maps)
  std::vector<SlotMap> colmap_;             // [j] outer layer -> layer j
  std::vector<SlotMap> supmap_;             // [j] layer j -> layer j - 1
  std::vector<double> colmap_b_;            // offsets of colmap_ at t_map_
  std::vector<double> supmap_b_;            // offsets of supmap_ at t_sup_
  struct MapOffset {                        // colmap_offset() / supmap_offset() at (tau, t0)
    double tau = kInf, t0 = kInf, b = 0;
  };
  mutable std::vector<MapOffset> colmap_off_, supmap_off_;  // [j]
  double t_sup_ = 0;                        // [s] time of the last support sweep
  bool maps_ready_ = false;                 // changes are noted from the start of the run
  bool col_full_ = true, sup_full_ = true;  // the next map / sweep is a full one
  bool incremental_ = true;                 // false: every map, sweep and relaxation pass is a full one (tests)
  std::vector<char> col_dirty_;             // per outer slot
  // occupancy bits of the open layers (bit s of layer j: occ(j, s) >= 0),
  // kept by note_cell() from the start of the run: update_columns() finds
  // the few places where a layer's occupancy changes from them
  std::vector<std::uint64_t> occ_bits_;
  std::vector<std::uint64_t> occ_bits_map_; // occ_bits_ at t_map_ (the cells changed since: the difference)
  std::vector<int> occ_bits_off_;           // [j] first word of layer j
  std::vector<int> occ_bits_layer_;         // [word] its layer
  std::vector<std::uint64_t> occ_words_changed_;  // bit i: word i of occ_bits_ changed since the last map
  std::vector<int> col_dirty_list_;
  std::vector<int> col_from_;               // per outer slot marked: the lowest layer whose cell changed
  std::vector<std::uint64_t> sup_bits_;     // slots to check, bits as occ_bits_ (a list and flags until 2026-12-05)
  std::vector<int> colmin_;                 // scratch of relax_surface(): window minima of col_
  int relax_min_reach_ = 3;                 // [outer cells] half-width of colmin_'s window
  std::vector<int> relax_reach_m_;          // [outer cells] how far a move that changed a cell of layer m can
                                            //     change what roll_target() sees
  int col_m_ = 1;                           // half-width m of that window [slots]
  double t_map_ = 0;                        // [s] time of the column map col_
  double t_win_ = 0;                        // [s] time of its window maxima colwin_
  double t_last_sample_ = 0;                // [s]
  double skip_H_ = 0;                       // [s] longest skip of a flight past the charge
  double r_open_min_ = 0;                   // [m] no element is ever inside this radius
  std::vector<double> cos0_, sin0_;         // direction of outer slot s relative to slot 0
  std::vector<double> col_mass_, col_centrifugal_;  // [kg/m], [N/m] of a column n layers high
  // snapshots
  std::vector<ChargeSnapshot> snaps_;
  double next_snap_ = kInf, snap_dt_ = 0;
  int snaps_left_ = 0;
  std::vector<std::string> notes_;
};

// ============================================================================
// Setup
// ============================================================================

LayerSim::LayerSim(const ChargeInput& in) : in_(in) {
  if (!in.surface) throw InputError("", "layer model: no liner surface given");
  const ChargeSpec& c = in.charge;
  const ModelSpec& ms = in.model;
  if (!(c.filling > 0 && c.filling < 1))
    throw InputError("charge.filling", fmt::format("filling = {}: the layer model needs 0 < filling < 1", c.filling));
  if (!(c.ball_diameter_m > 0))
    throw InputError("charge.ball_diameter_m", fmt::format("ball_diameter_m = {}: must be > 0", c.ball_diameter_m));
  if (!(in.mill.speed_rpm > 0))
    throw InputError("mill.speed_rpm", fmt::format("speed_rpm = {}: must be > 0", in.mill.speed_rpm));
  if (!(ms.time_step_s >= kLayerMinTimeStepS) || !std::isfinite(ms.time_step_s))
    throw InputError("model.time_step_s", fmt::format("time_step_s = {} s: allowed >= {} s (docs/models/layer.md §9)",
                                                      ms.time_step_s, kLayerMinTimeStepS));
  if (ms.variant == "1.0") variant_ = 10;
  else if (ms.variant == "1.1") variant_ = 11;
  else if (ms.variant == "1.2") variant_ = 12;
  else throw InputError("model.variant", fmt::format("variant = \"{}\": allowed one of \"1.0\", \"1.1\", \"1.2\"", ms.variant));
  if (!(ms.friction_coefficient >= 0 && ms.friction_coefficient < 5))
    throw InputError("model.friction_coefficient", fmt::format("friction_coefficient = {}: allowed 0 <= value < 5", ms.friction_coefficient));
  if (!(ms.repose_angle_deg > 0 && ms.repose_angle_deg < 90))
    throw InputError("model.repose_angle_deg", fmt::format("repose_angle_deg = {}: allowed 0 < value < 90", ms.repose_angle_deg));
  if (!(in.revolutions >= 0)) throw InputError("--revolutions", fmt::format("revolutions = {}: must be >= 0", in.revolutions));
  if (!(ms.relaxation_interval_cells >= 0.01 && ms.relaxation_interval_cells <= 4))
    throw InputError("model.relaxation_interval_cells",
                     fmt::format("relaxation_interval_cells = {}: allowed 0.01 <= value <= 4", ms.relaxation_interval_cells));
  if (!(ms.settle_revolutions >= 0))
    throw InputError("model.settle_revolutions", fmt::format("settle_revolutions = {}: must be >= 0", ms.settle_revolutions));
  if (ms.initial_phases != "aligned" && ms.initial_phases != "staggered")
    throw InputError("model.initial_phases",
                     fmt::format("initial_phases = \"{}\": allowed \"aligned\" or \"staggered\"", ms.initial_phases));
  if (ms.slurry_drag && c.discharge != Discharge::Overflow)
    throw InputError("model.slurry_drag", "slurry_drag = \"on\" needs an overflow mill ([mill] discharge = \"overflow\"): a grate mill has no slurry pool");
  parse_slip_law(ms.slip_model);  // refuses unknown names
  if (!(ms.unheld_friction_coefficient <= 2))
    throw InputError("model.unheld_friction_coefficient",
                     fmt::format("unheld_friction_coefficient = {}: allowed value <= 2 (< 0: friction_coefficient)",
                                 ms.unheld_friction_coefficient));
  if (!(ms.inner_radius_beta < 0 || (ms.inner_radius_beta > 0 && ms.inner_radius_beta <= 1)))
    throw InputError("model.inner_radius_beta",
                     fmt::format("inner_radius_beta = {}: allowed 0 < value <= 1 (< 0: Morrell's; ignored in a "
                                 "centrifuged mill)", ms.inner_radius_beta));
  if (!(ms.held_pocket_balls <= 100))
    throw InputError("model.held_pocket_balls",
                     fmt::format("held_pocket_balls = {}: allowed value <= 100 (< 0: the whole layer)", ms.held_pocket_balls));
  if (!(ms.element_size_diameters >= 1 && ms.element_size_diameters <= 4))
    throw InputError("model.element_size_diameters",
                     fmt::format("element_size_diameters = {}: allowed 1 <= value <= 4", ms.element_size_diameters));
  d_ball_ = c.ball_diameter_m;
  // Agglomerated elements (thesis §4.4.5: balls agglomerated into discrete
  // elements of equivalent volume): a square cell of k media diameters.
  d_ = ms.element_size_diameters * d_ball_;
  a_ = 0.5 * d_;
  inv_d_ = 1.0 / d_;
  J_ = c.filling;
  omega_ = in.mill.omega_rad_s();
  mu_ = ms.friction_coefficient;
  mu_unheld_ = ms.unheld_friction_coefficient < 0 ? mu_ : ms.unheld_friction_coefficient;
  pocket_balls_ = ms.held_pocket_balls;
  gamma_ = ms.repose_angle_deg * kPi / 180.0;
  drag_on_ = ms.slurry_drag;
}

void LayerSim::setup_geometry() {
  canon_ = make_canonical_surface(*in_.surface, in_.mill.rotation);
  metrics_ = metrics(canon_.surface, Rotation::Ccw, 7800.0);
  seg_ = metrics_.segments;
  R_eff_ = 0.5 * metrics_.effective_diameter_m;
  if (!(d_ball_ < 0.25 * R_eff_))
    throw InputError("charge.ball_diameter_m",
                     fmt::format("ball_diameter_m = {} m is too large for a mill of {:.3f} m inside the liners: the layer "
                                 "model needs at least four layers of media across the radius",
                                 d_ball_, 2 * R_eff_));
  if (!(d_ < 0.25 * R_eff_))
    throw InputError("model.element_size_diameters",
                     fmt::format("element_size_diameters = {} makes elements of {:.4g} m, too large for a mill of "
                                 "{:.3f} m inside the liners: the layer model needs at least four layers of elements "
                                 "across the radius",
                                 in_.model.element_size_diameters, d_, 2 * R_eff_));
  {
    // (an element is at least one ball: element_size_diameters >= 1 only shrinks the lattice)
    const double cells = kPi * R_eff_ * R_eff_ / (d_ * d_);
    if (!(cells <= kLayerMaxCells))
      throw InputError("charge.ball_diameter_m",
                       fmt::format("ball_diameter_m = {} m makes a lattice of {:.3g} cells in a mill of {:.3f} m inside "
                                   "the liners; the layer model takes at most {:.0f}: allowed ball_diameter_m >= {:.4g} "
                                   "m here",
                                   d_ball_, cells, 2 * R_eff_, kLayerMaxCells,
                                   R_eff_ * std::sqrt(kPi / kLayerMaxCells) / in_.model.element_size_diameters));
  }
  ride_ = build_liner_ride_table(
      canon_.surface, a_, 4,
      in_.model.load_contact_spacing_m > 0 ? in_.model.load_contact_spacing_m : load_contact_spacing_m(canon_.surface));
  {
    // liner_crossing()'s quick reject needs every ride point finite
    bool finite = true;
    for (const double r : ride_.edge_radius_m) finite = finite && r > 0 && r < kInf;
    ride_reject_ = finite ? std::cos(0.5 * ride_.bin_rad) * (1 - 1e-7) : 0.0;
  }
  if (in_.model.pocket_loads) setup_pocket_loads();
  phi_ = in_.mill.speed_rpm / critical_speed_rpm(2 * R_eff_);
  const ChargeSpec& c = in_.charge;
  // Densities (Morrell 1996): the charge bulk density sets the element mass.
  const double rho_w = 1000.0;
  const double w = c.slurry_solids_mass_fraction;
  rho_pulp_ = pulp_density(w, c.ore_density_kg_m3, rho_w);
  const double S_vol = (w / c.ore_density_kg_m3) * rho_pulp_;
  rho_c_ = morrell_charge_density(J_, c.ball_filling, c.porosity, c.slurry_void_fill, S_vol, c.ore_density_kg_m3,
                                  c.ball_density_kg_m3, rho_w);
  rho_solid_ = (c.ball_filling * c.ball_density_kg_m3 + (J_ - c.ball_filling) * c.ore_density_kg_m3) / J_;
  m_sphere_ = kPi / 6.0 * d_ball_ * d_ball_ * d_ball_ * rho_solid_;
  if (c.discharge == Discharge::Overflow) y_pool_ = -c.trunnion_radius_m;  // slurry at the trunnion (Morrell 1996)
}

void LayerSim::setup_pocket_loads() {
  // Pocket loads (docs/models/layer.md §7, "Pocket loads"). Between two
  // lifters the charge sits in a pocket: the face behind it pushes it up the
  // rising side, the face ahead holds it on the falling side. So the
  // tangential force of a column over a pocket (thesis eq. 4.11, W g cos
  // theta) is a normal load on that face, not shear on the plate. Layer q of
  // the column, whose element sits one diameter per layer above the ride
  // radius of its bin b, presses on the face where the ride radius, walking
  // from b towards the face, first falls below its own radius (by a tenth of a
  // diameter, a real step of the profile); its force is spread evenly over
  // the bins of the next diameter of the face's height (balls in a pocket do
  // not sit in exact stacks). A layer no face holds within one segment (above
  // the crest, or on a lifter's top) ends the pocket's depth. Built once per
  // run from the ride table, so a worn profile has its own pockets.
  const int nb = ride_.n_bins;
  const int seg_bins = std::max(1, static_cast<int>(std::ceil(static_cast<double>(nb) / canon_.surface.segments)));
  pocket_layers_ = static_cast<int>(std::ceil((ride_.max_ride_m - ride_.min_ride_m) / d_)) + 1;
  const int seg0 = canon_.segment_of_physical_0;
  const double cos_face_max = std::cos(kPocketFaceDeg * kPi / 180.0);  // the contact normal within this of e_t
  // The direction of the liner's push on a disc at c touching element e:
  // from the nearest point of the element to the disc's centre (the
  // element's normal on a face, the bisecting direction on a corner).
  const LinerSurface& sf = canon_.surface;
  auto push_normal = [&](const V& c, int e) {
    const V a = sf.nodes[e], ab = sf.nodes[sf.next(e)] - a;
    const double t = std::clamp((c - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const V d = c - (a + t * ab);
    const double len = d.norm();
    return len > 1e-12 ? V(d / len) : sf.normal[e];
  };
  // Whether a bin faces the push is judged at its centre, on the element the
  // disc touches there (the nearest contact ray's, as every other load lands:
  // docs/models/layer.md §7, "Where a load lands").
  auto centre_normal = [&](int bb) {
    const double psi = (bb + 0.5) * ride_.bin_rad;
    return push_normal(ride_.ride_radius_m[bb] * V(std::cos(psi), std::sin(psi)), ride_.contact(psi));
  };
  // Per contact ray j (bin j / m, ray j % m of it): the element touched,
  // the push's normal there, the ring's tangent e_t and the disc's radius,
  // computed once (the bands of all pockets and layers share them).
  const int m_rays = ride_.contact_rays_per_bin;
  const size_t n_rays = ride_.contact_element.size();
  struct Ray {
    int element;
    V n, et;
    double r;
  };
  std::vector<Ray> rays(n_rays);
  for (size_t j = 0; j < n_rays; ++j) {
    const int bb = static_cast<int>(j / m_rays), b1 = bb + 1 == nb ? 0 : bb + 1;
    const double psi = static_cast<double>(j) / m_rays * ride_.bin_rad;
    const V u(std::cos(psi), std::sin(psi));
    const V p0 = ride_.point(bb), d = ride_.point(b1) - p0;
    const double den = u.x() * d.y() - u.y() * d.x();
    const double r = std::abs(den) > 1e-15 ? (p0.x() * d.y() - p0.y() * d.x()) / den : ride_.edge_radius_m[bb];
    const int e = ride_.contact_element[j];
    rays[j] = {e, push_normal(r * u, e), V(-u.y(), u.x()), r};
  }
  std::vector<int> band;  // ride bins
  for (int dir = 0; dir < 2; ++dir) {
    const int step = dir == 0 ? -1 : 1;
    const double sign = dir == 0 ? 1.0 : -1.0;  // the push on the face is -sign |T| e_t
    pocket_depth_[dir].assign(nb, 0);
    pocket_begin_[dir].assign(static_cast<size_t>(nb) * pocket_layers_ + 1, 0);
    pocket_share_[dir].clear();
    for (int b = 0; b < nb; ++b) {
      int depth = 0;
      for (int q = 0; q < pocket_layers_; ++q) {
        pocket_begin_[dir][static_cast<size_t>(b) * pocket_layers_ + q] = static_cast<int>(pocket_share_[dir].size());
        if (depth < q) continue;  // the pocket ended below
        const double rho = ride_.ride_radius_m[b] - q * d_;
        int first = -1;
        for (int i = 1; i <= seg_bins && first < 0; ++i) {
          const int bb = ((b + step * i) % nb + nb) % nb;
          if (ride_.ride_radius_m[bb] < rho - 0.1 * d_) first = bb;
        }
        if (first < 0) continue;
        // the band: the bins of the next diameter of the face's height where
        // the disc's contact faces the push, along the ring there (the contact
        // normal, from the touched point to the disc's centre, at most
        // kPocketFaceDeg from the tangent: a disc resting on the plate or on
        // a crest takes none of it; one on a sharp crest corner does, whichever
        // of the two elements meeting there the ride table names)
        band.clear();
        for (int i = 0; i < seg_bins; ++i) {
          const int bb = ((first + step * i) % nb + nb) % nb;
          if (i > 0 && !(ride_.ride_radius_m[bb] > rho - d_)) break;
          const double psi = (bb + 0.5) * ride_.bin_rad;
          const V et(-std::sin(psi), std::cos(psi));
          if (sign * et.dot(centre_normal(bb)) >= cos_face_max) band.push_back(bb);
        }
        if (band.empty()) continue;  // no face takes it: the pocket ends
        const size_t start = pocket_share_[dir].size();
        const double f = 1.0 / band.size();
        // A bin's push is spread over its contact rays (trapezoidal weights:
        // the rays on its two edges count half, as each is shared with the
        // next bin), each loading the element a disc on that ray touches,
        // with the disc's centre on the ride polyline there. One element per
        // bin left a comb on the faces: on the Qiu mill's 20 deg faces a
        // quarter of the 10 mm elements took a push (test "pocket loads land
        // where the disc touches, whatever the contact rays and the element
        // size").
        for (const int bb : band)
          for (int i = 0; i <= m_rays; ++i) {
            const Ray& ray = rays[(static_cast<size_t>(bb) * m_rays + i) % n_rays];
            const double w = f * ((i == 0 || i == m_rays) ? 0.5 : 1.0) / m_rays;
            const int e = ray.element;
            const double kn = sign * ray.et.dot(ray.n) * w;
            if (!(kn > 0)) continue;  // a ray of the bin past the corner: no face there
            const double ks = std::abs(ray.et.x() * ray.n.y() - ray.et.y() * ray.n.x()) * w;
            const V lift = canon_.surface.element_segment[e] == seg0 ? V(-sign * w * ray.et) : V(0, 0);
            auto it = std::find_if(pocket_share_[dir].begin() + start, pocket_share_[dir].end(),
                                   [&](const PocketShare& x) { return x.element == e; });
            if (it == pocket_share_[dir].end()) {
              pocket_share_[dir].push_back({e, kn, ks, ray.r * kn, lift});
            } else {
              it->kn += kn;
              it->ks += ks;
              it->r += ray.r * kn;
              it->lifter += lift;
            }
          }
        if (pocket_share_[dir].size() == start) continue;  // every ray past a corner: no face takes it
        for (auto it = pocket_share_[dir].begin() + start; it != pocket_share_[dir].end(); ++it) it->r /= it->kn;
        depth = q + 1;
      }
      pocket_depth_[dir][b] = depth;
    }
    pocket_begin_[dir].back() = static_cast<int>(pocket_share_[dir].size());
  }
}

void LayerSim::layout_slots(bool tables) {
  // offsets of each layer's slots in the occupancy array, and the slot direction tables
  int off = 0;
  for (Layer& l : L_) {
    l.delta = kTwoPi / l.S;
    l.inv_delta = l.S / kTwoPi;
    l.offset = off;
    off += l.S;
  }
  occ_.assign(off, -1);
  if (!tables) return;
  slot_cos_.resize(off);
  slot_sin_.resize(off);
  for (const Layer& l : L_)
    for (int q = 0; q < l.S; ++q) {
      slot_cos_[l.offset + q] = std::cos(q * l.delta);
      slot_sin_[l.offset + q] = std::sin(q * l.delta);
    }
}

void LayerSim::setup_layers() {
  const int nl = static_cast<int>(std::floor(R_eff_ / d_));
  L_.resize(nl);
  std::vector<double> r(nl);
  for (int j = 0; j < nl; ++j) {
    Layer& l = L_[j];
    l.r = r[j] = R_eff_ - (j + 0.5) * d_;
    l.S = std::max(1, static_cast<int>(std::lround(kTwoPi * l.r / d_)));  // equal-area cells of about d x d
  }
  layout_slots(false);  // the flight angles need the cell angles; the tables wait for the final cell counts
  dir_tau_.assign(nl, std::numeric_limits<double>::quiet_NaN());
  dir_c_.assign(nl, 1.0);
  dir_s_.assign(nl, 0.0);
  phase0_.assign(nl, 0.0);
  z_ = std::pow(1.0 - J_, 0.4532);
  const double Nm = in_.mill.speed_rpm / 60.0;
  // Morrell's toe (thesis eq. 4.15) with the guard of reference §1.
  const double phi_c = 0.35 * (3.364 - J_);
  const bool centrifuged = phi_ >= phi_c || phi_ >= 1.0;
  toe_morrell_ = centrifuged ? 0.5 * kPi : morrell_toe_rad(J_, phi_);
  // Slip law and inner radius r_i (thesis eq. 4.14 with the shoulder from
  // McIvor, eq. 4.5, and the toe from eq. 4.15) depend on each other: a few
  // fixed-point passes, starting from Morrell's own shoulder.
  SlipInput si;
  si.law = parse_slip_law(in_.model.slip_model);
  si.mill_omega_rad_s = omega_;
  si.mill_radius_m = R_eff_;
  si.filling = J_;
  si.slip_parameter = in_.model.slip_parameter;
  double beta = std::atan(mu_);  // plain shell: held only by friction
  {
    double sum = 0;
    int n = 0;
    for (const auto& s : seg_)
      if (s.has_lifter && std::isfinite(s.face_angle_leading_deg)) sum += s.face_angle_leading_deg, ++n;
    if (n) beta = 0.5 * kPi - sum / n * kPi / 180.0;  // face angle to the shell
  }
  si.lifter_angle_rad = beta;
  double shoulder = centrifuged ? 0.5 * kPi : morrell_shoulder_rad(J_, phi_, toe_morrell_);
  // eq. 4.14 with Morrell's en-masse share beta, or the study's
  // (docs/models/layer-worn.md, "The en-masse share of eq. 4.14")
  auto inner_radius = [&](double thS) {
    beta_ = in_.model.inner_radius_beta > 0 ? in_.model.inner_radius_beta
                                            : morrell_inner_radius(R_eff_, Nm, J_, toe_morrell_, thS).beta;
    return inner_radius_for_beta(R_eff_, J_, toe_morrell_, thS, beta_);
  };
  beta_ = 1.0;  // centrifuged: all en masse, r_i from the filling alone
  r_i_ = centrifuged ? R_eff_ * std::sqrt(1.0 - J_) : inner_radius(shoulder);
  std::vector<double> w;
  for (int it = 0; it < 6; ++it) {
    si.inner_radius_m = r_i_;
    w = layer_angular_speeds(si, r);
    for (int j = 0; j < nl; ++j) L_[j].omega = w[j];
    setup_flight_angles();
    // the shoulder of the outer layer: mean launch angle over the segments
    double sum = 0;
    int n = 0;
    if (n_held_layers_ > 0) {
      for (const auto& h : held_[0])
        if (h.held && h.released) sum += h.release + h.dtheta, ++n;
    }
    if (n == 0 && std::isfinite(L_[0].release)) sum = L_[0].release, n = 1;
    if (centrifuged || n == 0) break;
    shoulder = sum / n;
    const double ri = inner_radius(shoulder);
    const bool done = std::abs(ri - r_i_) < 1e-4 * R_eff_;
    r_i_ = ri;
    if (done) break;
  }
  si.inner_radius_m = r_i_;
  w = layer_angular_speeds(si, r);
  for (int j = 0; j < nl; ++j) L_[j].omega = w[j];
  setup_flight_angles();
  note_unchecked_lifters();
  for (std::string& n : checked_range_notes("the layer model", J_, phi_)) notes_.push_back(std::move(n));
  // Which layers may hold elements: every layer that turns forward (v > 0,
  // outside z r_i). Version 1.2 confines the charge to the annulus between
  // Morrell's inner radius r_i and the liner (thesis §4.6.2, eq. 4.14, Fig.
  // 4-26): the layers whose band [r - d/2, r + d/2] lies outside r_i are
  // open, and the layer the circle r_i cuts is open with the share
  //   f = (r + d/2 - r_i) / d
  // of its cells (fewer, wider cells: f S of them), so that the open cells
  // hold the annulus' area, (r_m - r_i) / d layers' worth. The capacity is
  // then continuous in r_i and in the liner radius: a worn liner (larger
  // r_m) or a lower shoulder (other r_i) no longer switches a whole layer of
  // about 1/9 of the bed's depth in or out (docs/models/layer-worn.md).
  n_open_ = 0;
  for (int j = 0; j < nl; ++j) {
    if (!(L_[j].omega > 0)) break;
    if (variant_ == 12 && L_[j].r - 0.5 * d_ < r_i_) {
      const double f = (L_[j].r + 0.5 * d_ - r_i_) / d_;
      const int S = static_cast<int>(std::lround(f * L_[j].S));
      if (f > 0 && S >= 1) {
        partial_layer_ = j;
        partial_S_full_ = L_[j].S;
        L_[j].S = S;
        n_open_ = j + 1;
      }
      break;
    }
    n_open_ = j + 1;
  }
  // The charge must fit into the open layers; open more (slowest first) if not.
  N_ = static_cast<int>(std::lround(J_ * metrics_.free_area_m2 / (d_ * d_)));
  if (N_ < 1) throw InputError("charge.filling", fmt::format("filling = {} gives no element of {} m in this mill", J_, d_));
  auto capacity = [&] {
    long long c = 0;
    for (int j = 0; j < n_open_; ++j) c += L_[j].S;
    return c;
  };
  if (capacity() < N_ && partial_layer_ >= 0) {  // a partial layer is not enough: open it whole first
    L_[partial_layer_].S = partial_S_full_;
    partial_layer_ = -1;
  }
  while (capacity() < N_ && n_open_ < nl) {
    if (L_[n_open_].omega <= 0) L_[n_open_].omega = std::max(1e-3 * omega_, L_[n_open_ - 1].omega * 0.5);
    ++n_open_;
    notes_.push_back("the charge does not fit outside the inner radius; a slower layer was opened");
  }
  if (capacity() < N_) throw SimulationError("layer model: the charge does not fit inside the mill");
  layout_slots(true);  // the partial layer has fewer cells
  m_ = rho_c_ * J_ * metrics_.free_area_m2 / N_;
  if (centrifuged) notes_.push_back(fmt::format("the mill runs at {:.3f} of critical, beyond Morrell's phi_c = {:.3f}: the charge centrifuges", phi_, phi_c));
  sin_fa_.resize(nl);
  for (int j = 0; j < nl; ++j) {
    const double fa = flight_angle(j);
    sin_fa_[j] = std::isfinite(fa) ? std::sin(fa) : kInf;
  }
  // Per segment (docs/models/layer.md §3, "Per segment"; layer-worn.md, "Hi-lo liners"):
  // over the segment of a lifter that holds layer j the foot-stability rules
  // take that lifter's release, not the smallest over the ring. On a ring
  // whose lifters are alike the two are the same; on a worn hi-lo ring the
  // low lifters' early release (a worn face) let the relaxation roll the high
  // lifters' pockets down 31 deg before their release (the bundled mill with
  // 0.125 m low lifters at 4,244 h: 2,367 kW, toe 202 deg, 0.4 % of the
  // charge airborne).
  const size_t S = seg_.size();
  sin_fa_seg_.assign(static_cast<size_t>(nl) * S, kInf);
  fa_by_segment_.assign(static_cast<size_t>(nl), 0);
  for (int j = 0; j < nl; ++j)
    for (size_t k = 0; k < S; ++k) {
      double fa = rel_seg_[static_cast<size_t>(j) * S + k];
      if (j < n_held_layers_) {
        const HeldLaunch& h = held_[static_cast<size_t>(j)][k];
        if (h.held && h.released) fa = std::min(fa, h.release);
      }
      const double sf = std::isfinite(fa) ? std::sin(fa) : kInf;
      sin_fa_seg_[static_cast<size_t>(j) * S + k] = sf;
      if (std::isfinite(sf) != std::isfinite(sin_fa_[j]) || sf - sin_fa_[j] > kAlikeRad)
        fa_by_segment_[static_cast<size_t>(j)] = 1;
    }
  tan_g_ = std::tan(gamma_);
}

void LayerSim::note_unchecked_lifters() {
  // Two liners on which the layer model is far from the 2D DEM (a review,
  // 2026-12-06; docs/models/layer.md, "Lifters the layer model is not checked
  // on"): it holds and launches its outer layer from a lifter however low it
  // is and however far apart the rows are, where the DEM's charge slides over
  // a low lifter and slips between distant rows. Said where it acts.
  double h_min = kInf;
  int rows = 0, lifters = 0;
  for (const auto& sm : seg_) {
    lifters += sm.has_lifter ? 1 : 0;
    if (sm.has_lifter && std::isfinite(sm.face_angle_leading_deg)) h_min = std::min(h_min, sm.lifter_height_m), ++rows;
  }
  if (lifters == 0)
    notes_.push_back(
        "the liner has no lifters: the layer model lifts its charge by friction alone, and while its power there is "
        "near the 2D DEM's its shoulder is not: on the bundled Qiu mill as a plain plate 4,672 kW and 46.8 deg where "
        "the DEM gives 4,897 kW and 1.9 deg (docs/models/layer.md, \"Lifters the layer model is not checked on\"); "
        "read the shoulder and the impacts from the DEM ([model] charge = \"dem\")");
  if (rows == 0) return;
  if (h_min < kLowLifterDiameters * d_ball_)
    notes_.push_back(fmt::format(
        "the lowest lifter is {:.0f} mm, less than half a media diameter ({:.0f} mm): the layer model holds its outer "
        "layer on it as on a full lifter, and its power there is not checked: on the bundled Qiu mill with 20 mm "
        "lifters its net power is 10,297 kW where the 2D DEM's is 6,013 kW (docs/models/layer.md, \"Lifters the layer "
        "model is not checked on\")",
        1000 * h_min, 1000 * d_ball_));
  const double spacing = 2 * kPi * R_eff_ / rows / d_ball_;
  if (spacing > kWideRowsDiameters)
    notes_.push_back(fmt::format(
        "the {} lifter rows are {:.0f} media diameters apart: the layer model lifts its outer layer from every row as "
        "from close rows, and its power and shoulder there are not checked: on the bundled Qiu mill with 8 rows (30 "
        "diameters apart) its net power is 14 % above the 2D DEM's and its shoulder 46 deg higher "
        "(docs/models/layer.md, \"Lifters the layer model is not checked on\")",
        rows, spacing));
}

void LayerSim::setup_flight_angles() {
  const int nl = static_cast<int>(L_.size());
  const int S = static_cast<int>(seg_.size());
  // Layers held by the lifter of a segment: the balls stacked in a pocket
  // that still touch the lifter face, j < h / d (docs/models/layer.md).
  std::vector<int> n_held(S, 0);
  n_held_layers_ = 0;
  for (int k = 0; k < S; ++k) {
    const auto& sm = seg_[k];
    if (sm.has_lifter && std::isfinite(sm.face_angle_leading_deg))
      n_held[k] = lifter_held_layers(sm.lifter_height_m, d_);
    n_held_layers_ = std::max(n_held_layers_, std::min(n_held[k], nl));
  }
  held_.assign(n_held_layers_, std::vector<HeldLaunch>(S));
  // The lifter that pushes what rides over segment k: its own, or on a
  // segment without one (the zero-height low lifters of a hi-lo ring, or low
  // lifters worn flat) the first lifter behind it, against the rotation (k -
  // 1, as caught_behind() and pocket_lifter() take it); -1 on a ring without
  // lifters. The plate ahead of a lifter is its pocket's floor whatever the
  // segments: until 2026-12-07 a ball over a lifterless segment left at the
  // unheld angle with its layer's speed, and a hi-lo ring with 0 m low
  // lifters, the same surface as the uniform ring of half as many lifters,
  // threw its outer layer from 57 deg onto the bare liner (12.8 m/s): a
  // forecast life of 294 h against 3,026 h (the input sweep of 2026-12-07).
  // (pocket_lifter() reads it too.)
  holder_.assign(static_cast<size_t>(S), -1);
  for (int k = 0; k < S; ++k)
    for (int b = 0; b < S; ++b) {
      const int kb = ((k - b) % S + S) % S;
      if (n_held[static_cast<size_t>(kb)] > 0) {
        holder_[static_cast<size_t>(k)] = kb;
        break;
      }
    }
  const double R = canon_.surface.shell_radius_m;
  // Version 1.1: a line at the angle of repose through the flight point of
  // the layer at r_i (thesis §4.6.1, Fig. 4-25) bounds the flight angles.
  // Unheld layers: McIvor with beta = 0 (thesis eq. 4.5 applied to every
  // layer, §4.4.6): an element rests on the one behind it in its layer, a
  // radial "face", with the friction coefficient mu (the release study's
  // ModelSpec::unheld_friction_coefficient where it is set).
  auto davis = [&](int j) { return mcivor_flight_angle(L_[j].omega * L_[j].omega * L_[j].r / kGravity, 0.0, mu_unheld_); };
  double clip_bx = 0, clip_by = 0;
  bool clip = false;
  if (variant_ == 11) {
    // the layer nearest r_i
    int jb = 0;
    for (int j = 0; j < nl; ++j)
      if (std::abs(L_[j].r - r_i_) < std::abs(L_[jb].r - r_i_)) jb = j;
    const double th = davis(jb);
    if (std::isfinite(th) && L_[jb].omega > 0) {
      clip = true;
      clip_bx = L_[jb].r * std::cos(th);
      clip_by = L_[jb].r * std::sin(th);
    }
  }
  auto clip_angle = [&](double r) {
    if (!clip) return kInf;
    // B + s u, u = (cos gamma, sin gamma), meets the circle of radius r
    const double bu = clip_bx * std::cos(gamma_) + clip_by * std::sin(gamma_);
    const double b2 = clip_bx * clip_bx + clip_by * clip_by;
    if (r * r <= b2) return kInf;  // inside B: not clipped
    const double s = -bu + std::sqrt(bu * bu - b2 + r * r);
    return std::atan2(clip_by + s * std::sin(gamma_), clip_bx + s * std::cos(gamma_));
  };
  // Support rule (docs/models/layer.md §3, "Layers not held"): a layer never
  // leaves later than the layer it rests on. prev_min: the smallest flight
  // angle of the layer outside, its lifters' releases included (what a layer
  // in a lifter's pocket rests on); prev_bed: the same chain without the
  // lifters' releases (what a bed layer above the lifters rests on).
  //
  // Per segment (since 2026-12-06): a ball of a held layer rides over one
  // segment with the lifters and rests on the layer outside it over that
  // segment, so prev_min is kept per segment (prev_seg[k]); the layer's own
  // flight angle over segment k is rel_seg_[j S + k]. On a ring whose
  // lifters are alike every segment has the same chain and the same angles
  // as the one chain before; on a hi-lo ring the low lifters' releases no
  // longer set the flight angle of the layers over the high lifters (on the
  // bundled mill with 0.125 m low lifters worn for 4,244 h they let layer 1
  // go 30 deg before its high lifter did).
  double prev_bed = kInf;
  std::vector<double> prev_seg(static_cast<size_t>(S), kInf);
  rel_seg_.assign(static_cast<size_t>(nl) * static_cast<size_t>(S), kInf);
  for (int j = 0; j < nl; ++j) {
    Layer& l = L_[j];
    l.held = false;
    l.rel_min = kInf;
    l.rel_max = -kInf;
    const double cl = clip_angle(l.r);
    if (j < n_held_layers_) {
      for (int k = 0; k < S; ++k) {
        HeldLaunch& h = held_[j][k];
        h = HeldLaunch{};
        const int kh = holder_[static_cast<size_t>(k)];
        if (kh < 0 || j >= n_held[static_cast<size_t>(kh)] || !(l.omega > 0)) continue;
        const auto& sm = seg_[kh];
        h.held = true;
        l.held = true;
        const double r_plate = R - sm.plate_ref_thickness_m, r_crest = R - sm.max_thickness_m;
        const double r0 = r_plate - (j + 0.5) * d_;  // ball centre stacked in the pocket
        // a ball whose centre is above the crest bears on the crest corner:
        // the face it feels is inclined by asin((centre height - h) / a)
        const double above = (j + 0.5) * d_ - sm.lifter_height_m;
        const double alpha = std::max(sm.face_angle_leading_deg * kPi / 180.0,
                                      std::asin(std::clamp(above / a_, 0.0, 1.0)));
        // Support (docs/models/layer-worn.md): a ball of layer j >= 1 rests on
        // the layer outside it as well as on the lifter (its face or, above
        // the crest, the crest corner). It leaves when both have let go: no
        // earlier than it would as an unheld layer, min(own angle, flight
        // angle of the layer outside), the rule below for unheld layers. As
        // the lifter wears towards j d the crest corner's "face" steepens to
        // 90 deg and McIvor's angle (eq. 4.5) drops below the horizontal;
        // without this floor that released layer j - and, through the
        // support rule, every layer inside it - far below the outer layer,
        // and the layer jumped back to the unheld rule at h = j d.
        const double bed_hold = j >= 1 && l.omega > 0 ? std::min(davis(j), prev_seg[static_cast<size_t>(k)]) : -kInf;
        const LifterLaunch ll = lifter_launch(omega_, r0, r_crest, a_, alpha, mu_, in_.model.lifter_slide, cl, bed_hold);
        h.released = ll.released;
        if (!ll.released) continue;
        h.release = ll.release_rad;
        h.slide_s = ll.slide_time_s;
        h.dtheta = ll.launch_rad - ll.release_rad;
        h.radius = ll.launch_radius_m;
        h.vr = ll.v_radial_m_s;
        h.vt = ll.v_tangential_m_s;
        h.r0 = r0;
        l.rel_min = std::min(l.rel_min, h.release);
        l.rel_max = std::max(l.rel_max, h.release);
      }
      // a pocket its lifter cannot throw goes with the one behind (a hi-lo ring)
      if (!in_.model.lifter_slide) caught_behind(j);
    }
    // Unheld layers (and segments without a lifter at this layer): the layer
    // leaves where an element on the radial "face" of the one behind it can
    // no longer stay, McIvor's eq. 4.5 with beta = 0 and the friction
    // coefficient mu (with mu = 0 it is Davis' angle, where the normal force
    // vanishes), but never beyond the flight point of the layer it rests on.
    // A layer no lifter holds rests on the bed outside it, not on the balls a
    // lifter's pocket throws: the lifters' releases are not passed on to it
    // (prev_bed). Passing them on (prev_min, until 2026-12-06) let a worn
    // lifter's early release, McIvor's angle on a 40-55 deg face, become the
    // flight angle of the whole bed: the toe climbed 215 -> 242 deg and the
    // power +57 % over the Qiu mill's life, where the DEM's charge hardly
    // moves on the same profiles (+3 %; docs/models/layer-worn.md).
    const double own = std::min(l.omega > 0 ? davis(j) : kInf, cl);
    l.release = kInf;
    l.release_max = -kInf;
    for (int k = 0; k < S; ++k) {
      const size_t q = static_cast<size_t>(j) * static_cast<size_t>(S) + static_cast<size_t>(k);
      const bool held_here = j < n_held_layers_ && held_[static_cast<size_t>(j)][static_cast<size_t>(k)].held;
      const double th = std::min(own, held_here ? prev_seg[static_cast<size_t>(k)] : prev_bed);
      rel_seg_[q] = th;
      l.release = std::min(l.release, th);
      if (std::isfinite(th)) l.release_max = std::max(l.release_max, th);
    }
    for (int k = 0; k < S; ++k) {
      const size_t q = static_cast<size_t>(j) * static_cast<size_t>(S) + static_cast<size_t>(k);
      double p = rel_seg_[q];
      if (j < n_held_layers_) {
        const HeldLaunch& h = held_[static_cast<size_t>(j)][static_cast<size_t>(k)];
        if (h.held && h.released) p = std::min(p, h.release);
      }
      prev_seg[static_cast<size_t>(k)] = p;
    }
    // Segments alike to rounding (a ring of identical lifters: their releases
    // differ by about 5e-12 rad, the rotations of one profile) share one
    // chain, the smallest, as before the chain was kept per segment; so such
    // a ring runs bit for bit as it did.
    {
      const auto [lo, hi] = std::minmax_element(prev_seg.begin(), prev_seg.end());
      if (std::isfinite(*lo) && std::isfinite(*hi) && *hi - *lo <= kAlikeRad) std::fill(prev_seg.begin(), prev_seg.end(), *lo);
    }
    prev_bed = std::min(own, prev_bed);
  }
}

void LayerSim::caught_behind(int j) {
  // Caught behind (docs/models/layer-worn.md, "Caught behind"; layer.md §3).
  // Without the slide a released ball flies from its place in the pocket,
  // radius r0, with the lifter's speed omega r0. Below Davis' angle, where
  // gravity's inward part g sin(theta) is less than the centripetal
  // omega^2 r0 (thesis eq. 4.5 with mu = 0 and beta = 0), that parabola
  // curves less than the circle: it runs straight back into what carries
  // the ball, which still presses on it. Such a ball is not thrown; its
  // lifter no longer holds it, and it stays in the bed on the shell, pushed
  // along by the balls behind it down to the face of the lifter behind
  // (k - 1, against the rotation, as in pocket_lifter()). Where that lifter
  // lets layer j go later, the ball goes with its pocket and leaves at its
  // release. On a ring of alike lifters the lifter behind lets go where this
  // one does (to kAlikeRad), so nothing changes there; on a hi-lo ring the
  // worn low lifters' pockets go with the high lifters' (the high ones',
  // worn first in a blend, with the low ones'). Before (the bundled mill's
  // hi-lo forecast, 2026-12-06): a low lifter worn to 0.084 m let its
  // pocket go at McIvor's -0.26 deg; its balls hit the liner at once and
  // were put on the bed there or walked to the toe, and the power rose
  // +24 % over mid-life, then fell 7,645 -> 5,321 kW in 100 h of wear.
  const int S = static_cast<int>(seg_.size());
  auto& row = held_[static_cast<size_t>(j)];
  auto thrown = [&](int k, double release) {
    const double s_clear = omega_ * omega_ * row[k].r0 / kGravity;
    return !(s_clear < 1.0) || std::sin(release) >= s_clear;
  };
  std::vector<double> release(static_cast<size_t>(S), kInf);
  for (int k = 0; k < S; ++k)
    if (row[k].held && row[k].released) release[k] = row[k].release;
  bool changed = false;
  for (int k = 0; k < S; ++k) {
    HeldLaunch& h = row[k];
    if (!(h.held && h.released) || thrown(k, h.release)) continue;
    const int kb = (k + S - 1) % S;
    const double rb = release[kb];
    if (!std::isfinite(rb) || !(rb > h.release + kAlikeRad)) continue;
    h.release = rb;
    changed = true;
  }
  if (!changed) return;
  Layer& l = L_[j];
  l.rel_min = kInf;
  l.rel_max = -kInf;
  for (int k = 0; k < S; ++k)
    if (row[k].held && row[k].released) {
      l.rel_min = std::min(l.rel_min, row[k].release);
      l.rel_max = std::max(l.rel_max, row[k].release);
    }
}

void LayerSim::setup_initial_fill() {
  // The charge at rest: the N lowest cells of the open layers (ties by angle).
  struct Cell {
    double y, th;
    int j, s;
  };
  std::vector<Cell> cells;
  for (int j = 0; j < n_open_; ++j)
    for (int s = 0; s < L_[j].S; ++s) {
      const double th = L_[j].phase + s * L_[j].delta;
      cells.push_back({L_[j].r * std::sin(th), th, j, s});
    }
  std::sort(cells.begin(), cells.end(), [](const Cell& x, const Cell& y) {
    if (x.y != y.y) return x.y < y.y;
    if (x.th != y.th) return x.th < y.th;
    return x.j < y.j;
  });
  // Element ids are labels: a seeded shuffle makes sure nothing depends on them.
  std::vector<int> ids(N_);
  std::iota(ids.begin(), ids.end(), 0);
  std::mt19937_64 rng(in_.seed);
  std::shuffle(ids.begin(), ids.end(), rng);
  elem_layer_.assign(N_, -1);
  elem_slot_.assign(N_, -1);
  elem_y_entry_.assign(N_, 0.0);
  elem_t_slot_.assign(N_, 0.0);
  elem_sin_slot_.assign(N_, 0.0);
  for (int i = 0; i < N_; ++i) {
    const Cell& c = cells[i];
    enter_slot(ids[i], c.j, c.s, 0.0);
    elem_y_entry_[ids[i]] = c.y;
    deepest_ = std::max(deepest_, c.j);
  }
}

void LayerSim::enter_slot(int id, int j, int s, double tau) {
  occ(j, s) = id;
  note_cell(j, s, tau, true);
  elem_layer_[id] = j;
  elem_slot_[id] = s;
  elem_t_slot_[id] = tau;
  if (tau >= t_avg0_ && tau <= t_end_) {  // for the torque arm (leave_slot()), from the layer's cached direction
    double c, sn;
    slot_dir(j, s, tau, c, sn);
    elem_sin_slot_[id] = sn;
  }
}

void LayerSim::leave_slot(int id, int j, int s, double tau) {
  occ(j, s) = -1;
  note_cell(j, s, tau, false);
  elem_layer_[id] = -1;
  elem_slot_[id] = -1;
  const double ta = std::max(elem_t_slot_[id], t_avg0_), tb = std::min(tau, t_end_);
  if (!(tb > ta) || !occupancy_) return;
  const Layer& l = L_[j];
  layer_count_acc_[j] += tb - ta;
  const double a0 = phase0_[j] + l.omega * ta + s * l.delta, a1 = phase0_[j] + l.omega * tb + s * l.delta;
  const double spr = 1.0 / l.omega;
  occupancy_->add_arc(j, a0, a1, spr, d_ * d_, m_);  // canonical frame
  // its torque arm over the time it sat here (the power, eq. 4.3): the
  // integral of x = r cos(a0 + omega t) dt, exactly. The sines at the ends
  // from the layer's cached direction (slot_dir(): the same angles to
  // rounding) where the stay lies inside the averaging window, which is
  // nearly always (the libm calls cost 1.9 % of a run's instructions).
  double sin0, sin1;
  if (elem_t_slot_[id] >= t_avg0_) sin0 = elem_sin_slot_[id];
  else sin0 = std::sin(a0);
  if (tau <= t_end_) {
    double c;
    slot_dir(j, s, tau, c, sin1);
  } else {
    sin1 = std::sin(a1);
  }
  arm_time_ += m_ * l.r * (sin1 - sin0) * spr;
}

// ============================================================================
// Flights
// ============================================================================

V LayerSim::flight_position(const Flight& f, double tau) const {
  if (tau <= f.t0) {  // still sliding along the lifter face: between release and launch
    const double span = f.t0 - f.t_rel;
    const double x = span > 0 ? std::clamp((tau - f.t_rel) / span, 0.0, 1.0) : 1.0;
    return f.p_rel + x * (f.p0 - f.p_rel);
  }
  const double t = tau - f.t0;
  return V(f.p0.x() + f.v0.x() * t, f.p0.y() + f.v0.y() * t - 0.5 * kGravity * t * t);
}

V LayerSim::flight_velocity(const Flight& f, double tau) const {
  const double t = std::max(0.0, tau - f.t0);
  return V(f.v0.x(), f.v0.y() - kGravity * t);
}

void LayerSim::launch(int j, int s, double tau, int seg, bool relaunch) {
  const int id = occ(j, s);
  leave_slot(id, j, s, tau);
  Flight f;
  f.id = id;
  f.from_layer = j;
  f.t_rel = tau;
  const double th = slot_angle(j, s, tau);
  // the element leaves from where it is drawn: on the liner profile for the
  // outer layer (never inside a lifter), else at its layer's radius
  const double r_at = drawn_radius(j, th, tau);
  f.p_rel = r_at * V(std::cos(th), std::sin(th));
  if (seg >= 0 && held_[j][seg].slide_s > 0) {
    const HeldLaunch& h = held_[j][seg];
    const double tl = th + h.dtheta;
    const V er(std::cos(tl), std::sin(tl)), et(-std::sin(tl), std::cos(tl));
    f.t0 = tau + h.slide_s;
    f.p0 = h.radius * er;
    f.v0 = h.vr * er + h.vt * et;
  } else {
    // a held element leaves with its lifter's velocity, an unheld one with its layer's
    const double w = seg >= 0 ? omega_ : L_[j].omega;
    const V er(std::cos(th), std::sin(th)), et(-std::sin(th), std::cos(th));
    f.t0 = tau;
    f.p0 = r_at * er;
    f.v0 = w * r_at * et;
  }
  f.t_check = f.t0;
  f.t_next = f.t0;
  f.p_next = flight_position(f, f.t_next);
  f.r_next = f.p_next.norm();
  // a relaunch from the charge surface: clear one diameter before the charge counts again
  f.grace = relaunch ? f.t0 + d_ / std::max(f.v0.norm(), 0.1 * omega_ * r_at) : f.t0;
  // Work done by the mill since the element entered the charge at rest
  // (Morrell's energy reading of the C-model, reference §1): lift + kinetic.
  if (!relaunch && averaging_ && f.t0 >= t_avg0_ && f.t0 < t_end_)
    energy_ += m_ * (kGravity * (f.p0.y() - elem_y_entry_[id]) + 0.5 * f.v0.squaredNorm());
  ++n_flights_;
  if (flight_pos_.empty()) flight_pos_.assign(N_, -1);
  flight_pos_[id] = static_cast<int>(flights_.size());
  flights_.push_back(f);
  // A departure's flight is checked from its launch on (check_flights()). A
  // relaunch from a landing waits for the next step, as before the event
  // queue: an element that lands past its layer's flight angle against a
  // lifter can be relaunched into the liner at once, and would otherwise
  // bounce without end at one instant (found by the forecast soak, run 11).
  const int i = static_cast<int>(flights_.size()) - 1;
  if (in_step_ && !relaunch) schedule_flight(i);
  else wait_flight(i, in_step_ ? step_k_ + 1 : step_k_);
}

int LayerSim::pocket_lifter(int j, int seg, double psi) const {
  // canonical (anticlockwise) frame: a lifter pushes what lies ahead of its
  // crest, at larger angles; behind the crest, or on a segment without a
  // lifter, the element is ahead of the nearest lifter behind it
  // (the nearest lifter at or behind segment seg - 1: holder_, setup_flight_angles())
  const int S = static_cast<int>(seg_.size());
  int k = seg;
  if (holder_[static_cast<size_t>(k)] != k || std::remainder(psi - seg_[k].crest_angle_rad, kTwoPi) < 0) {
    k = holder_[static_cast<size_t>((seg + S - 1) % S)];
    if (k < 0) return -1;  // no lifter on the ring
  }
  const SegmentMetrics& sm = seg_[k];
  const double off = wrap2pi(psi - sm.crest_angle_rad);
  // the foot of the leading face: half the top plus the face's run over its
  // height (taking the crest at the middle of the top; an undercut face's
  // foot is under the top, counted from the crest)
  const double top = std::isfinite(sm.top_width_m) ? 0.5 * sm.top_width_m : 0.0;
  const double foot = std::max(0.0, top + sm.lifter_height_m * std::tan(sm.face_angle_leading_deg * kPi / 180.0));
  return off * L_[j].r < foot + pocket_balls_ * d_ ? k : -1;
}

void LayerSim::departures(double t0, double t1) {
  dep_events_.clear();
  const double dt = t1 - t0;
  for (int j = 0; j < n_open_; ++j) {
    Layer& l = L_[j];
    if (!(l.omega > 0)) continue;
    const double wdt = l.omega * dt;
    if (l.held) {
      // per-segment flight angles: scan the window between the lowest and highest
      const double lo = std::min(l.rel_min, l.release), hi = std::max(l.rel_max, l.release_max);
      if (!std::isfinite(lo)) continue;
      const double u = wrap2pi(lo - l.phase);
      const int s_lo = static_cast<int>(ceil_exact((u - 2 * wdt) * l.inv_delta));
      const int s_hi = static_cast<int>(ceil_exact((u + (hi - lo)) * l.inv_delta));
      for (int s = s_lo; s <= s_hi; ++s) {
        int si = s % l.S;
        if (si < 0) si += l.S;
        if (occ(j, si) < 0) continue;
        const double a0 = slot_angle(j, si, t0);
        const double psi = a0 + wdt - mill_angle(t1);
        int seg = canon_.surface.segment_of_angle(psi);
        // the release study (docs/models/layer.md §3, "The release study"): only the elements in
        // a lifter's pocket leave at its angle, the rest of the layer as unheld
        if (pocket_balls_ >= 0) seg = pocket_lifter(j, seg, psi);
        const HeldLaunch& h = seg >= 0 ? held_[j][seg] : kUnheldLaunch;
        // over a segment whose lifter does not hold it the layer's own angle
        // there (rel_seg_); the release study's elements outside every
        // pocket (seg = -1) the layer's smallest, as before
        const double rel = h.held ? (h.released ? h.release : kInf)
                                  : seg >= 0 ? rel_seg(j, seg) : l.release;
        if (std::isfinite(rel)) {
          const double w = remainder_2pi(rel - a0);
          if (w > -wdt && w <= wdt) dep_events_.push_back({t0 + w / l.omega, j, si, h.held ? seg : -1});
        }
        // an element still over a lifter past the lifter's release came in after it
        // (fell or landed there): part of the bed, it leaves at the layer's own
        // angle there (docs/models/layer.md §3, "Per segment", rule 4 of
        // layer-worn.md "Hi-lo liners")
        if (seg >= 0) {
          const double rb = late_ball_angle(j, seg);
          if (std::isfinite(rb)) {
            const double w = remainder_2pi(rb - a0);
            if (w > -wdt && w <= wdt) dep_events_.push_back({t0 + w / l.omega, j, si, -1});
          }
        }
      }
    } else {
      if (!std::isfinite(l.release)) continue;
      // slots crossing the flight angle in this step, or in the previous one
      // after its scan (placed there by a landing): w in (-wdt, wdt]
      const double u = wrap2pi(l.release - l.phase);
      const int s_lo = static_cast<int>(ceil_exact((u - wdt) * l.inv_delta));
      const int s_hi = static_cast<int>(ceil_exact((u + wdt) * l.inv_delta)) - 1;
      for (int s = s_lo; s <= s_hi; ++s) {
        int si = s % l.S;
        if (si < 0) si += l.S;
        if (occ(j, si) < 0) continue;
        const double w = u - s * l.delta;
        dep_events_.push_back({t0 + w / l.omega, j, si, -1});
      }
    }
  }
}

void LayerSim::drag_advance(Flight& f, double h) const {
  // the pool's drag (slurry_drag.h), velocity implicit, position trapezoidal
  SlurryDrag sd;
  sd.fluid_density_kg_m3 = rho_pulp_;
  sd.particle_density_kg_m3 = rho_solid_;
  sd.diameter_m = d_ball_;  // the drag acts on each ball of the element
  const V v_new = slurry_drag_step(sd, f.v0, h);
  f.p0 += 0.5 * h * (f.v0 + v_new);
  f.v0 = v_new;
  f.t0 += h;
}

bool LayerSim::liner_crossing(const V& pa, const V& va, const V& acc, double tau, double tb, double& t_hit,
                              int& bin) const {
  // Seen from the liner, which turns, the path over this short interval is
  // the parabola of its relative position, velocity and acceleration at tau
  // (centrifugal and Coriolis terms; error O(h^3)); its first crossing
  // through the ride polyline is a quadratic root per segment
  // (docs/models/layer.md §Impacts).
  const V u = va - omega_ * V(-pa.y(), pa.x());                                  // relative velocity
  const V arel = acc - 2.0 * omega_ * V(-u.y(), u.x()) + omega_ * omega_ * pa;   // relative acceleration
  const double rot = mill_angle(tau);
  // Quick reject before the rotation (a sincos) and the search: the
  // parabola over (tau, tb] stays within max(|p(0)|, |p(h)|) + |arel| h^2 / 8
  // of the axis (its chord, plus the largest gap to it); the ride polyline
  // between edges b and b + 1 stays beyond ride_radius_m[b] cos(h_bin / 2)
  // (the chord of the smaller edge). Where the first lies inside the second
  // over every bin the search can visit (its range from the same angles,
  // each within 2e-5 rad of the search's fast_atan2 of the rotated points,
  // widened by two bins each side), no root the search accepts exists: an
  // accepted root lies on its segment to about 1e-14 R (the quadratic's
  // residual), far within the 1e-7 of ride_reject_. So the result is the same;
  // and where the search runs, it skips the bins beyond the bound (reach).
  double reach = kInf;
  if (ride_reject_ > 0) {
    const double h = tb - tau;
    const V ph(pa.x() + u.x() * h + 0.5 * arel.x() * h * h, pa.y() + u.y() * h + 0.5 * arel.y() * h * h);
    const double rr = std::sqrt(std::max(pa.squaredNorm(), ph.squaredNorm())) +
                      0.125 * (std::abs(arel.x()) + std::abs(arel.y())) * h * h;
    const double lim = rr / ride_reject_;  // a bin whose ride radius exceeds it is not reached
    if (lim < ride_.min_ride_m) return false;
    reach = lim;  // the search skips the bins beyond it (whatever the range)
    const double psa = fast_atan2(pa.y(), pa.x()) - rot, psb = fast_atan2(ph.y(), ph.x()) - rot;
    const double d = remainder_2pi(psb - psa);
    if (std::abs(d) < 0.5) {
      const int mask = ride_.n_bins - 1;
      const int first = floor_int((d >= 0 ? psa : psa + d) * ride_.inv_bin) - 3;
      const int count = ceil_int(std::abs(d) * ride_.inv_bin) + 9;
      int k = 0;
      while (k < count && ride_.ride_radius_m[(first + k) & mask] > lim) ++k;
      if (k == count) return false;
    }
  }
  const double c = std::cos(rot), sn = std::sin(rot);
  auto to_liner = [&](const V& x) { return V(c * x.x() + sn * x.y(), -sn * x.x() + c * x.y()); };
  double th;
  if (!first_ride_crossing(ride_, 0.0, to_liner(pa), to_liner(u), to_liner(arel), 0.0, tb - tau, th, bin, reach)) return false;
  t_hit = tau + th;
  return true;
}

// Inlined (always_inline) into its callers: out of line it was called 1.7 M
// times on the bench's "media size -25%" case (relax_candidates(), place()),
// about 52 instructions a call of which the call was a good part.
__attribute__((always_inline)) inline bool LayerSim::inside_charge(const V& q, double r, double theta, double tq) const {
  if (r < r_open_min_) return false;
  int k = static_cast<int>((R_eff_ - r) * inv_d_);
  if (r > R_eff_) k = 0;
  if (k >= n_open_) return false;
  return occ(k, slot_of(k, theta, tq)) >= 0;
}

// Inlined into its one caller, check_flights(): a call checks about one
// interval (78,843 calls, some 81k intervals for media size -25 %), so the
// call's own cost (frame, the Landing handed back) was a good part of it.
__attribute__((always_inline)) inline bool LayerSim::check_flight(Flight& f, double t1, Landing& out) {
  // Each interval of the path is checked once, as soon as the steps reach its
  // start (so the number of checks does not depend on the time step); a
  // landing found beyond the current step is kept until the steps reach it.
  if (f.landed) {
    if (f.landing.t > t1) return false;
    out = f.landing;
    return true;
  }
  if (t1 <= f.t_next || t1 <= f.t0) return false;
  if (drag_on_) return check_flight_drag(f, t1, out);
  const double r_ride_min = ride_.min_ride_m;
  const double sample_len = 0.5 * d_;
  const V acc(0, -kGravity);
  double tau = f.t_next;
  // where the last call left the path (launch() for the first): the same
  // values as flight_position(f, tau) and its norm
  V pa = f.p_next, va = flight_velocity(f, tau);
  double ra = f.r_next;
  while (tau < t1) {
    const double spv = std::sqrt(va.squaredNorm());
    // Clear of the liner and of the charge: jump by the time needed to cover
    // the distance to the nearer (no check needed).
    // The clearance to the liner and to the innermost open layer holds at
    // any time; the one from the column map only for skip_H_ after it.
    // (Near the liner the interval is a near one whatever the bed's clearance.)
    const double d_liner = r_ride_min - ra;
    const double d_bed = d_liner <= sample_len ? kInf
                         : ra < r_open_min_    ? r_open_min_ - ra
                                               : bed_clearance(ra, fast_atan2(pa.y(), pa.x()), tau);
    const double dist = std::min(d_liner, d_bed);
    if (dist > sample_len) {
      const double sp = std::max(spv, 1e-3);
      const double cap = (ra < r_open_min_ || d_liner <= d_bed) ? kInf : skip_H_;
      tau += std::min(cap, (-sp + std::sqrt(sp * sp + 2 * kGravity * dist)) / kGravity);
      f.t_next = tau;
      f.p_next = pa = flight_position(f, tau);
      f.r_next = ra = pa.norm();
      if (tau >= t1) return false;
      va = flight_velocity(f, tau);
      continue;
    }
    // near something: check an interval of half a diameter, relative to the
    // turning liner too
    const double vx = va.x() + omega_ * pa.y(), vy = va.y() - omega_ * pa.x();
    const double vrel = std::sqrt(vx * vx + vy * vy);
    const double tb = tau + sample_len / std::max({spv, vrel, 1e-3});
    const V pb = flight_position(f, tb);
    const double rb = pb.norm();
    double t_hit = kInf;
    int bin = -1;
    if (rb >= r_ride_min || ra >= r_ride_min) liner_crossing(pa, va, acc, tau, tb, t_hit, bin);
    if (tb > f.grace && inside_charge(pb, rb, tb)) {  // ends in an occupied cell: bisect for the entry
      double lo = std::max(tau, f.grace), hi = tb;
      for (int it = 0; it < 6; ++it) {
        const double mid = 0.5 * (lo + hi);
        const V q = flight_position(f, mid);
        if (inside_charge(q, q.norm(), mid)) hi = mid;
        else lo = mid;
      }
      if (lo < t_hit) t_hit = lo, bin = -1;
    }
    if (t_hit < kInf) {
      Landing& l = f.landing;
      l.t = t_hit;
      l.bin = bin;
      l.p = flight_position(f, t_hit);
      l.v = flight_velocity(f, t_hit);
      f.landed = true;
      if (t_hit > t1) return false;
      out = l;
      return true;
    }
    tau = tb;
    f.t_next = tau;
    f.p_next = pa = pb;
    va = flight_velocity(f, tb);
    f.r_next = ra = rb;
    if (tau - f.t_rel > 60.0 * kTwoPi / omega_)
      throw SimulationError(fmt::format("layer model: element {} has been in flight for {:.1f} s without landing", f.id, tau - f.t_rel));
  }
  return false;
}

bool LayerSim::check_flight_drag(Flight& f, double t1, Landing& out) {
  // As check_flight, but below the slurry level the state is integrated with
  // the drag of the pool (1 ms steps, the thesis' integration step), and over
  // each step the path is the parabola of its mean acceleration.
  if (t1 <= f.t_check) return false;
  double tau = std::max(f.t_check, f.t0);
  const double r_ride_min = ride_.min_ride_m;
  const double sample_len = 0.5 * d_;
  while (tau < t1) {
    if (!f.drag) {
      const V p = flight_position(f, tau);
      if (p.y() < y_pool_) {  // entering the slurry pool: from here on the state is integrated
        f.v0 = flight_velocity(f, tau);
        f.p0 = p;
        f.t0 = tau;
        f.drag = true;
      }
    }
    const V pa = f.drag ? f.p0 : flight_position(f, tau);
    const V va = f.drag ? f.v0 : flight_velocity(f, tau);
    const double ra = pa.norm();
    const double sp = std::max({va.norm(), (va - omega_ * V(-pa.y(), pa.x())).norm(), 1e-3});
    double h = sample_len / sp;
    if (f.drag) h = std::min(h, 1e-3);
    const double tb = std::min(t1, tau + h);
    V acc(0, -kGravity);
    Flight next = f;
    if (f.drag) {
      drag_advance(next, tb - tau);
      acc = (next.v0 - f.v0) / (tb - tau);
    }
    const V pb = pa + va * (tb - tau) + 0.5 * acc * (tb - tau) * (tb - tau);
    const double rb = pb.norm();
    double t_hit = kInf;
    int bin = -1;
    if (rb >= r_ride_min || ra >= r_ride_min) liner_crossing(pa, va, acc, tau, tb, t_hit, bin);
    if (inside_charge(pb, rb, tb)) {
      double lo = tau, hi = tb;
      for (int it = 0; it < 6; ++it) {
        const double mid = 0.5 * (lo + hi), tm = mid - tau;
        const V q = pa + va * tm + 0.5 * acc * tm * tm;
        if (inside_charge(q, q.norm(), mid)) hi = mid;
        else lo = mid;
      }
      if (lo < t_hit) t_hit = lo, bin = -1;
    }
    if (t_hit < kInf) {
      const double tm = t_hit - tau;
      out.t = t_hit;
      out.bin = bin;
      out.p = pa + va * tm + 0.5 * acc * tm * tm;
      out.v = va + acc * tm;
      return true;
    }
    if (f.drag) f = next;
    tau = tb;
    f.t_check = tau;
    if (tau - f.t_rel > 60.0 * kTwoPi / omega_)
      throw SimulationError(fmt::format("layer model: element {} has been in flight for {:.1f} s without landing", f.id, tau - f.t_rel));
  }
  return false;
}

void LayerSim::check_flights(double t1) {
  // The events of the step in the order they happen (docs/models/layer.md
  // §4): departures, landings, and the checks of the flights' path
  // intervals. An interval is checked against the charge as it is when the
  // flight gets there, after every departure and landing before it; a
  // flight launched in the step is checked from its launch on. (Checking
  // every flight at the start of the step against the charge of that moment,
  // and a new flight only from the next step, made the results depend on the
  // step: Qiu mill +3.7 % power at 10 ms against 1 ms, docs/models/layer.md
  // §9.)
  std::sort(dep_events_.begin(), dep_events_.end(), [](const DepartureEvent& x, const DepartureEvent& y) {
    if (x.t != y.t) return x.t < y.t;
    if (x.j != y.j) return x.j < y.j;
    return x.s < y.s;
  });
  if (t1 != static_cast<double>(step_k_ + 1) * dt_)  // wait_flight() computes the steps' ends so
    throw SimulationError("layer model: the steps and the flights' wake steps disagree");
  events_.clear();
  step_t1_ = t1;
  for (int i = 0; i < static_cast<int>(dep_events_.size()); ++i) events_.push_back({dep_events_[i].t, kDepart, i});
  // the flights with something to do in this step: those filed under it
  // (the flights further ahead move into the ring as it comes round to them)
  wake_due_.swap(wake_ring_[step_k_ & (kWakeRing - 1)]);
  if (!wake_far_.empty() && (step_k_ & (kWakeRing - 1)) == 0) {
    size_t n = 0;
    for (const auto& w : wake_far_) {
      if (w.first - step_k_ >= kWakeRing) wake_far_[n++] = w;
      else if (w.first == step_k_) wake_due_.push_back(w.second);
      else wake_ring_[w.first & (kWakeRing - 1)].push_back(w.second);
    }
    wake_far_.resize(n);
  }
  for (const int id : wake_due_) {
    const int i = flight_pos_[id];
    const Flight& f = flights_[i];
    events_.push_back(f.landed ? StepEvent{f.landing.t, kLand, i} : StepEvent{next_check(f), kCheck, i});
  }
  wake_due_.clear();
  std::sort(events_.begin(), events_.end(), event_after);
  in_step_ = true;
  gone_.clear();
  while (!events_.empty()) {
    const StepEvent ev = events_.back();
    events_.pop_back();
    if (ev.kind() == kDepart) {
      const DepartureEvent& e = dep_events_[ev.index()];
      const int id = occ(e.j, e.s);
      if (id < 0) continue;
      // An element placed over a lifter after its slot crossed the lifter's
      // release is part of the bed there, not of the pocket (the rule of
      // check_departure()): it leaves at the layer's own angle over the
      // segment, departures()' second event, where that is later.
      if (e.seg >= 0 && elem_t_slot_[id] > e.t && std::isfinite(late_ball_angle(e.j, e.seg))) continue;
      // an element placed there after the slot crossed leaves when it came
      launch(e.j, e.s, std::max(e.t, elem_t_slot_[id]), e.seg);  // schedules its flight
      continue;
    }
    const int i = ev.index();
    Flight& f = flights_[i];
    if (ev.kind() == kCheck) {
      // the path up to the next event (at least one interval), then the
      // flight waits for its next interval or its landing
      double t_lim = events_.empty() ? t1 : std::min(t1, events_.back().t());
      // at least one interval: check_flight() walks whole intervals, but
      // check_flight_drag() ends one at t_lim, so it gets one drag step (1 ms)
      t_lim = std::max(t_lim, drag_on_ ? next_check(f) + 1e-3 : next_up(next_check(f)));
      Landing l;
      if (check_flight(f, t_lim, l) && !f.landed) {  // check_flight_drag() reports its landing in `l` only
        f.landing = l;
        f.landed = true;
      }
      schedule_flight(i);
      continue;
    }
    // a landing
    const Landing& l = f.landing;
    const double th = std::atan2(l.p.y(), l.p.x());
    if (l.bin >= 0 && averaging_ && l.t >= t_avg0_) {
      // a direct impact on the liner (docs/models/layer.md §Impacts)
      const double rot = mill_angle(l.t);
      const double c = std::cos(rot), sn = std::sin(rot);
      // the element the landing disc touches (the nearest contact ray's; the
      // crossing's bin names its smaller-edge element)
      const int e = ride_.contact(std::atan2(l.p.y() * c - l.p.x() * sn, l.p.x() * c + l.p.y() * sn));
      const V nl = ride_.ride_normal[l.bin];  // the ride curve's normal where it is crossed (as in sample())
      const V n(c * nl.x() - sn * nl.y(), sn * nl.x() + c * nl.y());
      const V t(n.y(), -n.x());
      const V v_liner = omega_ * V(-l.p.y(), l.p.x());
      const V vrel = l.v - v_liner;
      const double vn = -vrel.dot(n);
      if (vn > 0) {
        ImpactEvent iev;
        iev.element = canon_.physical_element[e];
        iev.normal_speed_m_s = vn;
        iev.tangential_speed_m_s = std::abs(vrel.dot(t));
        iev.mass_kg = m_sphere_;
        iev.diameter_m = d_ball_;
        iev.rate_per_s = m_ / m_sphere_;  // spheres per element per metre; divided by the duration at the end
        iev.direct = true;
        impacts_.push_back(iev);
      }
    }
    if (averaging_ && l.t >= t_avg0_) {
      ++n_avg_landings_;
      const double tf = l.t - f.t0;
      if (tf >= 2.0 * std::sqrt(d_ball_ / kGravity)) {  // a trajectory (docs/models/indicators.md)
        ++traj_count_[f.from_layer];
        ++n_traj_flights_;
      }
    }
    gone_.push_back(i);
    const Landing land = l;  // deposit() may launch (and so move flights_)
    deposit(f.id, th, land.t, land.v);
  }
  in_step_ = false;
  ++step_k_;
  // remove the landed flights (highest index first, swapping in the last)
  if (gone_.empty()) return;
  std::sort(gone_.begin(), gone_.end(), std::greater<int>());
  for (const int i : gone_) {
    if (i != static_cast<int>(flights_.size()) - 1) {
      flights_[i] = flights_.back();
      flight_pos_[flights_[i].id] = i;
    }
    flights_.pop_back();
  }
}

// inline (as wait_flight()): called once per checked interval (about 80k
// times for media size -25 %), mostly from check_flights()
inline void LayerSim::schedule_flight(int i) {
  // the flight's next event in this step: its landing, or the check of its
  // next interval
  const Flight& f = flights_[i];
  if (f.landed) {
    if (f.landing.t <= step_t1_) push_event({f.landing.t, kLand, i});
    else wait_flight(i, step_k_ + 1);
    return;
  }
  const double tc = next_check(f);
  if (tc < step_t1_) push_event({tc, kCheck, i});
  else wait_flight(i, step_k_ + 1);
}

inline void LayerSim::wait_flight(int i, long long k_min) {
  // The first step k >= k_min whose end t1 = (k + 1) dt (as run() computes
  // it) the flight's event is due by, on the tests of schedule_flight();
  // estimated from the time, then settled by those tests.
  const Flight& f = flights_[i];
  const bool landed = f.landed;
  const double w = landed ? f.landing.t : next_check(f);
  auto due = [&](long long k) {
    const double t1 = static_cast<double>(k + 1) * dt_;
    return landed ? w <= t1 : w < t1;
  };
  const double q = w / dt_;
  long long k = k_min;
  if (!(q <= static_cast<double>(k_min))) {
    // never (not finite: as the scan it replaced, which never found it due)
    if (!(q < 1e15)) return wait_far(std::numeric_limits<long long>::max(), f.id);
    k = static_cast<long long>(q);  // floor(w / dt): k dt <= w < (k + 1) dt but for rounding
    while (k > k_min && due(k - 1)) --k;
  }
  while (!due(k)) ++k;
  if (k - step_k_ >= kWakeRing) return wait_far(k, f.id);
  wake_ring_[k & (kWakeRing - 1)].push_back(f.id);
}

void LayerSim::wait_far(long long k, int id) { wake_far_.emplace_back(k, id); }

// ============================================================================
// Re-entry and foot stability
// ============================================================================

void LayerSim::deposit(int id, double theta, double tau, const V& v_land) {
  // Re-entry: on top of the column where the path met the charge (or the liner).
  int k = ncol(theta, tau);
  if (k >= n_open_) {
    // No room inside the allowed layers (version 1.2: inside r_i): the
    // element is moved towards the toe, against the rotation (thesis §4.6.2).
    int sk;
    // Every layer the model lets the charge use is full: the charge has
    // spread round the shell, as it does near critical speed (a review,
    // 2026-12-06: a mill set at 0.995 of critical reached 1.000 as its liner
    // wore, and the message said nothing of it)
    if (!toe_ward_room(theta, tau, false, k, sk))
      throw SimulationError(fmt::format(
          "layer model: no room left for a landing element: every layer the charge may fill is full (this liner: "
          "{:.4f} of critical speed at an effective diameter of {:.3f} m){}",
          phi_, 2 * R_eff_,
          phi_ >= 0.95 ? "; near critical speed the charge centrifuges: run the mill slower ([mill] speed_rpm or "
                         "speed_fraction_critical; a speed given as a fraction of critical rises as the liner wears, "
                         "since the rpm it sets is the new liner's)"
                       : ""));
  }
  // Foot stability, 1: momentum (thesis §4.4.2, Radziszewski 1998). The
  // element keeps the part of its velocity along the charge surface relative
  // to the surface and slides on it against Coulomb friction mu, over
  // u^2 / (2 mu g_n), column by column, unless a taller column stops it.
  {
    const double c = std::cos(theta), sn = std::sin(theta);
    const double r = L_[k].r;
    const double ut = (-sn * v_land.x() + c * v_land.y()) - L_[k].omega * r;  // along e_t, relative to the layer
    const double gn = std::max(0.1 * kGravity, L_[k].omega * L_[k].omega * r - kGravity * sn);  // pressing it on
    const double dist = mu_ > 0 ? ut * ut / (2.0 * mu_ * gn) : 0.0;
    const int n_cols = std::min(static_cast<int>(dist / d_), L_[0].S / 2);
    if (n_cols > 0) {
      // walk on the column map (outer cells, about one diameter each) to the
      // first column taller than where the element slides; then check there
      const Layer& l0 = L_[0];
      const double ph = l0.phase + l0.omega * (t_map_ - t_step0_);
      int s0 = static_cast<int>(wrap2pi(theta - ph + 0.5 * l0.delta) * l0.inv_delta);
      if (s0 >= l0.S) s0 -= l0.S;
      const int step = ut < 0 ? -1 : 1;
      int moved = 0;
      for (int i = 0; i < n_cols; ++i) {
        int next = s0 + step;
        if (next < 0) next += l0.S;
        else if (next >= l0.S) next -= l0.S;
        if (col_[next] > k || col_[next] >= n_open_) break;
        s0 = next;
        ++moved;
      }
      if (moved > 0) {
        const double thn = theta + step * moved * l0.delta;
        const int kn = ncol(thn, tau);
        if (kn < n_open_) {
          theta = thn;
          k = kn;
        }
      }
    }
  }
  place(id, k, slot_of(k, theta, tau), tau);
}

bool LayerSim::toe_ward_room(double& theta, double tau, bool holdable, int& k_out, int& s_out) const {
  // Steps of one outer cell against the rotation, up to two turns. Columns
  // the map (col_, at t_map_) shows full are passed over in one integer
  // scan; the first one it shows with room is checked exactly (ncol()), and
  // the scan goes on from there if the map was out of date.
  const Layer& l0 = L_[0];
  const int S0 = l0.S;
  const double step = l0.delta;
  int s0 = static_cast<int>(wrap2pi(theta - (l0.phase + l0.omega * (t_map_ - t_step0_)) + 0.5 * l0.delta) * l0.inv_delta);
  if (s0 >= S0) s0 -= S0;
  const int* col = col_.data();
  const int n_open = n_open_;
  int i = 0;
  while (i < 2 * S0) {
    // the next column the map shows with room, n >= 1 steps back (at most
    // 2 S0 - i): runs down to cell 0 without a wrap test per cell
    const int lim = 2 * S0 - i;
    int n = 0;
    for (;;) {
      if (s0 == 0) s0 = S0;  // the next step wraps
      const int stop = std::max(0, s0 - (lim - n));  // the lowest cell this run may reach
      int p = s0 - 1;
#if defined(__SSE2__)
      // sixteen cells a test (the runs of full columns are long: some 40
      // cells on average for media size -25 %); the block with room is then
      // found cell by cell below, as without it
      {
        const __m128i full = _mm_set1_epi32(n_open - 1);  // col > n_open - 1: full
        while (p - 16 >= stop) {
          const __m128i* q = reinterpret_cast<const __m128i*>(col + p - 15);
          const __m128i a = _mm_and_si128(_mm_cmpgt_epi32(_mm_loadu_si128(q), full),
                                          _mm_cmpgt_epi32(_mm_loadu_si128(q + 1), full));
          const __m128i b = _mm_and_si128(_mm_cmpgt_epi32(_mm_loadu_si128(q + 2), full),
                                          _mm_cmpgt_epi32(_mm_loadu_si128(q + 3), full));
          if (_mm_movemask_epi8(_mm_and_si128(a, b)) != 0xffff) break;
          p -= 16;
        }
      }
#endif
      while (p - 4 >= stop && std::min(std::min(col[p], col[p - 1]), std::min(col[p - 2], col[p - 3])) >= n_open) p -= 4;
      while (p > stop && col[p] >= n_open) --p;
      n += s0 - p;
      s0 = p;
      if (col[p] < n_open || n >= lim) break;
    }
    i += n;
    theta -= n * step;
    if (col_[s0] >= n_open_) break;
    int below, sk;  // sk = slot_of(kk, theta, tau) where kk < n_open
    const int kk = ncol_at(theta, tau, below, sk);
    if (kk >= n_open_) continue;
    if (holdable && past_flight_angle(kk, sk, tau)) continue;
    k_out = kk;
    s_out = sk;
    return true;
  }
  return false;
}

bool LayerSim::past_flight_angle(int k, int s, double tau) const {
  double c, sn;
  slot_dir(k, s, tau, c, sn);
  return past_flight_dir(k, c, sn, tau);
}

void LayerSim::place(int id, int k, int s, double tau) {
  // Foot stability, 2: an element on a slope steeper than the angle of
  // repose rolls down to the neighbouring column; one over a void falls onto
  // the column below; one on the rising side past the flight angle of its
  // layer (which cannot hold it there) rolls down the charge surface
  // (docs/models/layer.md §Foot).
  //
  // (cf, sf) is slot_dir(k, s, tau) throughout: roll_target() hands back the
  // direction it computed for its target, so a roll does not derive it again.
  double cf, sf;
  slot_dir(k, s, tau, cf, sf);
  // inlined (always_inline): k, s, cf and sf then stay in registers over
  // the loop, not behind the closure's references
  auto roll = [&]() __attribute__((always_inline)) {
    for (int it = 0; it < 400; ++it) {
      occ(k, s) = id;  // tentatively here; neighbours are judged with it in place
      int kn, sn;
      const bool rolls = roll_target(k, s, tau, kn, sn, cf, sf);
      occ(k, s) = -1;
      if (!rolls) break;
      k = kn;
      s = sn;
    }
  };
  roll();
  // Still past the flight angle (the surface below is full): the surface flow
  // carries it down to the toe, the first column against the rotation with
  // room at a place its layer can hold.
  if (past_flight_dir(k, cf, sf, tau)) {
    double theta = slot_angle(k, s, tau);
    int kk, sk;
    if (toe_ward_room(theta, tau, true, kk, sk)) {
      k = kk;
      s = sk;
      slot_dir(k, s, tau, cf, sf);
    }
    roll();
  }
  enter_slot(id, k, s, tau);
  elem_y_entry_[id] = L_[k].r * sf;
  deepest_ = std::max(deepest_, k);
  check_departure(k, s, tau, sf);
}

// Inlined into its two callers, place()'s roll loop and relax_surface()'s
// visits (the call and its spills: 1.2 M of 260 M instructions on the bench's
// "media size -25%" case).
__attribute__((always_inline)) inline bool LayerSim::roll_target(int k, int s, double tau, int& kn_out, int& sn_out,
                                                                 double& c, double& sn_th) {
  const int id = occ(k, s);
  const double th = slot_angle(k, s, tau);
  const double x = L_[k].r * c, y = L_[k].r * sn_th;
  const bool past = past_flight_dir(k, c, sn_th, tau);
  // the angle-of-repose rule is the foot's: it acts on the toe side of the
  // mill (the descending half); layers held by lifters do not roll
  const bool repose = c < 0 && !L_[k].held;
  if (!past && !repose && (k == 0 || L_[k].held)) return false;  // nothing can move it
  bool found = false;
  double best_y = y, c_out = 0, s_out = 0;
  // a neighbouring column is a target only by the past or the repose rule
  // (an unheld top on the rising side short of its flight angle can only
  // fall over an overhang, below)
  for (double dir : {-1.0, 1.0}) {
    if (!past && !repose) break;
    if (past && dir > 0) continue;  // past the flight angle: only down the rising side
    int kn, sn;
    double cn, snn, xn, yn;
    occ(k, s) = -1;  // the neighbouring column without this element
    const bool there = neighbour_top(k, s, th + dir * L_[k].delta, tau, past, kn, sn, cn, snn, xn, yn);
    occ(k, s) = id;
    if (!there) continue;
    const double drop = y - yn, run = std::abs(x - xn);
    if ((past || (repose && drop > tan_g_ * run)) && yn < best_y) {
      best_y = yn;
      kn_out = kn;
      sn_out = sn;
      c_out = cn;
      s_out = snn;
      found = true;
    }
  }
  // an overhang: the place one diameter straight below is empty; it falls
  // onto the top of the column there (on the liner the lifters hold it)
  if (k > 0 && !L_[k].held) {
    const V q(x, y - d_);
    const double rq = q.norm(), thq = fast_atan2(q.y(), q.x());
    if (!inside_charge(q, rq, thq, tau)) {
      int sqb, sq;  // sq = slot_of(kq, thq, tau) where kq < n_open
      const int kq = ncol_at(thq, tau, sqb, sq);
      if (kq < n_open_) {
        double cq, sq_th;
        slot_dir(kq, sq, tau, cq, sq_th);
        const double yq = L_[kq].r * sq_th;
        if (!(kq == k && sq == s) && yq < best_y - 0.25 * d_) {
          kn_out = kq;
          sn_out = sq;
          c_out = cq;
          s_out = sq_th;
          found = true;
        }
      }
    }
  }
  if (found) {
    c = c_out;
    sn_th = s_out;
  }
  return found;
}

void LayerSim::relax_surface(double tau) {
  // Passes each way round the outer cells until nothing rolls (at most 6);
  // in each column the top element rolls (on over as many columns as it
  // must), then the next one, until the column is stable.
  //
  // Only columns whose top could roll are visited: the first pass takes the
  // candidates of the fresh column map (relax_candidates(), a conservative
  // test), and a move marks the columns within reach of its source and its
  // destination (the neighbours roll_target() looks at lie within
  // relax_reach_m_ outer cells) for the rest of this pass and the next. Since a
  // column whose surroundings did not change cannot start to roll, this
  // visits every column the full sweep would move, in the same order.
  //
  // The columns to visit are bit sets (one bit per outer cell), so that a
  // pass finds its next marked column a word at a time and a mark sets a
  // range: a pass visits a few dozen of the hundreds of columns.
  const Layer& l0 = L_[0];
  const int S0 = l0.S;
  const int nw = (S0 + 63) / 64;
  relax_cur_.assign(nw, 0);
  relax_next_.assign(nw, 0);
  window_extreme(col_, relax_min_reach_, false, colmin_);
  if (incremental_) relax_candidates(tau);
  else bits_set(relax_cur_, 0, S0 - 1);
  auto mark = [&](int c, int m) {
    const int reach = relax_reach_m_[m];
    if (2 * reach + 1 >= S0) {  // the reach covers the ring
      bits_set(relax_cur_, 0, S0 - 1);
      bits_set(relax_next_, 0, S0 - 1);
      return;
    }
    // c - reach .. c + reach, circularly (shorter than the ring)
    const int lo = c - reach, hi = c + reach;
    if (lo < 0) {
      bits_set(relax_cur_, lo + S0, S0 - 1);
      bits_set(relax_next_, lo + S0, S0 - 1);
    } else if (hi >= S0) {
      bits_set(relax_cur_, 0, hi - S0);
      bits_set(relax_next_, 0, hi - S0);
    }
    bits_set(relax_cur_, std::max(lo, 0), std::min(hi, S0 - 1));
    bits_set(relax_next_, std::max(lo, 0), std::min(hi, S0 - 1));
  };
  const bool map_now = t_map_ == tau && t_step0_ == tau;  // as run() calls it, after update_columns(tau)
  for (int pass = 0; pass < 6; ++pass) {
    int moved = 0;
    const bool up = pass % 2 == 0;
    // the next marked column at or after (up) / before (down) q, as the
    // marks stand now (a move marks columns still to come in this pass)
    for (int s0 = up ? bits_next(relax_cur_, 0, S0) : bits_prev(relax_cur_, S0 - 1); s0 >= 0;
         s0 = up ? bits_next(relax_cur_, s0 + 1, S0) : bits_prev(relax_cur_, s0 - 1)) {
      const double th = slot_angle(0, s0, tau);
      bool stable = false;
      for (int top = 0; top < 32; ++top) {
        int s, s_free;  // s = slot_of(h - 1, th, tau) where h > 0
        // ncol_at(th, tau): with the map at tau (map_now) the centre of outer
        // cell s0 is in cell s0 of the map (th - phase = s0 delta to a few
        // ulps, far from the cell's edges), so the walks start there
        const int h = map_now ? ncol_from(s0, th, tau, s, s_free) : ncol_at(th, tau, s, s_free);
        stable = true;
        if (h == 0) break;
        const int k = h - 1;
        const int id = occ(k, s);
        if (id < 0) break;
        int kn, sn;
        double c0, s0y;
        slot_dir(k, s, tau, c0, s0y);
        const double y0 = L_[k].r * s0y;  // before roll_target() turns (c0, s0y) to the target's
        if (!roll_target(k, s, tau, kn, sn, c0, s0y)) break;
        stable = false;
        ++moved;
        // the mill lifted it to here since it entered; it settles lower
        if (averaging_ && tau >= t_avg0_) energy_ += m_ * kGravity * (y0 - elem_y_entry_[id]);
        leave_slot(id, k, s, tau);
        place(id, kn, sn, tau);
        mark(slot_of(0, slot_angle(k, s, tau), tau), k);  // the cell left (its centre: see relax_reach_m_)
        mark(slot_of(0, slot_angle(kn, sn, tau), tau), kn);
        if (elem_layer_[id] >= 0) mark(slot_of(0, slot_angle(elem_layer_[id], elem_slot_[id], tau), tau), elem_layer_[id]);
      }
      // The column is stable as things stand: the next pass need not look at
      // it again unless a later move within reach marks it anew (a visit
      // then finds what this one found).
      if (stable) relax_next_[s0 >> 6] &= ~(std::uint64_t{1} << (s0 & 63));
    }
    if (moved == 0) break;
    std::swap(relax_cur_, relax_next_);
    std::fill(relax_next_.begin(), relax_next_.end(), 0);
    if (!incremental_) bits_set(relax_cur_, 0, S0 - 1);
  }
}

void LayerSim::bits_set(std::vector<std::uint64_t>& b, int lo, int hi) {
  // bits lo .. hi (lo <= hi)
  const int w0 = lo >> 6, w1 = hi >> 6;
  const std::uint64_t m0 = ~std::uint64_t{0} << (lo & 63);
  const std::uint64_t m1 = ~std::uint64_t{0} >> (63 - (hi & 63));
  if (w0 == w1) {
    b[w0] |= m0 & m1;
    return;
  }
  b[w0] |= m0;
  for (int w = w0 + 1; w < w1; ++w) b[w] = ~std::uint64_t{0};
  b[w1] |= m1;
}

int LayerSim::bits_next(const std::vector<std::uint64_t>& b, int q, int n) {
  // the first set bit at or after q (bits at n and beyond are never set), -1 if none
  if (q >= n) return -1;
  int w = q >> 6;
  std::uint64_t x = b[w] & (~std::uint64_t{0} << (q & 63));
  const int nw = static_cast<int>(b.size());
  while (!x) {
    if (++w >= nw) return -1;
    x = b[w];
  }
  return (w << 6) + __builtin_ctzll(x);
}

int LayerSim::bits_prev(const std::vector<std::uint64_t>& b, int q) {
  // the last set bit at or before q, -1 if none
  if (q < 0) return -1;
  int w = q >> 6;
  std::uint64_t x = b[w] & (~std::uint64_t{0} >> (63 - (q & 63)));
  while (!x) {
    if (--w < 0) return -1;
    x = b[w];
  }
  return (w << 6) + 63 - __builtin_clzll(x);
}

void LayerSim::relax_candidates(double tau) {
  // The candidate test for every outer cell into relax_cur_: its cheap first
  // look (described at relax_candidate_exact()) evaluated here from
  // per-layer constants and the outer layer's direction at tau (the same
  // products as slot_dir(), so the same values), then the exact rest.
  const int n = n_open_;
  if (static_cast<int>(relax_tol_.size()) != n) {
    relax_tol_.resize(n);
    relax_past_sn_.resize(n);
    relax_ovh_sn_.resize(n);
    for (int k = 0; k < n; ++k) {
      const double tol = L_[k].delta + L_[0].delta;
      relax_tol_[k] = tol;
      relax_past_sn_[k] = sin_fa_[k] - tol;
      relax_ovh_sn_[k] = 0.3 - tol;
    }
  }
  const Layer& l0 = L_[0];
  const int S0 = l0.S;
  double c0, s0;
  slot_dir(0, 0, tau, c0, s0);  // refreshes the cached direction of layer 0 at tau
  const double dc = dir_c_[0], ds = dir_s_[0];
  const double* cs = &slot_cos_[l0.offset];
  const double* ss = &slot_sin_[l0.offset];
  const int* col = col_.data();
  const int* cmin = colmin_.data();
  std::uint64_t* bits = relax_cur_.data();
  // inside the charge (every column within reach full: h = h_min = n_open)
  // only the past rule can let a top through, where sin > past_sn_full: in
  // the arc of angles asin(past_sn_full) .. pi - asin(past_sn_full). Columns
  // outside it widened by one outer cell each side (far beyond the rounding
  // of the directions) are passed over without their direction: the arc's
  // outer cells are arc_start .. arc_start + arc_len - 1 (circularly).
  const double tol_full = relax_tol_[n - 1], past_sn_full = relax_past_sn_[n - 1];
  int arc_start = 0, arc_len = S0;
  if (past_sn_full >= 1.0 + 1e-9) {
    arc_len = 0;  // never past (the layer never lets go)
  } else if (past_sn_full > -0.9) {
    const double as = std::asin(std::min(past_sn_full, 1.0));
    const double ph = l0.phase + l0.omega * (tau - t_step0_);
    arc_start = static_cast<int>(wrap2pi(as - l0.delta - ph) * l0.inv_delta);
    if (arc_start >= S0) arc_start -= S0;
    arc_len = std::min(S0, static_cast<int>(std::ceil((kPi - 2.0 * as + 2.0 * l0.delta) * l0.inv_delta)) + 2);
  }
  // inlined (always_inline) into the loop below: out of line it was called
  // 2.4 M times on the bench's "media size -25%" case, every capture read
  // through the closure
  auto test = [&](int s) __attribute__((always_inline)) {
    const int h = col[s];
    if (h == 0) return;
    if (cmin[s] >= n) {
      int u = s - arc_start;
      if (u < 0) u += S0;
      if (u >= arc_len) return;
      // the first look, from the direction of the column's centre
      const double c = dc * cs[s] - ds * ss[s];
      if (!(c > -tol_full)) return;
      const double sn = ds * cs[s] + dc * ss[s];
      if (!(sn > past_sn_full)) return;
      if (relax_candidate_exact(s, h, n, tau)) bits[s >> 6] |= std::uint64_t{1} << (s & 63);
      return;
    }
    const int k = h - 1;
    const int h_min = cmin[s];  // < n
    const bool unheld = !L_[k].held;
    const double c = dc * cs[s] - ds * ss[s];
    const double sn = ds * cs[s] + dc * ss[s];
    const double tol = relax_tol_[k];
    const bool past = c > -tol && sn > relax_past_sn_[k];
    const bool overhang = k > 0 && unheld && (h_min < h || (sn > relax_ovh_sn_[k] && h < n));
    const bool repose = unheld && c < tol;  // h_min < n
    if (!past && !overhang && !repose) return;
    if (relax_candidate_exact(s, h, h_min, tau)) bits[s >> 6] |= std::uint64_t{1} << (s & 63);
  };
  // Most cells are passed over by test() at once: the empty columns, and
  // the full ones (h_min = n_open) outside the arc. Outside the arc they are
  // passed over a block of B cells at a time (the flags of a block in one
  // loop without branches, which the compiler vectorises); the cells of the
  // other blocks, and of those that meet the arc, are tested one by one.
  // The order does not matter: a test sets its own bit only.
  constexpr int B = 16;
  for (int p = 0; p < S0; p += B) {
    const int e = std::min(p + B, S0);
    // some column not empty; some column neither empty nor with a full
    // window (cmin - n < 0: its sign bit, spread over the word by the shift)
    int any = 0, open = 0;
    for (int s = p; s < e; ++s) {
      any |= col[s];
      open |= col[s] & ((cmin[s] - n) >> 31);
    }
    if (any == 0) continue;
    int u = p - arc_start;
    if (u < 0) u += S0;
    if (open == 0 && (arc_len == 0 || (u >= arc_len && u + (e - p) <= S0))) continue;  // no cell in the arc
    for (int s = p; s < e; ++s) test(s);
  }
}

// Inlined into relax_candidates(), its one caller (0.9 M of 261 M
// instructions on the bench's "media size -25%" case).
__attribute__((always_inline)) inline bool LayerSim::relax_candidate_exact(int s, int h, int h_min, double tau) const {
  // Whether the top of the column above outer cell s may roll, from the
  // fresh column map at tau. Conservative: false only where roll_target()
  // must return false for that top. h = col_[s] > 0 (= ncol() at the centre
  // of cell s: the map is fresh); the cheap first look (relax_candidates())
  // has let it through.
  //
  // Bounds used below: at any angle within relax_min_reach_ outer cells of s the
  // top found by ncol() is at least the smallest column height h_min there
  // (every cell of layer j < h_min is occupied at the outer-cell centres, and
  // each cell of layer j contains one of them), so a cell an element could
  // roll into lies between the radii of layers h_min and n_open - 1.
  // h_min = min(n_open, colmin_[s]), over s +- relax_min_reach_.
  //
  // The first look, from the direction of the column's centre (cheap): the
  // top's slot is within half its cell plus half an outer cell of it, so it
  // allows that much angle (sin and cos change no faster); past: c > -tol and
  // sn > sin_fa - tol; an overhang (see below): k > 0, unheld and (h_min < h
  // or sn > 0.3 - tol and h < n_open); repose: unheld, c < tol and h_min <
  // n_open. A held top moves only by the past rule; an unheld one also by
  // repose and (above the outer layer) over an overhang, as in roll_target().
  const int k = h - 1;
  const bool unheld = !L_[k].held;
  // the top itself: the cell ncol() and slot_of() find at the column's
  // centre, as relax_surface() takes it; the past, repose and overhang tests
  // below are roll_target()'s own, evaluated exactly as there
  const double th = slot_angle(0, s, tau);
  const int st = slot_of(k, th, tau);
  double ct, stp;
  slot_dir(k, st, tau, ct, stp);
  if (past_flight_dir(k, ct, stp, tau)) return true;
  if (!unheld) return false;
  const double x = L_[k].r * ct, y = L_[k].r * stp;
  // The repose bound first (cheaper than the overhang's look at the cell
  // below; the answer is the same either way round).
  if (ct < 0 && h_min < n_open_) {
    // the toe side, repose (with full columns all round there is nowhere to
    // roll): roll_target()'s own test decides, on the neighbouring tops it
    // will find (with the map at tau the visit's ncol_at() at the centre is
    // ncol_from(s); a top other than (k, st) is left to the visit). Its
    // neighbouring columns are walked here with the top in place, where
    // roll_target() takes it out first: the walks never look at its cell
    // (one cell of layer k to each side; with S_k >= 3 not the same cell).
    // A bound from the smallest column within reach, used before, let nearly
    // every top of a sloping surface through (2026-12-05: all 27,579 on the
    // bench's "media size -25%" case, of which 87 rolled; 169 of 104,164
    // rejected on its pilot mills).
    if (L_[k].S < 3 || !repose_exact(s, h, k, st, x, y, tau)) return true;
  }
  // an overhang. While sin(theta) <= 0.3 the point one diameter below the
  // top lies in the top's ring or outside it, where every column within
  // reach at least as tall as this one fills it; above that it may reach
  // into the next ring, which only a column shorter than n_open leaves room
  // in. Where these bounds leave it open, roll_target()'s own test decides
  // (the point below in an empty cell), evaluated exactly as there.
  if (k > 0 && (h_min < h || (stp > 0.3 && h < n_open_))) {
    const V q(x, y - d_);
    if (!inside_charge(q, q.norm(), tau)) return true;
  }
  return false;
}

bool LayerSim::repose_exact(int s, int h, int k, int st, double x, double y, double tau) const {
  // The top the visit will find: relax_surface()'s ncol_from(s) with the map
  // at tau starts at col_[s] = h <= n_open and walks no further if (k, st)
  // is occupied and the cell above it is not (then it is (k, st)).
  if (!(t_map_ == tau && t_step0_ == tau) || occ(k, st) < 0) return false;
  if (h < n_open_ && occ(h, slot_of(h, slot_angle(0, s, tau), tau)) >= 0) return false;
  // roll_target()'s repose rule on it (past is false), the same values
  const double th = slot_angle(k, st, tau);
  for (double dir : {-1.0, 1.0}) {
    int kn, sn;
    double cn, snn, xn, yn;
    if (!neighbour_top(k, st, th + dir * L_[k].delta, tau, false, kn, sn, cn, snn, xn, yn)) continue;
    const double drop = y - yn, run = std::abs(x - xn);
    if (drop > tan_g_ * run && yn < y) return false;
  }
  return true;
}

void LayerSim::check_departure(int j, int s, double tau, double sn) {
  const Layer& l = L_[j];
  if (!(l.omega > 0)) return;
  // Where the layer cannot hold it (past its flight angle, where sin(theta)
  // exceeds sin(flight angle)) it falls on at once. One that reaches its
  // flight angle later is launched by departures(), which also looks one
  // step back for elements placed after its scan.
  if (!(sn > sin_fa_[j] + 1e-12)) return;
  if (l.held) {
    // a held layer's element placed past its lifter's release is part of the
    // bed there: it leaves at once only past the layer's own angle over that
    // segment (until 2026-12-06 past the smallest angle of the ring, through
    // which the bed over the pockets drained: layer-worn.md, "Hi-lo liners")
    double c, snd;
    slot_dir(j, s, tau, c, snd);
    const double rb = rel_seg(j, segment_at(c, snd, tau));
    if (!(std::isfinite(rb) && sn > std::sin(rb) + 1e-12)) return;
  }
  launch(j, s, tau, -1, true);
}

void LayerSim::support_sweep(double tau) {
  // An element whose cell below has emptied (the layers slip past each other)
  // falls into it: no element hangs over a void (docs/models/layer.md §Foot).
  // Only slots whose support may have changed since the last sweep are
  // looked at (docs/models/layer.md §Incremental maps): those entered since,
  // those over a cell left since, and those whose cell below changed as the
  // layers slipped (SlotMap::changed). Layer by layer outwards and in
  // ascending slot order, as a sweep of every slot would be.
  const bool full = sup_full_;
  if (!full)
    for (int j = 1; j < n_open_; ++j) {
      const double D = (L_[j].omega - L_[j - 1].omega) * (tau - t_sup_) * L_[j - 1].inv_delta;
      // only an element whose new cell below is empty can fall
      const SlotMap& map = supmap_[j];
      const double b1 = supmap_offset(j, tau);
      const int* o = &occ_[L_[j].offset];
      const int* ob = &occ_[L_[j - 1].offset];
      if (!map.changed(supmap_b_[j], D, [&](int s) {
            if (o[s] >= 0 && ob[map.cell(s, b1)] < 0) mark_sup(j, s);
          }))
        for (int s = 0; s < L_[j].S; ++s) mark_sup(j, s);
    }
  sup_full_ = !incremental_;
  moved_.clear();
  for (int j = 1; j < n_open_; ++j) {
    const Layer& l = L_[j];
    const Layer& lb = L_[j - 1];
    const int* o = &occ_[l.offset];
    const int* ob = &occ_[lb.offset];
    // the cell of layer j - 1 under slot s of layer j: floor(base + s ratio)
    // mod S_{j-1}, as slot_of()
    const double base = supmap_offset(j, tau);
    const SlotMap& map = supmap_[j];
    // the marked slots in ascending order (all of them in a full sweep),
    // each word taken out of sup_bits_ as the walk reaches it: falls from
    // this layer mark the layer above (and the layers below, for the next
    // sweep), never this one
    std::uint64_t* marks = &sup_bits_[occ_bits_off_[j]];
    const int nw = occ_bits_off_[j + 1] - occ_bits_off_[j];
    for (int i = 0; i < nw; ++i) {
      std::uint64_t m = marks[i];
      marks[i] = 0;
      if (full) m = i == nw - 1 && (l.S & 63) ? (std::uint64_t{1} << (l.S & 63)) - 1 : ~std::uint64_t{0};
      for (; m; m &= m - 1) {
        const int s = (i << 6) + __builtin_ctzll(m);
        const int id = o[s];
        if (id < 0) continue;
        if (ob[map.cell(s, base)] >= 0) continue;  // supported (the common case)
        const double th = slot_angle(j, s, tau);
        int k = j, sk = s;
        while (k > 0) {
          const int sb = slot_of(k - 1, th, tau);
          if (occ(k - 1, sb) >= 0) break;
          --k;
          sk = sb;
        }
        if (k != j) {
          leave_slot(id, j, s, tau);
          enter_slot(id, k, sk, tau);
          moved_.push_back(id);
        }
      }
    }
  }
  for (int j = 1; j < n_open_; ++j) supmap_b_[j] = supmap_offset(j, tau);
  t_sup_ = tau;
  // those that fell past the flight angle of their new layer settle (after
  // the sweep, so that each starts from its own cell)
  for (const int id : moved_) {
    const int k = elem_layer_[id], sl = elem_slot_[id];
    if (k < 0 || !past_flight_angle(k, sl, tau)) continue;
    leave_slot(id, k, sl, tau);
    place(id, k, sl, tau);
  }
}

void LayerSim::note_cell(int j, int k, double tau, bool entered) {
  if (!maps_ready_) return;
  {
    const int i = occ_bits_off_[j] + (k >> 6);
    std::uint64_t& w = occ_bits_[i];
    const std::uint64_t bit = std::uint64_t{1} << (k & 63);
    w = entered ? w | bit : w & ~bit;
    occ_words_changed_[i >> 6] |= std::uint64_t{1} << (i & 63);
  }
  // (the columns over the cells changed since the last map are marked by
  // update_columns(), from occ_bits_map_)
  if (!sup_full_) {
    if (entered) {
      if (j >= 1) mark_sup(j, k);
    } else if (j + 1 < n_open_) {
      supmap_[j + 1].over(k, supmap_offset(j + 1, tau), [&](int s) { mark_sup(j + 1, s); });
    }
  }
}

// ============================================================================
// Sampling: loads, occupancy, power
// ============================================================================

void LayerSim::update_columns(double tau, bool window) {
  // Column above each outer cell: how many layers are filled from the liner
  // (no element hangs over a void). Incremental (docs/models/layer.md
  // §Incremental maps): only the columns through a cell entered or left since
  // the last map, or whose cell in some layer changed as the layers slipped
  // (SlotMap::changed), are recomputed; a full sweep otherwise.
  const Layer& l0 = L_[0];
  const int S0 = l0.S;
  bool full = col_full_;
  // A column of height h depends on its cells in layers 0 .. h only; one
  // whose cell in layer j <= h moved to a cell of the same occupancy keeps
  // its height (a change of occupancy of the old cell since the last map was
  // noted by note_cell()). A cell moves by at most one place while the
  // offset moves by less than half a cell, so only the outer cells whose
  // cell crosses a boundary of layer j's occupancy (an empty cell next to a
  // full one; a few per layer, from occ_bits_) can change: those are found
  // with SlotMap::across(), a superset of them checked as before (the
  // columns of SlotMap::changed() until 2026-12-05, S_0 |D| cells a layer).
  for (int j = 1; j < n_open_ && !full; ++j) {
    const double D = (l0.omega - L_[j].omega) * (tau - t_map_) * L_[j].inv_delta;
    if (!(std::abs(D) < 0.5)) {
      full = true;  // as SlotMap::changed(): too far for the runs to be reliable
      break;
    }
    const SlotMap& map = colmap_[j];
    const double b0 = colmap_b_[j], b1 = colmap_offset(j, tau);
    // the offset's change as b0 and b1 have it (wrap2pi may take b1 round
    // by S_j), and D: the cells cross within the span of both
    const int Sj = L_[j].S;
    double d = b1 - b0;
    if (d > 0.5 * Sj) d -= Sj;
    else if (d < -0.5 * Sj) d += Sj;
    if (D == 0 && d == 0) continue;
    const double lo = std::min({0.0, D, d}), hi = std::max({0.0, D, d});
    const int* o = &occ_[L_[j].offset];
    // local pointers: mark_col() stores, and the compiler would reload the
    // vectors' data on every cell otherwise
    const int* col = col_.data();
    const char* dirty = col_dirty_.data();
    auto check = [&](int s) {
      if (j > col[s] || dirty[s]) return;
      if ((o[map.cell(s, b0)] >= 0) != (o[map.cell(s, b1)] >= 0)) mark_col(s, j);
    };
    // boundaries K of layer j: bit K differs from bit K - 1 (mod S_j)
    const std::uint64_t* w = &occ_bits_[occ_bits_off_[j]];
    const int nw = (Sj + 63) >> 6;
    std::uint64_t carry = (w[(Sj - 1) >> 6] >> ((Sj - 1) & 63)) & 1;  // bit S_j - 1, before bit 0
    for (int i = 0; i < nw; ++i) {
      const std::uint64_t x = w[i];
      std::uint64_t e = x ^ ((x << 1) | carry);
      carry = x >> 63;
      if (i == nw - 1 && (Sj & 63)) e &= (std::uint64_t{1} << (Sj & 63)) - 1;
      while (e) {
        map.across((i << 6) + __builtin_ctzll(e), b0, lo, hi, check);
        e &= e - 1;
      }
    }
  }
  // The cells whose occupancy differs from the last map's (each once,
  // however often it was entered and left since): the columns over them at
  // b0 (exactly: SlotMap::over() gives a cell more each side) that reach
  // their layer (height >= j). Marked by note_cell() on every move until
  // 2026-12-05.
  if (!full) {
    const std::uint64_t *now = occ_bits_.data(), *then = occ_bits_map_.data();
    const int* col = col_.data();
    // the words written since the last map (note_cell())
    for (size_t q = 0; q < occ_words_changed_.size(); ++q)
      for (std::uint64_t m = occ_words_changed_[q]; m; m &= m - 1) {
        const int i = static_cast<int>(q << 6) + __builtin_ctzll(m);
        std::uint64_t e = now[i] ^ then[i];
        if (!e) continue;  // entered and left again
        const int j = occ_bits_layer_[i];
        const SlotMap& map = colmap_[j];
        const double b0 = colmap_b_[j];
        const int k0 = (i - occ_bits_off_[j]) << 6;
        do {
          const int k = k0 + __builtin_ctzll(e);
          e &= e - 1;
          if (j == 0) mark_col(k, 0);
          else map.over(k, b0, [&](int s) {
            if (col[s] >= j && map.cell(s, b0) == k) mark_col(s, j);
          });
        } while (e);
      }
  }
  for (size_t q = 0; q < occ_words_changed_.size(); ++q)
    for (std::uint64_t m = occ_words_changed_[q]; m; m &= m - 1) {
      const int i = static_cast<int>(q << 6) + __builtin_ctzll(m);
      occ_bits_map_[i] = occ_bits_[i];
    }
  std::fill(occ_words_changed_.begin(), occ_words_changed_.end(), 0);
  for (int j = 1; j < n_open_; ++j) colmap_b_[j] = colmap_offset(j, tau);
  if (full) {
    const int* o0 = &occ_[l0.offset];
    active_.clear();
    for (int s = 0; s < S0; ++s) {
      const bool on = o0[s] >= 0;
      col_[s] = on;
      if (on) active_.push_back(s);
    }
    for (int j = 1; j < n_open_ && !active_.empty(); ++j) {
      const int* o = &occ_[L_[j].offset];
      const SlotMap& map = colmap_[j];
      const double base = colmap_b_[j];
      size_t w = 0;
      for (const int s : active_) {
        if (o[map.cell(s, base)] >= 0) {
          col_[s] = j + 1;
          active_[w++] = s;
        }
      }
      active_.resize(w);
    }
  } else {
    // a marked column is full up to the lowest layer whose cell changed
    // (its cells below are as they were, in a column that reached that
    // layer): the walk starts there
    for (const int s : col_dirty_list_) {
      int h = col_from_[s];
      if (h == 0) {
        if (occ_[l0.offset + s] < 0) {
          col_[s] = 0;
          continue;
        }
        h = 1;
      }
      while (h < n_open_ && occ_[L_[h].offset + colmap_[h].cell(s, colmap_b_[h])] >= 0) ++h;
      col_[s] = h;
    }
  }
  for (const int s : col_dirty_list_) col_dirty_[s] = 0;
  col_dirty_list_.clear();
  col_full_ = !incremental_;
  t_map_ = tau;
  if (!window) return;
  window_extreme(col_, col_m_, true, colwin_);
  t_win_ = tau;
}

/// window_extreme()'s extremes: out[s] = op-extreme of val[s .. s + w - 1]
/// (val: the ring unrolled, n = S + w - 1 values). By doubling: after each
/// level, val[p] holds the extreme over a span twice as long (each level a
/// loop without a carried dependence); the window is then the union of two
/// spans L <= w < 2 L long, one at each end. Overwrites val and tmp.
template <class T, class Op>
void window_spans(T* val, T* tmp, int n, int w, int S, int* out, Op op) {
  int L = 1, len = n;  // val[p], p < len, is the extreme over p .. p + L - 1
  while (2 * L <= w) {
    len -= L;
    for (int p = 0; p < len; ++p) tmp[p] = op(val[p], val[p + L]);
    std::swap(val, tmp);
    L *= 2;
  }
  for (int s = 0; s < S; ++s) out[s] = op(val[s], val[s + w - L]);
}

void LayerSim::window_extreme(const std::vector<int>& v, int m, bool max, std::vector<int>& out) {
  // Extreme of v over s-m .. s+m (circular) for every s, by doubling spans
  // (window_spans(); O(S log m), loops the compiler vectorises). Column
  // heights fit 16 bits, which the vector instructions take 8 at a time.
  const int S = static_cast<int>(v.size());
  m = std::min(m, (S - 1) / 2);
  const int w = 2 * m + 1;
  const int n = S + 2 * m;  // unrolled: position p holds slot (p - m) mod S
  out.resize(S);
  win16_val_.resize(n);
  win16_tmp_.resize(n);
  std::int16_t* val16 = win16_val_.data();
  const int* vp = v.data();
  unsigned wide = 0;  // nonzero if a value does not fit 16 bits
  for (int i = 0; i < S; ++i) {
    val16[m + i] = static_cast<std::int16_t>(vp[i]);
    wide |= (static_cast<unsigned>(vp[i]) + 32768u) >> 16;
  }
  if (wide == 0) {
    std::int16_t* val = val16;
    std::copy(val + S, val + S + m, val);          // slots S - m .. S - 1
    std::copy(val + m, val + 2 * m, val + m + S);  // slots 0 .. m - 1
    if (max)
      window_spans(val, win16_tmp_.data(), n, w, S, out.data(), [](std::int16_t a, std::int16_t b) { return std::max(a, b); });
    else
      window_spans(val, win16_tmp_.data(), n, w, S, out.data(), [](std::int16_t a, std::int16_t b) { return std::min(a, b); });
    return;
  }
  win_pre_.resize(n);
  win_val_.resize(n);
  int* val = win_val_.data();
  std::copy(v.end() - m, v.end(), val);
  std::copy(v.begin(), v.end(), val + m);
  std::copy(v.begin(), v.begin() + m, val + m + S);
  if (max)
    window_spans(val, win_pre_.data(), n, w, S, out.data(), [](int a, int b) { return std::max(a, b); });
  else
    window_spans(val, win_pre_.data(), n, w, S, out.data(), [](int a, int b) { return std::min(a, b); });
}

double LayerSim::bed_clearance(double r, double theta, double tau) const {
  if (r < r_open_min_) return r_open_min_ - r;
  const Layer& l0 = L_[0];
  const int S0 = l0.S;
  auto outer_slot = [&](double t) {  // outer slot at theta at time t
    int s = static_cast<int>(wrap2pi(theta - (l0.phase + l0.omega * (t - t_step0_)) + 0.5 * l0.delta) * l0.inv_delta);
    return s >= S0 ? s - S0 : s;
  };
  int s_win;
  // The window maxima (of the map at t_win) cover the rotation of every
  // layer over (t_win, tau + H] and two extra cells of growth by landings
  // meanwhile.
  {
    const double rot_slots = omega_ * ((tau - t_win_) + skip_H_) * l0.inv_delta;
    const double lateral = r * l0.delta * (col_m_ - 0.5 - rot_slots);
    s_win = outer_slot(t_win_);
    const int h = std::min(n_open_, colwin_[s_win] + 2);
    const double radial = (R_eff_ - h * d_) - r;
    if (radial >= lateral || radial > 0.5 * d_) return std::min(radial, lateral);
  }
  // Closer look, with the (possibly newer) map at t_map: the distance to
  // each column within col_m cells is at least the larger of the radial gap
  // to its top and the angular gap to it; the columns beyond are at least
  // the angular gap to the edge away. Nearest columns first; stop once the
  // angular gap alone exceeds the best.
  const double rot_slots = omega_ * ((tau - t_map_) + skip_H_) * l0.inv_delta;
  const double cell = r * l0.delta;
  double best = cell * (col_m_ - 0.5 - rot_slots);
  // (a map of the window maxima's time: the slot found above)
  const int s = t_map_ == t_win_ ? s_win : outer_slot(t_map_);
  auto gap = [&](int h) { return (R_eff_ - std::min(n_open_, h + 2) * d_) - r; };
  {
    const double a = cell * std::max(0.0, 0 - 0.5 - rot_slots);
    if (a >= best) return best;
    best = std::min(best, std::max(gap(col_[s]), a));
  }
  // the columns q cells either side: gap() falls as the column rises (each
  // rounding is monotone), so min(max(gap(lo), a), max(gap(hi), a)) is
  // max(gap(the higher column), a), the same bits with one gap
  int lo = s, hi = s;
  for (int q = 1; q <= col_m_; ++q) {
    const double a = cell * std::max(0.0, q - 0.5 - rot_slots);
    if (a >= best) break;
    lo = lo == 0 ? S0 - 1 : lo - 1;
    hi = hi == S0 - 1 ? 0 : hi + 1;
    best = std::min(best, std::max(gap(std::max(col_[lo], col_[hi])), a));
  }
  return best;
}

V LayerSim::pocket_push(int b, int n, double c, double sn, double C, double Fr_g, const V& er, const V& et, double w,
                        double vslip_w, double cr, double sr, V& f_lifter) {
  // Pocket loads (setup_pocket_loads()): the faces holding the pocket take
  // the tangential force of the `depth` layers in it, each its own; the
  // layers above rest on the pocket and pass it their tangential force up to
  // Coulomb's limit mu N, N their radial load on it, shared equally by the
  // pocket's layers; the liner under the column keeps the rest as shear.
  // Returns the force left on the liner under the column.
  const double Ft = col_mass_[n] * kGravity * c;
  const int dir = Ft > 0 ? 0 : 1;
  const int depth = std::min(n, pocket_depth_[dir][b]);
  if (depth == 0) return (C + Fr_g) * er - Ft * et;
  const double gc = kGravity * std::abs(c);
  const double W_above = col_mass_[n] - col_mass_[depth];
  const double N_above = (col_centrifugal_[n] - col_centrifugal_[depth]) - W_above * kGravity * sn;
  const double T_above = std::min(gc * W_above, mu_ * std::max(0.0, N_above));
  const double above = T_above / depth;
  const std::vector<PocketShare>& sh = pocket_share_[dir];
  const int* begin = &pocket_begin_[dir][static_cast<size_t>(b) * pocket_layers_];
  V to_lifter(0, 0);  // liner frame
  for (int q = 0; q < depth; ++q) {
    const double T = gc * (col_mass_[q + 1] - col_mass_[q]) + above;
    for (int i = begin[q]; i < begin[q + 1]; ++i) {
      const PocketShare& x = sh[i];
      const double Nf = T * x.kn, Sf = T * x.ks, v = vslip_w * x.r;
      acc_N_[x.element] += Nf * w;
      acc_Ng_[x.element] += Nf * w;
      acc_S_[x.element] += Sf * w;
      acc_NV_[x.element] += Nf * v * w;
      acc_SV_[x.element] += Sf * v * w;
      to_lifter += T * x.lifter;
    }
  }
  f_lifter += V(cr * to_lifter.x() - sr * to_lifter.y(), sr * to_lifter.x() + cr * to_lifter.y());
  return (C + Fr_g) * er - (Ft > 0 ? 1.0 : -1.0) * (gc * W_above - T_above) * et;
}

// sample() is arithmetic on doubles throughout: with AVX2 where the CPU has
// it (a second copy, picked at load time) the three-operand forms spare the
// register copies of SSE2. The same operations in the same order, and avx2
// does not enable FMA, so the same results to the bit.
#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default")))
#endif
void LayerSim::sample(double tau, double w) {
  const double rot = mill_angle(tau);
  // --- flying elements, for the occupancy indicators (the en-masse ones
  // are integrated exactly as they leave their slots: leave_slot())
  const double cell_w = d_ * d_ * w, mass_w = m_ * w;
  for (const Flight& f : flights_) {
    const V q = flight_position(f, tau);  // canonical frame (the indicators are mirrored at the end)
    const int j = occupancy_->ring(q.norm());
    occupancy_->add_to_bin(j, occupancy_->angular_bin(j, wrap2pi(fast_atan2(q.y(), q.x()))), cell_w, mass_w);
    arm_fly_time_ += mass_w * q.x();  // the power's torque arm (results: eq. 4.3 and the momentum balance)
    if (tau >= f.t0) airborne_w_ += w;  // airborne: flying, not still sliding along a lifter face (lifter_slide)
  }
  occupancy_->add_time(w);
  airborne_t_ += w;
  // --- liner loads from the outer layer (thesis eqs. 4.10/4.11, 5.1/5.2),
  // with the column heights of update_columns(tau)
  const Layer& l0 = L_[0];
  const int S0 = l0.S;
  const double cr = std::cos(rot), sr = std::sin(rot);
  const double cp = std::cos(l0.phase), sp = std::sin(l0.phase);
  const double vslip_w = std::abs(omega_ - l0.omega);
  // The bin and the contact ray of a slot (below) change only where its liner
  // frame angle psi crosses a bin edge or a midpoint between contact rays:
  // points z = psi * zk that are whole numbers (zk = 2 m / h, m rays per bin
  // a power of two). psi, the atan2 of the rotated direction, is phase +
  // s delta - rot up to fast_atan2's error (at most 6.93e-7 rad, found over
  // the whole of [0, 1] in steps of 5e-9) and rounding (~1e-13 rad), so where
  // that sum is more than kMargin from every such point both are read from
  // it, the same integers without the atan2; the few slots nearer one (about
  // 4 kMargin / ray spacing of them) take the atan2 as before. Off with
  // model.incremental_maps = false, so that a test compares the two.
  constexpr double kMargin = 4e-6;  // [rad]
  const double zk = 2.0 * ride_.inv_contact_ray;
  const double z0 = wrap2pi(l0.phase - rot), zm = incremental_ ? kMargin * zk : 1.0;
  const LinerRideTable::HalfRays half_rays = ride_.half_rays();
  V f_lifter(0, 0);
  for (int s = 0; s < S0; ++s) {
    const int n = col_[s];
    if (n == 0) continue;
    // direction of slot s: (cos, sin)(phase + s delta) from the table
    const double c = cp * cos0_[s] - sp * sin0_[s], sn = sp * cos0_[s] + cp * sin0_[s];
    const double W = col_mass_[n], C = col_centrifugal_[n];  // [kg/m], [N/m] (eq. 5.1)
    const V er(c, sn), et(-sn, c);
    const double Fr_g = -W * kGravity * sn;  // outward radial gravity (eq. 4.10 / 5.2)
    const double Ft = W * kGravity * c;      // along the rotation, held by the liner (eq. 4.11)
    // liner frame angle of the slot: atan2 of the rotated direction; e: the
    // element the disc touches at psi, the nearest contact ray's (the bin's
    // smaller-edge element moved the loads up to a bin towards the crest:
    // docs/models/layer.md §Liner loads, "Where a load lands")
    const double z = (z0 + s * l0.delta) * zk;  // >= 0
    const int iz = static_cast<int>(z);
    const double fz = z - iz;  // exact
    int b, e;
    if (fz > zm && fz < 1.0 - zm) {
      b = half_rays.bin(iz);
      e = half_rays.contact(iz);
    } else {
      const double psi = fast_atan2(sn * cr - c * sr, c * cr + sn * sr);
      b = ride_.bin(psi);
      e = ride_.contact(psi);
    }
    // force of the column on the liner; with pocket loads the faces holding
    // the pocket take some of its tangential part (a call of its own, so that
    // the default loop keeps its code)
    const V F = pocket_layers_ > 0 && Ft != 0 ? pocket_push(b, n, c, sn, C, Fr_g, er, et, w, vslip_w, cr, sr, f_lifter)
                                              : V((C + Fr_g) * er - Ft * et);
    // split along the ride curve's normal, the direction the liner pushes a
    // disc riding there, not the touched element's: on a surface rough at
    // scales far below the disc (fine elements after many remeshes) the
    // element normals tilt from it, and N = -F.n fell with them: the lifter
    // of the bundled mill meshed at 2 mm wore 30 mm less than at 10 mm
    // (docs/models/layer.md §Liner loads, "Where a load lands")
    const V& nl = ride_.ride_normal[b];
    const V nrm(cr * nl.x() - sr * nl.y(), sr * nl.x() + cr * nl.y());
    const double N = -F.dot(nrm);
    if (!(N > 0)) continue;
    const double Nc = C * (-er.dot(nrm));
    const double S = std::abs(F.x() * nrm.y() - F.y() * nrm.x());
    const double vslip = vslip_w * ride_.ride_radius_m[b];  // outer layer on the liner
    acc_N_[e] += N * w;
    acc_Nc_[e] += Nc * w;
    acc_Ng_[e] += (N - Nc) * w;
    acc_S_[e] += S * w;
    acc_NV_[e] += N * vslip * w;
    acc_SV_[e] += S * vslip * w;
    if (canon_.surface.element_segment[e] == canon_.segment_of_physical_0) f_lifter += F;
  }
  // forces on lifter 0 against its angular position (thesis Figs. 4-21/4-22)
  const double lifter_angle = rot + canon_.segment_of_physical_0 * canon_.surface.segment_angle_rad();
  const V er0(std::cos(lifter_angle), std::sin(lifter_angle)), et0(-er0.y(), er0.x());
  const double lifter_phys = wrap2pi(canon_.physical_angle(lifter_angle));
  const int nb = static_cast<int>(lifter_n_.size());
  const int b = std::clamp(static_cast<int>(lifter_phys / kTwoPi * nb), 0, nb - 1);
  lifter_n_[b] += f_lifter.dot(er0);
  lifter_t_[b] += -f_lifter.dot(et0);
  lifter_cnt_[b] += 1;
}

void LayerSim::snapshot(double tau) {
  ChargeSnapshot sn;
  sn.time_s = tau;
  sn.liner_angle_rad = in_.mill.sense() * omega_ * tau;
  for (int j = 0; j < n_open_; ++j)
    for (int s = 0; s < L_[j].S; ++s) {
      if (occ(j, s) < 0) continue;
      const double th = slot_angle(j, s, tau);
      const double r = drawn_radius(j, th, tau);
      sn.position.push_back(canon_.physical_point(V(r * std::cos(th), r * std::sin(th))));
      sn.radius_m.push_back(a_);
      sn.state.push_back(0);
    }
  for (const Flight& f : flights_) {
    sn.position.push_back(canon_.physical_point(flight_position(f, tau)));
    sn.radius_m.push_back(a_);
    sn.state.push_back(tau < f.t0 ? 2 : 1);
  }
  snaps_.push_back(std::move(sn));
}

// ============================================================================
// The run
// ============================================================================

ChargeResult LayerSim::run() {
  const auto wall0 = std::chrono::steady_clock::now();
  setup_geometry();
  setup_layers();
  // Phases at t = 0 (docs/models/layer.md §Settling): "aligned" puts slot 0
  // of every layer at angle 0, so the cells of all layers line up radially
  // there, a lattice the layers' slip only slowly undoes; "staggered" turns
  // layer j by the fractional part of (j + 1) / golden ratio of its slot
  // angle, offsets that no two layers share.
  if (in_.model.initial_phases == "staggered")
    for (size_t j = 0; j < L_.size(); ++j) {
      const double f = (static_cast<double>(j) + 1.0) * 0.6180339887498949;
      L_[j].phase = phase0_[j] = (f - std::floor(f)) * L_[j].delta;
    }
  setup_initial_fill();
  // Support sweep and surface relaxation (foot stability) run on a fixed
  // schedule in time, every relaxation_interval_cells times the time the
  // shell takes to move one outer cell (default half), whatever the step; it
  // is a parameter of the model, not only of its numerics: the charge surface
  // steepens past the angle of repose between two relaxations
  // (docs/models/layer.md §9, "The relaxation interval").
  relax_dt_ = in_.model.relaxation_interval_cells * L_[0].delta / omega_;
  // time step: sub-step a step the model cannot take (docs/models/layer.md §Time step),
  // and one longer than the relaxation interval (which would run less often than scheduled)
  const double courant = in_.model.max_courant > 0 ? in_.model.max_courant : kLayerMaxCourant;
  const double dt_courant = courant * d_ / (omega_ * R_eff_);
  const double dt_max = std::min(dt_courant, relax_dt_);
  const double dt_req = in_.model.time_step_s;
  substeps_ = dt_req > dt_max ? static_cast<int>(std::ceil(dt_req / dt_max - 1e-9)) : 1;
  dt_ = dt_req / substeps_;
  if (substeps_ > 1 && dt_courant <= relax_dt_) {
    // two decimals, or four where two would round down to the limit ("0.45 ...
    // (stable up to 0.45)" read as a contradiction)
    const double c_req = omega_ * R_eff_ * dt_req / d_;
    std::string c_text = fmt::format("{:.2f}", c_req);
    if (std::stod(c_text) <= courant) c_text = fmt::format("{:.4f}", c_req);
    notes_.push_back(fmt::format("time_step_s = {} s moves the shell {} {} per step (stable up to {}): "
                                 "sub-stepped {} times ({:.4g} s)",
                                 dt_req, c_text, d_ == d_ball_ ? "media diameters" : "element widths", courant,
                                 substeps_, dt_));
  }
  else if (substeps_ > 1)
    notes_.push_back(fmt::format("time_step_s = {} s is longer than the relaxation interval ({} outer cells, {:.4g} s): "
                                 "sub-stepped {} times ({:.4g} s)",
                                 dt_req, in_.model.relaxation_interval_cells, relax_dt_, substeps_, dt_));
  // A known defect, said where it acts (docs/models/layer.md §9, "Why the fast
  // pilots change regime"): a lifter that lets a held layer go later than the
  // flight angle of the foot-stability rules (the smaller of the lifter's and
  // the unheld angle) leaves a window in which a relaxation rolls the element
  // down instead of its launch; the share of launches it takes is about
  // min(1, window / interval), the window in time at the layer's speed.
  {
    double worst = 0, gap = 0;
    int layer = -1;
    for (int j = 0; j < std::min(n_open_, n_held_layers_); ++j) {
      const double fa = flight_angle(j);
      if (!L_[j].held || !(L_[j].omega > 0) || !std::isfinite(fa)) continue;
      for (size_t k = 0; k < held_[j].size(); ++k) {
        const HeldLaunch& h = held_[j][k];
        // over its own segment the rules take min(layer's angle there, its release)
        const double fk = std::min(rel_seg(j, static_cast<int>(k)), h.release);
        if (!h.held || !h.released || !(h.release > fk)) continue;
        const double share = std::min(1.0, (h.release - fk) / L_[j].omega / relax_dt_);
        if (share > worst) worst = share, gap = h.release - fk, layer = j;
      }
    }
    if (worst >= kHeldWindowNoteShare)
      notes_.push_back(fmt::format("the lifters let layer {} go {:.2f} deg later than the foot-stability rules' flight "
                                   "angle: up to about {:.0f} % of its lifter launches become rolls down the charge "
                                   "surface (fewer direct impacts, the toe higher), a known defect of the layer model "
                                   "(docs/models/layer.md §9, \"Why the fast pilots change regime\")",
                                   layer, gap * 180.0 / kPi, 100.0 * worst));
  }
  const double T_rev = kTwoPi / omega_;
  const double revs = in_.revolutions > 0 ? in_.revolutions : 2.0;
  t_avg0_ = in_.model.settle_revolutions * T_rev;
  t_end_ = t_avg0_ + revs * T_rev;
  if (const std::string n = settling_note("[model] settle_revolutions", in_.model.settle_revolutions, revs); !n.empty())
    notes_.push_back(n);
  const long long n_steps = static_cast<long long>(std::ceil(t_end_ / dt_ - 1e-9));
  t_end_ = n_steps * dt_;
  // accumulators
  const int ne = canon_.surface.n_elements();
  for (auto* v : {&acc_N_, &acc_Nc_, &acc_Ng_, &acc_S_, &acc_NV_, &acc_SV_}) v->assign(ne, 0.0);
  lifter_n_.assign(180, 0.0);
  lifter_t_.assign(180, 0.0);
  lifter_cnt_.assign(180, 0);
  layer_count_acc_.assign(L_.size(), 0.0);
  traj_count_.assign(L_.size(), 0);
  // occupancy in the canonical (anticlockwise) frame; the angles are mirrored
  // at the end for a clockwise mill, so that its results are the exact mirror
  occupancy_ = std::make_unique<ChargeOccupancy>(R_eff_, d_, +1.0);
  ring_is_layer_ = occupancy_->n_rings() >= n_open_;
  for (int j = 0; j < n_open_ && ring_is_layer_; ++j) ring_is_layer_ = occupancy_->n_angular(j) == L_[j].S;
  col_.assign(L_[0].S, 0);
  colwin_.assign(L_[0].S, n_open_);
  colmap_.assign(n_open_, SlotMap());
  supmap_.assign(n_open_, SlotMap());
  for (int j = 1; j < n_open_; ++j) {
    colmap_[j] = SlotMap(L_[0].S, L_[j].S, L_[0].delta * L_[j].inv_delta);
    supmap_[j] = SlotMap(L_[j].S, L_[j - 1].S, L_[j].delta * L_[j - 1].inv_delta);
  }
  colmap_b_.assign(n_open_, 0.0);
  supmap_b_.assign(n_open_, 0.0);
  colmap_off_.assign(L_.size(), MapOffset());
  supmap_off_.assign(L_.size(), MapOffset());
  col_dirty_.assign(L_[0].S, 0);
  col_from_.assign(L_[0].S, 0);
  col_dirty_list_.clear();
  occ_bits_off_.assign(n_open_ + 1, 0);
  for (int j = 0; j < n_open_; ++j) occ_bits_off_[j + 1] = occ_bits_off_[j] + (L_[j].S + 63) / 64;
  occ_bits_.assign(occ_bits_off_[n_open_], 0);
  sup_bits_.assign(occ_bits_.size(), 0);
  occ_bits_layer_.resize(occ_bits_.size());
  occ_words_changed_.assign((occ_bits_.size() + 63) / 64, 0);
  for (int j = 0; j < n_open_; ++j)
    std::fill(occ_bits_layer_.begin() + occ_bits_off_[j], occ_bits_layer_.begin() + occ_bits_off_[j + 1], j);
  for (int j = 0; j < n_open_; ++j)
    for (int s = 0; s < L_[j].S; ++s)
      if (occ(j, s) >= 0) occ_bits_[occ_bits_off_[j] + (s >> 6)] |= std::uint64_t{1} << (s & 63);
  occ_bits_map_ = occ_bits_;
  incremental_ = in_.model.incremental_maps;
  col_full_ = sup_full_ = true;
  maps_ready_ = true;
  r_open_min_ = R_eff_ - n_open_ * d_;
  // roll_target() for the top (k, s) of the column at outer cell s0 looks
  // at the cells of every layer at the angles of that column's centre, of
  // the centres of the cells of layer k next to s (one delta_k each side of
  // the centre of s, which is within delta_k / 2 of the column's) and of the
  // point one diameter below the centre of s (within asin(d / r_k), and
  // fast_atan2()'s 1e-5 rad): all within P of the column's centre. A move
  // marks the outer cells round the outer cell of the centre of each cell
  // it changed (relax_surface()): a cell of layer m read at angle phi has
  // its centre within delta_m / 2 of phi, which is within delta_0 / 2 of its
  // outer cell's centre, so a reach of P + delta_m / 2 + delta_0 / 2 marks
  // every column that reads it (relax_reach_m_; P + delta_max / 2 + delta_0
  // / 2 for every layer at e128a72). The window minima bound the tops at those
  // angles (relax_candidate_exact()) from the outer cells within P +
  // delta_max (each cell of a layer holds an outer cell's centre; 3 delta_max
  // for both until 2026-12-05). The partial layer of version 1.2 may have
  // only a few wide cells, so the reach can exceed half the ring: it is then
  // the whole ring (relax_surface() marks each column once).
  {
    double P = 0, d_max = 0;
    for (int k = 0; k < n_open_; ++k) {
      const double dk = L_[k].delta;
      P = std::max({P, 1.5 * dk, 0.5 * dk + std::asin(std::min(1.0, d_ / L_[k].r)) + 1e-4});
      d_max = std::max(d_max, dk);
    }
    const double d0 = L_[0].delta, margin = 1e-4;
    relax_min_reach_ = std::min(static_cast<int>((P + d_max + margin) / d0) + 1, L_[0].S / 2);
    relax_reach_m_.assign(n_open_, 0);
    for (int m = 0; m < n_open_; ++m)
      relax_reach_m_[m] = std::min(static_cast<int>((P + 0.5 * L_[m].delta + 0.5 * d0 + margin) / d0) + 1, L_[0].S / 2);
  }
  cos0_.resize(L_[0].S);
  sin0_.resize(L_[0].S);
  for (int s = 0; s < L_[0].S; ++s) {
    cos0_[s] = std::cos(s * L_[0].delta);
    sin0_[s] = std::sin(s * L_[0].delta);
  }
  // a column n layers high above one outer cell holds the share S_j / S_0 of a cell of each layer
  col_mass_.assign(n_open_ + 1, 0.0);
  col_centrifugal_.assign(n_open_ + 1, 0.0);
  for (int j = 0; j < n_open_; ++j) {
    const double share = static_cast<double>(L_[j].S) / L_[0].S;
    col_mass_[j + 1] = col_mass_[j] + m_ * share;
    // the full m omega^2 r (the centripetal reaction), not thesis eq. 5.1's
    // printed 1/2, for which no derivation was found (docs/models/layer.md §7)
    col_centrifugal_[j + 1] = col_centrifugal_[j] + m_ * share * L_[j].omega * L_[j].omega * L_[j].r;
  }
  if (in_.record_snapshot) {
    snaps_left_ = 36;
    snap_dt_ = T_rev / snaps_left_;
    next_snap_ = t_end_ - T_rev + 0.5 * snap_dt_;
  }
  // Loads, flights' occupancy and the column map are sampled every two
  // degrees of mill rotation (a quadrature of the time averages); like the
  // relaxation (relax_dt_ above) independent of the time step
  // (docs/models/layer.md §Time step).
  const double sample_dt = (2.0 * kPi / 180.0) / omega_;
  // flight skips: at most two outer cells' worth of rotation; the column
  // window must cover the rotation over a sampling interval plus a skip
  const double w_max = omega_;
  skip_H_ = 2.0 * L_[0].delta / w_max;
  col_m_ = static_cast<int>(std::ceil(w_max * (sample_dt + dt_ + 2.0 * skip_H_) / L_[0].delta)) + 1;
  t_step0_ = 0;
  update_columns(0.0, true);
  // room for a step's waiting flights in each bucket of the ring (wait_flight()),
  // so that the first turns of the ring do not grow them one by one
  for (auto& b : wake_ring_) b.reserve(32);
  wake_due_.reserve(32);
  for (long long k = 0; k < n_steps; ++k) {
    const double t0 = k * dt_, t1 = (k + 1) * dt_;
    t_step0_ = t0;
    t_step1_ = t1;
    averaging_ = t1 > t_avg0_;
    departures(t0, t1);
    check_flights(t1);
    // advance the layers to t1
    for (int j = 0; j < n_open_; ++j) L_[j].phase = wrap2pi(L_[j].phase + L_[j].omega * dt_);
    t_step0_ = t1;
    if (std::floor(t1 / relax_dt_) > std::floor(t0 / relax_dt_)) {
      support_sweep(t1);
      update_columns(t1, false);  // fresh column tops for the relaxation
      relax_surface(t1);
    }
    if (std::floor(t1 / sample_dt) > std::floor(t0 / sample_dt) || k + 1 == n_steps) {
      update_columns(t1, true);
      if (averaging_) {
        const double w = t1 - std::max(t_last_sample_, t_avg0_);
        avg_time_ += w;
        sample(t1, w);
      }
      t_last_sample_ = t1;
    }
    if (t1 >= next_snap_ && snaps_left_ > 0) {
      snapshot(t1);
      next_snap_ += snap_dt_;
      --snaps_left_;
    }
  }
  // ---- the en-masse elements still in their slots: their arcs up to the end
  for (int j = 0; j < n_open_; ++j)
    for (int s = 0; s < L_[j].S; ++s) {
      const int id = occ(j, s);
      if (id < 0) continue;
      leave_slot(id, j, s, t_end_);
      enter_slot(id, j, s, t_end_);
    }
  // ---- conservation (always checked: a lost element is a bug, not a result)
  long long en_masse = 0;
  for (int x : occ_) en_masse += x >= 0;
  if (en_masse + static_cast<long long>(flights_.size()) != N_)
    throw SimulationError(fmt::format("layer model lost elements: {} en masse + {} in flight != {}", en_masse,
                                      flights_.size(), N_));
  // ---- results
  ChargeResult res;
  res.model = "layer";
  Indicators& I = res.indicators;
  const OccupancyIndicators oc = occupancy_->evaluate();
  auto phys_deg = [&](double deg) {
    double d = canon_.physical_angle(deg * kPi / 180.0) * 180.0 / kPi;
    d = std::fmod(d, 360.0);
    return d < 0 ? d + 360.0 : d;
  };
  I.toe_deg = phys_deg(oc.toe_deg);
  I.shoulder_deg = phys_deg(oc.shoulder_deg);
  I.com_angle_deg = phys_deg(oc.com_angle_deg);
  I.com_radius_m = oc.com_radius_m;
  I.charge_area_m2 = oc.charge_area_m2;
  I.n_layers = oc.n_layers;
  I.diameter_eff_m = 2 * R_eff_;
  I.fraction_critical = phi_;
  I.inner_radius_m = r_i_;
  // power (per metre, then the full mill)
  const double L = in_.mill.length_m;
  double pool_w_per_m = 0;
  if (in_.charge.discharge == Discharge::Overflow) {
    // slurry pool: the non-charge bins below the slurry level (thesis eq. 4.4)
    const ChargeOccupancy& o = *occupancy_;
    for (int j = 0; j < o.n_rings(); ++j)
      for (int i = 0; i < o.n_angular(j); ++i) {
        if (o.occupancy(j, i) >= oc.threshold) continue;
        const double rc = o.ring_mid_radius(j), tc = (i + 0.5) * kTwoPi / o.n_angular(j);
        if (rc * std::sin(tc) > y_pool_) continue;
        // canonical frame: x > 0 on the rising side, where the pool would resist
        pool_w_per_m += omega_ * kGravity * rho_pulp_ * o.bin_area(j) * rc * std::cos(tc);
      }
  }
  // Net power (thesis eq. 4.1): the charge by its torque arm, eq. 4.3 (Radziszewski
  // 1999: P = omega g sum m x), plus the slurry pool (eq. 4.4). The sum runs over
  // every element, the flying ones included: in a steady state the charge's
  // angular momentum does not change on average, so the mean torque of the liner
  // on it balances the mean torque of gravity on all of it (a flight's angular
  // momentum, changed by gravity on the way, reaches the liner through the bed
  // when it lands). The thesis' simulator counts only the elements en masse. The
  // elements in slots are integrated exactly as they leave them (leave_slot()),
  // the flying ones sampled every 2 deg (sample()). Until 2026-12-06 the sum ran
  // over the time-averaged mass of the occupancy grid's en-masse bins (at least
  // half the packed level), which counted the flights passing through dense
  // bins and dropped thin ones, among them the partial layer at r_i while under
  // half its cells were open: the power jumped by 3.9 % as r_i crossed that
  // layer's middle (docs/models/layer.md §8). The second figure is the rate of
  // lift and kinetic energy given to the elements that leave the charge:
  // Morrell's energy reading of his C-model (reference §1).
  const double arm_w_per_m = avg_time_ > 0 ? omega_ * kGravity * (arm_time_ + arm_fly_time_) / avg_time_ : 0.0;
  const double net_w_per_m = arm_w_per_m + pool_w_per_m;
  I.net_power_w_per_m = net_w_per_m;
  I.net_power_kw = net_w_per_m * L / 1000.0;
  I.slurry_pool_power_kw = pool_w_per_m * L / 1000.0;
  I.alt_net_power_kw = ((avg_time_ > 0 ? energy_ / avg_time_ : 0.0) + pool_w_per_m) * L / 1000.0;
  I.no_load_power_kw = morrell_no_load_power_kw(2 * R_eff_, phi_, L, in_.charge.cone_length_m);
  I.gross_power_kw = I.no_load_power_kw + I.net_power_kw;
  // layers, trajectories, speeds
  int n_traj = 0;
  for (size_t j = 0; j < traj_count_.size(); ++j)
    if (n_traj_flights_ > 0 && traj_count_[j] >= 0.01 * n_traj_flights_) ++n_traj;
  I.n_trajectories = n_traj;
  for (int j = 0; j < n_open_; ++j)
    if (avg_time_ > 0 && layer_count_acc_[j] / avg_time_ >= 1.0) I.layer_speed_rpm.push_back(L_[j].omega * 60.0 / kTwoPi);
  // forces on lifter 0
  for (size_t b = 0; b < lifter_n_.size(); ++b) {
    if (lifter_cnt_[b] == 0) continue;
    I.lifter_force_angle_deg.push_back((b + 0.5) * 360.0 / lifter_n_.size());
    I.lifter_normal_force_n_per_m.push_back(lifter_n_[b] / lifter_cnt_[b]);
    I.lifter_tangential_force_n_per_m.push_back(lifter_t_[b] / lifter_cnt_[b]);
  }
  // liner loads on the physical surface
  LinerLoads& LL = res.loads;
  LL.reset(in_.surface->n_elements(), avg_time_);
  if (avg_time_ > 0) {
    for (int e = 0; e < ne; ++e) {
      const int pe = canon_.physical_element[e];
      LL.normal_force_n_per_m[pe] = acc_N_[e] / avg_time_;
      LL.centrifugal_force_n_per_m[pe] = acc_Nc_[e] / avg_time_;
      LL.gravitational_force_n_per_m[pe] = acc_Ng_[e] / avg_time_;
      LL.shear_force_n_per_m[pe] = acc_S_[e] / avg_time_;
      LL.normal_slip_power_w_per_m[pe] = acc_NV_[e] / avg_time_;
      LL.shear_work_rate_w_per_m[pe] = acc_SV_[e] / avg_time_;
      LL.slip_speed_m_s[pe] = acc_N_[e] > 0 ? acc_NV_[e] / acc_N_[e] : 0.0;
    }
    LL.impacts = std::move(impacts_);
    for (auto& ev : LL.impacts) ev.rate_per_s /= avg_time_;
  }
  LL.has_impacts = true;
  // the share of the landings in the averaging window that strike the liner
  // (the impacts are those landings; every element has the same mass, so it
  // is the share of the landing mass, as the DEM's). Until 2026-12-05 the
  // denominator was every flight of the run, settling included, which read
  // low by the settling's share of the run (a third at the default 1 + 2
  // revolutions).
  I.direct_impact_fraction = n_avg_landings_ > 0 ? static_cast<double>(LL.impacts.size()) / n_avg_landings_ : 0.0;
  res.snapshots = std::move(snaps_);
  res.notes = notes_;
  RunStats& st = res.stats;
  st.simulated_s = t_end_;
  st.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  st.realtime_ratio = st.wall_s > 0 ? st.simulated_s / st.wall_s : 0.0;
  st.steps = n_steps;
  st.time_step_s = dt_;
  st.substeps = substeps_;
  st.elements = N_;
  st.flights = n_flights_;
  st.charge_mass_kg_per_m = N_ * m_;
  st.relaxation_interval_s = relax_dt_;
  st.airborne_fraction = airborne_t_ > 0 && N_ > 0 ? airborne_w_ / airborne_t_ / N_ : 0.0;
  st.inner_radius_beta = beta_;
  return res;
}

}  // namespace

ChargeResult LayerModel::run(const ChargeInput& in) const {
  LayerSim sim(in);
  return sim.run();
}

std::unique_ptr<ChargeModel> make_layer_model() { return std::make_unique<LayerModel>(); }

}  // namespace linerlife
