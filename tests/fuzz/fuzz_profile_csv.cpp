// Fuzz target: the measured-profile CSV loader and its validation against the
// bundled mill (issue 7 §2). Refusals are InputErrors; nothing else escapes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/errors.h"
#include "geometry/measured_profile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const linerlife::MeasuredProfile p = linerlife::parse_profile_csv(text, "fuzz.csv");
    linerlife::validate_measured_profile(p, 5.18, 64);
    linerlife::measured_profile_to_segment(p, 5.18, 64, 0.01);
  } catch (const linerlife::InputError&) {
  }
  return 0;
}
