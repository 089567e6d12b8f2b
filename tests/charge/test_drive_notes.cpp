// The charge model's notes gathered over many drives (charge/drive_notes.h):
// notes that differ only in their numbers are one kind, counted per drive.
#include <catch2/catch.hpp>

#include "charge/drive_notes.h"

using namespace linerlife;

TEST_CASE("drive notes: numbers do not make a new kind, words do", "[charge][notes]") {
  CHECK(note_kind("time_step_s = 0.02 s moves the shell 0.81 media diameters per step (stable up to 0.45)") ==
        note_kind("time_step_s = 0.1 s moves the shell 4.05 media diameters per step (stable up to 0.45)"));
  CHECK(note_kind("12 disc-liner contacts dropped, 3e-05 of 1.5e+07") == note_kind("7 disc-liner contacts dropped, 1 of 2"));
  CHECK(note_kind("the mill runs at 0.95 of critical") != note_kind("the mill runs at 0.95 of nominal"));
  CHECK(note_kind("version 1.2") == "version #");
  std::vector<DriveNote> all;
  add_drive_notes(all, {"sub-stepped 2 times (0.005 s)"}, 1);
  add_drive_notes(all, {}, 2);
  add_drive_notes(all, {"sub-stepped 3 times (0.0033 s)", "the charge centrifuges at 1.02 of critical"}, 3);
  REQUIRE(all.size() == 2);
  CHECK(all[0].text == "sub-stepped 2 times (0.005 s)");  // the first one's text
  CHECK(all[0].first_drive == 1);
  CHECK(all[0].drives == 2);
  CHECK(all[1].first_drive == 3);
  CHECK(all[1].drives == 1);
}
