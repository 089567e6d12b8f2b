#include <iostream>

#include "app/commands.h"

namespace linerlife {

const char* program_version() { return LINERLIFE_VERSION; }

Config load_config_or_default(const std::string& path) {
  return path.empty() ? load_default_config() : load_config_file(path);
}

void note(const std::string& text) { std::cerr << text << "\n"; }

}  // namespace linerlife
