#include "charge/dem/dem_model.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>

#include "charge/particle_indicators.h"
#include "charge/settling_note.h"
#include "geometry/errors.h"
#include "geometry/metrics.h"

namespace linerlife {

namespace {

[[noreturn]] void refuse(const std::string& key, const std::string& message) {
  throw InputError("dem." + key, "[dem] " + key + ": " + message);
}

void check_range(const std::string& key, double v, double lo, double hi, bool lo_open, const char* what) {
  if (!(std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi))
    refuse(key, fmt::format("{} = {} is out of range; allowed {} {} value <= {} ({})", key, v, lo,
                            lo_open ? "<" : "<=", hi, what));
}

/// The [dem] values the model relies on (the configuration schema checks the
/// same ranges; this guards callers of the library).
void validate_spec(const DemSpec& s) {
  if (s.contact_law != "linear" && s.contact_law != "hertz")
    refuse("contact_law", fmt::format("contact_law = \"{}\"; allowed \"linear\", \"hertz\"", s.contact_law));
  check_range("restitution", s.restitution, 0, 1, true, "coefficient of restitution");
  check_range("wall_restitution", s.wall_restitution, 0, 1, true, "coefficient of restitution");
  check_range("friction", s.friction, 0, 2, false, "Coulomb coefficient");
  check_range("wall_friction", s.wall_friction, 0, 2, false, "Coulomb coefficient");
  check_range("rolling_resistance", s.rolling_resistance, 0, 0.5, false, "rolling resistance coefficient");
  if (s.collision_time_s > 0 && s.stiffness > 0)
    refuse("stiffness", "give collision_time_s or stiffness, not both");
  if (s.collision_time_s > 0) check_range("collision_time_s", s.collision_time_s, kDemMinCollisionTimeS, 1, false, "s");
  if (s.time_step_s > 0) check_range("time_step_s", s.time_step_s, kDemMinTimeStepS, 0.1, false, "s");
  if (s.stiffness > 0) check_range("stiffness", s.stiffness, kDemMinStiffness, 1e15, false, "N/m per m");
  check_range("overlap_fraction", s.overlap_fraction, 0, 0.2, true, "overlap over diameter");
  if (!(s.steps_per_collision >= kDemMinStepsPerCollision))
    refuse("steps_per_collision",
           fmt::format("steps_per_collision = {} is below the stable range; allowed >= {} (docs/models/dem.md §2)",
                       s.steps_per_collision, kDemMinStepsPerCollision));
  check_range("coarse_grain", s.coarse_grain, 1, 20, false, "coarse-graining factor");
  check_range("ball_size_spread", s.ball_size_spread, 0, 0.5, false, "share of the ball diameter");
  check_range("packing_fraction_2d", s.packing_fraction_2d, 0.5, 0.9069, false, "2D packing fraction");
  check_range("revolutions", s.revolutions, 0, 1000, true, "mill revolutions");
  check_range("settle_revolutions", s.settle_revolutions, 0, 100, false, "mill revolutions");
  if (s.rock_diameter_max_m > 0 && s.rock_diameter_min_m > s.rock_diameter_max_m)
    refuse("rock_diameter_min_m", fmt::format("rock_diameter_min_m = {} m is larger than rock_diameter_max_m = {} m",
                                              s.rock_diameter_min_m, s.rock_diameter_max_m));
}

/// The key a charge that does not fit in the mill is refused under, and why:
/// the rows of place() are as tall as the largest disc, so a rock much larger
/// than the balls (rock_diameter_max_m) or coarse discs (coarse_grain) stack
/// few rows; otherwise the charge itself (filling) is too large.
struct PlacementBlame {
  std::string key;    // "dem.rock_diameter_max_m", "dem.coarse_grain" or "charge.filling"
  std::string value;  // "rock_diameter_max_m = 0.9 m": the key and its value, first in the message
  std::string why;    // after the count of discs: what to change
};

PlacementBlame placement_blame(const ChargeSpec& ch, const DemSpec& spec, double dmax) {
  const double s = spec.coarse_grain;
  const double d_ball = ch.ball_filling > 0 ? ch.ball_diameter_m : 0.0;
  const bool rocks = ch.filling > ch.ball_filling;
  if (rocks && spec.rock_diameter_max_m > d_ball)
    return {"dem.rock_diameter_max_m", fmt::format("rock_diameter_max_m = {} m", spec.rock_diameter_max_m),
            fmt::format("they are placed in rows as tall as the largest disc, this rock ({:.4g} m{}); lower "
                        "rock_diameter_max_m (the balls are {} m){}",
                        dmax, s > 1 ? fmt::format(" at coarse_grain = {}", s) : "", ch.ball_diameter_m,
                        s > 1 ? " or coarse_grain" : "")};
  if (s > 1)
    return {"dem.coarse_grain", fmt::format("coarse_grain = {}", s),
            fmt::format("they are placed in rows as tall as the largest disc ({:.4g} m); lower coarse_grain", dmax)};
  return {"charge.filling", fmt::format("filling = {}", ch.filling),
          fmt::format("they are placed in rows as tall as the largest disc ({:.4g} m); lower filling", dmax)};
}

/// Rows of discs from the bottom of the mill up (loose, shuffled sizes), each
/// row a horizontal chord of the crest circle: deterministic and cheap; the
/// bed settles during the settling revolutions. Refused under `blame` when
/// the discs do not fit.
DemParticles place(const ParticleSet& ps, double r_place, double omega_signed, unsigned long long seed,
                   const PlacementBlame& blame) {
  DemParticles p;
  const int n = ps.size();
  const double dmax = 2 * *std::max_element(ps.radius_m.begin(), ps.radius_m.end());
  const double gap = 0.02 * dmax, pitch = dmax + 2 * gap;
  DemRandom rng(seed ^ 0x5deece66dULL);
  int idx = 0;
  for (double y = -r_place + 0.5 * pitch; idx < n; y += pitch) {
    const double yy = std::max(std::abs(y - 0.5 * pitch), std::abs(y + 0.5 * pitch));
    if (yy >= r_place && y < 0) continue;  // the bottom row is a chord too short to hold a disc
    if (yy >= r_place)
      throw InputError(blame.key, fmt::format("{}: [dem] the {} discs of this charge do not fit in the mill (placed "
                                              "{}): {}",
                                              blame.value, n, idx, blame.why));
    const double half = std::sqrt(r_place * r_place - yy * yy);
    double x = -half;
    while (idx < n) {
      const double d = 2 * ps.radius_m[idx];
      if (x + d > half) break;
      const double px = x + 0.5 * d + gap * 0.5 * rng.uniform(), py = y + gap * (rng.uniform() - 0.5);
      p.x.push_back(px), p.y.push_back(py);
      // rigid rotation with the mill
      p.vx.push_back(-omega_signed * py), p.vy.push_back(omega_signed * px), p.w.push_back(omega_signed);
      p.radius.push_back(ps.radius_m[idx]);
      p.mass.push_back(ps.mass_kg_per_m[idx]);
      x += d + gap;
      ++idx;
    }
  }
  return p;
}

}  // namespace

DemSetup make_dem_setup(const ChargeInput& in) {
  const DemSpec& spec = in.model.dem;
  validate_spec(spec);
  if (!in.surface || in.surface->n_elements() < 3)
    throw InputError("liner", "the dem model needs the liner surface (none was given)");
  const LinerSurface& surface = *in.surface;
  const Mill& mill = in.mill;
  if (!(mill.speed_rpm > 0)) throw InputError("mill.speed_rpm", "the dem model needs the mill speed (> 0 rpm)");
  const ChargeSpec& ch = in.charge;
  if (!(ch.filling > 0)) throw InputError("charge.filling", "the dem model needs a charge (filling > 0)");

  DemSetup s;
  const LinerMetrics lm = metrics(surface, mill.rotation, 7800.0);
  s.free_area = lm.free_area_m2;
  s.r_eff = 0.5 * lm.effective_diameter_m;
  const double omega = mill.omega_rad_s();
  s.revolution_s = 2 * kPi / omega;
  s.v_ref = omega * s.r_eff;
  s.walls = make_wall_mesh(surface);
  s.r_crest = s.walls.min_radius;

  // Particles, with the coarse-graining the scene allows (docs/models/dem.md §3).
  // A charge of millions of discs (1 mm media in a SAG mill) is refused before
  // it is drawn, naming the size that makes the count.
  {
    const DiscCount n = count_discs(ch, spec, s.free_area);
    if (!(n.total() <= kDemMaxDiscs)) {
      // the rocks' finest size is a quarter of the balls' unless given
      const bool balls = n.balls >= n.rocks || !(spec.rock_diameter_min_m > 0);
      const std::string key = balls ? "charge.ball_diameter_m" : "dem.rock_diameter_min_m";
      const std::string value = balls ? fmt::format("ball_diameter_m = {} m", ch.ball_diameter_m)
                                      : fmt::format("rock_diameter_min_m = {} m", spec.rock_diameter_min_m);
      throw InputError(key, fmt::format("{}: the dem model would need {:.3g} discs ({:.3g} balls, {:.3g} rocks) for "
                                        "this charge; it takes at most {:.0f}: {}, or [dem] coarse_grain "
                                        "(one disc of s times the size for s^2 media)",
                                        value, n.total(), n.balls, n.rocks, kDemMaxDiscs,
                                        balls ? "larger media" : "a larger rock_diameter_min_m"));
    }
  }
  s.particles = make_particle_set(ch, spec, s.free_area, static_cast<unsigned long long>(spec.seed));
  const ParticleSet& ps = s.particles;
  if (ps.size() < 10) {
    if (spec.coarse_grain > 1)
      refuse("coarse_grain", fmt::format("coarse_grain = {} leaves {} discs; the charge needs at least 10 (lower "
                                         "coarse_grain, 1 at the least)",
                                         spec.coarse_grain, ps.size()));
    // one disc per medium already: the charge itself is too small for the
    // model (a coarse_grain of 1 cannot be lowered; the sweep of 2026-12-07
    // found the message asking for it)
    throw InputError("charge.filling",
                     fmt::format("filling = {} holds only {} discs in this mill (ball_diameter_m = {} m, one disc per "
                                 "medium); the dem model needs at least 10: a larger filling, or smaller media",
                                 ch.filling, ps.size(), ch.ball_diameter_m));
  }
  double dmin = std::numeric_limits<double>::max(), dmax = 0, dsum = 0;
  for (double r : ps.radius_m) dmin = std::min(dmin, 2 * r), dmax = std::max(dmax, 2 * r), dsum += 2 * r;
  s.mean_diameter = dsum / ps.size();
  if (spec.coarse_grain > 1) {
    double hmax = 0;
    for (const auto& sm : lm.segments) hmax = std::max(hmax, sm.lifter_height_m);
    // bed depth along the vertical through the axis, approximately J x diameter for the layers rule
    const double depth = ch.filling * 2 * s.r_eff;
    const double s_lifter = hmax > 0 ? hmax / (dmax / spec.coarse_grain) : std::numeric_limits<double>::max();
    const double s_layers = depth / (4 * s.mean_diameter / spec.coarse_grain);
    const double s_max = std::max(1.0, std::min(s_lifter, s_layers));
    if (spec.coarse_grain > s_max * (1 + 1e-9))
      refuse("coarse_grain",
             fmt::format("coarse_grain = {} is more than this mill allows: the largest disc ({:.4g} m) must not be "
                         "taller than the lifters ({:.4g} m) and the bed must keep 4 layers; allowed 1 <= "
                         "coarse_grain <= {:.3g}",
                         spec.coarse_grain, dmax, hmax, s_max));
  }

  // Contacts (contact_law.h). The default collision time makes the smallest disc overlap
  // overlap_fraction of its diameter meeting the liner at the liner speed (undamped linear
  // estimate delta = v t_c / pi); a given collision time is for the real sizes and
  // coarse-graining stretches it by s, keeping the relative overlap (docs/models/dem.md §3).
  const ContactLaw law = spec.contact_law == "hertz" ? ContactLaw::Hertz : ContactLaw::Linear;
  double tc = 0, k = 0;
  if (spec.stiffness > 0) {
    k = spec.stiffness;
  } else if (spec.collision_time_s > 0) {
    tc = spec.collision_time_s * spec.coarse_grain;
  } else {
    tc = kPi * spec.overlap_fraction * dmin / s.v_ref;
  }
  DemSettings& set = s.settings;
  try {
    set.particle = make_contact_params(law, spec.restitution, spec.friction, spec.rolling_resistance, tc, k, s.v_ref);
    set.wall = make_contact_params(law, spec.wall_restitution, spec.wall_friction, spec.rolling_resistance, tc, k,
                                   s.v_ref);
  } catch (const std::invalid_argument& e) {
    refuse("restitution", e.what());
  }
  // Shortest contact: the lightest pair, at the fastest impact a mill gives (hertz).
  double mmin = std::numeric_limits<double>::max();
  for (double m : ps.mass_kg_per_m) mmin = std::min(mmin, m);
  const double v_fast = s.v_ref + std::sqrt(2 * kGravity * 2 * s.r_eff);  // liner speed plus a fall across the mill
  s.collision_time_s = std::min(collision_time(set.particle, 0.5 * mmin, v_fast), collision_time(set.wall, mmin, v_fast));
  if (spec.time_step_s > 0) {
    set.dt = spec.time_step_s;
    if (set.dt > s.collision_time_s / kDemMinStepsPerCollision)
      refuse("time_step_s",
             fmt::format("time_step_s = {} s is beyond the stable range: the shortest contact lasts {:.4g} s and needs "
                         "at least {} steps; allowed time_step_s <= {:.4g} s",
                         set.dt, s.collision_time_s, kDemMinStepsPerCollision,
                         s.collision_time_s / kDemMinStepsPerCollision));
  } else {
    set.dt = s.collision_time_s / spec.steps_per_collision;
  }
  set.gravity_x = 0, set.gravity_y = -kGravity;
  set.wall_omega = mill.sense() * omega;
  set.wall_angle0 = 0;
  // threads = 0: all cores, dropping to 1 while a second thread does not pay
  // (the results are the same bits either way, docs/models/dem.md §6)
  set.threads = spec.threads > 0 ? spec.threads : omp_get_num_procs();
  set.adapt_threads = spec.threads == 0;
  set.impact_min_speed = spec.impact_min_speed_m_s;
  set.escape_radius = surface.shell_radius_m > 0 ? surface.shell_radius_m : s.walls.max_radius;
  set.speed_limit = 2 * v_fast;
  set.check_interval = 50;

  const double r_place = s.r_crest - 0.02 * dmax;
  s.initial = place(ps, r_place, set.wall_omega, static_cast<unsigned long long>(spec.seed),
                    placement_blame(ch, spec, dmax));
  return s;
}

ChargeResult run_dem(const ChargeInput& in, DemRunInfo* info_out) {
  return run_dem(in, make_dem_setup(in), info_out);
}

ChargeResult run_dem(const ChargeInput& in, DemSetup setup, DemRunInfo* info_out) {
  const auto t_start = std::chrono::steady_clock::now();
  const DemSpec& spec = in.model.dem;
  const ParticleSet& ps = setup.particles;
  const LinerSurface& surface = *in.surface;
  const double dt = setup.settings.dt;
  const double revs = in.revolutions > 0 ? in.revolutions : spec.revolutions;
  const long long settle_steps = std::llround(spec.settle_revolutions * setup.revolution_s / dt);
  const long long avg_steps = std::max<long long>(1, std::llround(revs * setup.revolution_s / dt));
  // 72 samples a revolution: the lifters move 5 deg between samples.
  const long long sample_every = std::max<long long>(1, std::llround(setup.revolution_s / 72 / dt));

  DemSystem sys(setup.settings, setup.walls, setup.initial);
  const int n = sys.size();
  const double sense = in.mill.sense();

  ParticleIndicatorGeometry g;
  g.sense = sense;
  g.omega = in.mill.omega_rad_s();
  g.r_eff = setup.r_eff;
  g.r_crest = setup.r_crest;
  g.r_shell = surface.shell_radius_m;
  g.pocket_area = std::max(0.0, setup.free_area - kPi * setup.r_crest * setup.r_crest);
  g.mean_diameter = setup.mean_diameter;
  ParticleIndicators pind(g);

  ChargeResult res;
  res.model = "dem";
  const auto t_int0 = std::chrono::steady_clock::now();
  const double all_steps = static_cast<double>(settle_steps + avg_steps);
  for (long long done = 0; done < settle_steps; done += sample_every) {  // in chunks: the thread count adapts
    sys.advance(std::min(sample_every, settle_steps - done));
    if (in.progress) in.progress(static_cast<double>(std::min(done + sample_every, settle_steps)) / all_steps);
  }
  sys.set_accumulate(true);
  const long long pc0 = sys.pair_contact_steps(), wc0 = sys.wall_contact_steps();
  const long long last_rev_start = avg_steps - std::llround(setup.revolution_s / dt);
  long long done = 0, sample_no = 0;
  std::vector<double> seg_fx(surface.segments), seg_fy(surface.segments);
  double sum_mx = 0;  // [kg m/m] sum over samples of sum m x
  while (done < avg_steps) {
    const long long chunk = std::min(sample_every, avg_steps - done);
    if (chunk > 1) sys.advance(chunk - 1);
    sys.record_contacts_next_step();
    sys.advance(1);
    done += chunk;
    ++sample_no;
    if (in.progress) in.progress(static_cast<double>(settle_steps + done) / all_steps);
    // occupancy sample
    ParticleFrame f;
    f.n = n;
    f.x = sys.x().data(), f.y = sys.y().data(), f.vx = sys.vx().data(), f.vy = sys.vy().data();
    f.radius = sys.radius().data(), f.mass = sys.mass().data(), f.contacts = sys.contacts().data();
    pind.add_sample(f);
    for (int i = 0; i < n; ++i) sum_mx += f.mass[i] * f.x[i];
    // force on each lifter row
    std::fill(seg_fx.begin(), seg_fx.end(), 0.0), std::fill(seg_fy.begin(), seg_fy.end(), 0.0);
    for (const auto& c : sys.take_contact_records()) {
      const int k = surface.element_segment[c.element];
      seg_fx[k] += c.fx, seg_fy[k] += c.fy;
    }
    for (int k = 0; k < surface.segments; ++k) {
      const double a = surface.segment_centre_rad(k) + sys.wall_angle();
      const double ca = std::cos(a), sa = std::sin(a);
      pind.add_lifter_force(a, seg_fx[k] * ca + seg_fy[k] * sa, -sense * (-seg_fx[k] * sa + seg_fy[k] * ca));
    }
    if (in.record_snapshot && done > last_rev_start && sample_no % 6 == 0) {
      ChargeSnapshot snap;
      snap.time_s = sys.time();
      snap.liner_angle_rad = sys.wall_angle();  // the physical frame's turn, as the layer model's
      for (int i = 0; i < n; ++i) {
        snap.position.emplace_back(sys.x()[i], sys.y()[i]);
        snap.radius_m.push_back(sys.radius()[i]);
        snap.state.push_back(sys.contacts()[i] > 0 ? 0 : 1);
      }
      res.snapshots.push_back(std::move(snap));
    }
  }
  const double t_int = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_int0).count();

  // Liner loads (time averages per metre of length).
  const WallLoadSums sums = sys.load_sums();
  const double dur = sums.duration;
  LinerLoads& L = res.loads;
  L.reset(surface.n_elements(), dur);
  // Coarse-graining by s (docs/models/dem.md §3, "Wall loads"): the forces
  // on the liner are the charge's and need no scaling, but two things scale
  // with the disc size. The slip of a disc's contact point against the liner
  // in the sheared bed is about the shear rate times its radius, s times the
  // real ball's; and a coarse disc at the wall stands for s^2 real bodies of
  // which only about s lie in the real wall layer. Slip and impact rates are
  // divided by s. Measured on Qiu and pilot tests 1 and 12 (s = 1.3-1.8):
  // without the division the wall slip and the real impact rate grew as about
  // s; with it they stay within 10 % of the media-size run
  // (docs/validation/speed-accuracy.md).
  const double s_cg = ps.coarse_grain;
  for (int e = 0; e < surface.n_elements(); ++e) {
    L.normal_force_n_per_m[e] = sums.normal[e] / dur;
    L.shear_force_n_per_m[e] = sums.shear[e] / dur;
    L.normal_slip_power_w_per_m[e] = sums.normal_slip[e] / dur / s_cg;
    L.shear_work_rate_w_per_m[e] = sums.shear_slip[e] / dur / s_cg;
    L.slip_speed_m_s[e] = sums.normal[e] > 0 ? sums.normal_slip[e] / sums.normal[e] / s_cg : 0.0;
  }
  // Impacts: a disc stands for m'/m_real real balls or rocks per metre of
  // length, of which 1/s are at the wall (above).
  L.has_impacts = true;
  double direct_mass = 0, all_mass = 0;
  const auto impacts = sys.take_impacts();
  L.impacts.reserve(impacts.size());
  for (const auto& r : impacts) {
    ImpactEvent ev;
    ev.element = r.element;
    ev.normal_speed_m_s = r.normal_speed;
    ev.tangential_speed_m_s = r.tangential_speed;
    ev.mass_kg = ps.real_mass_kg[r.particle];
    ev.diameter_m = ps.real_diameter_m[r.particle];
    ev.rate_per_s = ps.mass_kg_per_m[r.particle] / ps.real_mass_kg[r.particle] / dur / s_cg;
    // thrown onto the liner: airborne at least as long as a free fall of its own diameter
    ev.direct = r.free_steps * dt >= std::sqrt(2 * 2 * ps.radius_m[r.particle] / kGravity);
    const double mass_rate = ev.mass_kg * ev.rate_per_s;
    all_mass += mass_rate;
    if (ev.direct) direct_mass += mass_rate;
    L.impacts.push_back(ev);
  }

  // Indicators.
  Indicators& I = res.indicators;
  pind.finish(I);
  const double p_per_m = sums.drive_work / dur;  // P = T omega (2D slice, per metre)
  I.net_power_w_per_m = p_per_m;
  I.net_power_kw = p_per_m * in.mill.length_m / 1000.0;
  I.diameter_eff_m = 2 * setup.r_eff;
  I.fraction_critical = in.mill.speed_rpm / critical_speed_rpm(I.diameter_eff_m);
  // No-load power, thesis eq. 4.2 (Morrell 1996), no cone ends: 1.68 D^2.05 [phi L]^0.82 [kW].
  I.no_load_power_kw = 1.68 * std::pow(I.diameter_eff_m, 2.05) * std::pow(I.fraction_critical * in.mill.length_m, 0.82);
  I.gross_power_kw = I.no_load_power_kw + I.net_power_kw;
  I.alt_net_power_kw = std::numeric_limits<double>::quiet_NaN();
  I.direct_impact_fraction = all_mass > 0 ? direct_mass / all_mass : 0.0;

  // Statistics.
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  // A disc touching more liner elements at once than the contact list holds
  // (a concave pocket of many short elements) loses its shallowest contacts;
  // one touching more than the spring slots hold loses the static friction of
  // the extra ones. Neither is expected on a liner remeshed at its element
  // size; both are reported, never silent (docs/models/dem.md §4).
  if (sys.wall_hits_dropped() > 0 || sys.wall_springs_dropped() > 0)
    res.notes.push_back(fmt::format(
        "{} disc-liner contacts beyond the {} one disc can hold were dropped (the shallowest) and {} kept no "
        "tangential spring (beyond {}), out of {} disc-liner contact evaluations: the liner has pockets of "
        "many short elements; check the profile or coarsen [remesh] element_size_m",
        sys.wall_hits_dropped(), DemSystem::kMaxWallHits, sys.wall_springs_dropped(), DemSystem::kWallSlots,
        sys.wall_contact_steps()));
  if (const std::string note = settling_note("[dem] settle_revolutions", spec.settle_revolutions, revs); !note.empty())
    res.notes.push_back(note);
  RunStats& st = res.stats;
  st.simulated_s = sys.time();
  st.wall_s = wall;
  st.realtime_ratio = st.simulated_s / wall;
  st.steps = sys.step_count();
  st.elements = n;
  st.time_step_s = dt;
  st.particle_steps_per_s = static_cast<double>(n) * st.steps / t_int;
  st.contacts_per_s = static_cast<double>(sys.pair_contact_steps() + sys.wall_contact_steps()) / t_int;
  if (info_out) {
    DemRunInfo& info = *info_out;
    info.particles = n, info.balls = ps.n_balls, info.rocks = ps.n_rocks;
    info.coarse_grain = ps.coarse_grain;
    info.collision_time_s = setup.collision_time_s;
    info.time_step_s = dt;
    info.steps_per_collision = setup.collision_time_s / dt;
    double mmin = *std::min_element(ps.mass_kg_per_m.begin(), ps.mass_kg_per_m.end());
    info.particle_stiffness = setup.settings.particle.stiffness(0.5 * mmin);
    info.settle_s = settle_steps * dt, info.average_s = dur;
    info.steps = st.steps;
    info.threads = setup.settings.threads;
    info.wall_s = wall;
    info.integrate_wall_s = t_int;
    info.particle_steps_per_s = st.particle_steps_per_s;
    info.contacts_per_s = st.contacts_per_s;
    // coordination number: a particle contact touches two discs
    info.mean_contacts = static_cast<double>(2 * (sys.pair_contact_steps() - pc0) + sys.wall_contact_steps() - wc0) /
                         (static_cast<double>(avg_steps) * n);
    info.list_builds = sys.list_builds();
    info.max_overlap_ratio = sys.max_overlap_ratio();
    info.max_wall_overlap_ratio = sys.max_wall_overlap_ratio();
    info.wall_hits_dropped = sys.wall_hits_dropped();
    info.wall_springs_dropped = sys.wall_springs_dropped();
    info.impacts = static_cast<long long>(L.impacts.size());
    info.drive_power_w_per_m = p_per_m;
    info.torque_arm_power_w_per_m = setup.settings.wall_omega * kGravity * sum_mx / std::max<long long>(1, sample_no);
    info.charge_mass_kg_per_m = ps.ball_mass_kg_per_m + ps.rock_mass_kg_per_m;
    info.band_occupancy = pind.band_profile();
  }
  return res;
}

namespace {

class DemModel : public ChargeModel {
 public:
  ChargeResult run(const ChargeInput& in) const override { return run_dem(in); }
};

}  // namespace

std::unique_ptr<ChargeModel> make_dem_model() { return std::make_unique<DemModel>(); }

}  // namespace linerlife
