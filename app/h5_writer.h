// h5_writer.h - a small writer for results files. HDF5 stays in the .cpp
// (DESIGN.md §1). Layouts are documented in docs/output.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace linerlife {

class H5Writer {
 public:
  /// Creates (truncates) the file at `path`. Every call throws OutputError
  /// (naming the file) when HDF5 cannot write it.
  explicit H5Writer(const std::string& path);
  ~H5Writer();
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  /// Creates the group `path` (parents must exist, "/a/b").
  void group(const std::string& path);
  /// Attributes on an existing group or dataset.
  void attr(const std::string& object, const std::string& name, const std::string& value);
  void attr(const std::string& object, const std::string& name, double value);
  void attr(const std::string& object, const std::string& name, long long value);
  /// A dataset of doubles with shape `dims` (row-major); `units` goes in a "units" attribute.
  void dataset(const std::string& path, const std::vector<double>& data, const std::vector<size_t>& dims,
               const std::string& units = "");
  /// A dataset of integers (indices and counts: units "-" unless given).
  void dataset(const std::string& path, const std::vector<long long>& data, const std::vector<size_t>& dims,
               const std::string& units = "-");
  /// A scalar variable-length string dataset (e.g. the resolved configuration).
  void text(const std::string& path, const std::string& value);
  /// Flushes and closes; after this only the destructor may be called.
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool failed_ = false;  // a write failed: the file is abandoned, not closed again
};

}  // namespace linerlife
