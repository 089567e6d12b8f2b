#include "forecast/measured_history.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "geometry/errors.h"
#include "geometry/input_file.h"
#include "geometry/input_text.h"
#include "geometry/measured_profile.h"
#include "geometry/mill.h"

namespace linerlife {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

MeasuredHistory parse_measured_history(const std::string& text, const std::string& source) {
  MeasuredHistory h;
  h.source = source;
  std::istringstream in(without_utf8_bom(text));
  std::string line;
  int lineno = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(t);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    if (header_allowed && f.size() == 3 && trim(f[0]) == "hours" && trim(f[1]) == "x_m" && trim(f[2]) == "y_m") {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    double hr = 0, x = 0, y = 0;
    if (f.size() != 3 || !parse_decimal(f[0], hr) || !parse_decimal(f[1], x) || !parse_decimal(f[2], y))
      throw InputError(source, fmt::format("{}:{}: expected three numbers \"hours,x_m,y_m\", got \"{}\"; allowed "
                                           "decimal numbers such as 1000, 0.25 or 7.5e-2",
                                           source, lineno, printable(t)));
    if (hr < 0)
      throw InputError(source, fmt::format("{}:{}: hours = {}: operating hours must be >= 0", source, lineno, hr));
    if (h.snapshots.empty() || hr != h.snapshots.back().hours) {
      if (!h.snapshots.empty() && hr < h.snapshots.back().hours)
        throw InputError(source, fmt::format("{}:{}: hours = {} after a profile at {} h: the profiles must be in "
                                             "order of increasing hours",
                                             source, lineno, hr, h.snapshots.back().hours));
      h.snapshots.push_back({hr, {}, lineno, {}});
    }
    h.snapshots.back().points.emplace_back(x, y);
    h.snapshots.back().lines.push_back(lineno);
  }
  if (h.snapshots.empty()) throw InputError(source, fmt::format("{}: no measured profile in the file", source));
  for (const auto& s : h.snapshots)
    if (s.points.size() < 3)
      throw InputError(source, fmt::format("{}:{}: the profile at {} h has {} points; at least 3 are needed", source,
                                           s.first_line, s.hours, s.points.size()));
  return h;
}

MeasuredHistory load_measured_history(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, fmt::format("measured profile file {} does not exist", printable(path)));
  if (fs::is_directory(path, ec)) throw InputError(path, fmt::format("measured profile file {} is a directory", printable(path)));
  const std::string text = read_input_file(path, "measured profile file");
  return parse_measured_history(text, path);
}

void validate_measured_history(const MeasuredHistory& h, double R, int segments) {
  for (const auto& s : h.snapshots) {
    MeasuredProfile p;
    p.source = fmt::format("{}:{} (profile at {} h)", h.source, s.first_line, s.hours);
    p.points = s.points;
    p.lines = s.lines;
    validate_measured_profile(p, R, segments);
  }
}

std::vector<Eigen::Vector2d> unrolled_to_mill(const std::vector<Eigen::Vector2d>& xy, double R, int segments) {
  const double seg = 2 * kPi / segments;
  std::vector<Eigen::Vector2d> out;
  out.reserve(xy.size());
  for (const auto& q : xy) {
    const double th = q.x() / R - 0.5 * seg, r = R - q.y();
    out.emplace_back(r * std::cos(th), r * std::sin(th));
  }
  return out;
}

}  // namespace linerlife
