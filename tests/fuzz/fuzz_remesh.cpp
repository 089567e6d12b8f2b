// Fuzz target: a profile passed through remesh (issue 7 §2). The input picks a
// valid measured profile (fuzzed points, validated as the CSV loader does)
// and a recession field; the remesh must return a valid surface (simple, area
// not larger) or report worn-through. InputErrors from invalid profiles are
// the loader's job and end the case.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"
#include "geometry/remesh.h"

using namespace linerlife;

namespace {
/// Reads the next byte as a fraction in [0, 1].
struct Bytes {
  const uint8_t* d;
  size_t n, i = 0;
  double next() { return i < n ? d[i++] / 255.0 : 0.5; }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 8) return 0;
  Bytes b{data, size};
  // a pilot mill with 8 rows: segment width 0.2992 m
  Mill mill;
  mill.diameter_m = 0.762;
  mill.speed_rpm = 30;
  const double R = 0.381, width = 2 * M_PI * R / 8;
  MeasuredProfile prof;
  prof.source = "fuzz";
  const int npts = 3 + static_cast<int>(b.next() * 12);
  const double y0 = 0.002 + 0.02 * b.next();
  prof.points.emplace_back(0.0, y0);
  for (int k = 1; k + 1 < npts; ++k) prof.points.emplace_back(width * b.next(), 0.001 + 0.06 * b.next());
  prof.points.emplace_back(width, y0);
  LinerDesign d;
  d.segments = 8;
  d.measured = true;
  d.profile = prof;
  d.element_size_m = 0.002 + 0.006 * b.next();
  try {
    validate_measured_profile(prof, R, 8);
  } catch (const InputError&) {
    return 0;
  }
  const LinerSurface s = build_liner_surface(mill, d);
  std::vector<double> depth(static_cast<size_t>(s.n_nodes()));
  const double amp = 0.03 * b.next(), k = 1 + 60 * b.next(), ph = 6.3 * b.next();
  for (int i = 0; i < s.n_nodes(); ++i) depth[i] = amp * (0.5 + 0.5 * std::sin(k * std::atan2(s.nodes[i].y(), s.nodes[i].x()) + ph));
  RemeshOptions opt;
  opt.element_size_m = d.element_size_m;
  const RemeshResult r = remesh(s, depth, opt);
  double before = 0, after = 0;
  for (int j = 0; j < s.segments; ++j) before += segment_area(s, j), after += segment_area(r.surface, j);
  if (!(after <= before + 1e-12) || !std::isfinite(after)) std::abort();  // material never added
  // A liner worn through to the shell ends the run that wears it (the wear
  // run records it and stops; the forecast's worn-through root comes first):
  // its ring is not worn further, and where nodes are held on the shell it
  // may fold back along a segment edge (remesh-crash-5b45c4a7, seen in the
  // clang fuzz build only; docs/reliability.md, Fuzzing). Only a ring that
  // goes on must be simple.
  if (r.status == RemeshStatus::WornThrough) return 0;
  for (int j = 0; j < r.surface.segments; ++j) {
    std::vector<Eigen::Vector2d> chain;
    for (int i = r.surface.segment_begin[j]; i <= r.surface.segment_begin[j + 1]; ++i)
      chain.push_back(r.surface.nodes[i % r.surface.n_nodes()]);
    if (polyline_self_intersects(chain)) std::abort();
  }
  return 0;
}
