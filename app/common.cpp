#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <unistd.h>

#include "app/commands.h"
#include "charge/lifter_launch.h"
#include "forecast/forecast.h"
#include "forecast/parallel.h"
#include "geometry/input_text.h"

namespace linerlife {

const char* program_version() { return LINERLIFE_VERSION; }

CLI::Validator out_folder_check(const std::string& without) {
  return CLI::Validator(
      [without](std::string& dir) -> std::string {
        if (!dir.empty()) return "";
        return "an empty folder name (--out \"\"); allowed the path of a folder to write into, e.g. --out results "
               "(" + without + ")";
      },
      "");
}

std::string num(double v, const char* f) { return std::isfinite(v) ? fmt::format(fmt::runtime(f), v) : "n/a"; }
std::string num_or_3g(double v, double from, const char* f) { return num(v, std::abs(v) >= from ? f : "{:.3g}"); }

void print_written(const std::string& file, const std::string& dir, bool charts) {
  std::cout << fmt::format("Wrote {}{} in {}{}\n", file, charts ? " and charts" : "", dir,
                           charts ? "" : " (no charts: see the warning above)");
}

CLI::Validator decimal_check(bool integer) {
  return CLI::Validator(
      [integer](std::string& v) -> std::string {
        // what the CSV files accept (parse_decimal), a count without a point
        // or an exponent (its range is the command's to check); the value is
        // handed on as CLI11 reads it back exactly (a transform: CLI11 reads
        // the text itself after a check, and takes "010" for octal 8)
        double x = 0;
        const bool ok = parse_decimal(v, x) && (!integer || v.find_first_of(".eE") == std::string::npos);
        // a count is read into an int: beyond its range CLI11 said only
        // "Could not convert" (a review, 2026-12-07: --jobs 99999999999)
        constexpr double kIntMax = std::numeric_limits<int>::max();
        if (ok && integer && std::abs(x) > kIntMax)
          return fmt::format("\"{}\" is out of range; allowed a whole number between -{:.0f} and {:.0f}", printable(v),
                             kIntMax, kIntMax);
        if (ok) {
          v = integer ? fmt::format("{:.0f}", x) : fmt::format("{}", x);
          return "";
        }
        return fmt::format("\"{}\" is not {}", printable(v),
                           integer ? "a whole number; allowed decimal digits without a point or an exponent, e.g. 2"
                                   : "a decimal number; allowed decimal digits, e.g. 2, 0.5 or 1e7, within the range "
                                     "of a double (no hexadecimal, inf or nan)");
      },
      "");
}

CLI::Validator config_path_check() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        if (!path.empty()) return "";
        return "an empty configuration path (\"\"); allowed the path of a TOML file, or no CONFIG at all for the "
               "bundled Qiu mill";
      },
      "");
}

Config load_config_or_default(const std::string& path) {
  Config c = path.empty() ? load_default_config() : load_config_file(path);
  note_config(c);
  return c;
}

void note_config(const Config& c) {
  for (const std::string& n : c.notes) note("linerlife: note: " + n);
}

void note(const std::string& text) { std::cerr << text << "\n"; }

PercentLine::PercentLine(std::string label, bool on) : label_(std::move(label)), on_(on && isatty(STDERR_FILENO)) {}

PercentLine::~PercentLine() {
  if (shown_ >= 0) std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 10, "");
}

std::function<void(double)> PercentLine::callback() {
  if (!on_) return {};
  return [this](double f) {
    const int pct = static_cast<int>(100 * f);
    if (pct == shown_) return;
    shown_ = pct;
    std::fprintf(stderr, "\r  %s: %3d %%", label_.c_str(), pct);
    std::fflush(stderr);
  };
}

void rethrow_located(const Config& c, const InputError& e) { throw located(c, e); }

int forecast_jobs(int requested, int n, bool dem) {
  if (requested < 0)
    throw InputError("--jobs", fmt::format("--jobs {}: allowed 1 <= value (forecasts at once; absent or 0: one per "
                                           "core, one at a time with the DEM)", requested));
  if (requested == 0) return default_jobs(n, dem);
  const int jobs = std::min(requested, std::max(1, n));
  if (dem && jobs > 1)
    note(fmt::format("linerlife: note: --jobs {}: {} DEM forecasts at once, each spreading its contacts over the {} "
                     "cores: they share them (without --jobs the DEM's forecasts run one at a time)",
                     requested, jobs, available_cores()));
  return jobs;
}

double checked_revolutions(double n) {
  if (!(std::isfinite(n) && n >= kMinRevolutions && n <= 1e4))
    throw InputError("--revolutions", fmt::format("--revolutions {}: out of range; allowed {} <= value <= 1e4{}", n,
                                                  kMinRevolutions,
                                                  n < kMinRevolutions ? " (a shorter run averages over too few steps "
                                                                        "to give indicators)"
                                                                      : ""));
  return n;
}

InputError located(const Config& c, const InputError& e) {
  const std::string msg = e.what();
  const std::string& key = e.key();
  const auto dot = key.find('.');
  const std::string& file = c.lines_source.empty() ? c.source : c.lines_source;
  const auto origin = c.key_origin.find(key);
  if (dot == std::string::npos || msg.rfind(c.source + ":", 0) == 0 || msg.rfind(file + ":", 0) == 0 ||
      (origin != c.key_origin.end() && msg.rfind(origin->second + ":", 0) == 0))
    return e;  // already located
  const std::string name = key.substr(dot + 1);
  const KeySpec* spec = config_schema().find(key.substr(0, dot), name);
  if (!spec) return e;
  // whether the message already names the key ("name = ..." as a whole word,
  // or "[section] name: ..." as the DEM's refusals do)
  bool named = msg.find("] " + name + ":") != std::string::npos;
  for (size_t p = msg.find(name + " = "); p != std::string::npos && !named; p = msg.find(name + " = ", p + 1))
    named = p == 0 || !(std::isalnum(static_cast<unsigned char>(msg[p - 1])) || msg[p - 1] == '_');
  std::string quoted;
  if (!named) {
    const std::optional<ConfigValue> v = spec->get ? spec->get(c) : std::nullopt;
    if (v && v->kind == ConfigValue::Kind::Real) {
      // as the file wrote it (15.0, not 15) while it still holds that value
      const auto text = c.key_text.find(key);
      double written = 0;
      const bool same = text != c.key_text.end() && parse_decimal(text->second, written) && written == v->real;
      quoted = fmt::format("{} = {}: ", name, same ? text->second : fmt::format("{}", v->real));
    }
  }
  return InputError(key, config_location(c, key) + quoted + msg);
}

void note_drive_notes(const std::vector<DriveNote>& notes, long long drives) {
  for (const DriveNote& n : notes)
    note(fmt::format("linerlife: note: in {} of {} charge drives (first in drive {}): {}", n.drives, drives,
                     n.first_drive, n.text));
}

Json drive_notes_json(const std::vector<DriveNote>& notes) {
  Json a = Json::array();
  for (const DriveNote& n : notes) {
    Json o = Json::object();
    o.set("text", n.text).set("drives", n.drives).set("first_drive", n.first_drive);
    a.push(o);
  }
  return a;
}

std::string worn_power_caveat(const std::string& charge_model, const std::vector<double>& hours,
                              const std::vector<double>& net_power_kw) {
  if (charge_model != "layer" || net_power_kw.size() < 2 || hours.size() != net_power_kw.size()) return "";
  const double p0 = net_power_kw.front();
  if (!(p0 > 0)) return "";
  size_t worst = 0;
  double dev = 0;
  for (size_t i = 1; i < net_power_kw.size(); ++i) {
    const double d = net_power_kw[i] / p0 - 1.0;
    if (std::isfinite(d) && std::abs(d) > std::abs(dev)) dev = d, worst = i;
  }
  if (std::abs(dev) <= kWornPowerCaveatFraction) return "";
  // The figures of kWornPowerCaveatWhy: docs/models/layer-worn.md, "The
  // bed's support" and "The power's sum" (commands.h).
  return fmt::format("the layer model's net power moves by {:+.0f} % over this life ({:.0f} kW new, {:.0f} kW at {:.0f} h); {}",
                     100.0 * dev, p0, net_power_kw[worst], hours[worst], kWornPowerCaveatWhy);
}

std::vector<std::string> case_note_lines(const std::vector<std::string>& labels,
                                         const std::vector<std::vector<std::string>>& caveats) {
  std::vector<std::string> lines;
  std::string explained_in;  // the first case whose worn-power note was printed whole
  for (size_t i = 0; i < labels.size() && i < caveats.size(); ++i)
    for (std::string x : caveats[i]) {
      if (x.empty()) continue;
      const size_t why = x.find(kWornPowerCaveatWhy);
      if (why != std::string::npos) {
        if (explained_in.empty()) explained_in = labels[i];
        else
          x.replace(why, std::string::npos,
                    fmt::format("its power on worn liners is checked only on the Qiu mill (the note on {})", explained_in));
      }
      lines.push_back(fmt::format("linerlife: note: {}: {}", labels[i], x));
    }
  return lines;
}

std::string worn_power_caveat(const std::string& charge_model, const std::vector<LifeRecord>& history) {
  std::vector<double> hours, power;
  for (const LifeRecord& r : history) hours.push_back(r.hours), power.push_back(r.net_power_kw);
  return worn_power_caveat(charge_model, hours, power);
}

std::string dense_profile_caveat(const LinerDesign& liner) {
  const std::vector<Eigen::Vector2d>& pts = liner.profile.points;
  if (!liner.measured || pts.size() < 3) return "";
  std::vector<double> gap;
  gap.reserve(pts.size() - 1);
  for (size_t i = 1; i < pts.size(); ++i) gap.push_back((pts[i] - pts[i - 1]).norm());
  std::nth_element(gap.begin(), gap.begin() + gap.size() / 2, gap.end());
  const double median = gap[gap.size() / 2];
  if (!(median < kDenseProfileCaveatSpacingM)) return "";
  // The figures: docs/profile-csv.md, "Thin a dense scan" (bench/forecast_scatter.py
  // over five realisations, 2026-12-05).
  return fmt::format(
      "the measured profile's points are {:.2f} mm apart (median), closer than a scan of a liner resolves: until the "
      "first remesh every point is a surface node, and the wear rates on such short elements are rough, so the life "
      "scatters more over the charge model's sampling (the bundled lifter from points 0.17 mm apart: 1.8 %, from "
      "points 1.6 mm apart: 0.3 %, layer model, docs/profile-csv.md). Thin the profile to 1-2 mm between points",
      median * 1e3);
}

std::string hilo_caveat(const std::string& charge_model, const LinerDesign& liner) {
  if (charge_model != "layer" || !liner.hi_lo) return "";
  // The figures: docs/models/layer-worn.md, "Caught behind" (bench_layer_worn
  // --rings 1, and --model dem, on the rings of the bundled mill's hi-lo
  // forecast; the DEM-driven forecast of the same liner; 2026-12-06).
  return "a hi-lo liner: the layer model's charge on worn hi-lo rings is checked against the 2D DEM only on the "
         "bundled mill with 0.125 m low lifters: there its power stays within 3.5 % of the DEM's and its centre of "
         "mass within 1.2 deg over the life, its toe 14-19 deg short as on a new liner; low lifters taller than one "
         "ball step its power by about 6 % where they wear below it; it relines 32 % before a DEM-driven forecast at the same "
         "calibration (4,164 h against 6,144 h; docs/models/layer-worn.md, \"Caught behind\"). "
         "Read the relining date as indicative, or drive the forecast with [model] charge = \"dem\"";
}

std::string one_ball_caveat(const std::string& charge_model, double ball_diameter_m, const std::vector<double>& hours,
                            const std::vector<double>& lifter_height_m) {
  const double d = ball_diameter_m;
  if (charge_model != "layer" || !(d > 0) || hours.size() != lifter_height_m.size()) return "";
  // the layers the layer model's lifter holds at height h (its element one media diameter)
  auto held = [&](double h) { return lifter_held_layers(h, d); };
  for (size_t i = 1; i < hours.size(); ++i) {
    const double h0 = lifter_height_m[i - 1], h1 = lifter_height_m[i];
    if (!std::isfinite(h0) || !std::isfinite(h1) || !(held(h1) < held(h0))) continue;
    const double k = held(h0) - 1;  // the multiple of d passed first
    const double at = hours[i - 1] + (hours[i] - hours[i - 1]) * std::clamp((h0 - k * d) / (h0 - h1), 0.0, 1.0);
    // The figures: docs/models/layer-worn.md, "One ball's height" (linerlife
    // charge on the bundled mill with 45 deg faces, layer model and DEM, 2026-12-07).
    return fmt::format(
        "the lifter wore below {:g} media diameter{} ({:.3f} m) at about {:.0f} h: there the layer model's lifter stops "
        "holding a layer of balls and its charge changes in one step (the bundled mill with 45 deg faces: -10 % of "
        "power and -13.5 deg of shoulder within 0.2 mm of lifter height), where the 2D DEM's power stays within "
        "0.5 % (docs/models/layer-worn.md, \"One ball's height\"). Read the power history and the wear rates from "
        "there on with care, or check that part of the life with [model] charge = \"dem\"",
        k, k > 1 ? "s" : "", k * d, at);
  }
  return "";
}

std::string one_ball_caveat(const std::string& charge_model, double ball_diameter_m,
                            const std::vector<LifeRecord>& history) {
  std::vector<double> hours, h;
  for (const LifeRecord& r : history) hours.push_back(r.hours), h.push_back(r.lifter_height_m);
  return one_ball_caveat(charge_model, ball_diameter_m, hours, h);
}

std::string explicit_step_caveat(const ForecastSpec& spec, double speed_rpm, const ForecastResult& f) {
  if (spec.method == ForecastMethod::Ode || !(f.operating_hours > 0)) return "";
  const bool amplify = spec.method == ForecastMethod::Amplify;
  const double step_h = explicit_step_s(spec, speed_rpm) / 3600.0;  // the step the run took
  if (!(step_h > kExplicitStepCaveatFraction * f.operating_hours)) return "";
  const std::string setting =
      amplify ? fmt::format("amplification = {:g} on {:g} revolutions", spec.amplification, spec.amplify_revolutions)
              : fmt::format("euler_step_h = {:g}", spec.euler_step_h);
  return fmt::format(
      "the {} method stepped {:.0f} h at a time ({}), {:.0f} % of this {:.0f} h life, each step wearing the liner on "
      "the loads of its start: the life depends on the step. On the bundled Qiu mill amplify ends within 1.1 % of the "
      "ode method at amplification = 1e5 (241 h steps), 10 % early at 1e6 and 60 % early at 1e7; euler within 0.6 % "
      "at 400 h steps, 24 % early at 800 h (docs/validation/forecast.md). For a relining date use the ode method (the "
      "default), which re-drives the charge every refresh_tol_m of wear",
      method_name(spec.method), step_h, setting, 100.0 * step_h / f.operating_hours, f.operating_hours);
}

std::string no_wear_caveat(const WearSpec& wear, const ForecastResult& f) {
  if (!wear.laws.empty()) return "";
  // a review, 2026-12-08: the empirical model, which gives no loads on the
  // liner, allows only laws = "none", and the forecast of it ran to its horizon
  // with "no relining criterion reached" and nothing said why
  return fmt::format("[wear] laws = \"none\": nothing wears, so no relining criterion can be reached and the "
                     "forecast ran to its horizon ({:.0f} operating hours); a wear forecast needs wear laws and a "
                     "charge model that gives them the loads on the liner (\"layer\", \"dem\")",
                     f.operating_hours);
}

std::string few_drives_caveat(const ForecastSpec& spec, const ForecastResult& f) {
  if (spec.method != ForecastMethod::Ode || spec.refresh_always || f.history.size() < 2) return "";
  const LifeRecord& first = f.history.front();
  double worn = 0;  // [m] the most the liner's thinnest point or lifter height went down
  for (const LifeRecord& r : f.history) {
    if (std::isfinite(r.min_thickness_m)) worn = std::max(worn, first.min_thickness_m - r.min_thickness_m);
    if (std::isfinite(r.lifter_height_m) && std::isfinite(first.lifter_height_m))
      worn = std::max(worn, first.lifter_height_m - r.lifter_height_m);
  }
  // (a relative 1e-6 below: a criterion met at exactly five tolerances of
  // wear, 50 mm at 0.01 m, is not "less than five" by its rounding)
  if (!(worn > 0) || worn >= kFewDrivesCaveatRefreshes * spec.refresh_tol_m * (1 - 1e-6)) return "";
  // The figures: `linerlife forecast CFG --json` at refresh_tol_m = 0.002,
  // 0.0004 and 0.0001 m (a 0.2 m mill, 5 mm balls, 3 mm plate), 0.002 and
  // 0.0002 m (data/mills/pilot_test_01.toml with min_lifter_height_m = 0.015,
  // min_plate_thickness_m = 0.001), 2026-12-06.
  return fmt::format(
      "the liner wore {:.1f} mm over this life, {:.1f} times refresh_tol_m = {:g} m, and the charge was driven {} "
      "time{}: the life may not have converged in refresh_tol_m (a 0.2 m laboratory mill: 15,833 h on 1 drive, "
      "13,711 h on 25 at refresh_tol_m = 0.0001 m; pilot test 1: 7,692 h on 3, 7,733 h on 27). Check it with a "
      "refresh_tol_m of a fifth of the wear or less ({:.2g} m here)",
      1000 * worn, worn / spec.refresh_tol_m, spec.refresh_tol_m, f.stats.charge_redrives,
      f.stats.charge_redrives == 1 ? "" : "s", worn / kFewDrivesCaveatRefreshes);
}

std::string design_ranking_caveat(const std::vector<const Config*>& cases) {
  bool layer = false;
  for (const Config* c : cases) layer = layer || c->model.charge == "layer";
  if (!layer || cases.size() < 2) return "";
  // the liner's geometry: its [liner] lines but the mesh and the material
  auto liner_section = [](const Config& c) {
    const std::string t = config_to_toml(c, false);
    const auto a = t.find("\n[liner]\n");
    if (a == std::string::npos) return std::string();
    const std::string sec = t.substr(a, t.find("\n[", a + 1) - a);
    std::string out;
    size_t p = 0;
    while (p < sec.size()) {
      const size_t e = std::min(sec.find('\n', p), sec.size());
      const std::string line = sec.substr(p, e - p);
      bool skip = false;
      for (const char* k : {"element_size_m", "lifter_grid_cells", "density_kg_m3", "hardness_bhn"})
        skip = skip || line.rfind(std::string(k) + " ", 0) == 0;
      if (!skip) out += line + "\n";
      p = e + 1;
    }
    return out;
  };
  const std::string first = liner_section(*cases.front());
  bool differ = false;
  for (const Config* c : cases) differ = differ || liner_section(*c) != first;
  if (!differ) return "";
  // docs/validation/ball-mill.md, "Ranking lifter designs" and "Why the layer
  // model condemns the steep faces" (bench/design_ranking.py)
  bool slide = true;  // every layer case launches its held balls with the slide
  for (const Config* c : cases) slide = slide && (c->model.charge != "layer" || c->model.lifter_slide);
  if (slide)
    return "the layer model with lifter_slide = \"on\" ordered the example ball mill's six lifter designs as the 2D "
           "DEM did in 11 of 15 pairs and the bundled Qiu mill's three faces in 2 of 3 pairs, and it puts the Qiu "
           "mill's shoulder at 79 deg against the DEM's 29 (docs/validation/ball-mill.md, \"Why the layer model "
           "condemns the steep faces\"). Check the short list with the DEM ([model] charge = \"dem\", calibrated "
           "wear) before choosing";
  return "the layer model ranks lifter designs only roughly as the 2D DEM does: on the example ball mill it orders 8 "
         "of 15 pairs of six designs alike and puts the DEM's best second, 21 % behind its own, which is the DEM's "
         "fourth (its lives 46-76 % of the DEM's; with [model] lifter_slide = \"on\" 11 of 15), on the bundled Qiu "
         "mill 2 of 3 (faces 10/15/20 deg: the DEM 15 deg by 6.8 %, the layer model 20 deg by 25 %) "
         "(docs/validation/ball-mill.md, \"Ranking lifter designs\"). Check the short list with the DEM ([model] "
         "charge = \"dem\", calibrated wear) before choosing";
}

/// Whether some case runs layer V-1.2 and the cases' values of `of` differ by
/// more than 1 % (the condition of the two trend notes below).
template <class F>
bool v12_cases_differ(const std::vector<const Config*>& cases, F of) {
  bool v12 = false;
  double lo = 0, hi = 0;
  for (const Config* c : cases) {
    v12 = v12 || (c->model.charge == "layer" && c->model.variant == "1.2");
    lo = c == cases.front() ? of(*c) : std::min(lo, of(*c));
    hi = c == cases.front() ? of(*c) : std::max(hi, of(*c));
  }
  return v12 && cases.size() >= 2 && hi > 1.01 * lo;
}

std::string speed_trend_caveat(const std::vector<const Config*>& cases) {
  if (!v12_cases_differ(cases, [](const Config& c) { return c.mill.speed_rpm; })) return "";
  // bench/operating_trend.py on the Qiu mill, 66 to 90 % of critical (the
  // layer column since 2026-12-06: `linerlife charge` at each speed)
  // Not "draws less power as the speed rises": on other mills its power may
  // rise with the speed, and the note read as contradicting the table beneath
  // it (a review, 2026-12-07: the example ball mill at 14 and 15 rpm)
  // (-20 % since the power sum of 2e69c47, 2026-12-06: 6,190 -> 4,971 kW;
  // the note said -13 % and 74-82 % until 2026-12-08)
  return "the cases differ in mill speed, and the layer model (version 1.2) does not give the speed's effect on power "
         "reliably: on the bundled Qiu mill its power falls by 20 % from 66 to 90 % of critical, where the 2D DEM "
         "draws +41 % and Morrell's C-model +42 % (version 1.2 within 10 % of the DEM only from about 76 to 82 %) "
         "(docs/validation/charge.md, \"Operating trends\"). Read the speed's effect on power from [model] charge = "
         "\"empirical\" or \"dem\"";
}

std::string resolved_speed_caveat(const std::vector<const Config*>& cases) {
  if (cases.size() < 2) return "";
  double lo = 0, hi = 0;
  for (const Config* c : cases) {
    if (!c->speed_fraction_critical) return "";  // a case at a given rpm: the cases vary the speed themselves
    lo = c == cases.front() ? c->mill.speed_rpm : std::min(lo, c->mill.speed_rpm);
    hi = c == cases.front() ? c->mill.speed_rpm : std::max(hi, c->mill.speed_rpm);
    if (*c->speed_fraction_critical != *cases.front()->speed_fraction_critical) return "";  // varied on purpose
    if (c->mill.diameter_m != cases.front()->mill.diameter_m) return "";  // mills of other sizes: the right basis
  }
  if (!(hi > lo * (1 + 1e-9))) return "";
  // a review (2026-12-08): lifters 0.15, 0.2 and 0.23 m at 0.76 of critical ran
  // at 12.14 to 12.19 rpm, which neither the output nor the per-case files said
  return fmt::format("the speed is given as a fraction of critical ([mill] speed_fraction_critical = {:g}), which each "
                     "case resolves with the diameter inside its own new liners: the cases run at {:.4g} to {:.4g} rpm "
                     "({:+.2f} %). A mill's drive turns at one speed: give [mill] speed_rpm to compare them at it",
                     *cases.front()->speed_fraction_critical, lo, hi, 100.0 * (hi / lo - 1.0));
}

std::string filling_trend_caveat(const std::vector<const Config*>& cases) {
  if (!v12_cases_differ(cases, [](const Config& c) { return c.charge.filling; })) return "";
  // `linerlife charge FILE --model layer|empirical|dem --json` on
  // data/mills/ball_mill_5m.toml with filling = ball_filling set, and on the
  // Qiu mill with filling set (2026-12-08; docs/validation/charge.md). A
  // review's compare of the ball mill at 0.28, 0.35 and 0.42 had the power
  // fall and the life rise by 64 % with nothing said.
  return "the cases differ in filling, and the layer model (version 1.2) does not give the filling's effect on power "
         "reliably: on the example 5 m ball mill its power changes by +1.5 % from 25 to 45 % filling (2,132 -> "
         "2,164 kW, the highest 2,278 kW at 35 %), where the 2D DEM draws +42 % (1,856 -> 2,628 kW) and Morrell's "
         "C-model +36 %; on the bundled Qiu mill +6 % from 18 to 36 % against the DEM's +13 % "
         "(docs/validation/charge.md, \"Operating trends\"). Read the filling's effect on power from [model] charge = "
         "\"empirical\" or \"dem\"";
}

Json caveats_json(const std::vector<std::string>& caveats) {
  Json a = Json::array();
  for (const std::string& c : caveats) {
    if (c.empty()) continue;
    Json t = Json::object();
    t.set("text", c);
    a.push(t);
  }
  return a;
}

std::string caveat_lines(const std::vector<std::string>& caveats) {
  std::string all;
  for (const std::string& c : caveats)
    if (!c.empty()) all += (all.empty() ? "" : "\n") + c;
  return all;
}

Json caveats_json(const std::string& caveat) {
  Json a = Json::array();
  if (!caveat.empty()) {
    Json t = Json::object();
    t.set("text", caveat);
    a.push(t);
  }
  return a;
}

}  // namespace linerlife
