// charge_cases.h - the mills of the charge-model studies (docs/benchmarks.md,
// docs/validation/charge.md): the bundled Qiu mill, its 12 one-at-a-time
// variations of thesis §3.2.2 (speed, charge volume, steel volume, media size,
// number of lifters and diameter at +/-25 %), and the 16 pilot tests of thesis
// Table 4.1 (data/mills/).
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/config.h"
#include "charge/charge_model.h"
#include "geometry/build_liner_surface.h"

namespace linerlife::bench {

struct Case {
  std::string name;
  Config config;
};

inline std::string source_dir() { return LINERLIFE_SOURCE_DIR; }

/// The Qiu mill and its twelve +/-25 % variations (thesis §3.2.2, Fig. 3-3).
/// Built here, past the input checks: three of them (diameter -25 %, media
/// size +25 %, lifters +25 %) leave less room between the lifters at the plate
/// than one ball, which `linerlife charge` refuses (exit 2); they are timing
/// cases of the thesis' study, not mills the tool accepts (docs/benchmarks.md).
inline std::vector<Case> industrial_cases() {
  const Config base = load_config_file(source_dir() + "/data/mills/qiu2001_sag.toml");
  std::vector<Case> out{{"qiu", base}};
  for (double f : {0.75, 1.25}) {
    const char* tag = f < 1 ? "-25%" : "+25%";
    Config c = base;
    c.mill.speed_rpm *= f;
    out.push_back({fmt::format("speed {}", tag), c});
    c = base;
    c.charge.filling *= f;
    out.push_back({fmt::format("charge volume {}", tag), c});
    c = base;
    c.charge.ball_filling *= f;
    out.push_back({fmt::format("steel volume {}", tag), c});
    c = base;
    c.charge.ball_diameter_m *= f;
    out.push_back({fmt::format("media size {}", tag), c});
    c = base;
    c.liner.segments = static_cast<int>(std::lround(c.liner.segments * f));
    out.push_back({fmt::format("lifters {}", tag), c});
    c = base;
    c.mill.diameter_m *= f;  // same liner, same speed in rpm
    out.push_back({fmt::format("diameter {}", tag), c});
  }
  return out;
}

/// The 16 pilot tests (thesis Table 4.1).
inline std::vector<Case> pilot_cases() {
  std::vector<Case> out;
  for (int i = 1; i <= 16; ++i)
    out.push_back({fmt::format("pilot {:02d}", i),
                   load_config_file(fmt::format("{}/data/mills/pilot_test_{:02d}.toml", source_dir(), i))});
  return out;
}

/// The layer model's study options as bench options (docs/models/layer.md §3,
/// "The release study"; docs/models/layer-worn.md, "The en-masse share of eq.
/// 4.14"): `--unheld-mu MU`, `--pocket-balls P`, `--lifter-slide on|off` and
/// `--beta B` set their ModelSpec fields; false for any other option or value.
inline bool set_study_option(ModelSpec& m, const std::string& k, const std::string& v) {
  if (k == "--lifter-slide") {
    if (v != "on" && v != "off") return false;
    m.lifter_slide = v == "on";
  } else if (k == "--unheld-mu") m.unheld_friction_coefficient = std::stod(v);
  else if (k == "--pocket-balls") m.held_pocket_balls = std::stod(v);
  else if (k == "--beta") m.inner_radius_beta = std::stod(v);
  else return false;
  return true;
}

/// A ChargeInput for `c` (the surface must outlive it).
inline ChargeInput make_input(const Config& c, const LinerSurface& s, const std::string& model,
                              const std::string& variant, double revolutions) {
  ChargeInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.model.charge = model;
  if (!variant.empty()) in.model.variant = variant;
  in.surface = &s;
  in.revolutions = revolutions;
  return in;
}

}  // namespace linerlife::bench
