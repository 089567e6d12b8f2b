// input_file.h - the checks every input file (a configuration, a profile CSV,
// a measured profile history) passes before it is read whole into memory.
#pragma once

#include <cstdint>
#include <string>

namespace linerlife {

/// [bytes] The largest input file read: 10 MB, about a thousand times the
/// largest configuration or profile linerlife ships and room for a history of
/// some 400,000 measured points.
constexpr std::uintmax_t kMaxInputFileBytes = 10'000'000;

/// Reads the input file `path` whole, bounded: a regular file of at most
/// kMaxInputFileBytes, or a pipe (`<(...)`, /dev/stdin fed by a pipe) read up
/// to that size. Throws InputError keyed by `path` for a device such as
/// /dev/zero or a socket (read without end), for a file or a pipe's stream
/// larger than the bound, and for a file that cannot be read. `what` names the
/// file in the messages ("configuration file", "profile file", ...). Call it
/// after the caller's own "does not exist" and "is a directory" checks.
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace linerlife
