// layer_model.h - the thesis' real-time charge motion simulator (Arekar 2004,
// chapters 3-4, §5.5.1, Fig. 5-8; Radziszewski's agglomerated approach),
// versions 1.0, 1.1 (shoulder clipping) and 1.2 (layer adjustment) of thesis
// §4.6. Equations, sources and every modelling choice: docs/models/layer.md.
//
// In short: the charge is cut into agglomerated elements of one media
// diameter square (equal area, "equivalent volume") on concentric layers
// inside the liner; each layer turns rigidly at its slip-model speed; an
// element leaves its layer at the layer's flight angle (McIvor, thesis eq.
// 4.5; the lifter face angle and height for layers held by lifters), flies a
// ballistic parabola, re-enters the en-masse charge where the parabola first
// meets it (or the liner: an impact, found by exact parabola-polyline
// intersection) and settles there by the foot-stability rule. Liner loads
// accumulate every step from the outer layer.
#pragma once

#include <memory>

#include "charge/charge_model.h"

namespace linerlife {

class LayerModel : public ChargeModel {
 public:
  ChargeResult run(const ChargeInput& in) const override;
};

std::unique_ptr<ChargeModel> make_layer_model();

/// Courant number (shell travel per step / media diameter) above which the
/// layer model sub-steps (from the time-step study, docs/models/layer.md).
constexpr double kLayerMaxCourant = 0.45;

/// [s] The shortest time_step_s accepted: a tenth of the finest step of the
/// time-step study (1 ms, docs/models/layer.md §9), where power, toe and
/// shoulder have long converged; 1e-9 s never ended (1e10 steps a revolution).
constexpr double kLayerMinTimeStepS = 1e-4;

/// The most cells the layer model's lattice may have (pi R^2 / d^2 for the
/// radius R inside the liners and the element edge d). A large ball mill
/// (8 m, 15 mm balls) needs about 220,000; 1 mm media in the Qiu mill would
/// need 78 million, gigabytes of memory and hours a revolution.
constexpr double kLayerMaxCells = 1e6;

}  // namespace linerlife
