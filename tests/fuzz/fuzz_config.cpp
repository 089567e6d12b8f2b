// Fuzz target: the TOML configuration loader (issue 7 §2). Any input either
// loads or is refused with an InputError; nothing else may escape, crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/config.h"
#include "geometry/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    linerlife::load_config_text(text, "fuzz.toml", "/nonexistent");
  } catch (const linerlife::InputError&) {
  }
  return 0;
}
