// commands.h - the subcommands of `linerlife`, one file each
// (cmd_<name>.cpp), listed in one plain table in main.cpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/config.h"
#include "app/json.h"
#include "charge/drive_notes.h"
#include "geometry/errors.h"

namespace linerlife {

struct LifeRecord;
struct ForecastResult;

/// Adds a subcommand to `app` and sets `run` to what it does once parsed.
using RegisterCommand = void (*)(CLI::App& app, std::function<int()>& run);

void register_defaults(CLI::App& app, std::function<int()>& run);
void register_geometry(CLI::App& app, std::function<int()>& run);
void register_charge(CLI::App& app, std::function<int()>& run);
void register_wear(CLI::App& app, std::function<int()>& run);
void register_forecast(CLI::App& app, std::function<int()>& run);
void register_compare(CLI::App& app, std::function<int()>& run);
void register_calibrate(CLI::App& app, std::function<int()>& run);
void register_plot(CLI::App& app, std::function<int()>& run);

/// The check of an --out option: an empty folder name (`--out ""`) is refused
/// by the parser (exit 2, "--out: an empty folder name ..."); before, the
/// commands took it for no --out and wrote nothing. `without` says what the
/// command does without --out.
CLI::Validator out_folder_check(const std::string& without);

/// v in the format f, or "n/a" where it is not a finite number (a face angle
/// of a plain plate, a gauge of a worn-out lifter).
std::string num(double v, const char* f);
/// v in the format f from `from` up, to three significant figures below (a
/// laboratory mill's kW and tonnes, which "{:.0f}" printed as 0); "n/a" where
/// it is not a finite number.
std::string num_or_3g(double v, double from, const char* f);

/// The summary's last line after a results file was written: "Wrote FILE and
/// charts in DIR", or, where the charts failed (their warning above), says so.
void print_written(const std::string& file, const std::string& dir, bool charts);

/// The check of a numeric option, attached with ->transform() (which hands
/// its rewritten value on; ->check() would not): a decimal number as the CSV
/// files read it (parse_decimal), without a point or an exponent where
/// `integer`, rewritten as CLI11 reads it back exactly. CLI11 alone reads
/// `--revolutions 0x10` as 16, `0x1p-3` as 0.125 and `--jobs 010` as 8.
CLI::Validator decimal_check(bool integer);

/// Refuses an empty CONFIG argument (a script's unset variable), which would
/// otherwise run the bundled mill as if no file had been given.
CLI::Validator config_path_check();

/// The program version ("0.1.0 (git abc1234)").
const char* program_version();

/// The configuration named on the command line, or the bundled default mill;
/// its notes (Config::notes) are printed.
Config load_config_or_default(const std::string& path);

/// Prints a summary line to stderr unless quiet.
void note(const std::string& text);
/// The configuration file's notes (Config::notes), one "linerlife: note:" line each.
void note_config(const Config& c);

/// A run's progress as a percentage on one line of stderr ("\r  LABEL: NN %"),
/// drawn only when `on` and stderr is a terminal; the line is cleared when the
/// object goes, by an error too (wear, charge).
class PercentLine {
 public:
  PercentLine(std::string label, bool on);
  ~PercentLine();
  PercentLine(const PercentLine&) = delete;
  PercentLine& operator=(const PercentLine&) = delete;
  /// The callback for a run's share done (0..1); empty when nothing is drawn.
  std::function<void(double)> callback();

 private:
  std::string label_;
  bool on_;
  int shown_ = -1;  // the percentage on the line; -1: none drawn
};

/// An InputError raised while running a model on configuration `c` (the DEM's
/// step beyond the stable range, a criterion the start state already meets),
/// with the location of its key in the configuration ("FILE:LINE: ") and,
/// where the message does not quote it, "name = value: ". Errors already
/// located, and keys that are not "section.name", are rethrown unchanged.
[[noreturn]] void rethrow_located(const Config& c, const InputError& e);
/// The same error, located, without throwing it.
InputError located(const Config& c, const InputError& e);

/// A --revolutions option's value: refused (InputError) unless
/// kMinRevolutions <= n <= 1e4.
double checked_revolutions(double n);

/// How many of `n` independent forecasts (compare's cases, calibrate's finite
/// differences) run at once: --jobs `requested` (refused below 0), or with 0
/// one per available core, one at a time with the DEM (`dem`), whose every
/// forecast spreads its contacts over all the cores; an explicit count with
/// the DEM is kept, with a note that the forecasts share the cores.
int forecast_jobs(int requested, int n, bool dem);

/// The charge model's notes gathered over `drives` drives (a forecast's, a
/// wear run's), one line each on stderr: "linerlife: note: in N of M charge
/// drives (first in drive K): TEXT".
void note_drive_notes(const std::vector<DriveNote>& notes, long long drives);

/// The same as a JSON array of {text, drives, first_drive}.
Json drive_notes_json(const std::vector<DriveNote>& notes);

/// A caveat on a forecast's net power history, or "" if none is due. The
/// layer model's net power on worn liners is checked on the bundled Qiu mill
/// only (docs/models/layer-worn.md, "The power's sum"): within +10.2 % over
/// the bundled forecast's worn profiles where the 2D DEM's is within +3.4 %
/// (it rose by up to +57 % before the bed's support rule of 2026-12-06, and
/// by +15.7 % with the en-masse bins' power sum before 2e69c47). When the layer model's power departs from its
/// new-liner value by more than kWornPowerCaveatFraction anywhere in the
/// history, the caveat says by how much and where the DEM stands, so that the
/// history is not read as the motor's load.
constexpr double kWornPowerCaveatFraction = 0.15;
std::string worn_power_caveat(const std::string& charge_model, const std::vector<double>& hours,
                              const std::vector<double>& net_power_kw);
/// The same from a forecast's history.
std::string worn_power_caveat(const std::string& charge_model, const std::vector<LifeRecord>& history);
/// The worn-power caveat's explanation, after its figures (the figures:
/// docs/models/layer-worn.md, "The bed's support" and "The power's sum":
/// bench_layer_worn on the bundled forecast's 68 profiles, and --model dem on
/// those at 0, 3000, 4000, 6000 and 7355 h, 20 revolutions each).
inline constexpr const char* kWornPowerCaveatWhy =
    "its power on worn liners is checked only on the bundled Qiu mill's worn profiles, where at 20 revolutions a "
    "profile the 2D DEM's changes by at most +3.4 % and the layer model's by up to +10 %; a forecast's drives, "
    "of fewer revolutions, scatter further (docs/models/layer-worn.md). Read the power history as the layer model's, "
    "not as the mill motor's load (the liner loads come from the same charge)";
/// compare's notes on its cases, one line per caveat ("linerlife: note:
/// LABEL: TEXT"), in case order; the worn-power caveat's explanation is given
/// whole once and then referred to, each case keeping its own figures.
std::vector<std::string> case_note_lines(const std::vector<std::string>& labels,
                                         const std::vector<std::vector<std::string>>& caveats);
/// A caveat on a forecast from a measured profile whose points are closer
/// than kDenseProfileCaveatSpacingM (the median spacing), or "" if none is
/// due. Such a profile keeps every point as a surface node until the first
/// remesh, and the rates on those short elements are rough: a forecast of
/// the bundled lifter cut into 5,000 points (0.17 mm apart) scattered by
/// 1.76 % over five realisations of the layer model's sampling, cut into
/// 500 (1.6 mm) by 0.30 %, as the parametric lifter (docs/profile-csv.md).
constexpr double kDenseProfileCaveatSpacingM = 1e-3;
std::string dense_profile_caveat(const LinerDesign& liner);
/// A caveat on a forecast of a hi-lo liner by the layer model, or "" for any
/// other. The layer model's charge on worn hi-lo rings is checked against the
/// 2D DEM only on the bundled mill with 0.125 m low lifters (docs/models/
/// layer-worn.md, "Caught behind"): there it stays within 3.5 % of the DEM's
/// power, but the forecast relines 32 % before a DEM-driven one.
std::string hilo_caveat(const std::string& charge_model, const LinerDesign& liner);
/// A caveat on a forecast by the layer model whose (design-0) lifter wore
/// below a whole number k >= 1 of media diameters, or "" if it did not: there
/// the model's lifter stops holding a layer of balls (layer j is held while
/// j d < h), and its charge changes in one step where the 2D DEM's power stays
/// flat (docs/models/layer-worn.md, "One ball's height"). Names the first such
/// height and the time it was passed (interpolated between history records).
std::string one_ball_caveat(const std::string& charge_model, double ball_diameter_m, const std::vector<double>& hours,
                            const std::vector<double>& lifter_height_m);
std::string one_ball_caveat(const std::string& charge_model, double ball_diameter_m,
                            const std::vector<LifeRecord>& history);
/// A caveat on a forecast by an explicit method (amplify, euler) whose step
/// is longer than kExplicitStepCaveatFraction of the life it forecast, or ""
/// if none is due. Such a step wears the liner on the rates of its start (the
/// charge is not re-driven inside it), so the life depends on the step: on
/// the bundled Qiu mill amplify ends within 1.1 % of the ode method at
/// amplification 1e5 (241 h steps, 3 % of the life), 10 % early at 1e6 and
/// 60 % early at the default 1e7 (one step longer than the life); euler
/// within 0.6 % at 400 h steps (5 %), 24 % early at 800 h (14 %)
/// (docs/validation/forecast.md, "amplify" and "euler").
constexpr double kExplicitStepCaveatFraction = 0.1;
std::string explicit_step_caveat(const ForecastSpec& spec, double speed_rpm, const ForecastResult& f);
/// A caveat on an ode forecast whose liner wore less than
/// kFewDrivesCaveatRefreshes times refresh_tol_m over its life (the larger of
/// the drop of the thinnest point and of the lifter height), or "" if none is
/// due: the charge was re-driven only a few times, and the life may not have
/// converged in refresh_tol_m (a review, 2026-12-06: a 0.2 m laboratory mill
/// forecast 15,833 h on one charge drive, 13,711 h on 25).
constexpr double kFewDrivesCaveatRefreshes = 5.0;
std::string few_drives_caveat(const ForecastSpec& spec, const ForecastResult& f);
/// The caveat of a forecast without wear laws ([wear] laws = "none"): it can
/// reach no relining criterion ("" where laws are given).
std::string no_wear_caveat(const WearSpec& wear, const ForecastResult& f);
/// A caveat as it goes into --json: an array of {text}, empty without one.
Json caveats_json(const std::string& caveat);
/// Several caveats (the empty ones left out) as one --json array of {text}.
Json caveats_json(const std::vector<std::string>& caveats);
/// The same as one text, a line per caveat (the results files' `caveat` attribute).
std::string caveat_lines(const std::vector<std::string>& caveats);

/// `compare` of lifter designs by the layer model: its ranking of designs is
/// not the DEM's everywhere (docs/validation/ball-mill.md, "Ranking lifter
/// designs"). Non-empty when some case runs the layer model and the cases'
/// [liner] sections differ; says what the DEM comparison found and to check
/// the short list with the DEM.
std::string design_ranking_caveat(const std::vector<const Config*>& cases);

/// `compare` of mill speeds with the layer model's version 1.2: its power
/// falls as the speed rises where the DEM's and Morrell's rise
/// (docs/validation/charge.md, "Operating trends"). Non-empty when some case
/// runs layer V-1.2 and the cases' speeds differ by more than 1 %.
std::string speed_trend_caveat(const std::vector<const Config*>& cases);

/// The note of a comparison of fillings by the layer model V-1.2, whose power
/// hardly follows the filling on the example ball mill where the DEM's rises
/// (docs/validation/charge.md, "Operating trends"). Non-empty when some case
/// runs layer V-1.2 and the cases' fillings differ by more than 1 %.
std::string filling_trend_caveat(const std::vector<const Config*>& cases);

/// The note of a comparison whose cases all give the speed as the same
/// fraction of critical, which each resolves with its own new liners' diameter
/// to a different rpm. Non-empty when those rpm differ.
std::string resolved_speed_caveat(const std::vector<const Config*>& cases);

}  // namespace linerlife
