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

/// Throws InputError (keyed by `path`) unless `path` is a regular file of at
/// most kMaxInputFileBytes: a device such as /dev/zero, a pipe or a socket
/// would be read without end. `what` names the file in the message
/// ("configuration file", "profile file", ...). Call it after the caller's own
/// "does not exist" and "is a directory" checks.
void require_regular_input_file(const std::string& path, const std::string& what);

}  // namespace linerlife
