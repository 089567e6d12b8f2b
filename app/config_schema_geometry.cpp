// The [mill] and [liner] keys (DESIGN.md §4; issue 2 §2).
#include "app/config.h"
#include "app/config_schema_util.h"
#include "geometry/build_liner_surface.h"

namespace linerlife {

void add_mill_keys(Schema& s) {
  s.sections.push_back("mill");
  s.keys.push_back(real_key("mill", "diameter_m", "m", "Inside diameter of the shell (fixed as the liner wears)",
                            0.1, 15.0, true, false, std::nullopt,
                            [](Config& c, double v) { c.mill.diameter_m = v; },
                            [](const Config& c) { return c.mill.diameter_m; }, true));
  s.keys.push_back(real_key("mill", "length_m", "m", "Effective grinding length (2D results x length = full mill)",
                            0.0, 20.0, true, false, std::nullopt,
                            [](Config& c, double v) { c.mill.length_m = v; },
                            [](const Config& c) { return c.mill.length_m; }, true));
  s.keys.push_back(opt_real_key("mill", "speed_rpm", "rpm", "Mill speed (give this or speed_fraction_critical); at least 0.05 of critical "
                                "for the diameter inside the new liners, and below critical",
                                0.0, 200.0, true, false, [](Config& c, double v) { c.speed_rpm = v; },
                                [](const Config& c) { return c.speed_rpm; }, "or speed_fraction_critical"));
  s.keys.push_back(opt_real_key(
      "mill", "speed_fraction_critical", "-",
      "Mill speed as a fraction of critical for the diameter inside the new liners (or give speed_rpm; below 0.05 "
      "the charge does not tumble)",
      kMinSpeedFractionCritical, 1.0, false, true, [](Config& c, double v) { c.speed_fraction_critical = v; },
      [](const Config& c) { return c.speed_fraction_critical; }, "alternative to speed_rpm: give exactly one"));
  s.keys.push_back(string_key("mill", "rotation", "Direction of rotation seen from the feed end", {"ccw", "cw"}, "ccw",
                              [](Config& c, const std::string& v) {
                                c.mill.rotation = v == "cw" ? Rotation::Cw : Rotation::Ccw;
                              },
                              [](const Config& c) { return std::string(c.mill.rotation == Rotation::Cw ? "cw" : "ccw"); }));
}

void add_liner_keys(Schema& s) {
  s.sections.push_back("liner");
  s.keys.push_back(int_key("liner", "segments",
                           "Lifter rows round the shell (at least 2: one row's segment is the whole ring, which a "
                           "lifter cannot fit and the remesh cannot wear)",
                           kMinSegments, 400, true,
                           [](Config& c, long long v) { c.liner.segments = static_cast<int>(v); },
                           [](const Config& c) { return static_cast<long long>(c.liner.segments); }));
  auto design_key = [&](const char* name, const char* unit, const char* help, double lo, double hi, bool lo_open,
                        bool hi_open, double LifterDesign::*field) {
    s.keys.push_back(opt_real_key(
        "liner", name, unit, help, lo, hi, lo_open, hi_open,
        [field](Config& c, double v) { c.liner.design.*field = v; },
        [field](const Config& c) -> std::optional<double> {
          if (c.liner.measured) return std::nullopt;
          return c.liner.design.*field;
        },
        "required unless profile_csv is given"));
  };
  design_key("plate_thickness_m", "m", "Shell plate thickness (radial)", 0.0, 2.0, true, false,
             &LifterDesign::plate_thickness_m);
  design_key("lifter_height_m", "m", "Lifter height above the plate (0: plain plate)", 0.0, 2.0, false, false,
             &LifterDesign::lifter_height_m);
  design_key("lifter_top_width_m", "m", "Width of the flat lifter top (chord)", 0.0, 2.0, true, false,
             &LifterDesign::top_width_m);
  design_key("face_angle_leading_deg", "deg",
             "Leading face angle from the radial (the face towards the rotation; positive = relieved)", 0.0, 80.0,
             false, true, &LifterDesign::face_angle_leading_deg);
  design_key("face_angle_trailing_deg", "deg", "Trailing face angle from the radial", 0.0, 80.0, false, true,
             &LifterDesign::face_angle_trailing_deg);
  s.keys.push_back(real_key("liner", "corner_radius_m", "m", "Fillet radius of the two top corners (0: sharp)", 0.0,
                            0.5, false, false, std::optional<double>(0.0),
                            [](Config& c, double v) { c.liner.design.corner_radius_m = v; },
                            [](const Config& c) { return c.liner.design.corner_radius_m; }));
  s.keys.push_back(string_key("liner", "pattern", "Lifter pattern: every row alike, or alternating high and low rows",
                              {"uniform", "hi-lo"}, "uniform", [](Config& c, const std::string& v) { c.pattern = v; },
                              [](const Config& c) { return c.pattern; }));
  s.keys.push_back(opt_real_key("liner", "low_lifter_height_m", "m", "Height of the low lifters of a hi-lo pattern",
                                0.0, 2.0, false, false, [](Config& c, double v) { c.low_lifter_height_m = v; },
                                [](const Config& c) { return c.low_lifter_height_m; }, "only with pattern = \"hi-lo\""));
  s.keys.push_back(opt_real_key("liner", "low_lifter_top_width_m", "m", "Top width of the low lifters of a hi-lo pattern",
                                0.0, 2.0, true, false, [](Config& c, double v) { c.low_lifter_top_width_m = v; },
                                [](const Config& c) { return c.low_lifter_top_width_m; },
                                "only with pattern = \"hi-lo\""));
  s.keys.push_back(real_key("liner", "density_kg_m3", "kg/m3", "Density of the liner material", 500.0, 20000.0, false,
                            false, std::optional<double>(7800.0),
                            [](Config& c, double v) { c.liner.density_kg_m3 = v; },
                            [](const Config& c) { return c.liner.density_kg_m3; }));
  // (10 BHN, softer than pure aluminium, is a floor for a metal liner: the
  // impact laws divide by the hardness, and 1e-300 made an infinite rate)
  s.keys.push_back(real_key("liner", "hardness_bhn", "BHN", "Brinell hardness of the liner material", 10.0, 1000.0,
                            false, false, std::optional<double>(350.0),
                            [](Config& c, double v) { c.liner.hardness_bhn = v; },
                            [](const Config& c) { return c.liner.hardness_bhn; }));
  s.keys.push_back(opt_string_key("liner", "profile_csv",
                                  "Measured profile of one segment (CSV x_m,y_m, docs/profile-csv.md) instead of the "
                                  "parametric lifter; relative to this file",
                                  [](Config& c, const std::string& v) { c.profile_csv = v; },
                                  [](const Config& c) -> std::optional<std::string> {
                                    if (c.profile_csv.empty()) return std::nullopt;
                                    return c.profile_csv;
                                  },
                                  "optional"));
  s.keys.push_back(real_key("liner", "element_size_m", "m",
                            "Longest surface element (default from the convergence study in docs/geometry.md; at "
                            "least 1 mm, below the finest run of both element-size studies: 2.5 mm there, 1.5 mm in "
                            "docs/validation/forecast.md)",
                            kMinElementSizeM, 1.0, false, false, std::nullopt,
                            [](Config& c, double v) { c.liner.element_size_m = v; },
                            [](const Config& c) { return c.liner.element_size_m; }, true));
  s.keys.push_back(int_key("liner", "lifter_grid_cells", "n of the n x n lifter grid (thesis §5.6, Table B.1)", 20,
                           100, false, [](Config& c, long long v) { c.liner.lifter_grid_cells = static_cast<int>(v); },
                           [](const Config& c) { return static_cast<long long>(c.liner.lifter_grid_cells); }, 60));
}

}  // namespace linerlife
