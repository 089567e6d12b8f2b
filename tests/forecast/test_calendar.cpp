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
  // the shutdown days within a span (the forecast's summary says them)
  CHECK(shutdown_days_within(c, 4) == 0);       // before the stop (Jan 5 is day 4)
  CHECK(shutdown_days_within(c, 6.5) == 2.5);   // cut by the end: days 4, 5 and half of 6
  CHECK(shutdown_days_within(c, 17) == 7);
  CHECK(shutdown_days_within(c, 400) == 7);
  c.shutdowns.push_back({{2027, 1, 8}, 7});     // overlaps the first from Jan 8: Jan 5-14 stopped
  CHECK(shutdown_days_within(c, 400) == 10);
  c.availability = 1.0;
  CHECK(shutdown_days_within(c, 400) == 10);
  c.shutdowns.clear();
  CHECK(shutdown_days_within(c, 400) == 0);
}

TEST_CASE("a life of more than 1,000,000 calendar days is counted to its end", "[forecast][calendar]") {
  // a review: 1e6 h at availability 0.01 stopped at the old cap of 1,000,000
  // days (a relining date of 4764-11-27); it is 4,166,667 days
  Calendar c;
  c.start = {2027, 1, 1};
  c.availability = 0.01;
  CHECK(c.calendar_days_for(1e6) == Approx(1e6 / 0.24).epsilon(1e-9));
  // ISO 8601's expanded year past 9999 (the configuration refuses such a horizon)
  CHECK(iso_date(c.date_after(1e6)) == "+13434-12-12");
  c.availability = 0.02;
  CHECK(c.calendar_days_for(1e6) == Approx(1e6 / 0.48).epsilon(1e-9));
  CHECK(iso_date(c.date_after(1e6)) == "7730-12-22");
  // a shutdown beyond the day-by-day stretch (100 years) still stops the mill
  c.availability = 1.0;
  c.shutdowns.push_back({civil_from_days(days_from_civil(c.start) + 50000), 10});
  CHECK(c.calendar_days_for(24.0 * 49000) == Approx(49000));
  CHECK(c.calendar_days_for(24.0 * 60000) == Approx(60010));
  CHECK(c.operating_hours_after(60010) == Approx(24.0 * 60000));
  CHECK(c.operating_hours_after(50005) == Approx(24.0 * 50000));
  // and the two functions invert each other across the stretch's end
  c.availability = 0.7;
  c.shutdowns.push_back({{2031, 3, 1}, 14});
  for (const double h : {100.0, 5e4, 6.1e5, 6.2e5, 1e6, 3e6})
    CHECK(c.operating_hours_after(c.calendar_days_for(h)) == Approx(h).epsilon(1e-9));
}
