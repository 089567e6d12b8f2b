// `linerlife geometry [CONFIG] [--json] [--out DIR]`: builds the liner ring and
// reports what an engineer measures on it (docs/geometry.md).
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/json.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "app/results.h"
#include "geometry/build_liner_surface.h"
#include "geometry/lifter_grid.h"
#include "geometry/metrics.h"

namespace linerlife {
namespace {

struct GeometryOptions {
  std::string config;
  bool json = false;
  std::string out;
};

int run_geometry(const GeometryOptions& o) {
  const Config c = load_config_or_default(o.config);
  if (!o.out.empty()) check_output_dir_writable(o.out, {"geometry.h5"});
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  const LinerMetrics m = metrics(s, c.mill.rotation, c.liner.density_kg_m3);
  const SegmentMetrics& s0 = m.segments[0];
  const double nc = critical_speed_rpm(m.effective_diameter_m);

  if (o.json) {
    Json j = Json::object();
    j.set("config", c.source)
        .set("segments", s.segments)
        .set("pattern", c.pattern)
        .set("lifter_height_m", s0.lifter_height_m)
        .set("face_angle_leading_deg", s0.face_angle_leading_deg)
        .set("face_angle_trailing_deg", s0.face_angle_trailing_deg)
        .set("top_width_m", s0.top_width_m)
        // the thinnest point of the ring (kept under its first name; on a
        // measured or worn profile it is not the plate's nominal thickness,
        // which is plate_ref_thickness_m: docs/geometry.md)
        .set("plate_thickness_m", m.min_thickness_m)
        .set("min_thickness_m", m.min_thickness_m)
        .set("plate_ref_thickness_m", s0.plate_ref_thickness_m)
        .set("liner_area_m2", m.area_m2)
        .set("liner_mass_kg_per_m", m.mass_kg_per_m)
        .set("liner_mass_kg", m.mass_kg_per_m * c.mill.length_m)
        .set("diameter_eff_m", m.effective_diameter_m)
        .set("speed_rpm", c.mill.speed_rpm)
        .set("fraction_critical", c.mill.speed_rpm / nc)
        .set("n_surface_elements", s.n_elements())
        .set("element_size_m", c.liner.element_size_m);
    if (s.segments > 1 && c.liner.hi_lo) {
      const SegmentMetrics& s1 = m.segments[1];
      j.set("low_lifter_height_m", s1.lifter_height_m).set("low_top_width_m", s1.top_width_m);
    }
    std::cout << j.dump() << "\n";
  } else {
    std::cout << fmt::format("Liner of {} ({} rows{}, {} rotation)\n", c.source, s.segments,
                             c.liner.hi_lo ? ", hi-lo" : "", c.mill.rotation == Rotation::Ccw ? "anticlockwise" : "clockwise");
    std::cout << fmt::format("  lifter height above plate   {:>9.4f} m\n", s0.lifter_height_m);
    // a plain plate has no faces nor top: "n/a (no lifter)", not "n/a deg" (a review, 2026-12-07)
    auto value = [](double v, const char* f, const char* unit) {
      return std::isfinite(v) ? fmt::format("{:>9} {}", fmt::format(fmt::runtime(f), v), unit)
                              : fmt::format("{:>9} (no lifter)", "n/a");
    };
    std::cout << fmt::format("  leading face angle          {}\n",
                             value(s0.face_angle_leading_deg, "{:.2f}", "deg from the radial"));
    std::cout << fmt::format("  trailing face angle         {}\n",
                             value(s0.face_angle_trailing_deg, "{:.2f}", "deg from the radial"));
    std::cout << fmt::format("  top width                   {}\n", value(s0.top_width_m, "{:.4f}", "m"));
    if (c.liner.hi_lo && m.segments.size() > 1) {  // as --json's low_lifter_height_m, low_top_width_m
      const SegmentMetrics& s1 = m.segments[1];
      std::cout << fmt::format("  low lifter height           {:>9.4f} m\n", s1.lifter_height_m);
      std::cout << fmt::format("  low lifter top width        {}\n", value(s1.top_width_m, "{:.4f}", "m"));
    }
    std::cout << fmt::format("  minimum plate thickness     {:>9.4f} m\n", m.min_thickness_m);
    // three figures on a laboratory mill (a review, 2026-12-06: "0.0 t")
    const double ring_t = m.mass_kg_per_m * c.mill.length_m / 1000.0;
    std::cout << fmt::format("  liner mass (ring)           {:>9} kg per m of length, {} t for {} m\n",
                             num_or_3g(m.mass_kg_per_m, 100, "{:.0f}"), num_or_3g(ring_t, 10, "{:.1f}"), c.mill.length_m);
    std::cout << fmt::format("  diameter inside liners      {:>9.4f} m ({:.3f} of critical at {:.2f} rpm)\n",
                             m.effective_diameter_m, c.mill.speed_rpm / nc, c.mill.speed_rpm);
    std::cout << fmt::format("  surface elements            {:>9d} (at most {} m long)\n", s.n_elements(),
                             c.liner.element_size_m);
  }

  if (!o.out.empty()) {
    OutputDir dir(o.out);
    dir.prepare();
    const LifterGrid grid = fill_lifter_grid(lifter_grid_spec(s, 0, c.liner.lifter_grid_cells), s);
    const std::string tmp = dir.temp_path("geometry.h5");
    {
      H5Writer h5(tmp);
      write_run_header(h5, c, "geometry");
      write_surface(h5, "/surface", s);
      write_metrics(h5, "/metrics", m);
      write_lifter_grid(h5, "/lifter_grid", grid, c.liner.density_kg_m3, c.mill.length_m);
      h5.close();
    }
    dir.commit(tmp, "geometry.h5");
    const bool charts = draw_charts("geometry", dir.path("geometry.h5"), dir.dir());
    if (!o.json) print_written(dir.path("geometry.h5"), dir.dir(), charts);
  }
  return 0;
}

}  // namespace

void register_geometry(CLI::App& app, std::function<int()>& run) {
  auto opts = std::make_shared<GeometryOptions>();
  auto* cmd = app.add_subcommand("geometry", "Build the liner ring and report lifter height, face angles, mass...");
  cmd->add_option("CONFIG", opts->config, "Mill configuration (TOML); default: the bundled Qiu SAG mill")
      ->check(config_path_check());
  cmd->add_flag("--json", opts->json, "Print one JSON object instead of the human summary");
  cmd->add_option("--out", opts->out, "Write geometry.h5 and charts into this folder")
      ->check(out_folder_check("without --out nothing is written"));
  cmd->callback([&run, opts] { run = [opts] { return run_geometry(*opts); }; });
}

}  // namespace linerlife
