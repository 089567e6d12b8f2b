#include "geometry/build_liner_surface.h"

#include <cmath>

#include <fmt/format.h>

#include "geometry/errors.h"
#include "geometry/measured_profile.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;

double polar_angle(const V& p) { return std::atan2(p.y(), p.x()); }
V on_circle(double r, double th) { return {r * std::cos(th), r * std::sin(th)}; }

/// Appends the points of the arc of radius r from angle a to angle b (both
/// included unless skip_first), with chords no longer than h.
void append_arc(std::vector<V>& out, double r, double a, double b, double h, bool skip_first) {
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(b - a) * r / h)));
  for (int i = skip_first ? 1 : 0; i <= n; ++i) out.push_back(on_circle(r, a + (b - a) * i / n));
}

/// Appends the straight line from p to q (p excluded), pieces no longer than h.
void append_line(std::vector<V>& out, const V& p, const V& q, double h) {
  const int n = std::max(1, static_cast<int>(std::ceil((q - p).norm() / h)));
  for (int i = 1; i <= n; ++i) out.push_back(p + (q - p) * (static_cast<double>(i) / n));
}

/// Point where the line top + t d (t >= 0) meets the circle of radius r.
V meet_circle(const V& top, const V& d, double r) {
  const double b = top.dot(d), c = top.squaredNorm() - r * r;
  return top + (-b + std::sqrt(std::max(0.0, b * b - c))) * d;
}

/// The foot of a straight face leaving top corner `top` towards the plate
/// circle of radius rp, on side s (+1: towards +theta), at angle alpha from the
/// radial through the face's point at mid-height of the lifter (radius r_mid).
/// Fixed-point iteration on the angle of that point; converges in a few steps
/// because the face is short against the radius.
V face_foot(const V& top, double rp, double r_mid, double alpha, double s) {
  double phi = polar_angle(top);
  for (int it = 0; it < 100; ++it) {
    const V er(std::cos(phi), std::sin(phi));
    const V et(-std::sin(phi), std::cos(phi));
    const V d = std::cos(alpha) * er + s * std::sin(alpha) * et;
    const double phi_new = polar_angle(meet_circle(top, d, r_mid));
    if (std::abs(phi_new - phi) < 1e-16) break;
    phi = phi_new;
  }
  const V d = std::cos(alpha) * V(std::cos(phi), std::sin(phi)) + s * std::sin(alpha) * V(-std::sin(phi), std::cos(phi));
  return meet_circle(top, d, rp);
}

/// Replaces the corner p (between neighbours a and b) by a fillet of radius rc,
/// sampled with chords no longer than h; returns the points in order a -> b,
/// without a and b. Throws when the fillet does not fit on the shorter leg.
std::vector<V> fillet(const V& a, const V& p, const V& b, double rc, double h, double max_leg_a, double max_leg_b,
                      const char* key) {
  const V e1 = (a - p).normalized(), e2 = (b - p).normalized();
  const double beta = 0.5 * std::acos(std::clamp(e1.dot(e2), -1.0, 1.0));
  const double dt = rc / std::tan(beta);
  if (dt > max_leg_a || dt > max_leg_b)
    throw InputError(key, fmt::format("corner_radius_m = {} does not fit on the lifter: the fillet needs {:.4g} m "
                                      "of each leg but the shorter leg is {:.4g} m",
                                      rc, dt, std::min(max_leg_a, max_leg_b)));
  const V p1 = p + dt * e1, p2 = p + dt * e2;
  const V c = p + rc / std::sin(beta) * (e1 + e2).normalized();
  double a1 = polar_angle(p1 - c), a2 = polar_angle(p2 - c);
  // take the short way round
  double da = a2 - a1;
  while (da > kPi) da -= 2 * kPi;
  while (da < -kPi) da += 2 * kPi;
  std::vector<V> out{p1};
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(da) * rc / h)));
  for (int i = 1; i <= n; ++i) out.push_back(c + on_circle(rc, a1 + da * i / n));
  return out;
}

struct Trapezoid {
  V trail_foot, trail_top, lead_top, lead_foot;  // in anticlockwise order (-theta side first)
};

/// Key points of design d on a segment centred at angle 0. `lead_sign` is +1
/// when the leading face is on the +theta side (anticlockwise mill).
Trapezoid trapezoid(double R, const LifterDesign& d, double lead_sign) {
  const double deg = kPi / 180.0;
  const double rp = R - d.plate_thickness_m;
  const double xt = rp - d.lifter_height_m;  // top chord along the centreline
  const double a_plus = (lead_sign > 0 ? d.face_angle_leading_deg : d.face_angle_trailing_deg) * deg;
  const double a_minus = (lead_sign > 0 ? d.face_angle_trailing_deg : d.face_angle_leading_deg) * deg;
  Trapezoid t;
  t.lead_top = V(xt, 0.5 * d.top_width_m);
  t.trail_top = V(xt, -0.5 * d.top_width_m);
  const double r_mid = rp - 0.5 * d.lifter_height_m;
  t.lead_foot = face_foot(t.lead_top, rp, r_mid, a_plus, +1);
  t.trail_foot = face_foot(t.trail_top, rp, r_mid, a_minus, -1);
  return t;
}

}  // namespace

void validate_lifter_design(const Mill& mill, int segments, const LifterDesign& d, double h, const char* prefix) {
  const double R = mill.shell_radius_m();
  auto key = [&](const char* name) { return std::string(prefix) + name; };
  // the key as the user wrote it: "low_lifter_height_m" for the low lifter of a hi-lo liner
  const std::string pfx(prefix);
  const std::string written = pfx.rfind("liner.", 0) == 0 ? pfx.substr(6) : pfx;
  auto nm = [&](const char* name) { return written + name; };
  if (!(d.plate_thickness_m > 0 && d.plate_thickness_m <= 0.25 * R))
    throw InputError(key("plate_thickness_m"),
                     fmt::format("{} = {} m: must be > 0 and at most a quarter of the shell radius ({:.4g} m)",
                                 nm("plate_thickness_m"), d.plate_thickness_m, 0.25 * R));
  if (!(d.lifter_height_m >= 0 && d.lifter_height_m <= 0.25 * R))
    throw InputError(key("lifter_height_m"),
                     fmt::format("{} = {} m: a lifter taller than a quarter of the shell radius "
                                 "({:.4g} m) is not a mill liner; allowed 0 to {:.4g} m",
                                 nm("lifter_height_m"), d.lifter_height_m, 0.25 * R, 0.25 * R));
  for (auto [name, a] : {std::pair<const char*, double>{"face_angle_leading_deg", d.face_angle_leading_deg},
                         {"face_angle_trailing_deg", d.face_angle_trailing_deg}})
    if (!(a >= 0 && a < 80))
      throw InputError(key(name), fmt::format("{} = {} deg: allowed 0 <= angle < 80 deg (measured from the radial; "
                                              "undercut faces are not supported)",
                                              name, a));
  if (d.lifter_height_m == 0) return;
  const double rp = R - d.plate_thickness_m;
  const double xt = rp - d.lifter_height_m;
  const double seg = 2 * kPi / segments;
  const double chord_at_top = 2 * xt * std::sin(0.5 * seg);
  if (!(d.top_width_m > 0 && d.top_width_m < chord_at_top))
    throw InputError(key("lifter_top_width_m"),
                     fmt::format("{} = {} m: must be > 0 and narrower than the segment at the lifter "
                                 "top ({:.4g} m for {} segments)",
                                 nm("lifter_top_width_m"), d.top_width_m, chord_at_top, segments));
  const double feature = std::min({d.lifter_height_m, d.top_width_m});
  // the dimension that sets `feature`, named by both refusals below
  const bool top = d.top_width_m <= d.lifter_height_m;
  const char* limit = top ? "lifter_top_width_m" : "lifter_height_m";
  // A lifter feature narrower than four of the finest elements allowed
  // cannot be meshed at any element_size_m: name the feature, not the
  // element size (the message below asked for an element_size_m under its
  // own 1 mm floor for a 3 mm top).
  if (0.25 * feature < kMinElementSizeM) {
    throw InputError(key(limit),
                     fmt::format("{} = {} m is under four of the finest surface elements (element_size_m >= {} m), "
                                 "so no mesh resolves the lifter; allowed {} >= {} m{}",
                                 nm(limit), feature, kMinElementSizeM, nm(limit), 4 * kMinElementSizeM,
                                 top ? "" : fmt::format(", or {} = 0 for no lifter", nm("lifter_height_m"))));
  }
  if (h > 0.25 * feature) {
    // name the dimension that limits it, as written ("low_lifter_height_m"
    // for the low lifter of a hi-lo liner), with its value
    throw InputError("liner.element_size_m",
                     fmt::format("element_size_m = {} m is too coarse to resolve the {}lifter ({} = {} m): it must be "
                                 "at most a quarter of its height and top width ({:.4g} m)",
                                 h, written.empty() ? "" : "low ", nm(limit), feature, 0.25 * feature));
  }
  const Trapezoid t = trapezoid(R, d, +1);
  const double lead_half = std::abs(polar_angle(t.lead_foot)), trail_half = std::abs(polar_angle(t.trail_foot));
  const double half_base = std::max(lead_half, trail_half);
  const double plate_left = (0.5 * seg - half_base) * rp;  // plate arc on each side of the lifter
  if (plate_left < h) {
    // The blame (and the line number): for the lifter, the face whose foot
    // reaches furthest from its centre line; for the low lifter of a hi-lo
    // liner, which shares the faces with the high one that fitted, its top
    // width. Every value that sets the base is quoted, with what is allowed.
    const bool low = std::string(prefix) == "liner.low_";
    const bool lead = lead_half >= trail_half;
    const std::string w = low ? "low_lifter_top_width_m" : "lifter_top_width_m";
    const std::string hk = low ? "low_lifter_height_m" : "lifter_height_m";
    const std::string blamed = low ? w : lead ? "face_angle_leading_deg" : "face_angle_trailing_deg";
    const std::string value = low ? fmt::format("{} m", d.top_width_m)
                                  : fmt::format("{} deg", lead ? d.face_angle_leading_deg : d.face_angle_trailing_deg);
    throw InputError("liner." + blamed,
                     fmt::format("{} = {}: the {}lifter base does not fit in its segment: the foot of its {} face lies "
                                 "{:.4g} m along the plate from its centre line (from {} = {} m, {} = {} m, "
                                 "face_angle_leading_deg = {} deg, "
                                 "face_angle_trailing_deg = {} deg); allowed at most {:.4g} m, half the segment "
                                 "({:.4g} m) less one surface element ({} m) of plate; make the faces steeper (smaller "
                                 "angles), the lifter narrower or lower, or use fewer segments",
                                 blamed, value, low ? "low " : "", lead ? "leading" : "trailing", half_base * rp, w,
                                 d.top_width_m, hk,
                                 d.lifter_height_m, d.face_angle_leading_deg, d.face_angle_trailing_deg,
                                 0.5 * seg * rp - h, 0.5 * seg * rp, h));
  }
  if (d.corner_radius_m < 0)
    throw InputError(key("corner_radius_m"), fmt::format("corner_radius_m = {} m: must be >= 0", d.corner_radius_m));
}

std::vector<Eigen::Vector2d> segment_profile(const Mill& mill, const LinerDesign& design, int which) {
  const double R = mill.shell_radius_m();
  const double seg = 2 * kPi / design.segments;
  const double h = design.element_size_m;
  std::vector<V> out;
  if (design.measured) return measured_profile_to_segment(design.profile, R, design.segments, h);

  const LifterDesign& d = which == 0 ? design.design : design.low;
  const double rp = R - d.plate_thickness_m;
  if (d.lifter_height_m == 0) {
    append_arc(out, rp, -0.5 * seg, 0.5 * seg, h, false);
    return out;
  }
  const Trapezoid t = trapezoid(R, d, mill.sense());
  append_arc(out, rp, -0.5 * seg, polar_angle(t.trail_foot), h, false);
  out.back() = t.trail_foot;
  if (d.corner_radius_m > 0) {
    const double face_trail = (t.trail_top - t.trail_foot).norm(), face_lead = (t.lead_top - t.lead_foot).norm();
    const double half_top = 0.5 * d.top_width_m;
    auto f1 = fillet(t.trail_foot, t.trail_top, t.lead_top, d.corner_radius_m, h, face_trail, half_top,
                     "liner.corner_radius_m");
    auto f2 = fillet(t.trail_top, t.lead_top, t.lead_foot, d.corner_radius_m, h, half_top, face_lead,
                     "liner.corner_radius_m");
    append_line(out, t.trail_foot, f1.front(), h);
    out.insert(out.end(), f1.begin() + 1, f1.end());
    append_line(out, f1.back(), f2.front(), h);
    out.insert(out.end(), f2.begin() + 1, f2.end());
    append_line(out, f2.back(), t.lead_foot, h);
  } else {
    append_line(out, t.trail_foot, t.trail_top, h);
    append_line(out, t.trail_top, t.lead_top, h);
    append_line(out, t.lead_top, t.lead_foot, h);
  }
  append_arc(out, rp, polar_angle(t.lead_foot), 0.5 * seg, h, true);
  return out;
}

LinerSurface build_liner_surface(const Mill& mill, const LinerDesign& design) {
  if (design.segments < kMinSegments)
    throw InputError("liner.segments",
                     fmt::format("segments = {}: must be at least {} (one row's segment is the whole ring)",
                                 design.segments, kMinSegments));
  if (design.hi_lo && design.segments % 2 != 0)
    throw InputError("liner.segments",
                     fmt::format("segments = {}: a hi-lo pattern needs an even number of segments", design.segments));
  if (!design.measured) {
    validate_lifter_design(mill, design.segments, design.design, design.element_size_m, "liner.");
    if (design.hi_lo) validate_lifter_design(mill, design.segments, design.low, design.element_size_m, "liner.low_");
  }
  const int n_designs = design.hi_lo ? 2 : 1;
  std::vector<std::vector<V>> profiles;
  for (int k = 0; k < n_designs; ++k) profiles.push_back(segment_profile(mill, design, k));

  std::vector<int> design_of(static_cast<size_t>(design.segments), 0);
  if (design.hi_lo)
    for (int k = 0; k < design.segments; ++k) design_of[static_cast<size_t>(k)] = k % 2;
  return assemble_ring(mill.shell_radius_m(), design.segments, profiles, design_of);
}

std::vector<Eigen::Vector2d> rotate_points(const std::vector<Eigen::Vector2d>& p, double angle) {
  const double c = std::cos(angle), sn = std::sin(angle);
  std::vector<Eigen::Vector2d> out;
  out.reserve(p.size());
  for (const auto& q : p) out.emplace_back(c * q.x() - sn * q.y(), sn * q.x() + c * q.y());
  return out;
}

LinerSurface assemble_ring(double R, int segments, const std::vector<std::vector<Eigen::Vector2d>>& profiles,
                           const std::vector<int>& segment_design) {
  LinerSurface s;
  s.shell_radius_m = R;
  s.segments = segments;
  const double seg = 2 * kPi / segments;
  for (int k = 0; k < segments; ++k) {
    const int which = segment_design[static_cast<size_t>(k)];
    s.segment_begin.push_back(s.n_nodes());
    s.segment_design.push_back(which);
    const auto p = rotate_points(profiles[static_cast<size_t>(which)], k * seg);
    // the last node of a segment profile is the first of the next one
    for (size_t i = 0; i + 1 < p.size(); ++i) s.nodes.push_back(p[i]);
  }
  s.segment_begin.push_back(s.n_nodes());
  s.finalize();
  return s;
}

}  // namespace linerlife
