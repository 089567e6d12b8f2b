#include "app/output_dir.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "geometry/errors.h"

namespace linerlife {

namespace fs = std::filesystem;

namespace {

// The folder's path as the lock knows it: absolute, with the links of its
// existing part resolved (two spellings of one folder take one lock).
std::string lock_key(const std::string& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  if (ec || p.empty()) p = fs::absolute(dir, ec).lexically_normal();
  std::string s = p.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

// Whether the process that named a temporary is gone: no such process, or a
// zombie (a chart script killed with linerlife, app/plots.cpp, whose new
// parent has not yet reaped it, still answers kill(pid, 0)).
bool process_gone(long pid) {
  if (kill(static_cast<pid_t>(pid), 0) != 0) return errno == ESRCH;
  std::ifstream stat(fmt::format("/proc/{}/stat", pid));
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto close = line.rfind(')');  // the name in parentheses may hold spaces
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z';
}

}  // namespace

std::string output_dir_lock_path(const std::string& dir) {
  // FNV-1a, 64 bits: the same name from every build of the program
  std::uint64_t h = 1469598103934665603ull;
  for (const unsigned char ch : lock_key(dir)) h = (h ^ ch) * 1099511628211ull;
  // /tmp, not $TMPDIR: two runs with different TMPDIR must still meet at one lock
  std::error_code ec;
  fs::path tmp = "/tmp";
  if (!fs::is_directory(tmp, ec)) tmp = fs::temp_directory_path(ec);
  return (tmp / fmt::format("linerlife-out-{:016x}.lock", h)).string();
}

namespace {

// The locks this process holds. At a normal exit each lock file is removed
// while still locked, so /tmp keeps no file per folder ever written; a run
// killed leaves its file, which the next run into the folder locks as it is.
struct HeldLocks {
  std::mutex mutex;
  std::map<std::string, std::pair<int, std::string>> by_key;  // folder -> (fd, lock file)
  ~HeldLocks() {
    for (const auto& [key, held] : by_key) {
      struct stat a {}, b {};
      if (fstat(held.first, &a) == 0 && stat(held.second.c_str(), &b) == 0 && a.st_ino == b.st_ino &&
          a.st_dev == b.st_dev)
        unlink(held.second.c_str());
      close(held.first);
    }
  }
};

HeldLocks& held_locks() {
  static HeldLocks h;
  return h;
}

}  // namespace

void lock_output_dir(const std::string& dir) {
  HeldLocks& held = held_locks();
  const std::lock_guard<std::mutex> guard(held.mutex);
  const std::string key = lock_key(dir);
  if (held.by_key.count(key)) return;  // an flock is per open file: this process must not lock it twice
  const std::string path = output_dir_lock_path(dir);
  // A run that ends removes its lock file while holding it; a run that opened
  // the old file meanwhile finds, once locked, that the name is no longer its
  // file, and opens the new one (the usual flock-and-unlink pattern).
  for (int attempt = 0; attempt < 8; ++attempt) {
    // O_CLOEXEC: the chart scripts (fork and exec, app/plots.cpp) do not inherit the lock
    int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);  // another user's lock file: lockable read-only
    if (fd < 0) return;                                        // no temporary folder: nothing locked
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      char buf[32] = {};
      const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
      close(fd);
      if (err != EWOULDBLOCK) return;  // a file system without flock: nothing locked
      const long pid = n > 0 ? std::strtol(buf, nullptr, 10) : 0;
      throw InputError(dir, fmt::format("output folder {}: another linerlife run{} is writing into it; wait for it "
                                        "to end or give another --out folder",
                                        dir, pid > 0 ? fmt::format(" (process {})", pid) : std::string()));
    }
    struct stat a {}, b {};
    if (fstat(fd, &a) != 0 || stat(path.c_str(), &b) != 0 || a.st_ino != b.st_ino || a.st_dev != b.st_dev) {
      close(fd);  // removed by the run that held it: lock the new one
      continue;
    }
    // the holder's pid, for the message of a run refused (the lock is the
    // flock, not the text; a read-only lock file names no process)
    const std::string me = fmt::format("{}\n", static_cast<long>(getpid()));
    if (ftruncate(fd, 0) == 0 && pwrite(fd, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
      // the message of a refused run then names no process
    }
    held.by_key.emplace(key, std::make_pair(fd, path));  // open until the process ends
    return;
  }
}

void check_output_dir_writable(const std::string& dir, const std::vector<std::string>& names, bool before_work) {
  std::error_code ec;
  if (dir.empty()) throw InputError("--out", "--out \"\": give a folder");
  if (before_work) lock_output_dir(dir);
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
    // (named as a temporary of this process: the kill-and-resume test found
    // a .linerlife-probe-XXXXXX left by a killed run, which no run removed)
    std::string suffix;
    std::string probe = writability_probe_template(p.string(), &suffix);
    const int fd = mkstemps(probe.data(), static_cast<int>(suffix.size()));
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

std::string writability_probe_template(const std::string& dir, std::string* suffix) {
  const std::string sfx = fmt::format(".tmp.{}", static_cast<long>(getpid()));
  if (suffix) *suffix = sfx;
  return (fs::path(dir) / (".linerlife-probe-XXXXXX" + sfx)).string();
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
    if (process_gone(pid)) fs::remove(e.path(), ec);
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
