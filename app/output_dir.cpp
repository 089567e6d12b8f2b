#include "app/output_dir.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include "geometry/errors.h"

namespace linerlife {

namespace fs = std::filesystem;

void check_output_dir_writable(const std::string& dir, const std::vector<std::string>& names, bool before_work) {
  std::error_code ec;
  if (dir.empty()) throw InputError("--out", "--out \"\": give a folder");
  for (const std::string& n : names) {
    const fs::path f = fs::path(dir) / n;
    if (fs::exists(fs::symlink_status(f, ec)) && !fs::is_regular_file(f, ec))
      throw InputError(dir, fmt::format("output folder {} holds {}, which is not a file: the results go there; move "
                                        "it or choose another folder",
                                        dir, f.string()));
  }
  fs::path p = fs::absolute(dir, ec);
  if (fs::is_symlink(fs::symlink_status(p, ec)) && !fs::exists(p, ec))
    throw InputError(dir, fmt::format("output folder {} is a link to {}, which does not exist", dir,
                                      fs::read_symlink(p, ec).string()));
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) throw InputError(dir, fmt::format("output folder {} exists and is not a folder", dir));
    if (access(p.c_str(), W_OK | X_OK) != 0)
      throw InputError(dir, fmt::format("output folder {} cannot be written (permissions)", dir));
    // the permissions do not tell everything (/proc, a read-only mount): a
    // file made, written and removed at once
    std::string probe = (p / ".linerlife-probe-XXXXXX").string();
    const int fd = mkstemp(probe.data());
    int err = errno;
    bool wrote = false;
    if (fd >= 0) {
      wrote = write(fd, "x", 1) == 1;
      err = errno;
      close(fd);
      fs::remove(probe, ec);
    }
    if (wrote) return;
    const std::string why = fmt::format("output folder {} cannot be written: {}{}", dir,
                                        fd < 0 ? "a file cannot be made in it: " : "", std::strerror(err));
    if (before_work) throw InputError(dir, why);
    throw OutputError(why + " (is the disk full?)");
  }
  fs::path parent = p.parent_path();
  while (!parent.empty() && !fs::exists(parent, ec)) parent = parent.parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw InputError(dir, fmt::format("output folder {} cannot be created: {} is a file, not a folder", dir,
                                      parent.string()));
  if (parent.empty() || access(parent.c_str(), W_OK | X_OK) != 0)
    throw InputError(dir, fmt::format("output folder {} cannot be created: {} is not writable", dir,
                                      parent.empty() ? std::string("its parent") : parent.string()));
  // the permissions do not tell everything (a read-only or special file
  // system such as /proc): a folder made and removed at once
  std::string probe = (parent / ".linerlife-probe-XXXXXX").string();
  if (mkdtemp(probe.data()) == nullptr)
    throw InputError(dir, fmt::format("output folder {} cannot be created in {}: {}", dir, parent.string(),
                                      std::strerror(errno)));
  fs::remove(probe, ec);
}

void OutputDir::prepare() {
  if (prepared_) return;
  check_output_dir_writable(dir_, {}, false);
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw InputError(dir_, fmt::format("output folder {} cannot be created: {}", dir_, ec.message()));
  // a run killed while writing (SIGKILL, power loss) leaves its temporary;
  // the finished files it would have replaced are intact. Temporaries are
  // .NAME.tmp.PID, and the charts' .NAME.tmp.PID.png (matplotlib picks the
  // format from the extension, app/plots/plot_common.py).
  for (const auto& e : fs::directory_iterator(dir_, ec)) {
    const std::string n = e.path().filename().string();
    const auto at = n.rfind(".tmp.");
    if (n.empty() || n[0] != '.' || at == std::string::npos) continue;
    char* end = nullptr;
    const long pid = std::strtol(n.c_str() + at + 5, &end, 10);
    if (std::strcmp(end, ".png") == 0) end += 4;
    if (pid <= 0 || *end != '\0' || pid == static_cast<long>(getpid())) continue;
    if (kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove(e.path(), ec);
  }
  prepared_ = true;
}

std::string OutputDir::path(const std::string& name) const { return (fs::path(dir_) / name).string(); }

OutputDir::~OutputDir() {
  std::error_code ec;
  for (const std::string& t : pending_) fs::remove(t, ec);
}

std::string OutputDir::temp_path(const std::string& name) const {
  std::string t = (fs::path(dir_) / fmt::format(".{}.tmp.{}", name, static_cast<long>(getpid()))).string();
  const std::lock_guard<std::mutex> lock(mutex_);
  pending_.insert(t);
  return t;
}

void OutputDir::commit(const std::string& temp, const std::string& name) const {
  std::error_code ec;
  fs::rename(temp, path(name), ec);
  if (ec) throw OutputError(fmt::format("cannot rename {} to {}: {}", temp, path(name), ec.message()));
  const std::lock_guard<std::mutex> lock(mutex_);
  pending_.erase(temp);
}

std::string write_failure_hint(const std::string& file) {
  std::error_code ec;
  const fs::path dir = fs::path(file).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    return fmt::format("its folder {} no longer exists (removed during the run?)", dir.string());
  return "is the disk full or the file size limited?";
}

void OutputDir::write_text(const std::string& name, const std::string& text) const {
  const std::string tmp = temp_path(name);
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << text;
    f.flush();
    if (!f) throw OutputError(fmt::format("cannot write {}: {}", tmp, write_failure_hint(tmp)));
  }
  commit(tmp, name);
}

}  // namespace linerlife
