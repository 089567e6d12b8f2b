// Operating hours to calendar dates.
#include <catch2/catch.hpp>

#include "forecast/calendar.h"

using namespace linerlife;

TEST_CASE("civil dates round-trip and refuse impossible days", "[forecast][calendar]") {
  CHECK(days_from_civil({1970, 1, 1}) == 0);
  CHECK(days_from_civil({2000, 3, 1}) == 11017);
  CHECK(iso_date(civil_from_days(days_from_civil({2028, 2, 29}))) == "2028-02-29");
  CivilDate d;
  CHECK(parse_iso_date("2026-11-22", d));
  CHECK(d == CivilDate{2026, 11, 22});
  CHECK_FALSE(parse_iso_date("2026-02-30", d));
  CHECK_FALSE(parse_iso_date("2027-13-01", d));
  CHECK_FALSE(parse_iso_date("22/11/2026", d));
  CHECK_FALSE(parse_iso_date("2026-11-2", d));
}

TEST_CASE("availability and shutdowns stretch operating hours over the calendar", "[forecast][calendar]") {
  Calendar c;
  c.start = {2027, 1, 1};
  c.availability = 1.0;
  CHECK(c.calendar_days_for(240) == Approx(10));
  CHECK(iso_date(c.date_after(240)) == "2027-01-10");  // the 10th day completes 240 h
  CHECK(iso_date(c.date_after(241)) == "2027-01-11");
  c.availability = 0.9;  // 21.6 h a day
  CHECK(c.calendar_days_for(21.6 * 365) == Approx(365));
  CHECK(iso_date(c.date_after(21.6 * 365)) == "2027-12-31");
  // a 7-day shutdown from Jan 5 adds 7 calendar days to anything after it
  c.shutdowns.push_back({{2027, 1, 5}, 7});
  CHECK(c.calendar_days_for(21.6 * 4) == Approx(4));           // Jan 1-4, before the stop
  CHECK(c.calendar_days_for(21.6 * 10) == Approx(10 + 7));     // 4 days, 7 stopped, 6 more
  CHECK(c.operating_hours_after(17) == Approx(21.6 * 10));
  CHECK(iso_date(c.date_after(21.6 * 10)) == "2027-01-17");
}
