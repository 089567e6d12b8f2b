#include "app/config.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "geometry/build_liner_surface.h"
#include "geometry/errors.h"
#include "geometry/input_file.h"
#include "geometry/input_text.h"
#include "geometry/measured_profile.h"
#include "geometry/metrics.h"
#include "forecast/calendar.h"

namespace linerlife {

extern const char* const kBundledDefaultConfig;  // generated from data/mills/qiu2001_sag.toml

namespace {

std::string format_number(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string format_value(const ConfigValue& v) {
  switch (v.kind) {
    case ConfigValue::Kind::Real: return format_number(v.real);
    case ConfigValue::Kind::Int: return fmt::format("{}", v.integer);
    case ConfigValue::Kind::Date: return v.text;
    case ConfigValue::Kind::Shutdowns: {
      std::string out = "[";
      for (size_t i = 0; i < v.shutdowns.size(); ++i)
        out += fmt::format("{}{{ start = {}, days = {} }}", i ? ", " : "", iso_date(v.shutdowns[i].start),
                           format_number(v.shutdowns[i].days));
      return out + "]";
    }
    case ConfigValue::Kind::String: {
      std::string out = "\"";
      for (char c : v.text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      return out + "\"";
    }
  }
  return "";
}

const char* kind_name(ConfigValue::Kind k) {
  switch (k) {
    case ConfigValue::Kind::Real: return "a number";
    case ConfigValue::Kind::Int: return "an integer";
    case ConfigValue::Kind::String: return "a string";
    case ConfigValue::Kind::Date: return "a date";  // allowed() says how it is written
    case ConfigValue::Kind::Shutdowns: return "a list of shutdowns [{ start = YYYY-MM-DD, days = N }, ...]";
  }
  return "";
}

/// A computed limit as a message prints it: `digits` significant digits,
/// rounded away from the refused side, so that the printed value is itself
/// allowed (rounding to nearest printed "allowed 0.6701 <= speed_rpm" for a
/// limit of 0.670136, a value the loader refuses). `lower` for a lower bound
/// (rounded up), else an upper bound (rounded down); more digits where a
/// rounding at `digits` would cross zero.
std::string limit_text(double x, bool lower, int digits = 4) {
  if (!std::isfinite(x) || x == 0) return fmt::format("{}", x);
  for (int p = digits; p <= 17; ++p) {
    const double scale = std::pow(10.0, std::floor(std::log10(std::abs(x))) - (p - 1));
    const double r = lower ? std::ceil(x / scale) * scale : std::floor(x / scale) * scale;
    const std::string s = fmt::format("{:.{}g}", r, p);
    const double v = std::stod(s);
    if ((lower ? v >= x : v <= x) && (v > 0) == (x > 0)) return s;
  }
  return fmt::format("{}", x);
}

/// A float that holds a whole number, as `64.0` does (node_text() echoes it
/// with its decimal point; an integer key's refusal says how to write it).
bool whole_float(double x) { return std::isfinite(x) && x == std::floor(x) && std::abs(x) < 1e15; }

/// The start of each line of a configuration's text (for node_text()).
std::vector<std::size_t> line_starts(const std::string& text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts.push_back(i + 1);
  return starts;
}

/// A value as the user wrote it, or as close as can be said: a number is
/// echoed as its text in the file where `text` and its `starts` are given
/// (`segments = 6.4e1` was echoed "64.0", `filling = 0.49999999` "0.5"), other
/// values and numbers without their text as toml++ reads them.
std::string node_text(const toml::node& n, const std::string* text = nullptr,
                      const std::vector<std::size_t>* starts = nullptr) {
  if (text && starts && (n.is_integer() || n.is_floating_point())) {
    const toml::source_region& r = n.source();
    if (r.begin.line == r.end.line && r.begin.line >= 1 && r.begin.line <= starts->size() && r.begin.column >= 1 &&
        r.end.column > r.begin.column) {
      const std::size_t a = (*starts)[r.begin.line - 1] + r.begin.column - 1;
      const std::size_t len = r.end.column - r.begin.column;
      if (a + len <= text->size()) {
        const std::string raw = text->substr(a, len);
        if (raw.find_first_of(" \t\r\n#") == std::string::npos)
          return raw.size() > 60 ? raw.substr(0, 57) + "..." : raw;
      }
    }
  }
  std::ostringstream ss;
  n.visit([&](auto&& v) {
    using T = std::decay_t<decltype(v)>;
    if constexpr (std::is_same_v<T, toml::value<std::string>>) ss << '"' << v.get() << '"';
    else if constexpr (std::is_same_v<T, toml::value<double>>) {
      // as written: 64.0 is not echoed as 64 (it would read as the integer
      // that "expected an integer" refuses)
      const double x = v.get();
      ss << x;
      if (whole_float(x)) ss << ".0";
    } else if constexpr (std::is_same_v<T, toml::value<bool>>) ss << (v.get() ? "true" : "false");  // not 1 / 0
    else if constexpr (toml::is_value<T>) ss << v.get();
    else if constexpr (std::is_same_v<T, toml::table>) ss << "(a table)";
    else ss << "(an array)";
  });
  std::string t = ss.str();
  if (t.size() > 60) t = t.substr(0, 57) + "...";
  return t;
}

/// The entries of [forecast] shutdowns, each { start = YYYY-MM-DD, days = N }
/// with N whole days, 0 < N <= 3650; an entry that is not is refused naming
/// its number (1-based), its line and what is wrong with it.
std::vector<Shutdown> shutdown_list(const toml::array& arr, const std::string& source, const std::string& sname,
                                    const std::string& kname) {
  std::vector<Shutdown> list;
  for (size_t i = 0; i < arr.size(); ++i) {
    const toml::node& item = arr[i];
    auto bad = [&](const std::string& what) {
      throw InputError(sname + "." + kname,
                       fmt::format("{}:{}: [{}] {}: shutdown {} of {}: {}; each is {{ start = YYYY-MM-DD, days = N }} "
                                   "with N whole days, 0 < days <= 3650",
                                   source, item.source().begin.line, sname, kname, i + 1, arr.size(), what));
    };
    const toml::table* tbl = item.as_table();
    if (!tbl) bad(fmt::format("{} is not a table {{ start = ..., days = ... }}", node_text(item)));
    for (auto&& [fk, fv] : *tbl)
      if (fk.str() != "start" && fk.str() != "days")
        bad(fmt::format("unknown field \"{}\" (the fields are start and days)", std::string(fk.str())));
    const toml::node* st = tbl->get("start");
    const toml::node* dy = tbl->get("days");
    if (!st) bad("missing start");
    if (!dy) bad("missing days");
    if (!st->as_date())
      bad(fmt::format("start = {} is not a date (write it unquoted: start = 2027-06-01)", node_text(*st)));
    const toml::date dd = st->as_date()->get();
    if (!valid_date(dd.year, dd.month, dd.day))
      bad(fmt::format("start = {}: allowed a date from 0001-01-01 to 9999-12-31", node_text(*st)));
    if (!(dy->as_floating_point() || dy->as_integer())) bad(fmt::format("days = {} is not a number", node_text(*dy)));
    const double days =
        dy->as_floating_point() ? dy->as_floating_point()->get() : static_cast<double>(dy->as_integer()->get());
    if (!(days > 0) || days > 3650) bad(fmt::format("a shutdown of {} days", days));
    if (days != std::floor(days)) bad(fmt::format("days = {}: the mill stops for whole calendar days", days));
    list.push_back({{dd.year, dd.month, dd.day}, days});
  }
  return list;
}

}  // namespace

bool KeySpec::accepts(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string KeySpec::allowed() const {
  if (kind == ConfigValue::Kind::Date) return "YYYY-MM-DD, unquoted: a TOML date";
  if (kind == ConfigValue::Kind::Shutdowns)
    return "a list [{ start = YYYY-MM-DD, days = N }, ...] with N whole days, 0 < days <= 3650, none starting "
           "before start_date (may be empty)";
  if (kind == ConfigValue::Kind::String) {
    if (choices.empty()) return "a string";
    std::string s = "one of ";
    for (size_t i = 0; i < choices.size(); ++i) s += (i ? ", \"" : "\"") + choices[i] + "\"";
    return s;
  }
  const bool has_lo = lo > -1e299, has_hi = hi < 1e299;
  const std::string u = unit.empty() || unit == "-" ? "" : " " + unit;
  if (has_lo && has_hi)
    return fmt::format("{} {} value {} {}{}", lo, lo_open ? "<" : "<=", hi_open ? "<" : "<=", hi, u);
  if (has_lo) return fmt::format("value {} {}{}", lo_open ? ">" : ">=", lo, u);
  if (has_hi) return fmt::format("value {} {}{}", hi_open ? "<" : "<=", hi, u);
  return "any number";
}

const KeySpec* Schema::find(const std::string& section, const std::string& name) const {
  for (const auto& k : keys)
    if (k.section == section && k.name == name) return &k;
  return nullptr;
}

const Schema& config_schema() {
  static const Schema schema = [] {
    Schema s;
    add_mill_keys(s);
    add_charge_keys(s);
    add_liner_keys(s);
    add_model_keys(s);
    add_dem_keys(s);
    add_wear_keys(s);
    add_forecast_keys(s);
    return s;
  }();
  return schema;
}

std::string config_location(const Config& c, const std::string& key) {
  const auto o = c.key_origin.find(key);
  if (o != c.key_origin.end()) return o->second + ": ";
  const std::string& file = c.lines_source.empty() ? c.source : c.lines_source;
  auto it = c.key_lines.find(key);
  if (it != c.key_lines.end()) return fmt::format("{}:{}: ", file, it->second);
  const auto dot = key.find('.');
  if (dot != std::string::npos) {
    auto st = c.section_lines.find(key.substr(0, dot));
    if (st != c.section_lines.end() && st->second > 0) return fmt::format("{}:{}: ", file, st->second);
  }
  return file + ": ";
}

bool key_given(const Config& c, const std::string& key) {
  return c.key_lines.count(key) > 0 || c.key_origin.count(key) > 0;
}

std::string known_keys_text(const std::string& section) {
  const Schema& schema = config_schema();
  std::string list;
  if (std::find(schema.sections.begin(), schema.sections.end(), section) == schema.sections.end()) {
    for (const auto& s : schema.sections) list += (list.empty() ? "[" : ", [") + s + "]";
    return "the sections are " + list;
  }
  for (const auto& k : schema.keys)
    if (k.section == section) list += (list.empty() ? "" : ", ") + k.name;
  return fmt::format("the keys of [{}] are: {}", section, list.empty() ? "(none yet)" : list);
}

namespace {

/// Rethrows an InputError from a later check with the location of its key.
[[noreturn]] void fail_at(const Config& c, const std::string& key, const std::string& message) {
  throw InputError(key, config_location(c, key) + message);
}

/// The cross-key rules and the physical checks that need the geometry.
void check_and_resolve(Config& c) {
  // speed: exactly one of the two keys
  if (c.speed_rpm.has_value() == c.speed_fraction_critical.has_value())
    fail_at(c, "mill.speed_rpm",
            c.speed_rpm ? "give exactly one of [mill] speed_rpm and speed_fraction_critical, not both"
                        : "missing key [mill] speed_rpm or speed_fraction_critical (give exactly one)");
  // charge-motion keys that depend on each other
  if ((c.charge.discharge == Discharge::Overflow || c.charge.cone_length_m > 0) && !(c.charge.trunnion_radius_m > 0))
    fail_at(c, c.charge.discharge == Discharge::Overflow ? "mill.discharge" : "mill.cone_length_m",
            "missing key [mill] trunnion_diameter_m (required by discharge = \"overflow\" and by cone_length_m > 0)");
  if (c.charge.trunnion_radius_m >= c.mill.shell_radius_m())
    fail_at(c, "mill.trunnion_diameter_m",
            fmt::format("trunnion_diameter_m = {} is not smaller than the mill diameter {}",
                        2 * c.charge.trunnion_radius_m, c.mill.diameter_m));
  if (c.model.slurry_drag && c.charge.discharge != Discharge::Overflow)
    fail_at(c, "model.slurry_drag",
            "slurry_drag = \"on\" needs discharge = \"overflow\": a grate mill has no slurry pool");
  if (c.charge.ball_filling > c.charge.filling)
    fail_at(c, "charge.ball_filling",
            fmt::format("ball_filling = {} is larger than filling = {}: the balls are part of the charge, so "
                        "0 <= ball_filling <= filling",
                        c.charge.ball_filling, c.charge.filling));

  check_dem_keys(c);

  // liner design
  LinerDesign& L = c.liner;
  // An empty path is a script's unset variable, not a choice: the key left
  // out gives the parametric lifter. Taken as no key, it ran the standard
  // lifter without a word (a review, 2026-12-07), as an empty CONFIG once ran
  // the bundled mill (docs/reliability.md).
  if (c.profile_csv.empty() && key_given(c, "liner.profile_csv"))
    fail_at(c, "liner.profile_csv",
            "profile_csv = \"\": an empty path; allowed: the path of a measured profile CSV (docs/profile-csv.md), "
            "relative to this file; leave the key out for the parametric lifter");
  L.measured = !c.profile_csv.empty();
  const char* parametric[] = {"plate_thickness_m", "lifter_height_m", "lifter_top_width_m",
                              "face_angle_leading_deg", "face_angle_trailing_deg"};
  if (!L.measured)
    for (const char* k : parametric)
      if (!c.key_lines.count(std::string("liner.") + k))
        fail_at(c, std::string("liner.") + k,
                fmt::format("missing key [liner] {} (required unless profile_csv gives a measured profile)", k));
  if (c.pattern == "hi-lo") {
    if (L.measured) fail_at(c, "liner.pattern", "pattern = \"hi-lo\" cannot be combined with profile_csv");
    for (const char* k : {"low_lifter_height_m", "low_lifter_top_width_m"})
      if (!c.key_lines.count(std::string("liner.") + k))
        fail_at(c, std::string("liner.") + k, fmt::format("missing key [liner] {} (required by pattern = \"hi-lo\")", k));
    L.hi_lo = true;
    L.low = L.design;
    L.low.lifter_height_m = *c.low_lifter_height_m;
    L.low.top_width_m = *c.low_lifter_top_width_m;
  } else {
    for (const char* k : {"low_lifter_height_m", "low_lifter_top_width_m"})
      if (c.key_lines.count(std::string("liner.") + k))
        fail_at(c, std::string("liner.") + k, fmt::format("{} applies only with pattern = \"hi-lo\"", k));
  }
  if (L.measured) {
    // The parametric design keys are allowed beside profile_csv (a measured
    // profile added to a working file) but draw nothing: said, so that no one
    // edits them expecting a change (a review, 2026-12-06).
    std::vector<std::string> unused;
    std::string first;  // the key on the earliest line, where the note points
    // corner_radius_m has a default, which a re-printed configuration
    // (compare --vary) writes out: only a fillet asked for is worth a note
    std::vector<std::string> keys(std::begin(parametric), std::end(parametric));
    if (c.liner.design.corner_radius_m != 0) keys.push_back("corner_radius_m");
    for (const std::string& k : keys) {
      const auto it = c.key_lines.find("liner." + k);
      if (it == c.key_lines.end()) continue;
      unused.push_back(k);
      if (first.empty() || it->second < c.key_lines.at(first)) first = it->first;
    }
    if (!unused.empty()) {
      std::string list;
      for (size_t i = 0; i < unused.size(); ++i) list += (i ? ", " : "") + unused[i];
      c.notes.push_back(fmt::format("{}[liner] {} {} not used: profile_csv gives the liner's profile",
                                    config_location(c, first), list,
                                    unused.size() == 1 ? "is" : "are"));
    }
    namespace fs = std::filesystem;
    fs::path p(c.profile_csv);
    if (p.is_relative()) p = fs::path(c.base_dir) / p;
    try {
      L.profile = load_profile_csv(p.string());
      validate_measured_profile(L.profile, c.mill.shell_radius_m(), L.segments);
    } catch (const InputError& e) {
      fail_at(c, "liner.profile_csv", fmt::format("[liner] profile_csv = \"{}\": {}", printable(c.profile_csv), e.what()));
    }
  }

  // Geometry: building the ring runs every check of the design.
  Mill m = c.mill;
  m.speed_rpm = c.speed_rpm.value_or(1.0);
  LinerSurface surface;
  try {
    surface = build_liner_surface(m, L);
  } catch (const InputError& e) {
    fail_at(c, e.key(), e.what());
  }
  // The low lifters of a hi-lo liner are the lower ones (after the geometry,
  // which names a low lifter that is no mill liner at all under its own key).
  if (L.hi_lo && L.low.lifter_height_m > L.design.lifter_height_m)
    fail_at(c, "liner.low_lifter_height_m",
            fmt::format("low_lifter_height_m = {} m is taller than lifter_height_m = {} m: the low lifters of a hi-lo "
                        "pattern must not be taller than the high ones; allowed 0 <= low_lifter_height_m <= {} m",
                        L.low.lifter_height_m, L.design.lifter_height_m, L.design.lifter_height_m));
  const LinerMetrics lm = metrics(surface, m.rotation, L.density_kg_m3);
  // The trunnion sets the slurry level of an overflow mill and the cone ends'
  // power: it must open inside the liners, not only inside the shell.
  if (c.charge.trunnion_radius_m > 0 && 2 * c.charge.trunnion_radius_m >= lm.effective_diameter_m)
    fail_at(c, "mill.trunnion_diameter_m",
            fmt::format("trunnion_diameter_m = {} m is not smaller than the diameter inside the liners ({:.4f} m): "
                        "allowed 0 < trunnion_diameter_m < {:.4f} m",
                        2 * c.charge.trunnion_radius_m, lm.effective_diameter_m, lm.effective_diameter_m));
  const double nc = critical_speed_rpm(lm.effective_diameter_m);
  if (c.speed_fraction_critical) {
    c.mill.speed_rpm = *c.speed_fraction_critical * nc;
  } else {
    c.mill.speed_rpm = *c.speed_rpm;
    const double phi = c.mill.speed_rpm / nc;
    if (phi < kMinSpeedFractionCritical)
      fail_at(c, "mill.speed_rpm",
              fmt::format("speed_rpm = {} is only {:.3g} of the critical speed ({} rpm for the diameter inside the "
                          "liners, {:.4f} m): below {} of critical the charge does not tumble, it creeps up the shell "
                          "and slides back; allowed {} <= speed_rpm < {}",
                          c.mill.speed_rpm, phi, limit_text(nc, false, 5), lm.effective_diameter_m,
                          kMinSpeedFractionCritical,
                          limit_text(kMinSpeedFractionCritical * nc, true), limit_text(nc, false, 5)));
    if (phi >= 1.0)
      fail_at(c, "mill.speed_rpm",
              // the critical speed as the allowed limit prints it (rounded to 3
              // decimals it read 16.045 beside "allowed ... < 16.044")
              fmt::format("speed_rpm = {} is {:.3f} of the critical speed ({} rpm for the diameter inside the "
                          "liners, {:.4f} m): at or above critical the charge centrifuges; allowed 0 < speed_rpm < "
                          "{}",
                          c.mill.speed_rpm, phi, limit_text(nc, false, 5), lm.effective_diameter_m,
                          limit_text(nc, false, 5)));
  }
  // Media must fit between two lifters (the gap at the plate).
  if (!L.measured && L.design.lifter_height_m > 0) {
    const double R = c.mill.shell_radius_m();
    const double rp = R - L.design.plate_thickness_m;
    // Each lifter's base ends where the thickness first exceeds the plate
    // level, on each side of its segment's centre: the side facing +theta
    // (ahead[k]) and the other (behind[k]); an asymmetric lifter has two
    // different half-bases. The gap between lifter k and the next one is the
    // segment angle less lifter k's side ahead and the next's side behind.
    const int n = surface.segments;
    std::vector<double> ahead(n, 0.0), behind(n, 0.0);
    for (int k = 0; k < n; ++k)
      for (int i = surface.segment_begin[k]; i < surface.segment_begin[k + 1]; ++i) {
        const auto& q = surface.nodes[i];
        if (!(R - q.norm() > L.design.plate_thickness_m + 1e-9)) continue;
        const double a = std::remainder(std::atan2(q.y(), q.x()) - surface.segment_centre_rad(k), 2 * kPi);
        if (a > 0) ahead[k] = std::max(ahead[k], a);
        else behind[k] = std::max(behind[k], -a);
      }
    double gap = std::numeric_limits<double>::infinity();
    for (int k = 0; k < n; ++k) gap = std::min(gap, (surface.segment_angle_rad() - ahead[k] - behind[(k + 1) % n]) * rp);
    if (c.charge.ball_diameter_m >= gap)
      fail_at(c, "charge.ball_diameter_m",
              fmt::format("ball_diameter_m = {} m is larger than the spacing between lifters at the plate ({:.4g} m "
                          "for {} rows): the media cannot sit between the lifters",
                          c.charge.ball_diameter_m, gap, L.segments));
  }
  // Wear: materials, laws and their parameters.
  try {
    resolve_wear_config(c);
  } catch (const InputError& e) {
    fail_at(c, e.key(), e.what());
  }
}

}  // namespace

Config load_config_text(const std::string& text, const std::string& source, const std::string& base_dir) {
  Config c;
  c.source = source;
  c.base_dir = base_dir;
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    // the line as written, so that the message names the key (toml++ says
    // only what it expected: "expected month between 1 and 12")
    const auto line_no = e.source().begin.line;
    std::string line_text;
    {
      std::istringstream in(text);
      std::string l;
      for (std::uint32_t n = 1; std::getline(in, l); ++n)
        if (n == line_no) {
          const auto a = l.find_first_not_of(" \t"), b = l.find_last_not_of(" \t\r");
          if (a != std::string::npos) line_text = l.substr(a, b - a + 1);
          break;
        }
    }
    throw InputError(source, fmt::format("{}:{}: TOML syntax error{}: {}", source, line_no,
                                         line_text.empty() ? "" : " in \"" + printable(line_text, 80) + "\"",
                                         std::string(e.description())));
  }
  const std::vector<std::size_t> starts = line_starts(text);
  const Schema& schema = config_schema();
  std::set<std::string> known_sections(schema.sections.begin(), schema.sections.end());

  for (auto&& [skey, snode] : root) {
    const std::string sname(skey.str());
    const int sline = static_cast<int>(snode.source().begin.line);
    if (!known_sections.count(sname)) {
      throw InputError(sname, fmt::format("{}:{}: unknown section or top-level key \"{}\"; {}", source, sline,
                                          printable(sname), known_keys_text(sname)));
    }
    const toml::table* t = snode.as_table();
    if (!t)
      throw InputError(sname, fmt::format("{}:{}: \"{}\" must be a section [{}]", source, sline, printable(sname),
                                          printable(sname)));
    c.section_lines[sname] = sline;
    for (auto&& [kkey, knode] : *t) {
      const std::string kname(kkey.str());
      const int line = static_cast<int>(knode.source().begin.line);
      const KeySpec* spec = schema.find(sname, kname);
      const std::string full = sname + "." + kname;
      if (!spec)
        throw InputError(full, fmt::format("{}:{}: unknown key [{}] {} (a misspelling?); {}", source, line, sname,
                                           printable(kname), known_keys_text(sname)));
      ConfigValue v;
      bool ok = false;
      switch (spec->kind) {
        case ConfigValue::Kind::Real:
          if (auto f = knode.as_floating_point()) { v = ConfigValue::Real(f->get()); ok = true; }
          else if (auto i = knode.as_integer()) { v = ConfigValue::Real(static_cast<double>(i->get())); ok = true; }
          break;
        case ConfigValue::Kind::Int:
          if (auto i = knode.as_integer()) { v = ConfigValue::Int(i->get()); ok = true; }
          break;
        case ConfigValue::Kind::String:
          if (auto s = knode.as_string()) {
            // a NUL would cut a path short (profile_csv = "a.csv\0x" opened a.csv) and a message
            if (s->get().find('\0') != std::string::npos)
              throw InputError(full, fmt::format("{}:{}: [{}] {} = \"{}\": a NUL byte (\\x00) is not allowed in a string",
                                                 source, line, sname, kname, printable(s->get())));
            v = ConfigValue::String(s->get());
            ok = true;
          }
          break;
        case ConfigValue::Kind::Date:
          if (auto d = knode.as_date()) {
            const toml::date dd = d->get();
            // TOML allows year 0, which the calendar has not (it became 2000-01-01)
            if (!valid_date(dd.year, dd.month, dd.day))
              throw InputError(full, fmt::format("{}:{}: [{}] {} = {}: allowed a date from 0001-01-01 to 9999-12-31",
                                                 source, line, sname, kname, node_text(knode, &text, &starts)));
            v = ConfigValue::Date(iso_date({dd.year, dd.month, dd.day}));
            ok = true;
          }
          break;
        case ConfigValue::Kind::Shutdowns:
          if (auto arr = knode.as_array()) {
            v = ConfigValue::List(shutdown_list(*arr, source, sname, kname));
            ok = true;
          }
          break;
      }
      if (!ok) {
        // a whole number written with a decimal point: say how to write it
        const auto* fp = knode.as_floating_point();
        const std::string hint =
            spec->kind == ConfigValue::Kind::Int && fp && whole_float(fp->get())
                ? fmt::format(", without a decimal point ({} = {})", kname, static_cast<long long>(fp->get()))
                : std::string();
        throw InputError(full, fmt::format("{}:{}: [{}] {} = {}: expected {}{} ({})", source, line, sname, kname,
                                           printable(node_text(knode, &text, &starts)), kind_name(spec->kind), hint,
                                           spec->allowed()));
      }
      const bool numeric = spec->kind == ConfigValue::Kind::Real || spec->kind == ConfigValue::Kind::Int;
      const double num = spec->kind == ConfigValue::Kind::Int ? static_cast<double>(v.integer) : v.real;
      if (numeric && !spec->accepts(num))
        throw InputError(full, fmt::format("{}:{}: [{}] {} = {}: out of range; allowed {}", source, line, sname, kname,
                                           node_text(knode, &text, &starts), spec->allowed()));
      if (spec->kind == ConfigValue::Kind::String && !spec->choices.empty()) {
        bool found = false;
        for (auto& ch : spec->choices) found |= ch == v.text;
        if (!found)
          throw InputError(full, fmt::format("{}:{}: [{}] {} = \"{}\": allowed {}", source, line, sname, kname,
                                             printable(v.text), spec->allowed()));
      }
      c.key_lines[full] = line;
      c.key_text[full] = node_text(knode, &text, &starts);
      spec->set(c, v);
    }
  }
  // absent keys: defaults, or an error for required ones
  for (const auto& k : schema.keys) {
    if (c.key_lines.count(k.full_name())) continue;
    if (k.required)
      throw InputError(k.full_name(), fmt::format("{}{}missing required key [{}] {} ({}; allowed {})", source,
                                                  c.section_lines.count(k.section)
                                                      ? fmt::format(":{}: ", c.section_lines[k.section])
                                                      : ": ",
                                                  k.section, k.name, k.help, k.allowed()));
    if (k.default_value) k.set(c, *k.default_value);
  }
  // shutdowns are days of the forecast's calendar, which begins on start_date
  if (const toml::array* arr = root["forecast"]["shutdowns"].as_array()) {
    const auto& list = c.forecast.calendar.shutdowns;
    const long long start = days_from_civil(c.forecast.calendar.start);
    for (size_t i = 0; i < list.size() && i < arr->size(); ++i)
      if (days_from_civil(list[i].start) < start)
        throw InputError("forecast.shutdowns",
                         fmt::format("{}:{}: [forecast] shutdowns: shutdown {} of {} starts on {}, before start_date "
                                     "= {}; the forecast's calendar begins on start_date, so a shutdown must start "
                                     "on it or later",
                                     source, (*arr)[i].source().begin.line, i + 1, list.size(), iso_date(list[i].start),
                                     iso_date(c.forecast.calendar.start)));
  }
  // The horizon's date must be one a result can carry: a relining date after
  // 9999-12-31 has no ISO date (the calendar stopped at 1,000,000 days
  // before, a year-4764 date for a life that ends in 13434).
  {
    const Calendar& cal = c.forecast.calendar;
    const double hours = c.forecast.max_operating_hours;
    const CivilDate end = cal.date_after(hours);
    if (end.year > 9999) {
      const double days_max =
          static_cast<double>(days_from_civil({9999, 12, 31}) - days_from_civil(cal.start) + 1);  // to its midnight
      // the hours that fit, and the availability that fits these hours (the
      // operating hours of a calendar span are proportional to availability);
      // both rounded towards what is allowed: at availability = 1e-9 the
      // hours that fit are 0.07 h, and "<= 0 h" allowed nothing
      const double h_fit = cal.operating_hours_after(days_max);
      const double a_fit = cal.availability * hours / h_fit;
      const std::string h_text = h_fit >= 1 ? fmt::format("{:.0f}", std::floor(h_fit)) : limit_text(h_fit, false);
      const std::string alternative = a_fit <= 1 && h_fit > 0 ? fmt::format("availability >= {}", limit_text(a_fit, true))
                                                              : std::string("an earlier start_date");
      fail_at(c, "forecast.max_operating_hours",
              fmt::format("max_operating_hours = {} h ends on {}, at availability = {} from start_date = {}{}: a "
                          "relining date after 9999-12-31 cannot be written as a date; allowed max_operating_hours "
                          "<= {} h here, or {}",
                          hours,
                          cal.calendar_days_for(hours) > 365.2425e6 ? std::string("a date more than a million years ahead")
                                                                    : iso_date(end),
                          cal.availability, iso_date(cal.start),
                          cal.shutdowns.empty() ? ""
                                                : fmt::format(" with {} shutdown{}", cal.shutdowns.size(),
                                                              cal.shutdowns.size() == 1 ? "" : "s"),
                          h_text,
                          alternative));
    }
  }
  check_and_resolve(c);
  return c;
}

Config load_config_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, fmt::format("configuration file {} does not exist", path));
  if (fs::is_directory(path, ec))
    throw InputError(path, fmt::format("configuration file {} is a directory, not a TOML file", path));
  const std::string text = read_input_file(path, "configuration file");
  // A configuration read from a pipe (`<(...)`, /dev/stdin) has its relative
  // paths (profile_csv) taken from the working folder, not from /dev/fd.
  const fs::path base = fs::path(path).parent_path();
  const std::string b = base.string();
  const bool pseudo = b == "/dev" || b.rfind("/dev/", 0) == 0 || b.rfind("/proc/", 0) == 0;
  return load_config_text(text, path, base.empty() || pseudo ? "." : b);
}

const std::string& default_config_text() {
  static const std::string text(kBundledDefaultConfig);
  return text;
}

Config load_default_config() {
  return load_config_text(default_config_text(), "bundled qiu2001_sag.toml", ".");
}

std::string config_to_toml(const Config& c, bool annotate) {
  const Schema& schema = config_schema();
  std::string out;
  if (annotate)
    out += "# linerlife configuration: every key with its unit and allowed range.\n"
           "# SI units throughout; the key names carry the unit. Edit a copy and run\n"
           "#   linerlife <command> your.toml\n";
  for (const auto& sec : schema.sections) {
    out += fmt::format("\n[{}]\n", sec);
    for (const auto& k : schema.keys) {
      if (k.section != sec) continue;
      const auto v = k.get(c);
      if (annotate) {
        out += fmt::format("# {}", k.help);
        if (!k.unit.empty() && k.unit != "-") out += fmt::format(" [{}]", k.unit);
        out += fmt::format(". Allowed: {}.{}", k.allowed(), k.required ? " Required." : "");
        // what a file that leaves the key out gets: not always the value
        // printed below (the bundled mill's), e.g. slurry_void_fill 0 (a dry
        // charge) against the Qiu mill's 1.0
        if (!k.required && k.default_value) out += fmt::format(" If left out: {}.", format_value(*k.default_value));
        out += "\n";
      }
      if (v)
        out += fmt::format("{} = {}\n", k.name, format_value(*v));
      else if (annotate)
        out += fmt::format("# {} = ...{}\n", k.name, k.alternative_note.empty() ? "" : "  (" + k.alternative_note + ")");
    }
  }
  return out;
}

}  // namespace linerlife
