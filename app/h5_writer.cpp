#include "app/h5_writer.h"

#include <H5Cpp.h>
#include <fmt/format.h>

#include "app/output_dir.h"
#include "geometry/errors.h"

namespace linerlife {

struct H5Writer::Impl {
  explicit Impl(const std::string& p) : file_name(p), file(p, H5F_ACC_TRUNC) {}
  std::string file_name;
  H5::H5File file;
  /// Calls f with the group or dataset at `path`.
  template <class F>
  void with_object(const std::string& path, F&& f) {
    if (path == "/" || file.childObjType(path) == H5O_TYPE_GROUP) {
      H5::Group g = file.openGroup(path);
      f(static_cast<H5::H5Object&>(g));
    } else {
      H5::DataSet d = file.openDataSet(path);
      f(static_cast<H5::H5Object&>(d));
    }
  }
};

namespace {
struct QuietHdf5 {
  QuietHdf5() { H5::Exception::dontPrint(); }
};

/// HDF5's C++ exceptions are not std::exceptions: a write that fails (a full
/// disk, a file-size limit) becomes an OutputError naming the file.
template <class F>
void guarded(const std::string& file, bool& failed, const std::string& what, F&& f) {
  try {
    f();
  } catch (const H5::Exception& e) {
    failed = true;
    throw OutputError(fmt::format("cannot write {} ({}: {}): {}", file, what, e.getDetailMsg(),
                                  write_failure_hint(file)));
  }
}
}  // namespace

H5Writer::H5Writer(const std::string& path) {
  QuietHdf5();
  guarded(path, failed_, "create", [&] { impl_ = std::make_unique<Impl>(path); });
}

H5Writer::~H5Writer() {
  // After a failed write HDF5 1.10 cannot close the file (H5File's destructor
  // would print its failure): it is abandoned, and the run ends (main.cpp).
  if (failed_) {
    (void)impl_.release();
    return;
  }
  try {
    close();
  } catch (...) {
  }
}

void H5Writer::group(const std::string& path) {
  guarded(impl_->file_name, failed_, "group " + path, [&] { impl_->file.createGroup(path); });
}

void H5Writer::attr(const std::string& object, const std::string& name, const std::string& value) {
  guarded(impl_->file_name, failed_, "attribute " + object + " " + name, [&] {
    impl_->with_object(object, [&](H5::H5Object& o) {
      H5::StrType t(H5::PredType::C_S1, H5T_VARIABLE);
      t.setCset(H5T_CSET_UTF8);
      H5::Attribute a = o.createAttribute(name, t, H5::DataSpace(H5S_SCALAR));
      const char* c = value.c_str();
      a.write(t, &c);
    });
  });
}

void H5Writer::attr(const std::string& object, const std::string& name, double value) {
  guarded(impl_->file_name, failed_, "attribute " + object + " " + name, [&] {
    impl_->with_object(object, [&](H5::H5Object& o) {
      H5::Attribute a = o.createAttribute(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(H5S_SCALAR));
      a.write(H5::PredType::NATIVE_DOUBLE, &value);
    });
  });
}

void H5Writer::attr(const std::string& object, const std::string& name, long long value) {
  guarded(impl_->file_name, failed_, "attribute " + object + " " + name, [&] {
    impl_->with_object(object, [&](H5::H5Object& o) {
      H5::Attribute a = o.createAttribute(name, H5::PredType::NATIVE_LLONG, H5::DataSpace(H5S_SCALAR));
      a.write(H5::PredType::NATIVE_LLONG, &value);
    });
  });
}

void H5Writer::dataset(const std::string& path, const std::vector<double>& data, const std::vector<size_t>& dims,
                       const std::string& units) {
  guarded(impl_->file_name, failed_, "dataset " + path, [&] {
    std::vector<hsize_t> hd(dims.begin(), dims.end());
    H5::DataSpace space(static_cast<int>(hd.size()), hd.data());
    H5::DataSet ds = impl_->file.createDataSet(path, H5::PredType::NATIVE_DOUBLE, space);
    if (!data.empty()) ds.write(data.data(), H5::PredType::NATIVE_DOUBLE);
    ds.close();  // a failure here throws (in a destructor it would only be printed)
    if (!units.empty()) attr(path, "units", units);
  });
}

void H5Writer::dataset(const std::string& path, const std::vector<long long>& data, const std::vector<size_t>& dims,
                       const std::string& units) {
  guarded(impl_->file_name, failed_, "dataset " + path, [&] {
    std::vector<hsize_t> hd(dims.begin(), dims.end());
    H5::DataSpace space(static_cast<int>(hd.size()), hd.data());
    H5::DataSet ds = impl_->file.createDataSet(path, H5::PredType::NATIVE_LLONG, space);
    if (!data.empty()) ds.write(data.data(), H5::PredType::NATIVE_LLONG);
    ds.close();
    if (!units.empty()) attr(path, "units", units);
  });
}

void H5Writer::text(const std::string& path, const std::string& value) {
  guarded(impl_->file_name, failed_, "dataset " + path, [&] {
    H5::StrType t(H5::PredType::C_S1, H5T_VARIABLE);
    t.setCset(H5T_CSET_UTF8);
    H5::DataSet ds = impl_->file.createDataSet(path, t, H5::DataSpace(H5S_SCALAR));
    const char* c = value.c_str();
    ds.write(&c, t);
    ds.close();
  });
}

void H5Writer::close() {
  if (impl_ && !failed_) {
    guarded(impl_->file_name, failed_, "close", [&] {
      impl_->file.flush(H5F_SCOPE_GLOBAL);
      impl_->file.close();
    });
    impl_.reset();
  }
}

}  // namespace linerlife
