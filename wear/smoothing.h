// smoothing.h - profile smoothing (thesis §5.8): moving average, cubic
// smoothing spline (MATLAB csaps), Tukey's compound smoothers.
//
// What is smoothed: the recession depth field along the liner surface, one
// value per surface node, ordered by arc length (DESIGN.md §2; thesis §5.8
// smooths the worn liner heights, i.e. the same information). The wear run
// smooths the depth accumulated since the last remesh, just before it is
// applied. Sequences are either closed (periodic: the whole ring, or one
// liner whose neighbours are its copies) or open (a profile with two ends).
//
// Mass: the volume removed per metre is sum_i w_i y_i with w_i the node's
// share of surface length (half of each adjacent element). smooth_depth()
// clips negative depths (smoothing must never add material) and rescales
// the result so that sum w y is exactly the raw one; it reports how much
// correction the smoother needed (docs/validation/wear.md §5).
#pragma once

#include <string>
#include <vector>

namespace linerlife {

enum class SmoothingMethod { None, MovingAverage, Csaps, Tukey, TukeyCsaps };

struct SmoothingSpec {
  SmoothingMethod method = SmoothingMethod::Csaps;
  double csaps_p = 0.9999;  // [-] MATLAB's csaps smoothing parameter, x in metres of arc length (thesis: 0.9999)
  int window = 10;          // [-] moving-average filter length (thesis Fig. 5-18: 10)
  std::string tukey = "3RSSH,twice";  // Tukey sequence (tukey_smooth)
};

/// "none", "moving_average", "csaps", "tukey", "tukey_csaps" (the thesis' final
/// choice: the Tukey sequence, then csaps) -> method; throws InputError (key
/// "wear.smoothing") otherwise.
SmoothingMethod smoothing_method_from_name(const std::string& name);
const char* smoothing_method_name(SmoothingMethod m);

/// Centred moving average over `window` samples (thesis eq. 5.34 is the causal
/// form y(k) = mean(u(k - ns + 1 .. k)); it shifts features by ns/2 samples, so
/// the centred form is used: an even window takes window + 1 samples with half
/// weight at both ends). Open sequences shrink the window at the ends.
std::vector<double> moving_average(const std::vector<double>& y, int window, bool periodic);

/// Cubic smoothing spline of MATLAB's csaps: the f minimising
///   p sum_i w_i (y_i - f(x_i))^2 + (1 - p) int f''(x)^2 dx,
/// evaluated at the sites. spacing[i] = x_{i+1} - x_i > 0 [m] (periodic: n
/// values, the last closing the loop; open: n - 1 values, natural ends).
/// The weights are scaled to a mean of 1 (MATLAB's default weight is 1 per
/// site), so p means what it means in MATLAB for near-uniform sites.
/// Reinsch's method: (p R + (1 - p) Q^T W^-1 Q) gamma = p Q^T y,
/// f = y - ((1 - p)/p) W^-1 Q gamma, solved with Eigen's sparse LDL^T.
/// Constants and (open) straight lines pass unchanged, so sum w (y - f) = 0:
/// the spline keeps the weighted mass exactly. p = 1 interpolates; p -> 0 gives
/// the weighted least-squares line (open) or constant (periodic). The
/// equivalent smoothing length is about ((1 - p) h / p)^(1/4) for spacing h
/// (3.2 cm, about 3 elements, for the thesis' p = 0.9999 and h = 1 cm).
std::vector<double> csaps(const std::vector<double>& y, const std::vector<double>& spacing,
                          const std::vector<double>& w, double p, bool periodic);

/// Tukey's (1977) compound smoothers, named by their sequence (Velleman &
/// Hoaglin 1981): "3" running median of 3 (Tukey's end-point rule on open
/// sequences), "5" running median of 5, "R" repeat the preceding smoother
/// until nothing changes ("3R"), "S" split two-point plateaus and re-smooth
/// by 3R, "H" hanning (1/4, 1/2, 1/4), ",twice" smooth the residuals once
/// more and add them back. Examples: "3RSSH", "3RSSH,twice". The thesis'
/// "3RRSHRRSRR" is accepted with an R after an R read as a no-op and an R after
/// H as "3R" (repeating hanning to convergence would flatten the profile):
/// 3R S H 3R SR. Throws InputError (key "wear.smoothing_tukey") for an
/// unknown letter.
std::vector<double> tukey_smooth(const std::vector<double>& y, const std::string& sequence, bool periodic);

struct SmoothingResult {
  std::vector<double> values;          // smoothed, >= 0, sum w y equal to the raw field's
  double raw_mass = 0;                 // sum w y of the input
  double relative_change = 0;          // (sum w y_smoothed - raw) / raw before clipping and rescaling
  double relative_change_clipped = 0;  // the same after clipping negatives, before rescaling
};

/// Smooths a depth field y >= 0 on sites with `spacing` (as csaps) and mass
/// weights w, then clips negatives and rescales to conserve sum w y.
SmoothingResult smooth_depth(const std::vector<double>& y, const std::vector<double>& spacing,
                             const std::vector<double>& w, const SmoothingSpec& spec, bool periodic);

}  // namespace linerlife
