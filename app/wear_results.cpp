#include "app/wear_results.h"

#include <fmt/format.h>

#include "app/h5_writer.h"
#include "app/commands.h"
#include "app/results.h"
#include "geometry/metrics.h"
#include "wear/wear_laws.h"

namespace linerlife {
namespace {

void write_history(H5Writer& h5, const std::string& g, const WearHistory& hs) {
  h5.group(g);
  const size_t n = hs.time_s.size();
  h5.dataset(g + "/time_s", hs.time_s, {n}, "s");
  h5.dataset(g + "/total_kg_per_m", hs.total_kg_per_m, {n}, "kg/m");
  h5.dataset(g + "/centrifugal_kg_per_m", hs.centrifugal_kg_per_m, {n}, "kg/m");
  h5.dataset(g + "/gravitational_kg_per_m", hs.gravitational_kg_per_m, {n}, "kg/m");
  h5.dataset(g + "/impact_kg_per_m", hs.impact_kg_per_m, {n}, "kg/m");
  h5.dataset(g + "/per_segment_kg_per_m", hs.per_segment_kg_per_m, {n, static_cast<size_t>(hs.segments)}, "kg/m");
}

void write_rates(H5Writer& h5, const std::string& g, const WearRunResult& r) {
  h5.group(g);
  const size_t n = r.rates.total.size();
  h5.dataset(g + "/total_m_s", r.rates.total, {n}, "m/s");
  h5.dataset(g + "/centrifugal_m_s", r.rates.centrifugal, {n}, "m/s");
  h5.dataset(g + "/gravitational_m_s", r.rates.gravitational, {n}, "m/s");
  h5.dataset(g + "/impact_m_s", r.rates.impact, {n}, "m/s");
  write_surface(h5, g + "/surface", r.rates_surface);
}

}  // namespace

Json wear_summary(const Config& c, const WearRunResult& r, const Mill& mill, const std::string& model_name) {
  const double rho = c.material.density_kg_m3;
  const SegmentMetrics m0 = segment_metrics(r.initial, 0, mill.rotation, rho);
  const SegmentMetrics m1 = segment_metrics(r.final, 0, mill.rotation, rho);
  Json j = Json::object();
  j.set("config", c.source)
      .set("charge_model", model_name)
      .set("laws", law_list_text(c.wear.laws))
      .set("rotation", std::string(mill.rotation == Rotation::Ccw ? "ccw" : "cw"))
      .set("liner_computation", c.wear.liner_computation)
      .set("feedback", c.wear.feedback)
      .set("amplification_abrasion", c.wear.amplification_abrasion)
      .set("amplification_impact", c.wear.amplification_impact)
      .set("revolutions", c.wear.revolutions)
      // what ran: fewer than asked when the liner wore through
      .set("revolutions_simulated", r.simulated_s * mill.speed_rpm / 60.0)
      .set("mass_loss_kg_per_m", r.mass_loss_kg_per_m)
      .set("mass_loss_kg", r.mass_loss_kg_per_m * mill.length_m)
      .set("liner_mass_kg_per_m", r.liner_mass_final_kg_per_m)
      .set("liner_mass_initial_kg_per_m", r.liner_mass_initial_kg_per_m)
      .set("mass_loss_centrifugal_kg_per_m", r.mass_loss_centrifugal_kg_per_m)
      .set("mass_loss_gravitational_kg_per_m", r.mass_loss_gravitational_kg_per_m)
      .set("mass_loss_impact_kg_per_m", r.mass_loss_impact_kg_per_m)
      .set("impact_fraction", r.mass_loss_kg_per_m > 0 ? r.mass_loss_impact_kg_per_m / r.mass_loss_kg_per_m : 0.0)
      .set("commanded_mass_kg_per_m", r.commanded_mass_kg_per_m)
      .set("mass_balance_rel_error", r.mass_balance_rel_error)
      .set("max_recession_m", r.max_recession_m)
      .set("lifter_height_initial_m", m0.lifter_height_m)
      .set("lifter_height_m", m1.lifter_height_m)
      .set("face_angle_leading_initial_deg", m0.face_angle_leading_deg)
      .set("face_angle_leading_deg", m1.face_angle_leading_deg)
      .set("worn_through", r.worn_through)
      .set("steps", r.steps)
      .set("step_s", r.step_s)
      .set("remeshes", r.remeshes + r.fast_remeshes)
      .set("remeshes_exact", r.remeshes)
      .set("charge_drives", r.charge_drives)
      .set("charge_notes", drive_notes_json(r.notes))
      .set("smoothing", std::string(smoothing_method_name(c.wear.smoothing.method)))
      .set("smoothing_max_rel_change", r.smoothing_max_rel_change)
      .set("simulated_s", r.simulated_s)
      .set("wall_s", r.wall_s)
      .set("charge_wall_s", r.charge_wall_s)
      .set("remesh_wall_s", r.remesh_wall_s)
      .set("realtime_ratio", r.realtime_ratio);
  if (r.worn_through) j.set("message", r.message);
  return j;
}

void write_wear_h5(const std::string& path, const Config& c, const Json& summary, const WearRunResult& r,
                   const WearRunResult* abrasion_only, const WearRunResult* impact_only) {
  H5Writer h5(path);
  write_run_header(h5, c, "wear");
  h5.group("/wear");
  h5.attr("/wear", "density_kg_m3", c.material.density_kg_m3);
  h5.attr("/wear", "mass_loss_kg_per_m", r.mass_loss_kg_per_m);
  h5.attr("/wear", "mass_loss_impact_kg_per_m", r.mass_loss_impact_kg_per_m);
  h5.attr("/wear", "max_recession_m", r.max_recession_m);
  h5.attr("/wear", "simulated_s", r.simulated_s);
  h5.text("/wear/summary_json", summary.dump());
  write_surface(h5, "/surface_initial", r.initial);
  write_surface(h5, "/surface_final", r.final);
  h5.group("/snapshots");
  std::vector<double> times;
  for (size_t i = 0; i < r.snapshots.size(); ++i) {
    times.push_back(r.snapshots[i].time_s);
    write_surface(h5, fmt::format("/snapshots/{}", i), r.snapshots[i].surface);
  }
  h5.dataset("/snapshots/time_s", times, {times.size()}, "s");
  write_history(h5, "/history", r.history);
  write_rates(h5, "/rates", r);
  if (abrasion_only || impact_only) {
    h5.group("/companions");
    if (abrasion_only) write_surface(h5, "/companions/abrasion_only", abrasion_only->final);
    if (impact_only) write_surface(h5, "/companions/impact_only", impact_only->final);
  }
  h5.close();
}

}  // namespace linerlife
