#include "geometry/input_file.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "geometry/errors.h"

namespace linerlife {

std::string read_input_file(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  const bool pipe = !ec && fs::is_fifo(st);
  if (!ec && !pipe && !fs::is_regular_file(st))
    throw InputError(path, fmt::format("{} {} is not a regular file or a pipe (a device or a socket): give a file",
                                       what, path));
  auto too_large = [&](const std::string& size) {
    return InputError(path, fmt::format("{} {} is {} bytes; allowed at most {} bytes (10 MB): is it the right file?",
                                        what, path, size, kMaxInputFileBytes));
  };
  if (!ec && !pipe) {
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > kMaxInputFileBytes) throw too_large(std::to_string(size));
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path, fmt::format("{} {} cannot be read (permissions?)", what, path));
  // Read at most one byte past the bound, whatever the file claims to hold: a
  // pipe has no size, and a file may grow while it is read.
  std::string text;
  char buf[65536];
  while (f && text.size() <= kMaxInputFileBytes) {
    f.read(buf, sizeof buf);
    text.append(buf, static_cast<size_t>(f.gcount()));
  }
  if (f.bad()) throw InputError(path, fmt::format("{} {} cannot be read", what, path));
  if (text.size() > kMaxInputFileBytes) throw too_large("over " + std::to_string(kMaxInputFileBytes));
  return text;
}

}  // namespace linerlife
