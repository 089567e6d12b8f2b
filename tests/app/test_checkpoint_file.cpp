// A forecast checkpoint carries the charge model's notes gathered so far
// (charge/drive_notes.h) through checkpoint.h5, so a resumed forecast reports
// the notes of the drives before the interruption too.
#include <filesystem>

#include <catch2/catch.hpp>

#include "app/checkpoint_file.h"
#include "app/config.h"
#include "cli_runner.h"
#include "geometry/build_liner_surface.h"

using namespace linerlife;
using namespace linerlife::test;

TEST_CASE("a checkpoint file keeps the charge model's notes", "[app][forecast][resume]") {
  const Config c = load_default_config();
  ForecastCheckpoint k;
  k.method = "ode";
  k.t_s = 3600;
  k.base = build_liner_surface(c.mill, c.liner);
  const size_t n = static_cast<size_t>(k.base.segment_begin[1]);  // the cell of a uniform liner: one segment
  k.y.assign(n, 0.001);
  k.y_drive.assign(n, 0.0005);
  k.r_now.assign(n, 1e-9);
  k.next_regular_s = k.next_explicit_out_s = 360000;
  k.stats.charge_redrives = 7;
  ForecastInput in;
  in.initial = &k.base;
  const std::filesystem::path dir = temp_dir("checkpoint_notes");
  OutputDir out(dir.string());
  out.prepare();
  for (const auto& notes : {std::vector<DriveNote>{},
                            std::vector<DriveNote>{{"time_step_s = 0.02 s moves the shell 0.81 media diameters", 1, 7},
                                                   {"the charge does not fit outside the inner radius", 4, 2}}}) {
    k.notes = notes;
    write_checkpoint(out, "config text", k);
    const ForecastCheckpoint r = read_checkpoint(out.path("checkpoint.h5"), "config text", in, c.forecast);
    REQUIRE(r.notes.size() == notes.size());
    for (size_t i = 0; i < notes.size(); ++i) {
      CHECK(r.notes[i].text == notes[i].text);
      CHECK(r.notes[i].first_drive == notes[i].first_drive);
      CHECK(r.notes[i].drives == notes[i].drives);
    }
    CHECK(r.stats.charge_redrives == 7);
  }
  std::filesystem::remove_all(dir);
}
