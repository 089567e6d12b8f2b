#include "geometry/measured_profile.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "geometry/errors.h"
#include "geometry/input_file.h"
#include "geometry/input_text.h"
#include "geometry/mill.h"
#include "geometry/stretch_grid.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

/// What a field parse_decimal refuses is: "a non-finite value" (nan, inf),
/// "a hexadecimal number" (0x1p-3, which strtod reads), "beyond the range of
/// a double" (1e400), or "not a decimal number".
std::string not_decimal(const std::string& field) {
  const char* s = field.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (end != s && end == s + field.size()) {
    if (errno == ERANGE) return "beyond the range of a double";
    if (!std::isfinite(v)) return "a non-finite value";
    const auto x = field.find_first_of("xX");
    if (x != std::string::npos && x > 0 && field[x - 1] == '0') return "a hexadecimal number";
  }
  return "not a decimal number";
}

double cross(const V& a, const V& b) { return a.x() * b.y() - a.y() * b.x(); }

bool segments_intersect(const V& p1, const V& p2, const V& q1, const V& q2) {
  const double d1 = cross(p2 - p1, q1 - p1), d2 = cross(p2 - p1, q2 - p1);
  const double d3 = cross(q2 - q1, p1 - q1), d4 = cross(q2 - q1, p2 - q1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on_seg = [](const V& a, const V& b, const V& p) {
    return std::abs(cross(b - a, p - a)) <= 1e-14 * (b - a).squaredNorm() &&
           p.x() >= std::min(a.x(), b.x()) - 1e-15 && p.x() <= std::max(a.x(), b.x()) + 1e-15 &&
           p.y() >= std::min(a.y(), b.y()) - 1e-15 && p.y() <= std::max(a.y(), b.y()) + 1e-15;
  };
  return on_seg(p1, p2, q1) || on_seg(p1, p2, q2) || on_seg(q1, q2, p1) || on_seg(q1, q2, p2);
}

}  // namespace

bool polyline_self_intersects(const std::vector<V>& pts) { return first_self_crossing(pts).first >= 0; }

std::pair<int, int> first_self_crossing(const std::vector<V>& pts) {
  // The pair a scan of every i, then every j > i + 1, meets first: for each
  // stretch i in turn, the least j among the stretches that share a cell of
  // the grid with it (every stretch that touches it does). Before the grid
  // (2026-12-04) that scan itself ran: 1.25e9 pairs for 50,000 points.
  const int n = static_cast<int>(pts.size());
  if (n < 4) return {-1, -1};
  const StretchGrid grid(pts, 0.0);
  for (int i = 0; i + 1 < n; ++i) {
    int best = n;
    grid.for_each_cell_of_stretch(i, [&](int c) {
      const auto [first, last] = grid.stretches_in(c);
      for (const int* j = std::upper_bound(first, last, i + 1); j != last && *j < best; ++j)
        if (segments_intersect(pts[i], pts[i + 1], pts[*j], pts[*j + 1])) {
          best = *j;
          break;
        }
    });
    if (best < n) return {i, best};
  }
  return {-1, -1};
}

MeasuredProfile parse_profile_csv(const std::string& text, const std::string& source) {
  MeasuredProfile p;
  p.source = source;
  std::istringstream in(without_utf8_bom(text));
  std::string line;
  int lineno = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto comma = t.find(',');
    if (comma == std::string::npos)
      throw InputError(source, fmt::format("{}:{}: expected two comma-separated numbers \"x_m,y_m\", got \"{}\"",
                                           source, lineno, printable(t)));
    const std::string a = t.substr(0, comma), b = t.substr(comma + 1);
    double x = 0, y = 0;
    if (!parse_decimal(a, x) || !parse_decimal(b, y)) {
      if (header_allowed && trim(a) == "x_m" && trim(b) == "y_m") {
        header_allowed = false;
        continue;
      }
      const std::string field = trim(parse_decimal(a, x) ? b : a);
      throw InputError(source, fmt::format("{}:{}: \"{}\" is not a pair of numbers x_m,y_m (metres): \"{}\" is {}; "
                                           "allowed decimal numbers such as 0.075 or 7.5e-2",
                                           source, lineno, printable(t), printable(field), not_decimal(field)));
    }
    header_allowed = false;
    p.points.emplace_back(x, y);
    p.lines.push_back(lineno);
  }
  if (p.points.size() < 3)
    throw InputError(source, fmt::format("{}: a profile needs at least 3 points, found {}", source, p.points.size()));
  return p;
}

MeasuredProfile load_profile_csv(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, fmt::format("profile file {} does not exist", printable(path)));
  if (fs::is_directory(path, ec)) throw InputError(path, fmt::format("profile file {} is a directory", printable(path)));
  const std::string text = read_input_file(path, "profile file");
  return parse_profile_csv(text, path);
}

void validate_measured_profile(const MeasuredProfile& p, double R, int segments) {
  const double width = 2 * kPi * R / segments;
  const auto& pts = p.points;
  // "point 3 (line 5)": the point's number and, for a file, its line
  auto pt = [&](size_t i) {
    return i < p.lines.size() && p.lines.size() == pts.size() ? fmt::format("point {} (line {})", i + 1, p.lines[i])
                                                              : fmt::format("point {}", i + 1);
  };
  const double tol = 1e-3;
  if (std::abs(pts.front().x()) > tol || std::abs(pts.back().x() - width) > tol)
    throw InputError(p.source, fmt::format("{}: x must run from 0 to the segment width pi D / segments = {:.4f} m "
                                           "(within 1 mm); it runs from {:.4f} m at {} to {:.4f} m at {}",
                                           p.source, width, pts.front().x(), pt(0), pts.back().x(), pt(pts.size() - 1)));
  for (size_t i = 0; i < pts.size(); ++i) {
    if (pts[i].x() < -tol || pts[i].x() > width + tol)
      throw InputError(p.source, fmt::format("{}: {} has x = {} m, outside its segment [0, {:.4f}] m", p.source,
                                             pt(i), pts[i].x(), width));
    if (!(pts[i].y() > 0))
      throw InputError(p.source, fmt::format("{}: {} has y = {} m: the profile must stay inside the shell "
                                             "(thickness y > 0)",
                                             p.source, pt(i), pts[i].y()));
    if (!(pts[i].y() < 0.5 * R))
      throw InputError(p.source, fmt::format("{}: {} has y = {} m: thicker than half the shell radius ({:.4g} m)",
                                             p.source, pt(i), pts[i].y(), 0.5 * R));
  }
  if (std::abs(pts.front().y() - pts.back().y()) > tol)
    throw InputError(p.source, fmt::format("{}: the first and last thickness differ ({} m at {} vs {} m at {}); the "
                                           "profile repeats round the ring, so both ends must match within 1 mm",
                                           p.source, pts.front().y(), pt(0), pts.back().y(), pt(pts.size() - 1)));
  // Only the two ends lie on the segment edges. A radial step on an edge (the
  // next point still on it) makes the ring run back along the edge between
  // two segments, and a later point back on the edge touches the ring there
  // (the edge is the radial line the old body closes along); the remesh
  // cannot keep either simple (fuzz_remesh, corpus remesh-crash-f307528c,
  // remesh-crash-d0914b3b and remesh-crash-96d36db2).
  const size_t n = pts.size();
  for (size_t i = 1; i + 1 < n; ++i)
    if (pts[i].x() <= tol || pts[i].x() >= width - tol) {
      const bool at_start = pts[i].x() <= tol;
      const bool step = i == 1 ? at_start : (i == n - 2 && !at_start);
      throw InputError(p.source,
                       fmt::format("{}: {} lies on the segment edge as well as {}: {} is not allowed; move it at "
                                   "least 1 mm into the segment",
                                   p.source, pt(i), at_start ? pt(0) : pt(n - 1),
                                   step ? "a radial step on the edge" : "only the two ends may lie on the edges, a "
                                                                        "point that returns to an edge"));
    }
  // detail finer than kMinProfileDetailM (a point repeated, a needle): checked
  // before the crossings, which a repeated point would be reported as
  const double d_min = kMinProfileDetailM;
  for (size_t i = 0; i + 1 < n; ++i) {
    const double d = (pts[i + 1] - pts[i]).norm();
    if (d < d_min)
      throw InputError(p.source, fmt::format("{}: {} is {:.3g} mm from {}: consecutive points closer than {} mm are "
                                             "finer than any measurement of a liner; allowed at least {} mm apart "
                                             "(leave one of them out)",
                                             p.source, pt(i + 1), d * 1e3, pt(i), d_min * 1e3, d_min * 1e3));
  }
  const auto [a, b] = first_self_crossing(pts);
  if (a >= 0)
    throw InputError(p.source, fmt::format("{}: the profile crosses itself: the stretch from {} to {} crosses the one "
                                           "from {} to {}",
                                           p.source, pt(a), pt(a + 1), pt(b), pt(b + 1)));
  const auto [j, i] = first_point_near_stretch(pts, d_min);
  if (j >= 0) {
    const V e = pts[j + 1] - pts[j];
    const double t = std::clamp((pts[i] - pts[j]).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const double d = (pts[j] + t * e - pts[i]).norm();
    throw InputError(p.source, fmt::format("{}: {} is {:.3g} mm from the stretch from {} to {}: a needle or a fold "
                                           "of the profile thinner than {} mm is finer than any measurement of a "
                                           "liner; allowed at least {} mm between a point and the stretches it "
                                           "does not end",
                                           p.source, pt(i), d * 1e3, pt(j), pt(j + 1), d_min * 1e3, d_min * 1e3));
  }
}

std::pair<int, int> first_point_near_stretch(const std::vector<V>& pts, double d_min) {
  // As a scan of every stretch j, then every point i, meets it; only the
  // points in the grid cells of stretch j can be that near. Before the grid
  // (2026-12-04) that scan itself ran: 2.5e9 pairs for 50,000 points.
  const int n = static_cast<int>(pts.size());
  if (n < 2) return {-1, -1};
  const StretchGrid grid(pts, d_min);
  for (int j = 0; j + 1 < n; ++j) {
    const Eigen::Array2d lo = pts[j].cwiseMin(pts[j + 1]).array() - d_min;
    const Eigen::Array2d hi = pts[j].cwiseMax(pts[j + 1]).array() + d_min;
    const V e = pts[j + 1] - pts[j];
    int first = n;
    grid.for_each_cell_of_stretch(j, [&](int c) {
      const auto [begin, end] = grid.points_in(c);
      for (const int* k = begin; k != end && *k < first; ++k) {
        const int i = *k;
        if (i == j || i == j + 1 || (pts[i].array() < lo).any() || (pts[i].array() > hi).any()) continue;
        const double t = std::clamp((pts[i] - pts[j]).dot(e) / e.squaredNorm(), 0.0, 1.0);
        if ((pts[j] + t * e - pts[i]).norm() < d_min) {
          first = i;
          break;
        }
      }
    });
    if (first < n) return {j, first};
  }
  return {-1, -1};
}

std::vector<V> measured_profile_to_segment(const MeasuredProfile& p, double R, int segments, double h) {
  const double seg = 2 * kPi / segments;
  const double width = seg * R;
  auto to_mill = [&](const V& q) {
    const double th = q.x() / R - 0.5 * seg, r = R - q.y();
    return V(r * std::cos(th), r * std::sin(th));
  };
  std::vector<V> xy;
  for (size_t i = 0; i < p.points.size(); ++i) {
    V a = p.points[i];
    if (i == 0) a.x() = 0;                          // snap the ends onto the segment edges
    if (i + 1 == p.points.size()) a.x() = width;
    if (i == 0) {
      xy.push_back(a);
      continue;
    }
    // pieces are subdivided in the (x, y) frame, so plate stretches follow the
    // shell; their count comes from the length in the mill frame
    const V b = xy.back();
    const int n = std::max(1, static_cast<int>(std::ceil((to_mill(a) - to_mill(b)).norm() / h - 1e-9)));
    for (int j = 1; j < n; ++j) xy.push_back(b + (a - b) * (static_cast<double>(j) / n));
    xy.push_back(a);
  }
  // the two ends must have the same thickness: use their mean
  const double yend = 0.5 * (xy.front().y() + xy.back().y());
  xy.front().y() = yend;
  xy.back().y() = yend;
  std::vector<V> out;
  out.reserve(xy.size());
  for (const V& q : xy) out.push_back(to_mill(q));
  return out;
}

std::vector<V> segment_to_profile_xy(const std::vector<V>& nodes, double R, double centre, double seg) {
  std::vector<V> out;
  out.reserve(nodes.size());
  for (const V& q : nodes) {
    double th = std::atan2(q.y(), q.x()) - centre + 0.5 * seg;
    while (th < -kPi) th += 2 * kPi;
    while (th > kPi) th -= 2 * kPi;
    out.emplace_back(th * R, R - q.norm());
  }
  return out;
}

}  // namespace linerlife
