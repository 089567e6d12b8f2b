// `linerlife charge [CONFIG] [--model empirical|layer] [--variant 1.0|1.1|1.2]
// [--revolutions N] [--json] [--out DIR]`: moves the charge of the mill with a
// charge model and reports the nine mill indicators of thesis §4.4
// (docs/models/indicators.md), the power and the run statistics. --out writes
// charge.h5 (docs/output.md) and the charts.
#include <cmath>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/json.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "app/results.h"
#include "charge/charge_model.h"
#include "charge/morrell_c_model.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"

namespace linerlife {
namespace {

struct ChargeOptions {
  std::string config;
  std::string model;    // "" = from the configuration
  std::string variant;  // "" = from the configuration
  std::optional<double> revolutions;  // unset: the model's default
  bool json = false;
  std::string out;
};

std::string fmt_or_na(double v, const char* f) { return std::isfinite(v) ? fmt::format(fmt::runtime(f), v) : "n/a"; }

void write_charge_h5(const std::string& path, const Config& c, const LinerSurface& s, const ChargeInput& in,
                     const ChargeResult& r) {
  H5Writer h5(path);
  write_run_header(h5, c, "charge");
  write_surface(h5, "/surface", s);
  const Indicators& I = r.indicators;
  h5.group("/charge");
  h5.attr("/charge", "model", r.model);
  // the layer model's version only: the DEM's chart read "dem model, version
  // 1.2" from it (a review, 2026-12-07)
  if (r.model == "layer") h5.attr("/charge", "variant", in.model.variant);
  h5.attr("/charge", "rotation", std::string(c.mill.rotation == Rotation::Ccw ? "ccw" : "cw"));
  h5.attr("/charge", "angle_convention", std::string("degrees anticlockwise from 3 o'clock, physical mill frame"));
  const std::pair<const char*, double> scalars[] = {
      {"filling", c.charge.filling},
      {"fraction_critical", I.fraction_critical},
      {"diameter_eff_m", I.diameter_eff_m},
      {"toe_deg", I.toe_deg},
      {"shoulder_deg", I.shoulder_deg},
      {"com_angle_deg", I.com_angle_deg},
      {"com_radius_m", I.com_radius_m},
      {"net_power_kw", I.net_power_kw},
      {"net_power_w_per_m", I.net_power_w_per_m},
      {"no_load_power_kw", I.no_load_power_kw},
      {"gross_power_kw", I.gross_power_kw},
      {"alt_net_power_kw", I.alt_net_power_kw},
      {"slurry_pool_power_kw", I.slurry_pool_power_kw},
      {"charge_area_m2", I.charge_area_m2},
      {"inner_radius_m", I.inner_radius_m},
      {"direct_impact_fraction", I.direct_impact_fraction},
      {"media_diameter_m", c.charge.ball_diameter_m},
      {"length_m", c.mill.length_m},
  };
  for (const auto& [k, v] : scalars) h5.attr("/charge", k, v);
  h5.attr("/charge", "n_layers", static_cast<long long>(I.n_layers));
  h5.attr("/charge", "n_trajectories", static_cast<long long>(I.n_trajectories));
  h5.dataset("/charge/layer_speed_rpm", I.layer_speed_rpm, {I.layer_speed_rpm.size()}, "rpm");
  h5.group("/charge/lifter");
  h5.attr("/charge/lifter", "segment", 0LL);
  const size_t nl = I.lifter_force_angle_deg.size();
  h5.dataset("/charge/lifter/angle_deg", I.lifter_force_angle_deg, {nl}, "deg");
  h5.dataset("/charge/lifter/normal_force_n_per_m", I.lifter_normal_force_n_per_m, {nl}, "N/m");
  h5.dataset("/charge/lifter/tangential_force_n_per_m", I.lifter_tangential_force_n_per_m, {nl}, "N/m");
  h5.group("/stats");
  h5.attr("/stats", "simulated_s", r.stats.simulated_s);
  h5.attr("/stats", "wall_s", r.stats.wall_s);
  h5.attr("/stats", "realtime_ratio", r.stats.realtime_ratio);
  h5.attr("/stats", "steps", r.stats.steps);
  h5.attr("/stats", "time_step_s", r.stats.time_step_s);
  h5.attr("/stats", "substeps", static_cast<long long>(r.stats.substeps));
  h5.attr("/stats", "elements", r.stats.elements);
  // liner loads per surface element (docs/output.md)
  const LinerLoads& L = r.loads;
  const size_t ne = static_cast<size_t>(L.n_elements);
  h5.group("/loads");
  h5.attr("/loads", "duration_s", L.duration_s);
  h5.attr("/loads", "has_impacts", static_cast<long long>(L.has_impacts));
  h5.dataset("/loads/normal_force_n_per_m", L.normal_force_n_per_m, {ne}, "N/m");
  h5.dataset("/loads/centrifugal_force_n_per_m", L.centrifugal_force_n_per_m, {ne}, "N/m");
  h5.dataset("/loads/gravitational_force_n_per_m", L.gravitational_force_n_per_m, {ne}, "N/m");
  h5.dataset("/loads/shear_force_n_per_m", L.shear_force_n_per_m, {ne}, "N/m");
  h5.dataset("/loads/slip_speed_m_s", L.slip_speed_m_s, {ne}, "m/s");
  h5.dataset("/loads/normal_slip_power_w_per_m", L.normal_slip_power_w_per_m, {ne}, "W/m");
  h5.dataset("/loads/shear_work_rate_w_per_m", L.shear_work_rate_w_per_m, {ne}, "W/m");
  const size_t ni = L.impacts.size();
  std::vector<long long> el(ni), direct(ni);
  std::vector<double> vn(ni), vt(ni), mass(ni), dia(ni), rate(ni);
  for (size_t i = 0; i < ni; ++i) {
    const ImpactEvent& e = L.impacts[i];
    el[i] = e.element;
    direct[i] = e.direct;
    vn[i] = e.normal_speed_m_s;
    vt[i] = e.tangential_speed_m_s;
    mass[i] = e.mass_kg;
    dia[i] = e.diameter_m;
    rate[i] = e.rate_per_s;
  }
  h5.group("/loads/impacts");
  h5.dataset("/loads/impacts/element", el, {ni});
  h5.dataset("/loads/impacts/direct", direct, {ni});
  h5.dataset("/loads/impacts/normal_speed_m_s", vn, {ni}, "m/s");
  h5.dataset("/loads/impacts/tangential_speed_m_s", vt, {ni}, "m/s");
  h5.dataset("/loads/impacts/mass_kg", mass, {ni}, "kg");
  h5.dataset("/loads/impacts/diameter_m", dia, {ni}, "m");
  h5.dataset("/loads/impacts/rate_per_s", rate, {ni}, "1/s per m of length");
  // element positions over the last revolution
  if (!r.snapshots.empty()) {
    const size_t nf = r.snapshots.size(), n = r.snapshots.front().position.size();
    std::vector<double> t(nf), ang(nf), xy(nf * n * 2, std::nan("")), rad(n, 0.0);
    std::vector<long long> st(nf * n, -1);
    for (size_t k = 0; k < nf; ++k) {
      const ChargeSnapshot& sn = r.snapshots[k];
      t[k] = sn.time_s;
      ang[k] = sn.liner_angle_rad;
      for (size_t i = 0; i < sn.position.size() && i < n; ++i) {
        xy[(k * n + i) * 2] = sn.position[i].x();
        xy[(k * n + i) * 2 + 1] = sn.position[i].y();
        st[k * n + i] = sn.state[i];
        rad[i] = sn.radius_m[i];
      }
    }
    h5.group("/snapshots");
    h5.attr("/snapshots", "state_codes", std::string("0 en masse, 1 in flight, 2 sliding out along a lifter face"));
    h5.dataset("/snapshots/time_s", t, {nf}, "s");
    h5.dataset("/snapshots/liner_angle_rad", ang, {nf}, "rad");
    h5.dataset("/snapshots/position_m", xy, {nf, n, 2}, "m");
    h5.dataset("/snapshots/state", st, {nf, n});
    h5.dataset("/snapshots/radius_m", rad, {n}, "m");
  }
  h5.close();
}

int run_charge(const ChargeOptions& o) {
  if (o.revolutions) checked_revolutions(*o.revolutions);
  Config c = load_config_or_default(o.config);
  if (!o.model.empty()) c.model.charge = o.model;
  if (!o.variant.empty()) c.model.variant = o.variant;
  // the versions are the layer model's (thesis §4.6): refused, not ignored, with another model
  if (!o.variant.empty() && c.model.charge != "layer")
    throw InputError("--variant", fmt::format("--variant {}: the {} model has no versions; --variant chooses the layer "
                                              "model's version of thesis §4.6 (1.0, 1.1 or 1.2): drop it, or run "
                                              "--model layer",
                                              o.variant, c.model.charge));
  const ChargeModelEntry& entry = find_charge_model(c.model.charge);
  // a closed-form model has no run length: refused, not ignored (as --variant)
  if (o.revolutions && !entry.runs_in_time)
    throw InputError("--revolutions", fmt::format("--revolutions {}: the {} model is closed-form and moves no charge; "
                                                  "--revolutions sets the run length of the models that do (layer, "
                                                  "dem): drop it, or choose one of them with --model",
                                                  *o.revolutions, entry.name));
  if (!o.out.empty()) check_output_dir_writable(o.out, {"charge.h5"});
  const LinerSurface s = build_liner_surface(c.mill, c.liner);
  ChargeInput in;
  in.mill = c.mill;
  in.charge = c.charge;
  in.model = c.model;
  in.surface = &s;
  in.revolutions = o.revolutions.value_or(0.0);
  in.record_snapshot = !o.out.empty();
  ChargeResult r;
  {
    // the DEM runs for tens of seconds (the models that end in milliseconds report nothing)
    PercentLine line(fmt::format("charge ({})", entry.name), !o.json);
    in.progress = line.callback();
    try {
      r = entry.make()->run(in);
    } catch (const InputError& e) {
      rethrow_located(c, e);  // refused inside the model (the DEM's step): the key's line
    }
  }
  in.progress = nullptr;  // the line is gone
  for (const auto& n : r.notes) note("linerlife: note: " + n);
  const Indicators& I = r.indicators;
  const bool layer = r.model == "layer";
  // a model with flights has a direct-impact fraction; Morrell's C-model has
  // none (its 0 in charge.h5 is no measurement): null in --json, no line
  const bool flights = r.model != "empirical";
  if (o.json) {
    Json speeds = Json::array();
    for (double v : I.layer_speed_rpm) speeds.push(v);
    Json j = Json::object();
    j.set("model", r.model);
    if (layer) j.set("variant", in.model.variant);
    j.set("config", c.source)
        .set("rotation", std::string(c.mill.rotation == Rotation::Ccw ? "ccw" : "cw"))
        .set("angle_convention", "degrees anticlockwise from 3 o'clock, physical mill frame")
        .set("speed_rpm", c.mill.speed_rpm)
        .set("length_m", c.mill.length_m)
        .set("filling", c.charge.filling)
        .set("fraction_critical", I.fraction_critical)
        .set("diameter_eff_m", I.diameter_eff_m)
        .set("toe_deg", I.toe_deg)
        .set("shoulder_deg", I.shoulder_deg)
        .set("com_angle_deg", I.com_angle_deg)
        .set("com_radius_m", I.com_radius_m)
        .set("net_power_kw", I.net_power_kw)
        .set("gross_power_kw", I.gross_power_kw)
        .set("no_load_power_kw", I.no_load_power_kw)
        .set("alt_net_power_kw", I.alt_net_power_kw)
        .set("slurry_pool_power_kw", I.slurry_pool_power_kw)
        .set("n_layers", I.n_layers);
    if (I.n_trajectories >= 0) j.set("n_trajectories", I.n_trajectories);
    else j.set("n_trajectories", std::nan(""));
    // docs/models/indicators.md's "also reported", as in charge.h5 (a review,
    // 2026-12-07: the HDF5 file had them, --json not)
    j.set("charge_area_m2", I.charge_area_m2)
        .set("inner_radius_m", I.inner_radius_m)
        .set("direct_impact_fraction", flights ? I.direct_impact_fraction : std::nan(""))
        .set("media_diameter_m", c.charge.ball_diameter_m)
        .set("layer_speed_rpm", speeds)
        .set("simulated_s", r.stats.simulated_s)
        .set("wall_s", r.stats.wall_s)
        .set("realtime_ratio", r.stats.realtime_ratio)
        .set("time_step_s", r.stats.time_step_s)
        .set("substeps", r.stats.substeps)
        .set("elements", r.stats.elements)
        .set("n_impacts", static_cast<long long>(r.loads.impacts.size()));
    // the model's notes, as on the standard error (a sub-stepped time step, a
    // known defect where it acts): a script reading --json sees them too
    j.set("notes", caveats_json(r.notes));  // [{"text": ...}], as forecast's caveats
    if (r.stats.particle_steps_per_s > 0)  // particle models only (docs/models/dem.md)
      j.set("particles", r.stats.elements)
          .set("particle_steps_per_s", r.stats.particle_steps_per_s)
          .set("contacts_per_s", r.stats.contacts_per_s);
    std::cout << j.dump() << "\n";
  } else {
    std::cout << fmt::format("Charge of {} with the {} model{} ({} mill)\n", c.source, r.model,
                             layer ? " version " + in.model.variant : "",
                             c.mill.rotation == Rotation::Ccw ? "anticlockwise" : "clockwise");
    std::cout << fmt::format("  diameter inside liners   {:>9.4f} m, {:.3f} of critical at {:.2f} rpm\n", I.diameter_eff_m,
                             I.fraction_critical, c.mill.speed_rpm);
    std::cout << fmt::format("  toe / shoulder           {:>9} / {} deg (anticlockwise from 3 o'clock)\n",
                             fmt_or_na(I.toe_deg, "{:.1f}"), fmt_or_na(I.shoulder_deg, "{:.1f}"));
    std::cout << fmt::format("  centre of mass           {:>9} deg at {} m\n", fmt_or_na(I.com_angle_deg, "{:.1f}"),
                             fmt_or_na(I.com_radius_m, "{:.3f}"));
    // Morrell's gross carries his lumped factor k on the net (docs/models/empirical.md); the
    // layer model's and the DEM's gross is no-load + net (docs/models/indicators.md)
    std::cout << fmt::format("  power, net / gross       {:>9.1f} / {:.1f} kW for {} m (no-load {:.1f} kW{})\n",
                             I.net_power_kw, I.gross_power_kw, c.mill.length_m, I.no_load_power_kw,
                             r.model == "empirical" ? fmt::format("; gross = no-load + k x net, Morrell's k = {}",
                                                                  MorrellInput{}.k_calibration)
                                                    : "");
    // the second power figure: the layer model's energy rate, the empirical model's
    // Hogg-Fuerstenau; the DEM has none (NaN), and the line is left out
    if (std::isfinite(I.alt_net_power_kw))
      std::cout << fmt::format("  {:<24} {:>9.1f} kW\n",
                               layer ? "energy-rate net power" : "Hogg-Fuerstenau net", I.alt_net_power_kw);
    // the indicators (docs/models/indicators.md), not the model's rings, whose
    // speeds follow: "9 / 6" above ten speeds read as a contradiction (a review,
    // 2026-12-08)
    std::cout << fmt::format("  layers / trajectories    {:>9} / {} (en-masse depth through the centre of mass / "
                             "streams in flight)\n",
                             I.n_layers, I.n_trajectories >= 0 ? std::to_string(I.n_trajectories) : "n/a");
    std::cout << fmt::format("  charge area (en masse)   {:>9.3f} m2\n", I.charge_area_m2);
    if (flights)
      std::cout << fmt::format("  direct liner impacts     {:>9.3f} of the charge landing from flight\n",
                               I.direct_impact_fraction);
    std::string sp;
    for (double v : I.layer_speed_rpm) sp += fmt::format(" {:.2f}", v);
    std::cout << fmt::format("  layer speeds [rpm]      {}{}\n", sp.empty() ? " n/a" : sp,
                             sp.empty() ? "" : fmt::format(" ({} rings, outermost first)", I.layer_speed_rpm.size()));
    if (layer || r.stats.particle_steps_per_s > 0)
      std::cout << fmt::format("  simulated {:.1f} s in {:.3f} s wall: {:.3g} x real time ({} elements, step {:.3g} s)\n",
                               r.stats.simulated_s, r.stats.wall_s, r.stats.realtime_ratio, r.stats.elements,
                               r.stats.time_step_s);
  }
  if (!o.out.empty()) {
    OutputDir dir(o.out);
    dir.prepare();
    const std::string tmp = dir.temp_path("charge.h5");
    write_charge_h5(tmp, c, s, in, r);
    dir.commit(tmp, "charge.h5");
    const bool charts = draw_charts("charge", dir.path("charge.h5"), dir.dir());
    if (!o.json) print_written(dir.path("charge.h5"), dir.dir(), charts);
  }
  return 0;
}

}  // namespace

void register_charge(CLI::App& app, std::function<int()>& run) {
  auto opts = std::make_shared<ChargeOptions>();
  auto* cmd = app.add_subcommand("charge", "Move the charge and report toe, shoulder, power... (the nine indicators)");
  cmd->add_option("CONFIG", opts->config, "Mill configuration (TOML); default: the bundled Qiu SAG mill")
      ->check(config_path_check());
  cmd->add_option("--model", opts->model, "Charge model (default: [model] charge of the configuration)")
      ->check(CLI::IsMember({"empirical", "layer", "dem"}));
  cmd->add_option("--variant", opts->variant, "Layer model version of thesis §4.6 (default: [model] variant)")
      ->check(CLI::IsMember({"1.0", "1.1", "1.2"}));
  cmd->add_option("--revolutions", opts->revolutions,
                  "Mill revolutions to average over, after settling (default: 2 for the layer model, [dem] revolutions for "
                  "the dem model; 0.05 <= N <= 1e4; not for the empirical model)")
      ->transform(decimal_check(false));
  cmd->add_flag("--json", opts->json, "Print one JSON object instead of the human summary");
  cmd->add_option("--out", opts->out, "Write charge.h5 and charts into this folder")
      ->check(out_folder_check("without --out nothing is written"));
  cmd->callback([&run, opts] { run = [opts] { return run_charge(*opts); }; });
}

}  // namespace linerlife
