// config_schema_util.h - short constructors for schema rows, so each section
// file reads as a table of keys.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/config.h"

namespace linerlife {

/// A number with a unit and a range; `def` is used when the key is absent
/// (nullopt: required if `required`, otherwise left unset).
inline KeySpec real_key(const char* sec, const char* name, const char* unit, const char* help, double lo, double hi,
                        bool lo_open, bool hi_open, std::optional<double> def, std::function<void(Config&, double)> set,
                        std::function<double(const Config&)> get, bool required = false) {
  KeySpec k;
  k.section = sec;
  k.name = name;
  k.kind = ConfigValue::Kind::Real;
  k.unit = unit;
  k.help = help;
  k.lo = lo, k.hi = hi, k.lo_open = lo_open, k.hi_open = hi_open;
  k.required = required;
  if (def) k.default_value = ConfigValue::Real(*def);
  k.set = [set](Config& c, const ConfigValue& v) { set(c, v.real); };
  k.get = [get](const Config& c) -> std::optional<ConfigValue> { return ConfigValue::Real(get(c)); };
  return k;
}

/// A number that may be absent (no default); the getter says whether it was given.
inline KeySpec opt_real_key(const char* sec, const char* name, const char* unit, const char* help, double lo,
                            double hi, bool lo_open, bool hi_open, std::function<void(Config&, double)> set,
                            std::function<std::optional<double>(const Config&)> get, const char* note) {
  KeySpec k = real_key(sec, name, unit, help, lo, hi, lo_open, hi_open, std::nullopt, set, nullptr);
  k.alternative_note = note;
  k.get = [get](const Config& c) -> std::optional<ConfigValue> {
    auto v = get(c);
    if (!v) return std::nullopt;
    return ConfigValue::Real(*v);
  };
  return k;
}

inline KeySpec int_key(const char* sec, const char* name, const char* help, long long lo, long long hi, bool required,
                       std::function<void(Config&, long long)> set, std::function<long long(const Config&)> get,
                       std::optional<long long> def = std::nullopt) {
  KeySpec k;
  k.section = sec;
  k.name = name;
  k.kind = ConfigValue::Kind::Int;
  k.unit = "-";
  k.help = help;
  k.lo = static_cast<double>(lo), k.hi = static_cast<double>(hi);
  k.required = required;
  if (def) k.default_value = ConfigValue::Int(*def);
  k.set = [set](Config& c, const ConfigValue& v) { set(c, v.integer); };
  k.get = [get](const Config& c) -> std::optional<ConfigValue> { return ConfigValue::Int(get(c)); };
  return k;
}

inline KeySpec string_key(const char* sec, const char* name, const char* help, std::vector<std::string> choices,
                          const char* def, std::function<void(Config&, const std::string&)> set,
                          std::function<std::string(const Config&)> get) {
  KeySpec k;
  k.section = sec;
  k.name = name;
  k.kind = ConfigValue::Kind::String;
  k.help = help;
  k.choices = std::move(choices);
  if (def) k.default_value = ConfigValue::String(def);
  k.set = [set](Config& c, const ConfigValue& v) { set(c, v.text); };
  k.get = [get](const Config& c) -> std::optional<ConfigValue> { return ConfigValue::String(get(c)); };
  return k;
}

inline KeySpec opt_string_key(const char* sec, const char* name, const char* help,
                              std::function<void(Config&, const std::string&)> set,
                              std::function<std::optional<std::string>(const Config&)> get, const char* note) {
  KeySpec k = string_key(sec, name, help, {}, nullptr, set, nullptr);
  k.alternative_note = note;
  k.get = [get](const Config& c) -> std::optional<ConfigValue> {
    auto v = get(c);
    if (!v) return std::nullopt;
    return ConfigValue::String(*v);
  };
  return k;
}

}  // namespace linerlife
