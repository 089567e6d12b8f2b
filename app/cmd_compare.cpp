// `linerlife compare CONFIG... | CONFIG --vary KEY=v1,v2,...`: forecasts for
// several lifter designs or operating choices side by side (face angle,
// height, rows, hi-lo, speed...): liner life, mean and end-of-life power,
// direct liner impacts. The cases' forecasts are independent: they run
// several at once (--jobs), each on one thread, with the same results as one
// after the other.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <set>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/config_edit.h"
#include "app/forecast_setup.h"
#include "app/json.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "app/results.h"
#include "forecast/parallel.h"
#include "geometry/errors.h"
#include "geometry/input_text.h"

namespace linerlife {
namespace {

struct CompareOptions {
  std::vector<std::string> configs;
  std::vector<std::string> vary;  // KEY=v1,v2,...; several: every combination
  std::string method;
  bool json = false;
  std::string out;
  int jobs = 0;  // forecasts at once; 0: forecast_jobs()
};

struct Case {
  std::string label;
  Config config;
  std::string origin{};  // --vary: "--vary K1=V1 --vary K2=V2", what config_with() set
  std::vector<std::pair<std::string, std::string>> varied{};  // --vary: (key, value) in --vary order
  ForecastResult result;
  double mean_power_kw = 0, final_power_kw = 0, mean_direct_impacts = 0;
  std::vector<std::string> caveats{};  // on the power history (worn_power_caveat()), a hi-lo liner (hilo_caveat()), a lifter worn below whole media diameters (one_ball_caveat()), the method's step (explicit_step_caveat()), the drives (few_drives_caveat())
};

/// Time average of a history column over the life (trapezoids).
double time_mean(const std::vector<LifeRecord>& h, double LifeRecord::*field) {
  double area = 0, span = 0;
  for (size_t i = 1; i < h.size(); ++i) {
    const double dt = h[i].hours - h[i - 1].hours;
    const double a = h[i - 1].*field, b = h[i].*field;
    if (!std::isfinite(a) || !std::isfinite(b) || dt <= 0) continue;
    area += 0.5 * (a + b) * dt;
    span += dt;
  }
  return span > 0 ? area / span : (h.empty() ? NAN : h.front().*field);
}

/// The values of --vary KEY=v1,v2,...: split at the commas that are not
/// inside a TOML string ("..." or '...') or a list or table ([...], {...}),
/// so that a value holding commas can be varied when written as TOML:
/// wear.laws="abrasion/archard","abrasion/archard, impact/finnie" or
/// forecast.shutdowns=[],[{start=2027-06-01,days=7}]. Throws naming the
/// option for a quote or bracket left open.
std::vector<std::string> split_values(const std::string& option, const std::string& s) {
  std::vector<std::string> out(1);
  char quote = 0;
  int depth = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const char ch = s[i];
    if (quote) {
      if (ch == '\\' && quote == '"' && i + 1 < s.size()) {  // an escape in a basic string (\", \\, \u0077)
        out.back() += ch;
        out.back() += s[++i];
        continue;
      }
      if (ch == quote) quote = 0;
    } else if ((ch == '"' || ch == '\'') &&
               (depth > 0 || out.back().find_first_not_of(" \t") == std::string::npos)) {
      // a string opens at the start of a value or inside a list or table; an
      // apostrophe inside a bare value (o'brien.csv) is a letter
      quote = ch;
    } else if (ch == '[' || ch == '{') {
      ++depth;
    } else if ((ch == ']' || ch == '}') && depth > 0) {
      --depth;
    } else if (ch == ',' && depth == 0) {
      out.emplace_back();
      continue;
    }
    out.back() += ch;
  }
  if (quote || depth > 0)
    throw InputError("--vary", fmt::format("--vary {}: a {} is not closed; write a value that holds commas as TOML, "
                                           "e.g. wear.laws=\"abrasion/archard\",\"abrasion/archard, impact/finnie\"",
                                           option, quote ? "quote" : "bracket"));
  return out;
}

/// An error of one case, located in its configuration; a --vary case's
/// message starts with the case ("--vary K1=V1 --vary K2=V2: ...", every
/// varied key in --vary order) unless it already does.
InputError in_case(const Case& k, const InputError& e) {
  const InputError l = located(k.config, e);
  if (k.origin.empty()) return l;
  const std::string msg = l.what();
  for (const auto& o : k.config.key_origin)
    if (msg.rfind(o.second + ":", 0) == 0) {
      if (o.second == k.origin) return l;
      // one key's option: the whole case instead
      return InputError(l.key(), k.origin + msg.substr(o.second.size()));
    }
  return InputError(l.key(), k.origin + ": " + msg);
}

/// The cases of `compare CONFIG --vary K1=... [--vary K2=...]`: every
/// combination of the values, the first key varying slowest.
std::vector<Case> vary_cases(const Config& base, const std::vector<std::string>& vary) {
  struct Axis {
    std::string key;
    std::vector<std::string> values;
  };
  std::vector<Axis> axes;
  for (const std::string& v : vary) {
    const auto eq = v.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 >= v.size())
      throw InputError("--vary", fmt::format("--vary {}: write KEY=v1,v2,... (e.g. liner.face_angle_leading_deg=15,25)", v));
    Axis a{v.substr(0, eq), split_values(v, v.substr(eq + 1))};
    // the key, before any case is built (config_with() checks it again); a
    // space next to '=' made "unknown configuration key [mill] speed_rpm ",
    // the space invisible at the end of the line (a review, 2026-12-07)
    if (a.key.find_first_of(" \t") != std::string::npos)
      throw InputError("--vary", fmt::format("--vary {}: the key \"{}\" has a space in it; write KEY=v1,v2,... "
                                             "without spaces around '=' (e.g. mill.speed_rpm=10,9)",
                                             v, a.key));
    const auto dot = a.key.find('.');
    if (dot == std::string::npos)
      throw InputError("--vary", fmt::format("--vary {}: \"{}\" is not a key; write it as section.key, e.g. "
                                             "liner.face_angle_leading_deg", v, a.key));
    if (!config_schema().find(a.key.substr(0, dot), a.key.substr(dot + 1)))
      throw InputError("--vary", fmt::format("--vary {}: unknown configuration key [{}] {}; {}", v,
                                             a.key.substr(0, dot), a.key.substr(dot + 1),
                                             known_keys_text(a.key.substr(0, dot))));
    if (v.back() == ',') throw InputError("--vary", fmt::format("--vary {}: an empty value", v));
    // the mill's speed is one setting, given in rpm or as a fraction of critical
    auto same = [](const std::string& x, const std::string& y) {
      auto speed = [](const std::string& k) { return k == "mill.speed_rpm" || k == "mill.speed_fraction_critical"; };
      return x == y || (speed(x) && speed(y));
    };
    for (const Axis& b : axes)
      if (same(b.key, a.key))
        throw InputError("--vary", fmt::format("--vary {}: {} is already varied; give its values in one --vary", v, b.key));
    if (a.values.size() < 2 && vary.size() == 1)
      throw InputError("--vary", fmt::format("--vary {}: give at least two values", v));
    for (const std::string& x : a.values)
      if (x.empty()) throw InputError("--vary", fmt::format("--vary {}: an empty value", v));
    // the same value twice makes two identical cases under one label (a
    // review); numbers are compared as numbers (10 and 10.0 are one value)
    auto same_value = [](const std::string& x, const std::string& y) {
      double dx = 0, dy = 0;
      return x == y || (parse_decimal(x, dx) && parse_decimal(y, dy) && dx == dy);
    };
    for (size_t i = 0; i < a.values.size(); ++i)
      for (size_t k = 0; k < i; ++k)
        if (same_value(a.values[i], a.values[k]))
          throw InputError("--vary", fmt::format("--vary {}: {} is given twice (values {} and {}); each value makes "
                                                 "a case, and two cases would be the same forecast",
                                                 v, a.values[i], k + 1, i + 1));
    axes.push_back(std::move(a));
  }
  // Every combination is a whole forecast (some 20 s each on the bundled
  // mill); 8 million cases filled the memory before the first ran (a review).
  constexpr double kMaxCases = 1000;
  double cases_wanted = 1;
  for (const Axis& a : axes) cases_wanted *= static_cast<double>(a.values.size());
  if (cases_wanted > kMaxCases) {
    std::string counts;
    for (const Axis& a : axes) counts += (counts.empty() ? "" : " x ") + std::to_string(a.values.size());
    throw InputError("--vary", fmt::format("--vary: {} = {:.0f} cases; allowed at most {:.0f} (each is a whole "
                                           "forecast): fewer values, or several compare runs",
                                           counts, cases_wanted, kMaxCases));
  }
  size_t n = 1;
  for (const Axis& a : axes) n *= a.values.size();
  if (n < 2) throw InputError("--vary", fmt::format("--vary: {} case; give at least two values", n));
  std::vector<Case> cases;
  for (size_t i = 0; i < n; ++i) {
    // mixed-radix digits, the last axis fastest
    std::vector<size_t> at(axes.size());
    size_t r = i;
    for (size_t a = axes.size(); a-- > 0;) {
      at[a] = r % axes[a].values.size();
      r /= axes[a].values.size();
    }
    Case k;
    k.config = base;
    for (size_t a = 0; a < axes.size(); ++a) {
      const std::string kv = axes[a].key + "=" + axes[a].values[at[a]];
      k.label += (a ? " " : "") + kv;
      k.varied.emplace_back(axes[a].key, axes[a].values[at[a]]);
      try {
        k.config = config_with(k.config, axes[a].key, axes[a].values[at[a]], "--vary");
      } catch (const InputError& e) {
        // "--vary K=V: ..." for the key refused, after the case's keys before it
        throw InputError(e.key(), k.origin + (k.origin.empty() ? "" : " ") + e.what());
      }
      k.origin += (a ? " " : "") + std::string("--vary ") + kv;
    }
    cases.push_back(std::move(k));
  }
  return cases;
}

int run_compare(const CompareOptions& o) {
  std::vector<Case> cases;
  if (!o.vary.empty()) {
    if (o.configs.size() > 1)
      throw InputError("--vary", "--vary takes one configuration (or none: the bundled mill); got " +
                                     std::to_string(o.configs.size()));
    const Config base = load_config_or_default(o.configs.empty() ? "" : o.configs.front());
    cases = vary_cases(base, o.vary);
    // a case's own notes (a varied lifter key beside profile_csv is not used:
    // the cases would be the same), each once, after the file's
    std::set<std::string> said(base.notes.begin(), base.notes.end());
    for (const Case& k : cases)
      for (const std::string& n : k.config.notes)
        if (said.insert(n).second) note("linerlife: note: " + k.label + ": " + n);
  } else {
    if (o.configs.size() < 2)
      throw InputError("compare", "compare needs two or more configurations, or one with --vary KEY=v1,v2,...");
    // one file given twice (under any name) is two identical forecasts under
    // one label, as --vary x=10,10.0 would be, which is refused (a review,
    // 2026-12-07: `compare a.toml a.toml` ran both)
    for (size_t i = 0; i < o.configs.size(); ++i)
      for (size_t j = 0; j < i; ++j) {
        std::error_code ec;
        if (std::filesystem::equivalent(o.configs[i], o.configs[j], ec) && !ec)
          throw InputError("compare", fmt::format("compare {} ... {}: the file is given twice (configurations {} and "
                                                  "{}): the two cases would be the same forecast",
                                                  printable(o.configs[j]), printable(o.configs[i]), j + 1, i + 1));
      }
    for (const auto& p : o.configs) {
      Case k;
      k.label = p;
      k.config = load_config_file(p);
      note_config(k.config);
      cases.push_back(std::move(k));
    }
  }
  bool dem = false;
  for (const Case& k : cases) dem = dem || k.config.model.charge == "dem";
  const int n = static_cast<int>(cases.size());
  const int jobs = forecast_jobs(o.jobs, n, dem);
  if (!o.out.empty()) check_output_dir_writable(o.out, {"compare.h5"});
  // set every case up before running any, so a bad one is refused at once
  std::vector<ForecastSetup> setups;
  for (Case& k : cases) {
    if (!o.method.empty())
      k.config.forecast.method = o.method == "amplify" ? ForecastMethod::Amplify
                                 : o.method == "euler" ? ForecastMethod::Euler
                                                       : ForecastMethod::Ode;
    try {
      setups.push_back(make_forecast_setup(k.config, {false, false, false}, false));
    } catch (const InputError& e) {
      throw in_case(k, e);
    }
  }
  // the cases' warnings, each once with the cases it concerns
  {
    std::vector<std::string> labels;
    std::vector<std::vector<std::string>> warnings;
    for (size_t i = 0; i < cases.size(); ++i) {
      labels.push_back(cases[i].label);
      warnings.push_back(setups[i].warnings);
    }
    for (const std::string& line : case_warning_lines(labels, warnings)) std::cerr << line << "\n";
  }
  // The forecasts, `jobs` at once (forecast/parallel.h: no case after a
  // failing one starts, and the lowest failing case is reported, as one after
  // the other).
  std::mutex progress;
  parallel_for(n, jobs, [&](int i) {
    Case& k = cases[static_cast<size_t>(i)];
    if (!o.json) {
      const std::lock_guard<std::mutex> lock(progress);
      std::cerr << fmt::format("  forecast {}/{}: {}\n", i + 1, n, k.label);
    }
    try {
      k.result = run_forecast(setups[static_cast<size_t>(i)].input, *setups[static_cast<size_t>(i)].provider,
                              k.config.forecast);
    } catch (const InputError& e) {
      throw in_case(k, e);  // refused inside the forecast: the key's line, this case's value
    } catch (const SimulationError& e) {
      // which case failed (a review, 2026-12-06: exit 3 with CVODE's text and no case)
      throw SimulationError(fmt::format("case {} ({}): {}", i + 1, k.label, e.what()));
    }
  });
  for (Case& k : cases) {
    if (!k.result.notes.empty()) std::cerr << fmt::format("  {}:\n", k.label);
    note_drive_notes(k.result.notes, k.result.stats.charge_redrives);
    k.mean_power_kw = time_mean(k.result.history, &LifeRecord::net_power_kw);
    k.final_power_kw = k.result.history.back().net_power_kw;
    k.mean_direct_impacts = time_mean(k.result.history, &LifeRecord::direct_impact_fraction);
    k.caveats = {worn_power_caveat(k.config.model.charge, k.result.history), hilo_caveat(k.config.model.charge, k.config.liner),
                 one_ball_caveat(k.config.model.charge, k.config.charge.ball_diameter_m, k.result.history),
                 explicit_step_caveat(k.config.forecast, k.config.mill.speed_rpm, k.result),
                 few_drives_caveat(k.config.forecast, k.result)};
  }
  {
    std::vector<std::string> labels;
    std::vector<std::vector<std::string>> caveats;
    for (const Case& k : cases) labels.push_back(k.label), caveats.push_back(k.caveats);
    for (const std::string& line : case_note_lines(labels, caveats)) note(line);
  }

  // designs ranked by the layer model: check the short list with the DEM
  std::vector<const Config*> configs;
  for (const Case& k : cases) configs.push_back(&k.config);
  const std::string ranking = design_ranking_caveat(configs);
  if (!ranking.empty()) note("linerlife: note: " + ranking);
  // speeds compared by the layer model V-1.2: its power goes the wrong way
  const std::string speed = speed_trend_caveat(configs);
  if (!speed.empty()) note("linerlife: note: " + speed);
  // fillings compared by the layer model V-1.2: its power hardly follows them
  const std::string filling = filling_trend_caveat(configs);
  if (!filling.empty()) note("linerlife: note: " + filling);
  // one fraction of critical, several rpm: each case's new liners set its own
  const std::string resolved = resolved_speed_caveat(configs);
  if (!resolved.empty()) note("linerlife: note: " + resolved);
  // a measured profile with points closer than a scan resolves: the lives scatter more
  std::string dense;
  for (const Case& k : cases)
    if (dense.empty()) dense = dense_profile_caveat(k.config.liner);
  if (!dense.empty()) note("linerlife: note: " + dense);

  if (o.json) {
    Json arr = Json::array();
    for (const Case& k : cases) {
      const LifeRecord& last = k.result.history.back();
      Json j = Json::object();
      j.set("case", k.label)
          .set("reached", k.result.reached)
          .set("criterion", k.result.criterion)
          .set_or_null("relining_date", k.result.reached ? iso_date(k.result.relining_date) : std::string())
          .set("end_date", iso_date(k.result.relining_date))
          .set("operating_hours", k.result.operating_hours)
          .set("tonnes", k.result.tonnes)
          .set("speed_rpm", k.config.mill.speed_rpm)  // as resolved (speed_fraction_critical: with its new liners)
          .set("mean_net_power_kw", k.mean_power_kw)
          .set("final_net_power_kw", k.final_power_kw)
          .set("mean_direct_impact_fraction", k.mean_direct_impacts)
          .set("lifter_height_m_final", last.lifter_height_m)
          .set("face_angle_leading_deg_final", last.face_angle_leading_deg)
          .set("caveats", caveats_json(k.caveats));
      if (!k.varied.empty()) {
        Json v = Json::object();
        for (const auto& kv : k.varied) v.set(kv.first, kv.second);
        j.set("vary", v);
      }
      arr.push(j);
    }
    const Json all = caveats_json(std::vector<std::string>{ranking, speed, filling, resolved, dense});
    std::cout << Json::object().set("cases", arr).set("caveats", all).dump() << "\n";
  } else {
    size_t w = 36;
    for (const Case& k : cases) w = std::max(w, k.label.size() + 1);
    // power: the net power's mean over the life and at its end; direct: the
    // mean share of the landings that strike the liner (docs/models/indicators.md)
    std::cout << fmt::format("{:<{}} {:>11} {:>9} {:>22} {:>10} {:>10} {:>8}\n", "case", w, "relining", "hours",
                             "criterion", "mean kW", "end kW", "direct");
    for (const Case& k : cases)
      std::cout << fmt::format("{:<{}} {:>11} {:>9.0f} {:>22} {:>10.0f} {:>10.0f} {:>8.3f}\n", k.label, w,
                               k.result.reached ? iso_date(k.result.relining_date) : "not reached",
                               k.result.operating_hours, k.result.criterion,
                               k.mean_power_kw, k.final_power_kw, k.mean_direct_impacts);
    std::cout << "(mean kW / end kW: net power averaged over the life / at its end; direct: the share of the "
                 "landing charge that strikes the liner directly, averaged over the life)\n";
  }

  if (!o.out.empty()) {
    OutputDir dir(o.out);
    dir.prepare();
    const std::string tmp = dir.temp_path("compare.h5");
    {
      H5Writer h5(tmp);
      write_run_header(h5, cases.front().config, "compare");
      h5.group("/cases");
      std::vector<double> hours, mean_p, end_p, direct;
      std::string labels;
      for (size_t i = 0; i < cases.size(); ++i) {
        const Case& k = cases[i];
        hours.push_back(k.result.operating_hours);
        mean_p.push_back(k.mean_power_kw);
        end_p.push_back(k.final_power_kw);
        direct.push_back(k.mean_direct_impacts);
        labels += (i ? "\n" : "") + k.label;
        const std::string g = fmt::format("/cases/{}", i);
        h5.group(g);
        h5.attr(g, "label", k.label);
        h5.attr(g, "speed_rpm", k.config.mill.speed_rpm);  // as resolved
        // --vary: the case's values, one line per key of /cases' varied_keys
        if (!k.varied.empty()) {
          std::string values;
          for (size_t a = 0; a < k.varied.size(); ++a) values += (a ? "\n" : "") + k.varied[a].second;
          h5.attr(g, "varied_values", values);
        }
        h5.text(g + "/config", config_to_toml(k.config, false));
        write_forecast(h5, g + "/forecast", k.result, k.config.forecast);
        const std::string lines = caveat_lines(k.caveats);
        if (!lines.empty()) h5.attr(g + "/forecast", "caveat", lines);  // as forecast.h5's
      }
      h5.attr("/cases", "labels", labels);
      if (!cases.front().varied.empty()) {  // --vary: every case sets the same keys in the same order
        std::string keys;
        for (size_t a = 0; a < cases.front().varied.size(); ++a) keys += (a ? "\n" : "") + cases.front().varied[a].first;
        h5.attr("/cases", "varied_keys", keys);
      }
      const std::string all = caveat_lines({ranking, speed, filling, resolved, dense});
      if (!all.empty()) h5.attr("/cases", "caveat", all);
      h5.dataset("/cases/operating_hours", hours, {hours.size()}, "h");
      h5.dataset("/cases/mean_net_power_kw", mean_p, {mean_p.size()}, "kW");
      h5.dataset("/cases/final_net_power_kw", end_p, {end_p.size()}, "kW");
      h5.dataset("/cases/mean_direct_impact_fraction", direct, {direct.size()}, "-");
      h5.close();
    }
    dir.commit(tmp, "compare.h5");
    const bool charts = draw_charts("compare", dir.path("compare.h5"), dir.dir());
    if (!o.json) print_written(dir.path("compare.h5"), dir.dir(), charts);
  }
  return 0;
}

}  // namespace

void register_compare(CLI::App& app, std::function<int()>& run) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand("compare", "Forecasts for several lifter designs or operating choices side by side");
  cmd->add_option("CONFIG", o->configs, "Two or more configurations, or one with --vary")->check(config_path_check());
  cmd->add_option("--vary", o->vary,
                  "KEY=v1,v2,... one key (section.key) over several values (a string key's without quotes: "
                  "mill.rotation=ccw,cw; a value holding commas as TOML: wear.laws=\"a/b\",\"a/b, c/d\"); "
                  "repeated: every combination (a repeated KEY=v with one value sets that key in every case)")
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--method", o->method, "ode (default), amplify or euler")->check(CLI::IsMember({"ode", "amplify", "euler"}));
  cmd->add_flag("--json", o->json, "Print one JSON object instead of the table");
  cmd->add_option("--out", o->out, "Write compare.h5 and charts into this folder")
      ->check(out_folder_check("without --out nothing is written"));
  cmd->add_option("--jobs", o->jobs, "Forecasts run at once (default: one per core; one at a time with the DEM)")
      ->transform(decimal_check(true));
  cmd->callback([&run, o] { run = [o] { return run_compare(*o); }; });
}

}  // namespace linerlife
