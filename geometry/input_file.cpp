#include "geometry/input_file.h"

#include <filesystem>

#include <fmt/format.h>

#include "geometry/errors.h"

namespace linerlife {

void require_regular_input_file(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec) return;  // the caller's open reports it
  if (!fs::is_regular_file(st))
    throw InputError(path, fmt::format("{} {} is not a regular file (a device, a pipe or a socket): give a file", what,
                                       path));
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxInputFileBytes)
    throw InputError(path, fmt::format("{} {} is {} bytes; allowed at most {} bytes (10 MB): is it the right file?",
                                       what, path, size, kMaxInputFileBytes));
}

}  // namespace linerlife
