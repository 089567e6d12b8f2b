#include "forecast/calendar.h"

#include <cmath>
#include <cstdio>

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

std::string iso_date(const CivilDate& d) { return fmt::format("{:04d}-{:02d}-{:02d}", d.year, d.month, d.day); }

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

/// Hours the mill runs on calendar day `day` (0 = the start day).
double hours_on_day(const Calendar& c, long long day) {
  const long long abs_day = days_from_civil(c.start) + day;
  for (const Shutdown& s : c.shutdowns) {
    const long long b = days_from_civil(s.start);
    if (abs_day >= b && abs_day < b + static_cast<long long>(std::ceil(s.days))) return 0.0;
  }
  return 24.0 * c.availability;
}

}  // namespace

double Calendar::calendar_days_for(double operating_hours) const {
  if (operating_hours <= 0) return 0;
  double left = operating_hours;
  for (long long day = 0; day < 1000000; ++day) {
    const double h = hours_on_day(*this, day);
    if (h > 0 && h >= left - 1e-9) return static_cast<double>(day) + std::min(1.0, left / h);
    left -= h;
  }
  return 1e6;  // 2700 years: beyond any liner
}

double Calendar::operating_hours_after(double calendar_days) const {
  double hours = 0;
  const long long whole = static_cast<long long>(std::floor(calendar_days));
  for (long long day = 0; day < whole; ++day) hours += hours_on_day(*this, day);
  return hours + (calendar_days - static_cast<double>(whole)) * hours_on_day(*this, whole);
}

CivilDate Calendar::date_after(double operating_hours) const {
  const double days = calendar_days_for(operating_hours);
  // the day on which the hours are complete (a day ending exactly at midnight counts as that day)
  const long long whole = static_cast<long long>(std::ceil(days)) - (days > 0 ? 1 : 0);
  return civil_from_days(days_from_civil(start) + whole);
}

}  // namespace linerlife
