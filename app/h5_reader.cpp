#include "app/h5_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <H5Cpp.h>
#include <fmt/format.h>

#include "geometry/errors.h"

namespace linerlife {

struct H5Reader::Impl {
  explicit Impl(const std::string& p) : file(p, H5F_ACC_RDONLY) {}
  H5::H5File file;
  template <class F>
  auto with_object(const std::string& path, F&& f) const {
    if (path == "/" || file.childObjType(path) == H5O_TYPE_GROUP) {
      H5::Group g = file.openGroup(path);
      return f(static_cast<H5::H5Object&>(g));
    }
    H5::DataSet d = file.openDataSet(path);
    return f(static_cast<H5::H5Object&>(d));
  }
};

H5Reader::H5Reader(const std::string& path) : path_(path) {
  // Whether the file opens at all first, with the system's reason: HDF5's own
  // failure says only that the open failed, which read as "not a readable
  // HDF5 file" for a results file the user may not read (a review,
  // 2026-12-07). HDF5 seeks, so only a regular file will do: on a named pipe
  // its open waited for a writer without end (found with that review).
  // O_NONBLOCK: the probe itself must not wait on a pipe.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    throw InputError(path, fmt::format("{} cannot be read: {}", path, std::strerror(err)));
  }
  struct stat st {};
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  ::close(fd);
  if (!regular)
    throw InputError(path, fmt::format("{} is not a regular file (a pipe, a device or a socket): give the HDF5 file "
                                       "itself",
                                       path));
  H5::Exception::dontPrint();
  try {
    impl_ = std::make_unique<Impl>(path);
  } catch (const H5::Exception&) {
    throw InputError(path, fmt::format("{} is not a readable HDF5 file", path));
  }
}

H5Reader::~H5Reader() = default;

bool H5Reader::exists(const std::string& path) const {
  try {
    return impl_->file.nameExists(path);
  } catch (const H5::Exception&) {
    return false;
  }
}

namespace {
[[noreturn]] void bad(const std::string& file, const std::string& what) {
  throw InputError(file, fmt::format("{}: cannot read {} (a damaged or foreign file?)", file, what));
}
}  // namespace

std::string H5Reader::attr_string(const std::string& object, const std::string& name) const {
  try {
    return impl_->with_object(object, [&](H5::H5Object& o) {
      H5::Attribute a = o.openAttribute(name);
      std::string v;
      a.read(a.getStrType(), v);
      return v;
    });
  } catch (const H5::Exception&) {
    bad(path_, object + "@" + name);
  }
}

double H5Reader::attr_double(const std::string& object, const std::string& name) const {
  try {
    return impl_->with_object(object, [&](H5::H5Object& o) {
      double v = 0;
      o.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &v);
      return v;
    });
  } catch (const H5::Exception&) {
    bad(path_, object + "@" + name);
  }
}

long long H5Reader::attr_int(const std::string& object, const std::string& name) const {
  try {
    return impl_->with_object(object, [&](H5::H5Object& o) {
      long long v = 0;
      o.openAttribute(name).read(H5::PredType::NATIVE_LLONG, &v);
      return v;
    });
  } catch (const H5::Exception&) {
    bad(path_, object + "@" + name);
  }
}

std::vector<double> H5Reader::doubles(const std::string& path) const {
  try {
    H5::DataSet d = impl_->file.openDataSet(path);
    std::vector<double> v(static_cast<size_t>(d.getSpace().getSimpleExtentNpoints()));
    if (!v.empty()) d.read(v.data(), H5::PredType::NATIVE_DOUBLE);
    return v;
  } catch (const H5::Exception&) {
    bad(path_, path);
  }
}

std::vector<long long> H5Reader::ints(const std::string& path) const {
  try {
    H5::DataSet d = impl_->file.openDataSet(path);
    std::vector<long long> v(static_cast<size_t>(d.getSpace().getSimpleExtentNpoints()));
    if (!v.empty()) d.read(v.data(), H5::PredType::NATIVE_LLONG);
    return v;
  } catch (const H5::Exception&) {
    bad(path_, path);
  }
}

std::string H5Reader::text(const std::string& path) const {
  try {
    H5::DataSet d = impl_->file.openDataSet(path);
    std::string v;
    d.read(v, d.getStrType());
    return v;
  } catch (const H5::Exception&) {
    bad(path_, path);
  }
}

}  // namespace linerlife
