// `linerlife wear [CONFIG] [--revolutions N] [--amplification A] [--feedback]
// [--rotation ccw|cw] [--json] [--out DIR]`: the per-step coupled wear run of
// thesis chapter 5 (wear/wear_run.h; docs/models/wear.md §6). The charge model
// of [model] charge is driven on the liner, the amplified wear of every time
// step is applied to the profile, the profile is remeshed, and with
// --feedback the charge is driven again on the worn profile.
//
// --out writes wear.h5 (layout in docs/models/wear.md §7) and the charts of
// thesis Figs. 5-13, 5-16, 5-17 and B-5. For Figs. 5-16 and 5-17 the run is
// repeated with the abrasion laws only and with the impact laws only.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <optional>

#include "app/commands.h"
#include "app/forecast_setup.h"
#include "app/json.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "app/results.h"
#include "app/wear_results.h"
#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "geometry/metrics.h"
#include "wear/wear_laws.h"
#include "wear/wear_run.h"

namespace linerlife {
namespace {

struct WearOptions {
  std::string config;
  std::optional<double> revolutions;
  std::optional<double> amplification;
  bool feedback = false;
  std::string rotation;
  bool json = false;
  std::string out;
};

/// The laws of `spec` of one kind only.
WearSpec only(const WearSpec& spec, WearKind kind) {
  WearSpec s = spec;
  s.laws.clear();
  for (const auto& name : spec.laws)
    if (find_wear_law(name).kind == kind) s.laws.push_back(name);
  return s;
}

bool has_kind(const WearSpec& spec, WearKind kind) {
  for (const auto& name : spec.laws)
    if (find_wear_law(name).kind == kind) return true;
  return false;
}

/// A note where the wear run is not amplified because nothing asked for it:
/// a file without [wear] amplification_abrasion / amplification_impact (the
/// bundled ball mill) ran at the built-in 1 and wore 1 g per metre without a
/// word (a review, 2026-12-07). The thesis' coupled run amplifies the wear
/// (Table B.1); the bundled Qiu file sets 1e6.
std::optional<std::string> unamplified_note(const Config& c, bool cli_amplification) {
  if (cli_amplification || key_given(c, "wear.amplification_abrasion") || key_given(c, "wear.amplification_impact"))
    return std::nullopt;
  if (c.wear.amplification_abrasion != 1.0 || c.wear.amplification_impact != 1.0) return std::nullopt;
  return fmt::format(
      "{} sets neither [wear] amplification_abrasion nor amplification_impact, so the wear is not amplified (the "
      "built-in 1): {} revolutions wear the liner as {} revolutions of the mill do, next to nothing. The coupled wear "
      "run amplifies the wear to show how the profile moves (thesis Table B.1; the bundled Qiu file sets 1e6): set "
      "them, or give --amplification. For the liner's life, run `linerlife forecast`.",
      c.source, c.wear.revolutions, c.wear.revolutions);
}

int run_wear_command(const WearOptions& o) {
  Config c = load_config_or_default(o.config);
  if (o.amplification) {
    const double a = *o.amplification;
    if (!(std::isfinite(a) && a > 0 && a <= 1e9))
      throw InputError("--amplification", fmt::format("--amplification {}: out of range; allowed 0 < value <= 1e9", a));
    c.wear.amplification_abrasion = c.wear.amplification_impact = a;
  }
  if (o.revolutions) c.wear.revolutions = checked_revolutions(*o.revolutions);
  if (o.feedback) c.wear.feedback = true;
  validate_wear_spec(c.wear);
  // The liner is built for the configured rotation (its leading face faces
  // it); --rotation turns the mill the other way with the same liner, as the
  // thesis' Rotation switch does (Table B.1, Fig. B-1).
  Mill mill = c.mill;
  if (!o.rotation.empty()) mill.rotation = o.rotation == "cw" ? Rotation::Cw : Rotation::Ccw;
  const ChargeModelEntry& entry = find_charge_model(c.model.charge);
  try {
    make_wear_model(c.wear, entry);  // the law-model combination, before any work
  } catch (const InputError& e) {
    rethrow_located(c, e);  // the [wear] laws line of the file
  }
  warn_wear_loads(c);
  if (const auto n = unamplified_note(c, o.amplification.has_value())) note("linerlife: note: " + *n);
  if (!o.out.empty()) check_output_dir_writable(o.out, {"wear.h5"});

  WearRunInput in;
  in.mill = mill;
  in.charge = c.charge;
  in.model = c.model;
  in.surface = build_liner_surface(c.mill, c.liner);
  in.material = c.material;
  in.wear = c.wear;
  in.remesh.element_size_m = c.liner.element_size_m;
  WearRunResult r;
  {
    PercentLine line("wear", !o.json);
    in.progress = line.callback();
    try {
      r = run_wear(in, entry);
    } catch (const InputError& e) {
      rethrow_located(c, e);  // refused inside the model (the DEM's step): the key's line
    }
  }
  in.progress = nullptr;  // the line is gone
  note_drive_notes(r.notes, r.charge_drives);

  std::optional<WearRunResult> abrasion_only, impact_only;
  if (!o.out.empty() && has_kind(c.wear, WearKind::Abrasion) && has_kind(c.wear, WearKind::Impact)) {
    in.wear = only(c.wear, WearKind::Abrasion);
    abrasion_only = run_wear(in, entry);
    in.wear = only(c.wear, WearKind::Impact);
    impact_only = run_wear(in, entry);
  }

  const Json j = wear_summary(c, r, mill, entry.name);
  if (o.json) {
    std::cout << j.dump() << "\n";
  } else {
    const SegmentMetrics m0 = segment_metrics(r.initial, 0, mill.rotation, c.material.density_kg_m3);
    const SegmentMetrics m1 = segment_metrics(r.final, 0, mill.rotation, c.material.density_kg_m3);
    // the revolutions that ran: a run that wore through stopped before the ones asked for
    const std::string revs =
        r.worn_through ? fmt::format("{:.2f} of {} revolutions, stopped", r.simulated_s * mill.speed_rpm / 60.0,
                                     c.wear.revolutions)
                       : fmt::format("{} revolutions", c.wear.revolutions);
    std::cout << fmt::format("Wear run of {} ({} charge model, {}, amplification {:g}/{:g}{})\n", c.source,
                             entry.name, revs, c.wear.amplification_abrasion, c.wear.amplification_impact,
                             c.wear.feedback ? ", feedback" : "");
    std::cout << fmt::format("  laws                        {}\n", law_list_text(c.wear.laws));
    std::cout << fmt::format("  mass lost                   {:>10.3f} kg per m of length ({:.1f} kg for {} m)\n",
                             r.mass_loss_kg_per_m, r.mass_loss_kg_per_m * mill.length_m, mill.length_m);
    std::cout << fmt::format("    from impact               {:>10.1f} %\n",
                             r.mass_loss_kg_per_m > 0 ? 100 * r.mass_loss_impact_kg_per_m / r.mass_loss_kg_per_m : 0.0);
    std::cout << fmt::format("  liner mass after            {:>10.1f} kg per m\n", r.liner_mass_final_kg_per_m);
    std::cout << fmt::format("  deepest recession           {:>10.4f} m\n", r.max_recession_m);
    std::cout << fmt::format("  lifter height               {:>10.4f} m (was {:.4f})\n", m1.lifter_height_m,
                             m0.lifter_height_m);
    std::cout << fmt::format("  leading face angle          {:>10} deg (was {})\n", num(m1.face_angle_leading_deg, "{:.2f}"),
                             num(m0.face_angle_leading_deg, "{:.2f}"));
    std::cout << fmt::format("  simulated / wall time       {:>10.2f} s / {:.3f} s ({:.0f} x real time)\n",
                             r.simulated_s, r.wall_s, r.realtime_ratio);
    if (r.worn_through) std::cout << "  stopped: " << r.message << "\n";
  }

  if (!o.out.empty()) {
    OutputDir dir(o.out);
    dir.prepare();
    const std::string tmp = dir.temp_path("wear.h5");
    write_wear_h5(tmp, c, j, r, abrasion_only ? &*abrasion_only : nullptr, impact_only ? &*impact_only : nullptr);
    dir.commit(tmp, "wear.h5");
    const bool charts = draw_charts("wear", dir.path("wear.h5"), dir.dir());
    if (!o.json) print_written(dir.path("wear.h5"), dir.dir(), charts);
  }
  return 0;
}

}  // namespace

void register_wear(CLI::App& app, std::function<int()>& run) {
  auto opts = std::make_shared<WearOptions>();
  auto* cmd = app.add_subcommand(
      "wear", "The per-step coupled wear run (thesis ch. 5): charge model, amplified wear, remeshing, feedback");
  cmd->add_option("CONFIG", opts->config, "Mill configuration (TOML); default: the bundled Qiu SAG mill")
      ->check(config_path_check());
  cmd->add_option("--revolutions", opts->revolutions, "Mill revolutions to simulate ([wear] revolutions)")
      ->transform(decimal_check(false));
  cmd->add_option("--amplification", opts->amplification,
                  "Wear amplification A for abrasion and impact ([wear] amplification_*; Qiu 2001: 1e7)")
      ->transform(decimal_check(false));
  cmd->add_flag("--feedback", opts->feedback, "Drive the charge on the worn profile ([wear] feedback = 1)");
  cmd->add_option("--rotation", opts->rotation, "Turn the mill this way with the same liner ([mill] rotation)")
      ->check(CLI::IsMember({"ccw", "cw"}));
  cmd->add_flag("--json", opts->json, "Print one JSON object instead of the human summary");
  cmd->add_option("--out", opts->out, "Write wear.h5 and charts into this folder")
      ->check(out_folder_check("without --out nothing is written"));
  cmd->callback([&run, opts] { run = [opts] { return run_wear_command(*opts); }; });
}

}  // namespace linerlife
