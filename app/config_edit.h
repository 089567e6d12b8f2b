// config_edit.h - variations of a configuration for `compare --vary` and the
// calibrated configuration `calibrate` writes: the resolved TOML text of a
// configuration with one key set, reloaded through the full checks.
#pragma once

#include <string>

#include "app/config.h"

namespace linerlife {

/// `c` with "section.key" set to `value` (TOML syntax: 25.0, "hi-lo",
/// 2027-01-01; a string key's value may come without its quotes, hi-lo, as
/// `compare --vary mill.rotation=ccw,cw` gives it), checked like a file. Throws InputError naming `what` (the
/// command-line option) for an unknown key or a refused value.
Config config_with(const Config& c, const std::string& section_key, const std::string& value, const std::string& what);

}  // namespace linerlife
