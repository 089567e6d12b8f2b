#include "geometry/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Eigenvalues>

namespace linerlife {
namespace {

using V = Eigen::Vector2d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double cross(const V& a, const V& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The nodes of segment k, both edge nodes included, in anticlockwise order.
std::vector<V> segment_nodes(const LinerSurface& s, int k) {
  std::vector<V> out;
  for (int i = s.segment_begin[k]; i < s.segment_begin[k + 1]; ++i) out.push_back(s.nodes[i]);
  out.push_back(s.nodes[s.segment_begin[k + 1] % s.n_nodes()]);
  return out;
}

/// Walks from the crest index towards `step` (+1 or -1) and returns the first
/// point where the thickness falls below `level` (linear interpolation), and
/// the index of the last vertex still at or above it.
bool first_crossing(const std::vector<V>& p, const std::vector<double>& t, int crest, int step, double level, V& where,
                    int& last_above) {
  for (int i = crest; i + step >= 0 && i + step < static_cast<int>(p.size()); i += step) {
    const int j = i + step;
    if (t[j] < level) {
      const double f = (t[i] - level) / (t[i] - t[j]);
      where = p[i] + f * (p[j] - p[i]);
      last_above = i;
      return true;
    }
  }
  return false;
}

/// The same crossing found from the outside in: walks from the segment's end
/// on side `step` (the plate) towards the crest and returns the first place
/// where the thickness rises to `level`, as the same pair of vertices (the one
/// at or above it on the crest's side first). On a face whose thickness falls
/// steadily from the crest to the plate it is first_crossing()'s point; on a
/// top that wear has hollowed into a groove deeper than the band (two horns)
/// it is still on the lifter's flank, where a walk from the higher horn would
/// go down into the groove. False if the end itself is at or above `level`.
bool flank_crossing(const std::vector<V>& p, const std::vector<double>& t, int crest, int step, double level, V& where,
                    int& last_above) {
  const int end = step > 0 ? static_cast<int>(p.size()) - 1 : 0;
  if (t[end] >= level) return false;
  for (int j = end; j != crest; j -= step) {
    const int i = j - step;
    if (t[i] >= level) {
      const double f = (t[i] - level) / (t[i] - t[j]);
      where = p[i] + f * (p[j] - p[i]);
      last_above = i;
      return true;
    }
  }
  return false;
}

/// A straight line fitted to one lifter face.
struct FaceFit {
  bool ok = false;
  V centroid, direction;  // direction points outwards, to the plate
  double angle_deg = kNaN;
};

/// Fits the face on side `step` from the crest (+1 towards +theta) over the
/// thickness band [lo, hi] by a length-weighted total least squares line. The
/// angle is measured from the radial through the fit's centroid, positive when
/// the face leans away from the lifter towards the plate (0 radial, 90 flat on
/// the shell, beyond 90 a face worn into a ledge that rises away from the
/// crest; negative undercut). The band's ends are
/// found from the plate inwards (flank_crossing(): a grooved top does not
/// count as the face); where the plate itself is as thick as the band's end,
/// from the crest outwards (first_crossing()).
FaceFit fit_face(const std::vector<V>& p, const std::vector<double>& t, int crest, int step, double lo, double hi) {
  FaceFit f;
  V phi, plo;
  int ihi = 0, ilo = 0;
  if (!flank_crossing(p, t, crest, step, lo, plo, ilo) || !flank_crossing(p, t, crest, step, hi, phi, ihi)) {
    if (!first_crossing(p, t, crest, step, hi, phi, ihi)) return f;
    if (!first_crossing(p, t, crest, step, lo, plo, ilo)) return f;
  }
  std::vector<V> chain{phi};
  for (int i = ihi + step; step > 0 ? i <= ilo : i >= ilo; i += step) chain.push_back(p[i]);
  chain.push_back(plo);
  // length-weighted moments of the polyline
  double L = 0;
  V m1 = V::Zero();
  Eigen::Matrix2d m2 = Eigen::Matrix2d::Zero();
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    const V& a = chain[i];
    const V& b = chain[i + 1];
    const double l = (b - a).norm();
    if (l <= 0) continue;
    L += l;
    m1 += 0.5 * l * (a + b);
    m2 += l / 3.0 * (a * a.transpose() + 0.5 * (a * b.transpose() + b * a.transpose()) + b * b.transpose());
  }
  if (L <= 0) return f;
  const V c = m1 / L;
  const Eigen::Matrix2d cov = m2 / L - c * c.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(cov);
  V d = es.eigenvectors().col(1);  // largest eigenvalue
  const V er = c.normalized();
  // Oriented like the band's chord, from its upper end to its lower one (to
  // the plate), not by the sign of its radial part: a face worn almost flat
  // has a fitted line nearly tangential, whose radial part changes sign as it
  // tilts through 90 deg, and the reading jumped from +90 to -90 deg there
  // (docs/validation/forecast.md, the explicit step at A = 1e6). Where the
  // radial part is not small both orientations agree.
  if (d.dot(plo - phi) < 0) d = -d;
  const V et = step * V(-er.y(), er.x());  // away from the crest
  f.ok = true;
  f.centroid = c;
  f.direction = d;
  f.angle_deg = std::atan2(d.dot(et), d.dot(er)) * 180.0 / kPi;
  return f;
}

/// Where the fitted face line meets the line tangent to the crest (the line
/// perpendicular to the crest's radial at the crest).
V meet_crest_tangent(const FaceFit& f, const V& crest) {
  const V e = crest.normalized();
  const double denom = f.direction.dot(e);
  const double s = std::abs(denom) > 1e-12 ? (crest.norm() - f.centroid.dot(e)) / denom : 0.0;
  return f.centroid + s * f.direction;
}

}  // namespace

double segment_area(const LinerSurface& s, int k) {
  const double R = s.shell_radius_m;
  const std::vector<V> p = segment_nodes(s, k);
  double enclosed = 0;  // polyline with the origin, anticlockwise
  for (size_t i = 0; i + 1 < p.size(); ++i) enclosed += 0.5 * cross(p[i], p[i + 1]);
  return 0.5 * R * R * s.segment_angle_rad() - enclosed;
}

double free_area(const LinerSurface& s) {
  double a = 0;
  for (int i = 0; i < s.n_nodes(); ++i) a += 0.5 * cross(s.nodes[i], s.nodes[s.next(i)]);
  return a;
}

SegmentMetrics segment_metrics(const LinerSurface& s, int k, Rotation rotation, double density) {
  SegmentMetrics m;
  m.segment = k;
  m.design = s.segment_design.empty() ? 0 : s.segment_design[k];
  const double R = s.shell_radius_m;
  const std::vector<V> p = segment_nodes(s, k);
  std::vector<double> t(p.size());
  for (size_t i = 0; i < p.size(); ++i) t[i] = R - p[i].norm();
  m.area_m2 = segment_area(s, k);
  m.mass_kg_per_m = m.area_m2 * density;
  m.min_thickness_m = *std::min_element(t.begin(), t.end());
  const int crest = static_cast<int>(std::max_element(t.begin(), t.end()) - t.begin());
  // The crest is the point of the polyline closest to the mill axis; it can lie
  // inside an element (the middle of a flat chordal top).
  V crest_point = p[crest];
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    const V ab = p[i + 1] - p[i];
    const double l2 = ab.squaredNorm();
    if (l2 <= 0) continue;
    const V q = p[i] + std::clamp(-p[i].dot(ab) / l2, 0.0, 1.0) * ab;
    if (q.norm() < crest_point.norm()) crest_point = q;
  }
  m.max_thickness_m = R - crest_point.norm();
  m.crest_angle_rad = std::atan2(crest_point.y(), crest_point.x());
  m.plate_ref_thickness_m = 0.5 * (t.front() + t.back());
  m.lifter_height_m = std::max(0.0, m.max_thickness_m - m.plate_ref_thickness_m);
  // resolution of the surface: twice the mean element length of the segment
  double len = 0;
  for (size_t i = 0; i + 1 < p.size(); ++i) len += (p[i + 1] - p[i]).norm();
  const double resolution = 2.0 * len / static_cast<double>(p.size() - 1);
  m.has_lifter = m.lifter_height_m > resolution;
  m.face_angle_leading_deg = m.face_angle_trailing_deg = m.top_width_m = kNaN;
  if (!m.has_lifter) return m;
  const double lo = m.plate_ref_thickness_m + 0.2 * m.lifter_height_m;
  const double hi = m.plate_ref_thickness_m + 0.8 * m.lifter_height_m;
  const int lead = rotation == Rotation::Ccw ? +1 : -1;
  const FaceFit fplus = fit_face(p, t, crest, +1, lo, hi), fminus = fit_face(p, t, crest, -1, lo, hi);
  m.face_angle_leading_deg = lead > 0 ? fplus.angle_deg : fminus.angle_deg;
  m.face_angle_trailing_deg = lead > 0 ? fminus.angle_deg : fplus.angle_deg;
  if (fplus.ok && fminus.ok) {
    // width between the two face lines at the crest tangent; 0 once they cross
    const V a = meet_crest_tangent(fplus, crest_point), b = meet_crest_tangent(fminus, crest_point);
    const V et(-crest_point.y(), crest_point.x());
    m.top_width_m = std::max(0.0, (a - b).dot(et.normalized()));
  }
  return m;
}

LinerMetrics metrics(const LinerSurface& s, Rotation rotation, double density) {
  LinerMetrics m;
  for (int k = 0; k < s.segments; ++k) {
    m.segments.push_back(segment_metrics(s, k, rotation, density));
    m.area_m2 += m.segments.back().area_m2;
    m.mass_kg_per_m += m.segments.back().mass_kg_per_m;
  }
  m.min_thickness_m = std::min_element(m.segments.begin(), m.segments.end(), [](auto& x, auto& y) {
                        return x.min_thickness_m < y.min_thickness_m;
                      })->min_thickness_m;
  m.free_area_m2 = free_area(s);
  m.effective_diameter_m = 2.0 * std::sqrt(m.free_area_m2 / kPi);
  return m;
}

}  // namespace linerlife
