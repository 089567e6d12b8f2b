// load_transfer.h - carries LinerLoads from one surface to another that has
// different elements (after a remesh), or averages them over the liners of
// the same design (thesis Table B.1 LinerComputation = one liner).
//
// Each element of the target takes the loads of the source element nearest
// to it (by midpoint, within the same segment). Forces and powers (per
// element, per metre of mill length) are shared out among the target
// elements mapped to the same source element in proportion to their length,
// and a source element no target element maps to gives its loads to the
// target element nearest to it, so the totals over a segment are kept
// exactly. Speeds are copied. Impacts move to the target element nearest to
// the element they hit.
#pragma once

#include <cstddef>  // before charge/liner_loads.h, which uses size_t without including it
#include <vector>

#include "charge/liner_loads.h"
#include "geometry/liner_surface.h"

namespace linerlife {

/// `loads` (on `from`) carried onto `to`; both surfaces have the same segments.
LinerLoads transfer_loads(const LinerLoads& loads, const LinerSurface& from, const LinerSurface& to);

/// The representative segment of every design (the first segment with it):
/// rep[d] for d = 0 (high) and, for a hi-lo pattern, 1 (low).
std::vector<int> representative_segments(const LinerSurface& s);

/// Number of segments of each design.
std::vector<int> design_counts(const LinerSurface& s);

/// The ring rebuilt with every segment a copy of its design's
/// representative, rotated onto its place. Segment k's last node is the first
/// node of segment k + 1, so the representatives must agree at the edges they
/// share with the next segment (they do when their edge nodes were moved alike).
LinerSurface replicate_representatives(const LinerSurface& s);

/// Loads averaged over the segments of each design and placed on its
/// representative segment (zero on every other segment): what one
/// representative liner of each design sees on average per revolution. Each
/// segment is rotated onto its representative and carried over as in
/// transfer_loads; the sum over the segments of a design is divided by their
/// number. Impact rates are divided likewise.
LinerLoads average_onto_representatives(const LinerLoads& loads, const LinerSurface& s);

}  // namespace linerlife
