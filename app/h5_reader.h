// h5_reader.h - reading back what H5Writer wrote (checkpoints, `plot`). HDF5
// stays in the .cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace linerlife {

class H5Reader {
 public:
  /// Opens `path` read-only; throws InputError naming the file if it cannot:
  /// with the system's reason where the file does not open at all
  /// ("Permission denied"), else saying it is not a readable HDF5 file.
  explicit H5Reader(const std::string& path);
  ~H5Reader();
  bool exists(const std::string& path) const;
  std::string attr_string(const std::string& object, const std::string& name) const;
  double attr_double(const std::string& object, const std::string& name) const;
  long long attr_int(const std::string& object, const std::string& name) const;
  std::vector<double> doubles(const std::string& path) const;
  std::vector<long long> ints(const std::string& path) const;
  std::string text(const std::string& path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
};

}  // namespace linerlife
