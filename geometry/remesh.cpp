#include "geometry/remesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <fmt/format.h>

#include "geometry/errors.h"
#include "geometry/metrics.h"
#include "geometry/mill.h"
#include "geometry/resample.h"

namespace linerlife {
namespace {

using V = Eigen::Vector2d;
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_2;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWH = CGAL::Polygon_with_holes_2<K>;
using PolygonSet = CGAL::Polygon_set_2<K>;

Point to_cgal(const V& v) { return Point(v.x(), v.y()); }
V to_eigen(const Point& p) { return V(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

/// Adds `poly` to `out` with anticlockwise orientation if it is simple and has
/// area; a non-simple quadrilateral (a bow tie) goes in as two triangles.
void add_region(std::vector<Polygon>& out, const std::vector<V>& pts, double min_area) {
  Polygon poly;
  for (const V& p : pts) poly.push_back(to_cgal(p));
  if (poly.is_simple()) {
    if (std::abs(CGAL::to_double(poly.area())) <= min_area) return;
    if (poly.orientation() == CGAL::CLOCKWISE) poly.reverse_orientation();
    out.push_back(poly);
    return;
  }
  if (pts.size() == 4) {
    add_region(out, {pts[0], pts[1], pts[2]}, min_area);
    add_region(out, {pts[0], pts[2], pts[3]}, min_area);
  }
}

double polar_angle(const V& p) { return std::atan2(p.y(), p.x()); }

/// Liner area between a segment chain (both edge nodes) and the shell arc.
double chain_area(const std::vector<V>& p, double R, double seg) {
  double enclosed = 0;
  for (size_t i = 0; i + 1 < p.size(); ++i) enclosed += 0.5 * (p[i].x() * p[i + 1].y() - p[i].y() * p[i + 1].x());
  return 0.5 * R * R * seg - enclosed;
}

}  // namespace

std::vector<double> element_to_node_depth(const LinerSurface& s, const std::vector<double>& d) {
  if (static_cast<int>(d.size()) != s.n_elements())
    throw std::invalid_argument("element_to_node_depth: one depth per element expected");
  std::vector<double> out(s.n_nodes());
  for (int i = 0; i < s.n_nodes(); ++i) {
    const int a = s.prev(i), b = i;
    const double w = s.length[a] + s.length[b];
    out[i] = w > 0 ? (d[a] * s.length[a] + d[b] * s.length[b]) / w : 0.5 * (d[a] + d[b]);
  }
  return out;
}

LinerSurface displace_nodes(const LinerSurface& s, const std::vector<double>& depth, double max_miter) {
  const auto dir = node_offset_directions(s, max_miter);
  LinerSurface out = s;
  for (int i = 0; i < s.n_nodes(); ++i) out.nodes[i] = s.nodes[i] + depth[i] * dir[i];
  out.finalize();
  return out;
}

namespace {

/// New node positions, held min_thickness_m short of the shell; the first node
/// that would pass it is reported in `status`.
std::vector<V> moved_nodes(const LinerSurface& s, const std::vector<double>& depth, const RemeshOptions& opt,
                           SegmentRemesh& status) {
  const int n = s.n_nodes();
  if (static_cast<int>(depth.size()) != n) throw std::invalid_argument("remesh: one depth per node expected");
  for (double d : depth)
    if (!(d >= 0) || !std::isfinite(d)) throw std::invalid_argument("remesh: depths must be finite and >= 0");
  const double rmax = s.shell_radius_m - opt.min_thickness_m;
  const auto dir = node_offset_directions(s, opt.max_miter);
  std::vector<V> moved(n);
  for (int i = 0; i < n; ++i) {
    V q = s.nodes[i] + depth[i] * dir[i];
    if (q.norm() > rmax) {
      // largest t in [0, depth] with |p + t dir| = rmax
      const V& p = s.nodes[i];
      const double a = dir[i].squaredNorm(), b = p.dot(dir[i]), c = p.squaredNorm() - rmax * rmax;
      const double t = c >= 0 ? 0.0 : (-b + std::sqrt(std::max(0.0, b * b - a * c))) / a;
      q = p + std::clamp(t, 0.0, depth[i]) * dir[i];
      if (status.status == RemeshStatus::Ok) {
        status.status = RemeshStatus::WornThrough;
        status.worn_through_segment = s.segment_of_angle(polar_angle(p));
        status.worn_through_angle_rad = polar_angle(p);
        status.message = fmt::format("the liner is worn through to the shell in segment {} at {:.2f} deg",
                                     status.worn_through_segment, status.worn_through_angle_rad * 180.0 / kPi);
      }
    }
    moved[i] = q;
  }
  return moved;
}

/// The new chain of segment k (both edge nodes) given the moved nodes.
std::vector<V> remesh_chain(const LinerSurface& s, const std::vector<double>& depth, const std::vector<V>& moved,
                            int k, const RemeshOptions& opt, double& detached) {
  const int n = s.n_nodes();
  const double R = s.shell_radius_m, h = opt.element_size_m;
  const double min_area = 1e-12 * h * h;
  const int b = s.segment_begin[k], e = s.segment_begin[k + 1];  // e may equal n (wraps to 0)
  // the elements whose sweep can reach this segment: its own and two on each side
  const int first = b - 2, last = e + 1;  // element indices, taken modulo n
  bool moves = false;
  for (int i = first; i <= last + 1 && !moves; ++i) moves = depth[((i % n) + n) % n] > 0;
  std::vector<V> chain;
  if (!moves) {
    for (int i = b; i <= e; ++i) chain.push_back(s.nodes[i % n]);
    return chain;
  }
  // Old body: surface from b to e, then the shell arc back.
  const double th0 = s.segment_start_rad(k), th1 = s.segment_start_rad(k + 1);
  std::vector<V> body;
  for (int i = b; i <= e; ++i) {
    // repeated vertices (a zero-length element) make CGAL call the polygon non-simple
    const V& q = s.nodes[i % n];
    if (body.empty() || (q - body.back()).norm() > 1e-12 * h) body.push_back(q);
  }
  const int narc = std::max(2, static_cast<int>(std::ceil((th1 - th0) * R / h)));
  for (int j = narc; j >= 0; --j) {
    const double th = th0 + (th1 - th0) * j / narc;
    body.emplace_back(R * std::cos(th), R * std::sin(th));
  }
  Polygon body_poly;
  for (const V& p : body) body_poly.push_back(to_cgal(p));
  if (!body_poly.is_simple())
    throw SimulationError(fmt::format("remesh: the liner profile of segment {} crosses itself before this remesh, so "
                                      "the worn body is undefined; recede in smaller steps (remesh more often) or "
                                      "smooth the recession field",
                                      k));
  if (body_poly.orientation() == CGAL::CLOCKWISE) body_poly.reverse_orientation();

  std::vector<Polygon> swept;
  for (int i = first; i <= last; ++i) {
    const int a = ((i % n) + n) % n, c = (a + 1) % n;
    if (depth[a] <= 0 && depth[c] <= 0) continue;
    add_region(swept, {s.nodes[a], s.nodes[c], moved[c], moved[a]}, min_area);
  }
  PolygonSet removed;
  removed.join(swept.begin(), swept.end());
  PolygonSet left(body_poly);
  left.difference(removed);
  std::vector<PolygonWH> pieces;
  left.polygons_with_holes(std::back_inserter(pieces));

  // Keep the piece that holds the shell; count the others as cut loose.
  const double shell_tol = 0.5 * opt.min_thickness_m;
  int keep = -1;
  for (size_t j = 0; j < pieces.size() && keep < 0; ++j)
    for (auto v = pieces[j].outer_boundary().vertices_begin(); v != pieces[j].outer_boundary().vertices_end(); ++v)
      if (to_eigen(*v).norm() > R - shell_tol) {
        keep = static_cast<int>(j);
        break;
      }
  if (keep < 0) throw SimulationError(fmt::format("remesh: segment {} lost its contact with the shell", k));
  for (size_t j = 0; j < pieces.size(); ++j)
    if (static_cast<int>(j) != keep) detached += std::abs(CGAL::to_double(pieces[j].outer_boundary().area()));

  // The outer boundary is anticlockwise with the body on its left, so the
  // surface part runs clockwise round the mill axis: collect the chain of
  // vertices off the shell, starting after the last shell vertex.
  std::vector<V> ring;
  for (auto v = pieces[keep].outer_boundary().vertices_begin(); v != pieces[keep].outer_boundary().vertices_end(); ++v)
    ring.push_back(to_eigen(*v));
  const int m = static_cast<int>(ring.size());
  auto on_shell = [&](int j) { return ring[((j % m) + m) % m].norm() > R - shell_tol; };
  int start = -1;
  for (int j = 0; j < m; ++j)
    if (on_shell(j) && !on_shell(j + 1)) {
      start = j + 1;
      break;
    }
  if (start < 0) throw SimulationError(fmt::format("remesh: no liner surface left in segment {}", k));
  for (int j = start; !on_shell(j); ++j) chain.push_back(ring[j % m]);
  std::reverse(chain.begin(), chain.end());  // anticlockwise round the axis
  // Snap the chain ends onto the segment's radial edges (they lie there up
  // to round-off) so neighbouring segments share their edge node exactly.
  auto snap = [](V& p, double th) { const double r = p.norm(); p = V(r * std::cos(th), r * std::sin(th)); };
  snap(chain.front(), th0);
  snap(chain.back(), th1);
  return resample_polyline(chain, h);
}

}  // namespace

SegmentRemesh remesh_segment(const LinerSurface& s, const std::vector<double>& depth, int k, const RemeshOptions& opt) {
  SegmentRemesh r;
  const std::vector<V> moved = moved_nodes(s, depth, opt, r);
  r.nodes = remesh_chain(s, depth, moved, k, opt, r.detached_area_m2);
  r.removed_area_m2 = segment_area(s, k) - chain_area(r.nodes, s.shell_radius_m, s.segment_angle_rad());
  return r;
}

RemeshResult remesh(const LinerSurface& s, const std::vector<double>& depth, const RemeshOptions& opt) {
  RemeshResult res;
  SegmentRemesh status;
  const std::vector<V> moved = moved_nodes(s, depth, opt, status);
  res.status = status.status;
  res.worn_through_segment = status.worn_through_segment;
  res.worn_through_angle_rad = status.worn_through_angle_rad;
  res.message = status.message;

  double old_area = 0;
  for (int k = 0; k < s.segments; ++k) old_area += segment_area(s, k);
  // Stitch: a segment's last node is the next segment's first (both lie on the
  // same radial edge and come from the same swept regions).
  LinerSurface& out = res.surface;
  out.shell_radius_m = s.shell_radius_m;
  out.segments = s.segments;
  out.segment_design = s.segment_design;
  for (int k = 0; k < s.segments; ++k) {
    const std::vector<V> p = remesh_chain(s, depth, moved, k, opt, res.detached_area_m2);
    out.segment_begin.push_back(out.n_nodes());
    for (size_t i = 0; i + 1 < p.size(); ++i) out.nodes.push_back(p[i]);
  }
  out.segment_begin.push_back(out.n_nodes());
  out.finalize();
  double new_area = 0;
  for (int k = 0; k < out.segments; ++k) new_area += segment_area(out, k);
  res.removed_area_m2 = old_area - new_area;
  return res;
}

RemeshResult remesh_elements(const LinerSurface& s, const std::vector<double>& element_depth, const RemeshOptions& opt) {
  return remesh(s, element_to_node_depth(s, element_depth), opt);
}

}  // namespace linerlife
