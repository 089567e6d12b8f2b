#include "forecast/calendar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace linerlife {

// Howard Hinnant, "chrono-Compatible Low-Level Date Algorithms" (days_from_civil / civil_from_days).
long long days_from_civil(const CivilDate& d) {
  const long long y = d.year - (d.month <= 2 ? 1 : 0);
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const long long yoe = y - era * 400;
  const long long mp = (d.month + 9) % 12;
  const long long doy = (153 * mp + 2) / 5 + d.day - 1;
  const long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

CivilDate civil_from_days(long long z) {
  z += 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const long long doe = z - era * 146097;
  const long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const long long mp = (5 * doy + 2) / 153;
  CivilDate d;
  d.day = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  d.month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  d.year = static_cast<int>(yoe + era * 400 + (d.month <= 2 ? 1 : 0));
  return d;
}

std::string iso_date(const CivilDate& d) {
  // ISO 8601's four-digit year ends at 9999; beyond, its expanded form (a sign
  // and more digits). The configuration refuses a forecast horizon that would
  // need it (app/config.cpp), so a forecast's dates never do.
  if (d.year > 9999 || d.year < 0)
    return fmt::format("{}{:05d}-{:02d}-{:02d}", d.year < 0 ? '-' : '+', std::abs(d.year), d.month, d.day);
  return fmt::format("{:04d}-{:02d}-{:02d}", d.year, d.month, d.day);
}

bool valid_date(int y, int m, int d) {
  if (m < 1 || m > 12 || d < 1 || y < 1 || y > 9999) return false;
  const CivilDate c{y, m, d};
  return civil_from_days(days_from_civil(c)) == c;
}

bool parse_iso_date(const std::string& s, CivilDate& out) {
  int y = 0, m = 0, d = 0;
  char tail = 0;
  if (s.size() != 10 || std::sscanf(s.c_str(), "%4d-%2d-%2d%c", &y, &m, &d, &tail) != 3) return false;
  if (!valid_date(y, m, d)) return false;
  out = {y, m, d};
  return true;
}

namespace {

/// Days counted one by one from the start, the hours added as the days pass:
/// 100 years, more than any liner lasts. Beyond, the count goes by whole
/// stretches between shutdowns (the same hours to rounding), so a life of any
/// length is counted to its end; it stopped at 1,000,000 days before.
constexpr long long kDailyDays = 36525;

/// The shutdowns as half-open day ranges [begin, end) from the start day,
/// sorted and merged; those over before the start are left out.
std::vector<std::pair<long long, long long>> stops(const Calendar& c) {
  const long long d0 = days_from_civil(c.start);
  std::vector<std::pair<long long, long long>> r;
  for (const Shutdown& s : c.shutdowns) {
    const long long b = days_from_civil(s.start) - d0;
    const long long e = b + static_cast<long long>(std::ceil(s.days));
    if (e > 0 && e > b) r.emplace_back(b, e);
  }
  std::sort(r.begin(), r.end());
  std::vector<std::pair<long long, long long>> merged;
  for (const auto& iv : r)
    if (!merged.empty() && iv.first <= merged.back().second)
      merged.back().second = std::max(merged.back().second, iv.second);
    else
      merged.push_back(iv);
  return merged;
}

/// Walks the calendar day by day, then stretch by stretch: the running days
/// of the stops' gaps, each 24 * availability hours.
class DayWalk {
 public:
  explicit DayWalk(const Calendar& c) : stops_(stops(c)), hours_(24.0 * c.availability) {}
  /// Hours the mill runs on day `day`; days must be asked in increasing order.
  double hours_on(long long day) {
    while (next_ < stops_.size() && stops_[next_].second <= day) ++next_;
    return next_ < stops_.size() && day >= stops_[next_].first ? 0.0 : hours_;
  }
  /// From `day` on, past the daily count: the first day of the next shutdown
  /// at or after it (max: none), or `day` itself if it is a shutdown day.
  long long run_end(long long day) {
    while (next_ < stops_.size() && stops_[next_].second <= day) ++next_;
    if (next_ == stops_.size()) return std::numeric_limits<long long>::max();
    return std::max(day, stops_[next_].first);
  }
  long long stop_end() const { return stops_[next_].second; }  // after run_end(day) == day
  double hours_per_day() const { return hours_; }

 private:
  std::vector<std::pair<long long, long long>> stops_;
  double hours_;
  size_t next_ = 0;
};

}  // namespace

double Calendar::calendar_days_for(double operating_hours) const {
  // (a NaN walked the calendar without end: a damaged checkpoint's history, 2026-12-04)
  if (!std::isfinite(operating_hours))
    throw std::invalid_argument(fmt::format("calendar: {} operating hours", operating_hours));
  if (operating_hours <= 0) return 0;
  DayWalk walk(*this);
  double left = operating_hours;
  long long day = 0;
  for (; day < kDailyDays; ++day) {
    const double h = walk.hours_on(day);
    if (h > 0 && h >= left - 1e-9) return static_cast<double>(day) + std::min(1.0, left / h);
    left -= h;
  }
  const double h = walk.hours_per_day();
  for (;;) {
    const long long end = walk.run_end(day);
    if (end == day) {  // a shutdown
      day = walk.stop_end();
      continue;
    }
    const double run_days = end == std::numeric_limits<long long>::max() ? HUGE_VAL : static_cast<double>(end - day);
    if (left <= run_days * h + 1e-9) return static_cast<double>(day) + left / h;
    left -= run_days * h;
    day = end;
  }
}

double Calendar::operating_hours_after(double calendar_days) const {
  if (!(calendar_days > 0)) return 0;
  DayWalk walk(*this);
  double hours = 0;
  const long long whole = static_cast<long long>(std::floor(calendar_days));
  long long day = 0;
  for (; day < std::min(whole, kDailyDays); ++day) hours += walk.hours_on(day);
  while (day < whole) {
    const long long end = walk.run_end(day);
    if (end == day) {
      day = std::min(walk.stop_end(), whole);
      continue;
    }
    const long long to = std::min(end, whole);
    hours += static_cast<double>(to - day) * walk.hours_per_day();
    day = to;
  }
  return hours + (calendar_days - static_cast<double>(whole)) * walk.hours_on(whole);
}

CivilDate Calendar::date_after(double operating_hours) const {
  // at most about 8e8 years ahead, so that the day count and the year stay
  // within their integers (availability = 1e-300 made 1e303 days, a cast
  // out of range and the year +2030437328; the configuration refuses a date
  // past 9999 anyway, and says "more than a million years" where it is)
  const double days = std::min(calendar_days_for(operating_hours), 3e11);
  // the day on which the hours are complete (a day ending exactly at midnight counts as that day)
  const long long whole = static_cast<long long>(std::ceil(days)) - (days > 0 ? 1 : 0);
  return civil_from_days(days_from_civil(start) + whole);
}

double shutdown_days_within(const Calendar& cal, double calendar_days) {
  // The days the mill does not run for a shutdown are the days not worked at
  // its availability: D - H(D) / (24 a), H the operating hours of the first D
  // days (overlapping shutdowns count once); rounding below a microday is 0.
  if (!(calendar_days > 0) || cal.shutdowns.empty()) return 0;
  const double down = calendar_days - cal.operating_hours_after(calendar_days) / (24.0 * cal.availability);
  const double rounded = std::round(down * 1e6) / 1e6;
  return rounded > 0 ? rounded : 0;
}

}  // namespace linerlife
