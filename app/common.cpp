#include <iostream>

#include <fmt/format.h>

#include "app/commands.h"

namespace linerlife {

const char* program_version() { return LINERLIFE_VERSION; }

Config load_config_or_default(const std::string& path) {
  return path.empty() ? load_default_config() : load_config_file(path);
}

void note(const std::string& text) { std::cerr << text << "\n"; }

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

}  // namespace linerlife
