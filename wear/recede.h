// recede.h - moves the liner surface into the liner body by a recession
// depth per node: the fast path of geometry's remesh() for the small steps of
// the wear run, with remesh() itself wherever the fast path does not apply.
//
// Fast path, segment by segment (only segments with a moving node): the nodes
// are displaced along their offset directions (displace_nodes, the same
// directions remesh() uses), and the displaced chain is accepted when it
// stays simple, no element turns over, every interior node stays strictly
// inside the segment's angular span and short of the shell. It is then
// resampled to the element size exactly as remesh() resamples. On these
// conditions the region between the two chains is what remesh() removes
// (the union of the swept quadrilaterals has no other boundary), so the
// result is remesh()'s up to round-off, at a few microseconds a segment
// instead of milliseconds of exact Boolean operations. One local repair: an
// element shorter than the step that turns over at a worn convex corner (a
// small swallowtail) is dropped and the corner put where its two neighbours'
// offsets cross, which is the envelope remesh() keeps. Otherwise (loops,
// wear through, a step too deep for the element size) the whole surface goes
// through remesh(). Either way the area removed is measured on the result.
#pragma once

#include <vector>

#include "geometry/remesh.h"

namespace linerlife {

/// remesh(s, node_depth_m, opt) by the fast path when it applies. `fast` (if
/// given) tells which path was taken.
RemeshResult recede(const LinerSurface& s, const std::vector<double>& node_depth_m, const RemeshOptions& opt,
                    bool* fast = nullptr);

/// The fast path alone, for the given segments: their new chains (both edge
/// nodes included, resampled) in `chains`, or false when the fast path does
/// not apply to one of them (then use remesh()). Segment edge nodes move
/// radially, so two neighbouring segments computed apart still share them.
bool recede_segments(const LinerSurface& s, const std::vector<double>& node_depth_m, const RemeshOptions& opt,
                     const std::vector<int>& segments, std::vector<std::vector<Eigen::Vector2d>>& chains);

}  // namespace linerlife
