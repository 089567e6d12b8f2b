#include "app/results.h"

#include <chrono>
#include <ctime>

#include <fmt/format.h>

#include "app/commands.h"

namespace linerlife {

void write_run_header(H5Writer& h5, const Config& c, const std::string& command) {
  h5.attr("/", "program", std::string("linerlife"));
  h5.attr("/", "version", std::string(program_version()));
  h5.attr("/", "command", command);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  h5.attr("/", "created", std::string(buf));
  h5.attr("/", "config_source", c.source);
  h5.text("/config", config_to_toml(c, false));
  h5.attr("/config", "resolved_speed_rpm", c.mill.speed_rpm);
}

void write_surface(H5Writer& h5, const std::string& g, const LinerSurface& s) {
  h5.group(g);
  h5.attr(g, "shell_radius_m", s.shell_radius_m);
  h5.attr(g, "segments", static_cast<long long>(s.segments));
  const size_t n = s.nodes.size();
  std::vector<double> xy(2 * n), nrm(2 * n);
  for (size_t i = 0; i < n; ++i) {
    xy[2 * i] = s.nodes[i].x();
    xy[2 * i + 1] = s.nodes[i].y();
    nrm[2 * i] = s.normal[i].x();
    nrm[2 * i + 1] = s.normal[i].y();
  }
  h5.dataset(g + "/nodes", xy, {n, 2}, "m");
  h5.dataset(g + "/normal", nrm, {n, 2}, "-");
  h5.dataset(g + "/length", s.length, {n}, "m");
  std::vector<long long> sb(s.segment_begin.begin(), s.segment_begin.end());
  std::vector<long long> sd(s.segment_design.begin(), s.segment_design.end());
  h5.dataset(g + "/segment_begin", sb, {sb.size()});
  h5.dataset(g + "/segment_design", sd, {sd.size()});
}

void write_metrics(H5Writer& h5, const std::string& g, const LinerMetrics& m) {
  h5.group(g);
  h5.attr(g, "liner_area_m2", m.area_m2);
  h5.attr(g, "liner_mass_kg_per_m", m.mass_kg_per_m);
  h5.attr(g, "free_area_m2", m.free_area_m2);
  h5.attr(g, "effective_diameter_m", m.effective_diameter_m);
  h5.attr(g, "min_thickness_m", m.min_thickness_m);
  const size_t n = m.segments.size();
  auto col = [&](const char* name, const char* units, auto field) {
    std::vector<double> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = field(m.segments[i]);
    h5.dataset(g + "/" + name, v, {n}, units);
  };
  col("lifter_height_m", "m", [](const SegmentMetrics& s) { return s.lifter_height_m; });
  col("face_angle_leading_deg", "deg", [](const SegmentMetrics& s) { return s.face_angle_leading_deg; });
  col("face_angle_trailing_deg", "deg", [](const SegmentMetrics& s) { return s.face_angle_trailing_deg; });
  col("top_width_m", "m", [](const SegmentMetrics& s) { return s.top_width_m; });
  col("plate_ref_thickness_m", "m", [](const SegmentMetrics& s) { return s.plate_ref_thickness_m; });
  col("min_thickness_m", "m", [](const SegmentMetrics& s) { return s.min_thickness_m; });
  col("area_m2", "m2", [](const SegmentMetrics& s) { return s.area_m2; });
  col("mass_kg_per_m", "kg/m", [](const SegmentMetrics& s) { return s.mass_kg_per_m; });
}

void write_lifter_grid(H5Writer& h5, const std::string& g, const LifterGrid& grid, double density, double length) {
  h5.group(g);
  const auto& s = grid.spec;
  h5.attr(g, "segment", static_cast<long long>(s.segment));
  h5.attr(g, "x0_m", s.x0);
  h5.attr(g, "y0_m", s.y0);
  h5.attr(g, "dx_m", s.dx);
  h5.attr(g, "dy_m", s.dy);
  h5.attr(g, "grid_area_m2", grid.grid_area_m2);
  h5.attr(g, "plate_area_m2", grid.plate_area_m2);
  h5.attr(g, "cell_mass_full_kg", density * s.dx * s.dy * length);
  h5.dataset(g + "/fraction", grid.fraction, {static_cast<size_t>(s.ny), static_cast<size_t>(s.nx)}, "-");
}

}  // namespace linerlife
