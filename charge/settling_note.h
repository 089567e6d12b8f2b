// settling_note.h - the note of a run that averages the charge before it has
// settled. Every time-stepped model starts from rest (the layer model with its
// cells filled from the bottom, the DEM with rows of discs): the charge rises
// to its shoulder and settles within about half a revolution
// (docs/models/layer.md §Settling: 0.5 revolution the least settling tried, 22
// of 29 mills within the settled windows' spread). A review (2026-12-06) ran
// the Qiu mill with settle_revolutions = 0 over 0.05 revolution: 1,073 kW
// against 5,946 kW settled, toe 175 deg against 215, without a word.
#pragma once

#include <algorithm>
#include <string>

#include <fmt/format.h>

namespace linerlife {

/// Revolutions from rest after which the averages of the settling study
/// were settled (docs/models/layer.md §Settling).
inline constexpr double kSettledAfterRevolutions = 0.5;

/// The note for a run that settles `settle` revolutions and then averages
/// over `averaged`, naming `key` (e.g. "[model] settle_revolutions"); empty
/// when the averaging starts after kSettledAfterRevolutions.
inline std::string settling_note(const std::string& key, double settle, double averaged) {
  if (!(settle < kSettledAfterRevolutions) || !(averaged > 0)) return {};
  const double share = std::min(1.0, (kSettledAfterRevolutions - settle) / averaged);
  return fmt::format("{} = {}: the averages start {} revolutions after the start from rest, and the charge settles "
                     "in about {} revolution; {:.0f} % of the averaged time is before that, so power, toe and "
                     "shoulder may be far from the settled ones (the Qiu mill from rest over 0.05 revolution: "
                     "1,073 kW against 5,946 kW settled; docs/models/layer.md §Settling)",
                     key, settle, settle, kSettledAfterRevolutions, 100.0 * share);
}

}  // namespace linerlife
