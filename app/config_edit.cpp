#include "app/config_edit.h"

#include <cctype>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "geometry/errors.h"

namespace linerlife {

Config config_with(const Config& c, const std::string& section_key, const std::string& value, const std::string& what) {
  const auto dot = section_key.find('.');
  if (dot == std::string::npos)
    throw InputError(what, fmt::format("{}: \"{}\" is not a key; write it as section.key, e.g. "
                                       "liner.face_angle_leading_deg",
                                       what, section_key));
  const std::string sec = section_key.substr(0, dot), key = section_key.substr(dot + 1);
  const KeySpec* spec = config_schema().find(sec, key);
  if (!spec)
    throw InputError(what,
                     fmt::format("{}: unknown configuration key [{}] {}; {}", what, sec, key, known_keys_text(sec)));
  // A string key's value from the command line comes without TOML's quotes
  // (--vary mill.rotation=ccw,cw): quote it, unless it is quoted already.
  std::string toml_value = value;
  if (spec->kind == ConfigValue::Kind::String && (value.empty() || (value.front() != '"' && value.front() != '\''))) {
    toml_value = "\"";
    for (char ch : value) {
      if (ch == '"' || ch == '\\') toml_value += '\\';
      toml_value += ch;
    }
    toml_value += '"';
  }
  // A value that is not TOML at all (--vary mill.diameter_m=big) is the
  // option's fault, not a syntax error of the configuration file.
  try {
    (void)toml::parse("v = " + toml_value + "\n", std::string("--vary"));
  } catch (const toml::parse_error&) {
    throw InputError(what, fmt::format("{} {}={}: {} is not a value for [{}] {}; allowed {}", what, section_key, value,
                                       value, sec, key, spec->allowed()));
  }
  std::string text = config_to_toml(c, false);
  const auto s = text.find("\n[" + sec + "]\n");
  if (s == std::string::npos) throw std::logic_error("config_with: section missing from the printed configuration");
  const auto next = text.find("\n[", s + 1);
  const auto k = text.find("\n" + key + " = ", s);
  const std::string line = key + " = " + toml_value;
  if (k != std::string::npos && (next == std::string::npos || k < next))
    text.replace(k + 1, text.find('\n', k + 1) - k - 1, line);
  else
    text.insert(text.find('\n', s + 1) + 1, line + "\n");
  // a key given as speed_rpm replaces a speed given as a fraction, and back
  if (sec == "mill" && (key == "speed_rpm" || key == "speed_fraction_critical")) {
    const std::string other = key == "speed_rpm" ? "speed_fraction_critical" : "speed_rpm";
    const auto o = text.find("\n" + other + " = ");
    if (o != std::string::npos) text.erase(o + 1, text.find('\n', o + 1) - o);
  }
  // The printed text has its own line numbers; messages point at the lines
  // of the file it came from, and at the option for the changed key.
  const std::string printed = fmt::format("{} ({} = {})", c.source, section_key, value);
  const std::string origin = fmt::format("{} {}={}", what, section_key, value);
  Config r;
  try {
    r = load_config_text(text, printed, c.base_dir);
  } catch (const InputError& e) {
    // "PRINTED:LINE: message" -> "ORIGIN: FILE:LINE: message" (or "ORIGIN: message" for the changed key)
    std::string msg = e.what();
    if (msg.rfind(printed + ":", 0) == 0) {
      size_t p = printed.size() + 1;
      while (p < msg.size() && std::isdigit(static_cast<unsigned char>(msg[p]))) ++p;
      if (msg.compare(p, 2, ": ") == 0) p += 2;
      else if (p < msg.size() && msg[p] == ' ') ++p;
      msg = (e.key() == section_key ? std::string() : config_location(c, e.key())) + msg.substr(p);
    }
    throw InputError(what, fmt::format("{}: {}", origin, msg));
  }
  r.lines_source = c.lines_source.empty() ? c.source : c.lines_source;
  r.key_lines = c.key_lines;
  r.section_lines = c.section_lines;
  r.key_origin = c.key_origin;
  r.key_origin[section_key] = origin;
  return r;
}

}  // namespace linerlife
