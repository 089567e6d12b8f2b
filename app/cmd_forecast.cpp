// `linerlife forecast [CONFIG] [--method ode|amplify|euler] [--json] [--out DIR]`:
// the product's main job. Integrates the wear of the liner over operating
// time with the charge motion re-driven on the worn geometry, to the first
// relining criterion, and turns the operating hours into a date
// (docs/models/forecast.md).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <unistd.h>

#include "app/checkpoint_file.h"
#include "app/commands.h"
#include "app/forecast_setup.h"
#include "app/json.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "app/results.h"
#include "geometry/errors.h"

namespace linerlife {
namespace {

struct ForecastOptions {
  std::string config;
  std::string method;
  bool json = false;
  bool quiet = false;
  bool resume = false;
  std::string out;
};

/// A progress bar on stderr when it is a terminal; silent otherwise.
ProgressFn progress_bar(bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  return [](double hours, double fraction) {
    const int width = 30, filled = static_cast<int>(std::round(fraction * width));
    std::fprintf(stderr, "\r  [%s%s] %3.0f %% of the life used, %8.0f operating hours", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), 100 * fraction, hours);
    std::fflush(stderr);
  };
}

namespace {

/// Forwards to a rate provider and fails at drive `fail_at` (0-based).
class FailingRateProvider : public RateProvider {
 public:
  FailingRateProvider(std::unique_ptr<RateProvider> inner, long long fail_at)
      : inner_(std::move(inner)), fail_at_(fail_at) {}
  RateSample sample(const LinerSurface& s, double revolutions) override {
    if (inner_->drive_count() >= fail_at_)
      throw SimulationError(fmt::format("charge drive {} failed (injected by LINERLIFE_FAIL_AT_DRIVE={})",
                                        inner_->drive_count(), fail_at_));
    return inner_->sample(s, revolutions);
  }
  long long drive_count() const override { return inner_->drive_count(); }
  void set_drive_count(long long n) override { inner_->set_drive_count(n); }

 private:
  std::unique_ptr<RateProvider> inner_;
  long long fail_at_;
};

}  // namespace

int run_forecast_command(const ForecastOptions& o) {
  Config c = load_config_or_default(o.config);
  if (!o.method.empty())
    c.forecast.method = o.method == "amplify" ? ForecastMethod::Amplify
                        : o.method == "euler" ? ForecastMethod::Euler
                                              : ForecastMethod::Ode;
  if (o.resume && o.out.empty()) throw InputError("--resume", "--resume continues the run in an --out DIR: give --out");
  if (!o.out.empty()) check_output_dir_writable(o.out, {"forecast.h5", "checkpoint.h5"});
  ForecastSetup setup = make_forecast_setup(c);
  const std::string config_text = config_to_toml(c, false);
  // Fault injection for the tests of the failure path (docs/reliability.md):
  // LINERLIFE_FAIL_AT_DRIVE=N makes charge drive N fail as a charge model that
  // blew up would. Not a user setting; it never changes a run that succeeds.
  if (const char* fail = std::getenv("LINERLIFE_FAIL_AT_DRIVE"))
    setup.provider = std::make_unique<FailingRateProvider>(std::move(setup.provider), std::atoll(fail));

  // checkpoints go to DIR/checkpoint.h5; --resume continues from it
  ForecastHooks hooks;
  hooks.progress = progress_bar(o.quiet);
  bool drew = false;  // a progress line is on the terminal: end it before a message
  if (hooks.progress)
    hooks.progress = [bar = hooks.progress, &drew](double hours, double fraction) {
      drew = true;
      bar(hours, fraction);
    };
  hooks.checkpoint_interval_s = c.forecast.checkpoint_interval_s;
  ForecastCheckpoint resume_from;
  std::unique_ptr<OutputDir> dir;
  if (!o.out.empty()) {
    dir = std::make_unique<OutputDir>(o.out);
    const std::string cp = dir->path("checkpoint.h5");
    if (o.resume) {
      if (std::filesystem::exists(cp)) {
        resume_from = read_checkpoint(cp, config_text, setup.input, c.forecast);
        hooks.resume = &resume_from;
        if (!o.json && !o.quiet)
          std::cerr << fmt::format("  resuming from {} at {:.0f} operating hours\n", cp, resume_from.t_s / 3600.0);
      } else {
        // said whatever --quiet and --json: the user asked to continue a run
        // and gets a whole new one (a note on stderr, the run goes on)
        std::error_code ec;
        const bool results = std::filesystem::exists(dir->path("forecast.h5"), ec);
        note(fmt::format("linerlife: note: --resume: no checkpoint in {} ({} does not exist): the forecast starts "
                         "from the new liner{}",
                         o.out, cp, results ? "; the forecast.h5 there, of a run that ended, is replaced when it ends"
                                            : ""));
      }
    }
    // the folder is created with the first file written into it, so that input
    // refused inside the forecast (a liner that already meets a criterion, a
    // DEM step beyond the stable range) leaves nothing behind
    hooks.checkpoint = [&dir, &config_text](const ForecastCheckpoint& cpt) {
      dir->prepare();
      write_checkpoint(*dir, config_text, cpt);
    };
  }
  ForecastResult partial;
  hooks.partial = &partial;
  ForecastResult f;
  try {
    f = run_forecast(setup.input, *setup.provider, c.forecast, hooks);
  } catch (const InputError& e) {
    // input refused inside the forecast (a criterion the start state already
    // meets, the DEM's step): point at the key's line, with its value
    if (drew) std::fprintf(stderr, "\n");
    rethrow_located(c, e);
  } catch (const SimulationError&) {
    if (drew) std::fprintf(stderr, "\n");
    // the results so far, marked partial; the checkpoint stays for a look
    if (dir && !partial.history.empty()) {
      dir->prepare();
      const std::string tmp = dir->temp_path("forecast.h5");
      {
        H5Writer h5(tmp);
        write_run_header(h5, c, "forecast");
        h5.attr("/", "partial", 1LL);
        write_surface(h5, "/surface", *setup.input.initial);
        write_surface(h5, "/final_surface", partial.final_surface);
        write_forecast(h5, "/forecast", partial, c.forecast);
        h5.attr("/forecast", "partial", 1LL);
        h5.close();
      }
      dir->commit(tmp, "forecast.h5");
      // no charts for a partial file: an earlier run's would be read as its
      // own (a review, 2026-12-06); `linerlife plot` draws them on request
      for (const char* png : kForecastCharts) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(dir->path(png), ec)) std::filesystem::remove(dir->path(png), ec);
      }
      std::cerr << fmt::format("linerlife: the results up to the failure are in {} (marked partial)\n",
                               dir->path("forecast.h5"));
    }
    throw;
  }
  if (drew) std::fprintf(stderr, "\n");
  note_drive_notes(f.notes, f.stats.charge_redrives);
  const LifeRecord& last = f.history.back();
  const std::vector<std::string> caveats{worn_power_caveat(c.model.charge, f.history), dense_profile_caveat(c.liner),
                                         hilo_caveat(c.model.charge, c.liner),
                                         one_ball_caveat(c.model.charge, c.charge.ball_diameter_m, f.history),
                                         explicit_step_caveat(c.forecast, c.mill.speed_rpm, f),
                                         few_drives_caveat(c.forecast, f), no_wear_caveat(c.wear, f)};
  const std::string caveat = caveat_lines(caveats);  // as forecast.h5 keeps them

  if (o.json) {
    Json hist = Json::object();
    std::vector<double> h, lh, crest, fa, pw, mass, thin;
    for (const LifeRecord& r : f.history) {
      h.push_back(r.hours);
      lh.push_back(r.lifter_height_m);
      crest.push_back(r.crest_thickness_m);
      fa.push_back(r.face_angle_leading_deg);
      pw.push_back(r.net_power_kw);
      mass.push_back(r.liner_mass_kg_per_m);
      thin.push_back(r.min_thickness_m);
    }
    hist.set("hours", h).set("lifter_height_m", lh).set("face_angle_leading_deg", fa).set("net_power_kw", pw)
        .set("crest_thickness_m", crest).set("liner_mass_kg_per_m", mass).set("min_thickness_m", thin);
    if (c.liner.hi_lo) {  // the low lifters (segment 1), as the high ones above
      std::vector<double> low_h, low_fa;
      for (const LifeRecord& r : f.history) {
        low_h.push_back(r.low_lifter_height_m);
        low_fa.push_back(r.low_face_angle_leading_deg);
      }
      hist.set("low_lifter_height_m", low_h).set("low_face_angle_leading_deg", low_fa);
    }
    Json j = Json::object();
    j.set("config", c.source)
        .set("method", method_name(c.forecast.method))
        .set("charge_model", c.model.charge)
        .set("reached", f.reached)
        .set("criterion", f.criterion)
        .set("start_date", iso_date(c.forecast.calendar.start))
        // no date when no criterion was reached (the run ended on the
        // horizon, whose date is end_date): a script reading relining_date
        // gets no date that is not one
        .set_or_null("relining_date", f.reached ? iso_date(f.relining_date) : std::string())
        .set("end_date", iso_date(f.relining_date))
        .set("operating_hours", f.operating_hours)
        .set("calendar_days", f.calendar_days)
        .set("tonnes", f.tonnes)
        .set("lifter_height_m_final", last.lifter_height_m)
        .set("face_angle_leading_deg_final", last.face_angle_leading_deg)
        .set("face_angle_trailing_deg_final", last.face_angle_trailing_deg)
        .set("min_thickness_m_final", last.min_thickness_m)
        .set("liner_mass_kg_per_m_final", last.liner_mass_kg_per_m)
        .set("charge_redrives", f.stats.charge_redrives)
        .set("remeshes", f.stats.remeshes)
        .set("cvode_steps", f.stats.cvode_steps)
        .set("rhs_evals", f.stats.rhs_evals)
        .set("error_test_failures", f.stats.error_test_failures)
        .set("explicit_steps", f.stats.explicit_steps)
        .set("charge_simulated_s", f.stats.charge_simulated_s)
        .set("wall_s", f.stats.wall_s)
        .set("charge_notes", drive_notes_json(f.notes))
        .set("caveats", caveats_json(caveats))
        .set("history", hist);
    std::cout << j.dump() << "\n";
  } else {
    const LifeRecord& first = f.history.front();
    std::cout << fmt::format("Forecast for {} ({} method, {} charge model)\n", c.source, method_name(c.forecast.method),
                             c.model.charge);
    if (f.reached)
      std::cout << fmt::format("  relining date            {}  ({} reached)\n", iso_date(f.relining_date), f.criterion);
    else
      std::cout << fmt::format("  no relining criterion reached within {} operating hours (until {})\n",
                               c.forecast.max_operating_hours, iso_date(f.relining_date));
    // The days to one decimal, and the shutdown days in them: rounded to the
    // whole day and without the shutdowns, 441.76 days read as 442 beside a
    // date 441 days on, and 153 days for 3,000 h at 0.9 as if the 14 days of a
    // shutdown were not in them (a review, 2026-12-07).
    const double down = shutdown_days_within(c.forecast.calendar, f.calendar_days);
    std::cout << fmt::format("  operating hours          {:>10.0f} h from {} ({:.1f} calendar days at {} "
                             "availability{})\n",
                             f.operating_hours, iso_date(c.forecast.calendar.start), f.calendar_days,
                             c.forecast.calendar.availability,
                             down > 0 ? fmt::format(", {:g} of them shut down", down) : "");
    if (c.forecast.throughput_t_per_h > 0)
      std::cout << fmt::format("  ore processed            {:>10} at {} t/h\n",
                               f.tonnes >= 1e5 ? num(f.tonnes / 1e6, "{:.3f} Mt") : num(f.tonnes, "{:.4g} t"),
                               c.forecast.throughput_t_per_h);
    std::cout << fmt::format("  lifter height            {:>10.4f} m  -> {:.4f} m{}\n", first.lifter_height_m,
                             last.lifter_height_m, c.liner.hi_lo ? " (the high lifters)" : "");
    if (c.liner.hi_lo)
      std::cout << fmt::format("  low lifter height        {:>10.4f} m  -> {:.4f} m\n", first.low_lifter_height_m,
                               last.low_lifter_height_m);
    if (std::isfinite(first.face_angle_leading_deg) || std::isfinite(last.face_angle_leading_deg))
      std::cout << fmt::format("  leading face angle       {:>10} deg -> {} deg\n",
                               num(first.face_angle_leading_deg, "{:.1f}"), num(last.face_angle_leading_deg, "{:.1f}"));
    else  // a plain plate ("n/a deg -> n/a deg" before)
      std::cout << "  leading face angle       n/a (no lifter)\n";
    if (c.liner.hi_lo)
      std::cout << fmt::format("  low leading face angle   {:>10} deg -> {} deg\n",
                               num(first.low_face_angle_leading_deg, "{:.1f}"),
                               num(last.low_face_angle_leading_deg, "{:.1f}"));
    std::cout << fmt::format("  thinnest point           {:>10.4f} m  -> {:.4f} m\n", first.min_thickness_m,
                             last.min_thickness_m);
    // to the kW on a plant mill, to three figures on a laboratory one (a
    // review, 2026-12-06: "0 kW -> 0 kW" for a 0.2 m mill)
    // a drive averages more revolutions than `charge` does by default, so its
    // power differs from charge's by the sampling (a review, 2026-12-07: 1,702
    // against 1,734 kW on a ball mill, with no word why)
    // (the amplify method's later drives average amplify_revolutions: no note)
    const std::string averaged =
        c.forecast.method != ForecastMethod::Amplify && c.model.charge != "empirical"  // closed form: no revolutions
            ? fmt::format(" (each the mean of a drive's {:g} revolutions)", c.forecast.revolutions_per_drive)
            : "";
    std::cout << fmt::format("  net power                {:>10} kW -> {} kW{}\n",
                             num_or_3g(first.net_power_kw, 100, "{:.0f}"), num_or_3g(last.net_power_kw, 100, "{:.0f}"),
                             averaged);
    // the ode method's steps are CVODE's, the explicit methods' their own
    const std::string steps = c.forecast.method == ForecastMethod::Ode
                                  ? fmt::format("{} CVODE steps", f.stats.cvode_steps)
                                  : fmt::format("{} {} step{}", f.stats.explicit_steps, method_name(c.forecast.method),
                                                f.stats.explicit_steps == 1 ? "" : "s");
    std::cout << fmt::format("  effort                   {} charge drive{}, {} remesh{}, {}, {:.1f} s wall\n",
                             f.stats.charge_redrives, f.stats.charge_redrives == 1 ? "" : "s", f.stats.remeshes,
                             f.stats.remeshes == 1 ? "" : "es", steps, f.stats.wall_s);
  }
  // after the summary it qualifies (its net power line)
  std::cout.flush();
  for (const std::string& x : caveats)
    if (!x.empty()) note("linerlife: note: " + x);

  if (dir) {
    dir->prepare();
    const std::string tmp = dir->temp_path("forecast.h5");
    {
      H5Writer h5(tmp);
      write_run_header(h5, c, "forecast");
      h5.attr("/", "partial", 0LL);
      write_surface(h5, "/surface", *setup.input.initial);
      write_surface(h5, "/final_surface", f.final_surface);
      write_forecast(h5, "/forecast", f, c.forecast);
      h5.attr("/forecast", "partial", 0LL);
      if (!caveat.empty()) h5.attr("/forecast", "caveat", caveat);  // the file is what is kept
      h5.close();
    }
    dir->commit(tmp, "forecast.h5");
    std::filesystem::remove(dir->path("checkpoint.h5"));  // the run is complete
    const bool charts = draw_charts("forecast", dir->path("forecast.h5"), dir->dir());
    if (!o.json) print_written(dir->path("forecast.h5"), dir->dir(), charts);
  }
  return 0;
}

}  // namespace

void register_forecast(CLI::App& app, std::function<int()>& run) {
  auto o = std::make_shared<ForecastOptions>();
  auto* cmd = app.add_subcommand("forecast", "Forecast the liner's wear life and relining date (the main job)");
  cmd->add_option("CONFIG", o->config, "Mill configuration (TOML); default: the bundled Qiu SAG mill")
      ->check(config_path_check());
  cmd->add_option("--method", o->method, "ode (default), amplify (the thesis/Qiu method) or euler")
      ->check(CLI::IsMember({"ode", "amplify", "euler"}));
  cmd->add_flag("--json", o->json, "Print one JSON object instead of the human summary");
  cmd->add_flag("--quiet", o->quiet, "No progress bar");
  cmd->add_option("--out", o->out, "Write forecast.h5 and charts into this folder (and checkpoints while running)")
      ->check(out_folder_check("without --out nothing is written"));
  cmd->add_flag("--resume", o->resume, "Continue the run in --out DIR from its last checkpoint (without one: a note "
                                       "on stderr, even with --quiet, and the run starts from the new liner)");
  cmd->callback([&run, o] { run = [o] { return run_forecast_command(*o); }; });
}

}  // namespace linerlife
