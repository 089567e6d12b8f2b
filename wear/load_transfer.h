// load_transfer.h - carries LinerLoads from one surface to another that has
// different elements (after a remesh), or averages them over the liners of
// the same design (thesis Table B.1 LinerComputation = one liner).
//
// Segment by segment, every element of the target takes the load per unit
// length of the source element closest to its midpoint, times its own length,
// and each field is then scaled so that the segment's total is kept: the
// charge's push on a liner stays what the charge model gave, and its
// distribution follows position on the profile. (Keeping each source
// element's load on the stretch of new profile it maps to instead would pile
// the load onto a receding convex corner, whose elements shrink, and make the
// rate there run away.) Speeds follow as <N v> / <N>. Impacts are copied onto
// the targets of the element they hit with their rates scaled alike, and
// impacts identical but for their rate on one element are merged.
#pragma once

#include <cstddef>  // before charge/liner_loads.h, which uses size_t without including it
#include <vector>

#include "charge/liner_loads.h"
#include "geometry/liner_surface.h"

namespace linerlife {

/// `loads` (on `from`) carried onto `to`; both surfaces have the same segments.
/// With `only`, only those segments are carried (the others must carry no
/// loads; they stay zero), which saves looking at them.
LinerLoads transfer_loads(const LinerLoads& loads, const LinerSurface& from, const LinerSurface& to,
                          const std::vector<int>* only = nullptr);

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

/// The ring rebuilt from new chains of the representatives (`chains[d]` for
/// representative_segments()[d], both edge nodes included, as
/// recede_segments() gives them), every segment a rotated copy.
LinerSurface replicate_chains(const LinerSurface& s, const std::vector<std::vector<Eigen::Vector2d>>& chains);

/// Loads averaged over the segments of each design and placed on its
/// representative segment (zero on every other segment): what one
/// representative liner of each design sees on average per revolution. Each
/// segment is rotated onto its representative and carried over as in
/// transfer_loads; the sum over the segments of a design is divided by their
/// number. Impact rates are divided likewise (identical impacts merged).
LinerLoads average_onto_representatives(const LinerLoads& loads, const LinerSurface& s);

}  // namespace linerlife
