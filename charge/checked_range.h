// checked_range.h - the fillings and speeds on which the charge models were
// checked, and the note a run outside them gets.
//
// docs/validation/charge.md compares Morrell's model, the three layer versions
// and the 2D DEM on the 16 pilot tests (fillings 0.30 and 0.45; 0.593 of
// critical at 29 rpm, the odd-numbered tests, and 0.817-0.819 at 40 rpm), the
// Qiu mill (0.24, 0.773) and, on the Qiu mill, the operating
// trends (fillings 0.18-0.36 at 0.773; 0.66-0.90 of critical at 0.24);
// docs/validation/ball-mill.md the 5 m ball mill (0.35, 0.75). Outside
// that box nothing has said how far the fast models are from the DEM: a
// review (2026-12-06) forecast the bundled mill at 5 % filling to 193 h
// against 7,355 h at 24 %, without a word.
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

namespace linerlife {

constexpr double kCheckedFillingMin = 0.18;
constexpr double kCheckedFillingMax = 0.45;
constexpr double kCheckedSpeedMin = 0.59;  // fraction of critical (the 29 rpm pilot tests: 0.593)
constexpr double kCheckedSpeedMax = 0.90;

/// Notes for a filling or a fraction of critical outside the checked box
/// (none inside it; the bounds themselves are inside). `model` names the
/// model in the note ("the layer model", "Morrell's model").
inline std::vector<std::string> checked_range_notes(const std::string& model, double filling,
                                                    double fraction_critical) {
  std::vector<std::string> out;
  // A bound given as written is inside: Morrell's model takes the critical
  // speed as 42.3 / sqrt(D) (reference/charge-models.md), 3e-5 of a fraction
  // from critical_speed_rpm(), so speed_fraction_critical = 0.59 reached it as
  // 0.58997 (a review, 2026-12-06). The notes print three decimals.
  constexpr double kMargin = 5e-4;
  auto outside = [&](const std::string& what, double lo, double hi, const std::string& noun) {
    out.push_back(fmt::format("{} outside {:.2f}-{:.2f}, the {} on which {} was checked against the 2D DEM "
                              "(docs/validation/charge.md): its results here are an extrapolation, to be checked "
                              "with the DEM ([model] charge = \"dem\")",
                              what, lo, hi, noun, model));
  };
  if (filling < kCheckedFillingMin - kMargin || filling > kCheckedFillingMax + kMargin)
    outside(fmt::format("filling {} is", filling), kCheckedFillingMin, kCheckedFillingMax, "fillings");
  if (fraction_critical < kCheckedSpeedMin - kMargin || fraction_critical > kCheckedSpeedMax + kMargin)
    outside(fmt::format("the mill runs at {:.3f} of critical,", fraction_critical), kCheckedSpeedMin, kCheckedSpeedMax,
            "speeds");
  return out;
}

}  // namespace linerlife
