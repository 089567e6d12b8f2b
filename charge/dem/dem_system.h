// dem_system.h - the 2D soft-disc DEM engine: discs, contacts with each other
// and with a rotating polyline wall, velocity-Verlet integration, OpenMP over
// threads, deterministic for a given thread count.
//
// One step (velocity Verlet, Allen & Tildesley 1987 §3.2; Verlet 1967):
//   v(n+1/2) = v(n) + dt/2 F(n)/m,  x(n+1) = x(n) + dt v(n+1/2)
//   F(n+1)   = F(x(n+1), v(n+1/2))       (damping from the half-step velocity)
//   v(n+1)   = v(n+1/2) + dt/2 F(n+1)/m
// and the same for the rotation with the torque and I = m r^2 / 2.
//
// Neighbours: a Verlet list (pairs i < j closer than r_i + r_j + skin) built
// from a cell list and rebuilt when the two largest displacements since the
// last build add up to the skin (or the largest and the wall's turn at its
// outermost node do); the tangential spring of each pair moves to the new
// list. Walls: each disc near the wall is tested against its candidate
// elements, listed with the neighbour list in the wall's body frame. Threads:
// the work of each phase is cut into 8 fixed partitions (particle ranges for
// the kicks and the liner contacts, a work-balanced split of the list rows for
// the particle contacts), partition k adding into its own force buffer k; the
// buffers are summed in partition order, so a run repeats bit for bit whatever
// the thread count and whichever thread ran which partition. Each thread works
// through its own block of partitions first (docs/models/dem.md §6).
//
// Units SI; 2D discs are cylinders of unit length: masses [kg/m], forces [N/m],
// torques [N m/m], moments of inertia [kg m2/m].
#pragma once

#include <string>
#include <vector>

#include "charge/dem/contact_law.h"
#include "charge/dem/wall_mesh.h"

namespace linerlife {

struct DemSettings {
  ContactParams particle;      // particle-particle contacts
  ContactParams wall;          // particle-wall contacts
  double dt = 0;               // [s] time step (the caller checks it against the collision time)
  double gravity_x = 0;        // [m/s2]
  double gravity_y = -9.81;    // [m/s2]
  double wall_omega = 0;       // [rad/s] wall angular velocity about the origin, anticlockwise positive
  double wall_angle0 = 0;      // [rad] wall body-frame angle at t = 0
  double skin = 0;             // [m] Verlet-list skin; 0: 0.75 x the mean radius
  int threads = 1;             // OpenMP threads at most; the results do not depend on it
  bool adapt_threads = false;  // between 1 and `threads`, use whichever ran faster lately (a shared machine)
  double impact_min_speed = 0.1;  // [m/s] wall-contact onsets at least this fast (normal) are recorded
  double escape_radius = 0;    // [m] > 0: a disc centre farther than this from the origin has left the mill
  double speed_limit = 0;      // [m/s] > 0: a disc faster than this means the run blew up
  int check_interval = 50;     // [steps] between blow-up checks
};

/// The initial state of the discs (all vectors the same size).
struct DemParticles {
  std::vector<double> x, y;    // [m] centre
  std::vector<double> vx, vy;  // [m/s]
  std::vector<double> w;       // [rad/s] anticlockwise
  std::vector<double> radius;  // [m]
  std::vector<double> mass;    // [kg/m]
  int size() const { return static_cast<int>(x.size()); }
};

/// A wall contact that began with the disc approaching at least
/// impact_min_speed: the particle, the element and the speeds at onset.
struct ImpactRecord {
  long long step = 0;           // global step of the onset
  int particle = 0;             // id (index in DemParticles)
  int element = 0;
  double normal_speed = 0;      // [m/s] centre velocity relative to the wall point, along -normal (> 0)
  double tangential_speed = 0;  // [m/s] magnitude of that relative velocity along the wall
  long long free_steps = 0;     // steps the disc had been without any contact before this one
};

/// One wall contact at the step contact records were asked for.
struct WallContactRecord {
  int particle = 0;             // id (index in DemParticles)
  int element = 0;              // element (for a node contact: the element that starts there)
  double fx = 0, fy = 0;        // [N/m] force on the wall, lab frame
  double cx = 0, cy = 0;        // [m] contact point, lab frame
};

/// Per element sums of load x dt while accumulation is on (LinerLoads before
/// dividing by the duration). A node contact is shared half and half.
struct WallLoadSums {
  double duration = 0;                  // [s]
  std::vector<double> normal;           // [N s/m]  sum max(F_n, 0) dt
  std::vector<double> shear;            // [N s/m]  sum |F_t| dt
  std::vector<double> normal_slip;      // [J/m]    sum max(F_n, 0) |v_slip| dt
  std::vector<double> shear_slip;       // [J/m]    sum |F_t| |v_slip| dt
  double drive_work = 0;                // [J/m]    sum Omega x (torque of the contact forces on the discs) dt
};

class DemSystem {
 public:
  /// walls may have no elements. Throws std::invalid_argument for bad sizes.
  DemSystem(const DemSettings& settings, WallMesh walls, const DemParticles& particles);
  ~DemSystem();
  DemSystem(DemSystem&&) noexcept;
  DemSystem& operator=(DemSystem&&) noexcept;

  /// Advances `steps` time steps. Throws SimulationError (with what, where,
  /// when and what to change) if a disc leaves the mill, passes through the
  /// wall (its centre crosses a wall element during a step), or moves faster
  /// than speed_limit, or a value turns non-finite.
  void advance(long long steps);

  // --- state ---
  int size() const { return n_; }
  double time() const { return time_; }            // [s]
  long long step_count() const { return step_; }
  double wall_angle() const { return angle_; }       // [rad]
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& vx() const { return vx_; }
  const std::vector<double>& vy() const { return vy_; }
  const std::vector<double>& w() const { return w_; }
  const std::vector<double>& radius() const { return r_; }
  const std::vector<double>& mass() const { return m_; }
  const std::vector<int>& contacts() const { return ncontact_; }  // contacts of each disc at the last step
  /// The discs are reordered in space at every list build; ids()[i] is the
  /// index disc i had in the DemParticles given to the constructor.
  const std::vector<int>& ids() const { return id_; }
  int index_of(int id) const;  // current index of the disc with that id (O(n); for tests)
  const DemSettings& settings() const { return set_; }
  const WallMesh& walls() const { return walls_; }
  /// Sets the velocity of the disc with index i (tests; before the first advance ids equal indices).
  void set_velocity(int i, double vx, double vy, double w);

  // --- liner loads ---
  /// Starts (zeroing) or stops the per-element load sums and the impact list.
  void set_accumulate(bool on);
  /// The sums so far, combined over threads in thread order.
  WallLoadSums load_sums() const;
  /// Impacts recorded since the last call, in (step, particle, element) order.
  std::vector<ImpactRecord> take_impacts();
  /// Asks for the wall contacts of the next step.
  void record_contacts_next_step() { record_next_ = true; }
  std::vector<WallContactRecord> take_contact_records();

  // --- diagnostics ---
  double kinetic_energy() const;    // [J/m] translation + rotation
  double potential_energy() const;  // [J/m] -m g . x
  double elastic_energy() const;    // [J/m] in the normal and tangential springs at the last force evaluation
  double momentum_x() const, momentum_y() const;  // [N s/m]
  double wall_impulse_x() const, wall_impulse_y() const;  // [N s/m] integral of the wall forces on the discs
  long long pair_contact_steps() const { return pair_contact_steps_; }  // sum over steps of particle contacts
  long long wall_contact_steps() const { return wall_contact_steps_; }
  long long list_builds() const { return builds_; }
  int last_threads() const { return last_threads_; }  // threads the last advance() used
  double list_entries_per_disc() const { return n_ ? static_cast<double>(nb_j_.size()) / n_ : 0.0; }  // at the last build
  double max_overlap_ratio() const { return max_overlap_ratio_; }  // largest disc-disc overlap / smaller radius seen
  double max_wall_overlap_ratio() const { return max_wall_overlap_ratio_; }  // largest disc-wall overlap / radius
  /// Tangential springs of liner contacts kept per disc from step to step.
  static constexpr int kWallSlots = 4;
  /// Liner contacts one disc can have at once (beyond, the deepest are kept).
  static constexpr int kMaxWallHits = 16;
  /// Disc-liner contacts dropped beyond kMaxWallHits of one disc, and contacts
  /// beyond kWallSlots whose tangential spring was not kept, summed over steps.
  long long wall_hits_dropped() const { return wall_hits_dropped_; }
  long long wall_springs_dropped() const { return wall_springs_dropped_; }

 private:
  struct ThreadData;
  struct PackedElement;
  struct ForceAcc;
  struct StepClock {
    long long step = 0;  // step the forces are evaluated for
    double time = 0;     // [s]
    double c = 1, s = 0;  // cos, sin of the wall angle
    double cp = 1, sp = 0;  // cos, sin of the wall angle one step earlier
    bool record = false;  // keep the wall contacts of this step
  };
  void rebuild_prepare(double time);
  void rebuild_permute(int t);
  void rebuild_swap();
  void rebuild_rows(int t, const StepClock& clk);
  void rebuild_finish();
  template <bool Hertz>
  void pair_forces(int t);
  template <bool Hertz>
  void wall_forces(int t, bool first, const StepClock& clk);
  void gather(int t, bool kick, bool do_check, bool drift_next);
  void kick_drift(int t);
  std::string check_failure(long long step, double time) const;
  void fail(const std::string& message);

  DemSettings set_;
  WallMesh walls_;
  int n_ = 0, nt_ = 1;
  // The work of a step is cut into this many fixed partitions whatever the
  // thread count, so a run repeats bit for bit on 1 or 2 threads.
  static constexpr int kPartitions = 8;
  int np_ = kPartitions;
  std::vector<int> part_lo_, part_hi_;  // discs partition k's contacts can write to (its rows and their partners)
  // particles (SoA)
  std::vector<double> x_, y_, vx_, vy_, w_, r_, m_, invm_, invI_;
  std::vector<double> fx_, fy_, tq_;  // accelerations [m/s2] and angular acceleration [rad/s2] of the last gather
  std::vector<double> xref_, yref_;
  std::vector<int> ncontact_;
  std::vector<long long> free_steps_;
  // wall contact history: kWallSlots per particle
  std::vector<int> wslot_elem_;     // -1 empty
  std::vector<double> wslot_xi_;
  // neighbour list (CSR, rows i, partners j > i)
  std::vector<int> nb_start_, nb_j_, old_start_, old_j_;
  std::vector<double> nb_xi_, old_xi_;
  std::vector<int> row_split_;      // thread t owns rows [row_split_[t], row_split_[t+1])
  std::vector<double> row_weight_;  // cumulative work estimate of the rows (for row_split_)
  double build_angle_ = 0, build_angle_next_ = 0;  // [rad] wall angle at the last list build
  // cell list
  double cell_ = 0, cx0_ = 0, cy0_ = 0;
  int cnx_ = 0, cny_ = 0;
  std::vector<int> cell_start_;     // particles are kept in cell order: cell c holds [cell_start_[c], cell_start_[c+1])
  std::vector<int> cell_of_;        // cell of each particle at the last build
  std::vector<int> order_;          // at the last build: new index -> index before the build
  std::vector<int> id_;             // the index a particle had in DemParticles
  std::vector<int> scratch_i_;
  std::vector<double> shadow_d_[9];  // reorder targets of x, y, vx, vy, w, r, m, invm, invI
  std::vector<int> shadow_id_, shadow_slot_e_;
  std::vector<long long> shadow_free_;
  std::vector<double> shadow_slot_xi_;
  std::vector<ThreadData> td_;
  std::vector<PackedElement> packed_;  // walls_ elements, one cache line each
  std::vector<ForceAcc> wacc_;         // liner contact force, torque and count of each disc (one partition writes each)
  // time
  double time_ = 0, angle_ = 0, cos_a_ = 1, sin_a_ = 0;
  long long step_ = 0;
  bool forces_valid_ = false, rebuild_needed_ = true, accumulate_ = false, record_next_ = false;
  double skin_ = 0, rmax_ = 0, rmin_ = 0;
  long long pair_contact_steps_ = 0, wall_contact_steps_ = 0, builds_ = 0;
  // adaptive thread count: [s] per particle-step, moving average, for 1 thread and for nt_
  double cost_ema_[2] = {0, 0};
  long long calls_ = 0;
  int last_threads_ = 1;
  double max_overlap_ratio_ = 0, max_wall_overlap_ratio_ = 0;
  long long wall_hits_dropped_ = 0, wall_springs_dropped_ = 0;
  double accum_duration_ = 0;
  long long accum_start_step_ = 0;
  // failure raised inside the parallel region
  int failed_ = 0;
  std::string failure_;
};

}  // namespace linerlife
