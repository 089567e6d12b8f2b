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

void write_forecast(H5Writer& h5, const std::string& g, const ForecastResult& f, const ForecastSpec& spec) {
  h5.group(g);
  h5.attr(g, "method", std::string(method_name(spec.method)));
  h5.attr(g, "reached", static_cast<long long>(f.reached));
  h5.attr(g, "criterion", f.criterion);
  h5.attr(g, "operating_hours", f.operating_hours);
  h5.attr(g, "calendar_days", f.calendar_days);
  h5.attr(g, "relining_date", f.reached ? iso_date(f.relining_date) : std::string());  // "": no criterion reached
  h5.attr(g, "end_date", iso_date(f.relining_date));  // where the run ended: the relining date or the horizon's
  h5.attr(g, "start_date", iso_date(spec.calendar.start));
  h5.attr(g, "tonnes", f.tonnes);
  const auto& st = f.stats;
  h5.attr(g, "charge_redrives", static_cast<long long>(st.charge_redrives));
  h5.attr(g, "remeshes", static_cast<long long>(st.remeshes));
  h5.attr(g, "cvode_steps", st.cvode_steps);
  h5.attr(g, "rhs_evals", st.rhs_evals);
  h5.attr(g, "error_test_failures", st.error_test_failures);
  h5.attr(g, "nonlinear_failures", st.nonlinear_failures);
  h5.attr(g, "explicit_steps", static_cast<long long>(st.explicit_steps));
  h5.attr(g, "wall_s", st.wall_s);
  h5.attr(g, "charge_wall_s", st.charge_wall_s);
  h5.attr(g, "charge_simulated_s", st.charge_simulated_s);

  const std::string hg = g + "/history";
  h5.group(hg);
  const size_t n = f.history.size();
  auto col = [&](const char* name, const char* units, auto field) {
    std::vector<double> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = field(f.history[i]);
    h5.dataset(hg + "/" + name, v, {n}, units);
  };
  col("hours", "h", [](const LifeRecord& r) { return r.hours; });
  col("calendar_days", "d", [&](const LifeRecord& r) { return spec.calendar.calendar_days_for(r.hours); });
  col("lifter_height_m", "m", [](const LifeRecord& r) { return r.lifter_height_m; });
  col("crest_thickness_m", "m", [](const LifeRecord& r) { return r.crest_thickness_m; });
  col("face_angle_leading_deg", "deg", [](const LifeRecord& r) { return r.face_angle_leading_deg; });
  col("face_angle_trailing_deg", "deg", [](const LifeRecord& r) { return r.face_angle_trailing_deg; });
  col("top_width_m", "m", [](const LifeRecord& r) { return r.top_width_m; });
  col("min_thickness_m", "m", [](const LifeRecord& r) { return r.min_thickness_m; });
  col("liner_mass_kg_per_m", "kg/m", [](const LifeRecord& r) { return r.liner_mass_kg_per_m; });
  col("net_power_kw", "kW", [](const LifeRecord& r) { return r.net_power_kw; });
  col("toe_deg", "deg", [](const LifeRecord& r) { return r.toe_deg; });
  col("shoulder_deg", "deg", [](const LifeRecord& r) { return r.shoulder_deg; });
  col("direct_impact_fraction", "-", [](const LifeRecord& r) { return r.direct_impact_fraction; });
  col("impact_fraction", "-", [](const LifeRecord& r) { return r.impact_fraction; });
  col("low_lifter_height_m", "m", [](const LifeRecord& r) { return r.low_lifter_height_m; });
  col("low_face_angle_leading_deg", "deg", [](const LifeRecord& r) { return r.low_face_angle_leading_deg; });

  const std::string pg = g + "/profiles";
  h5.group(pg);
  std::vector<double> xy, hours;
  std::vector<long long> offset{0};
  for (const ProfileRecord& p : f.profiles) {
    for (const auto& q : p.nodes) {
      xy.push_back(q.x());
      xy.push_back(q.y());
    }
    offset.push_back(offset.back() + static_cast<long long>(p.nodes.size()));
    hours.push_back(p.hours);
  }
  h5.dataset(pg + "/nodes", xy, {xy.size() / 2, 2}, "m");
  h5.dataset(pg + "/offset", offset, {offset.size()});
  h5.dataset(pg + "/hours", hours, {hours.size()}, "h");
}

}  // namespace linerlife
