// config.h - the one TOML input file (DESIGN.md §4): loading, checking and
// printing it. Every key is declared once in a schema (config_schema_*.cpp)
// with its type, unit, range and help text; the loader, the error messages and
// `linerlife defaults` all read that table.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "charge/charge_spec.h"
#include "forecast/forecast_spec.h"
#include "geometry/lifter_design.h"
#include "geometry/mill.h"
#include "wear/liner_material.h"
#include "wear/wear_spec.h"

namespace linerlife {

/// The fewest mill revolutions a run may average over (--revolutions, [wear]
/// revolutions and drive_revolutions): 18 deg of mill rotation, 9 of the layer
/// model's 2-deg samples. A shorter window averages over a step or two, or
/// none, and gives all-zero or undefined indicators (docs/reliability.md).
constexpr double kMinRevolutions = 0.05;

/// Everything a run is configured with, in SI units.
struct Config {
  std::string source;    // the file it came from, or "bundled qiu2001_sag.toml"
  std::string base_dir;  // relative paths in the file are resolved against it

  Mill mill;                                      // speed_rpm resolved by resolve_setup() if given as a fraction
  std::optional<double> speed_rpm;                // [rpm] as given
  std::optional<double> speed_fraction_critical;  // [-] as given
  ChargeSpec charge;
  LinerDesign liner;
  std::string profile_csv;  // as given ("" = parametric design)
  std::string pattern = "uniform";
  std::optional<double> low_lifter_height_m, low_lifter_top_width_m;
  ModelSpec model;
  WearSpec wear;               // laws resolved from wear_laws_text by resolve_wear_config()
  std::string wear_laws_text = "abrasion/radziszewski, impact/sheldon_kanhere";  // [wear] laws as given
  LinerMaterial material;      // density and hardness from [liner], ball density from [charge], the rest from [wear]
  ForecastSpec forecast;

  // Things the file's reader should know that are no error (keys given but
  // not used); printed once by the command that loads the file (note_config()).
  std::vector<std::string> notes;

  std::map<std::string, int> key_lines;  // "section.key" -> line in the source (1-based)
  std::map<std::string, std::string> key_text;  // "section.key" -> its value as written (a number its text: 6.4e1)
  std::map<std::string, int> section_lines;
  // A configuration derived from a file by config_with() (compare --vary):
  // the file the lines above refer to, and where each changed key was set
  // ("--vary liner.face_angle_leading_deg=15"), for config_location().
  std::string lines_source;                     // "" = source
  std::map<std::string, std::string> key_origin;  // "section.key" -> where it was set
};

/// A configuration value as TOML holds it.
struct ConfigValue {
  enum class Kind { Real, Int, String, Date, Shutdowns } kind = Kind::Real;
  double real = 0;
  long long integer = 0;
  std::string text;                 // String; Date as "YYYY-MM-DD"
  std::vector<Shutdown> shutdowns;  // Shutdowns: [{start = YYYY-MM-DD, days = N}, ...]
  static ConfigValue Real(double v) { ConfigValue c; c.kind = Kind::Real; c.real = v; return c; }
  static ConfigValue Int(long long v) { ConfigValue c; c.kind = Kind::Int; c.integer = v; return c; }
  static ConfigValue String(std::string v) { ConfigValue c; c.kind = Kind::String; c.text = std::move(v); return c; }
  static ConfigValue Date(std::string v) { ConfigValue c; c.kind = Kind::Date; c.text = std::move(v); return c; }
  static ConfigValue List(std::vector<Shutdown> v) { ConfigValue c; c.kind = Kind::Shutdowns; c.shutdowns = std::move(v); return c; }
};

/// One key of the schema.
struct KeySpec {
  std::string section, name;
  ConfigValue::Kind kind = ConfigValue::Kind::Real;
  std::string unit;  // shown in help and messages ("m", "rpm", "-")
  std::string help;  // one line
  // Allowed range for numbers: lo (<, <=) value (<, <=) hi.
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  std::vector<std::string> choices;  // for strings
  bool required = false;
  std::optional<ConfigValue> default_value;  // used when the key is absent; none: stays unset
  std::string alternative_note;              // printed for optional keys without a default
  std::function<void(Config&, const ConfigValue&)> set;
  std::function<std::optional<ConfigValue>(const Config&)> get;  // for printing a configuration

  std::string full_name() const { return section + "." + name; }
  /// "0 < value < 0.5", "one of \"ccw\", \"cw\"", ...
  std::string allowed() const;
  /// Whether a finite number v lies in the allowed range.
  bool accepts(double v) const;
};

struct Schema {
  std::vector<std::string> sections;  // in printing order
  std::vector<KeySpec> keys;
  const KeySpec* find(const std::string& section, const std::string& name) const;
};

/// The schema: the sections and keys of every module, in order.
const Schema& config_schema();

/// What an unknown key's message lists: "the keys of [mill] are: diameter_m,
/// ..." for a known section, else "the sections are [mill], [charge], ...".
std::string known_keys_text(const std::string& section);

// One function per section adds its keys (config_schema_<section>.cpp).
void add_mill_keys(Schema& s);
void add_charge_keys(Schema& s);
void add_liner_keys(Schema& s);
void add_model_keys(Schema& s);
void add_dem_keys(Schema& s);

/// The cross-key rules of [dem] (config_schema_dem.cpp); throws InputError.
void check_dem_keys(const Config& c);
void add_wear_keys(Schema& s);

/// Fills Config::material from [liner], [charge] and [wear], parses the laws
/// and checks the wear specification (config_schema_wear.cpp). Throws
/// InputError naming the key.
void resolve_wear_config(Config& c);
void add_forecast_keys(Schema& s);

/// Parses and checks a configuration: TOML syntax, unknown sections and keys,
/// types, ranges, missing required keys and the cross-key rules. Throws
/// InputError whose message names the source, line, key, value and what is
/// allowed.
Config load_config_text(const std::string& text, const std::string& source, const std::string& base_dir);

/// load_config_text() on a file; a missing or unreadable file or a directory
/// is an InputError naming the path.
Config load_config_file(const std::string& path);

/// The bundled default mill (data/mills/qiu2001_sag.toml, compiled in).
Config load_default_config();
const std::string& default_config_text();

/// The full annotated configuration file for `c`: every key on its own line
/// at the start of the line ("diameter_m = 10.36"), each preceded by its help,
/// unit and allowed range. Loading it back gives the same configuration.
std::string config_to_toml(const Config& c, bool annotate);

/// "FILE:LINE: " for the key "section.name" if known, else "FILE: "; for a
/// key set by config_with(), where it was set ("--vary KEY=V: ").
std::string config_location(const Config& c, const std::string& key);

/// Whether the key "section.name" was set, by the file or by config_with()
/// (--vary), rather than left at its default.
bool key_given(const Config& c, const std::string& key);

}  // namespace linerlife
