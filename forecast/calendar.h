// calendar.h - operating hours to calendar dates: a start date, the fraction
// of calendar time the mill runs (availability) and planned shutdowns.
#pragma once

#include <string>
#include <vector>

namespace linerlife {

struct CivilDate {
  int year = 2000, month = 1, day = 1;
  bool operator==(const CivilDate& o) const { return year == o.year && month == o.month && day == o.day; }
};

/// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's algorithm).
long long days_from_civil(const CivilDate& d);
CivilDate civil_from_days(long long z);
/// "YYYY-MM-DD".
std::string iso_date(const CivilDate& d);
/// Parses "YYYY-MM-DD"; false if malformed or not a real date.
bool parse_iso_date(const std::string& s, CivilDate& out);
/// Whether y-m-d is a real date.
bool valid_date(int y, int m, int d);

struct Shutdown {
  CivilDate start;
  double days = 0;  // [d] whole calendar days from the start date on which the mill does not run
};

struct Calendar {
  CivilDate start;           // first calendar day of operation (00:00)
  double availability = 1;   // [-] fraction of calendar time the mill runs outside shutdowns, in (0, 1]
  std::vector<Shutdown> shutdowns;

  /// Calendar days elapsed [d, fractional] from the start until `hours` of operation.
  double calendar_days_for(double operating_hours) const;
  /// Operating hours accumulated after `calendar_days` [d] from the start.
  double operating_hours_after(double calendar_days) const;
  /// The date on which `hours` of operation are complete.
  CivilDate date_after(double operating_hours) const;
};

/// The calendar days of planned shutdowns within the first `calendar_days`
/// [d] from the start (a shutdown cut by the end counts its days before it).
double shutdown_days_within(const Calendar& cal, double calendar_days);

}  // namespace linerlife
