// output_dir.h - the --out folder. Nothing is created before the input has
// been checked; every file is written under a temporary name in the folder
// and renamed into place when complete, so a crash never leaves a
// half-written result.
#pragma once

#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace linerlife {

class OutputDir {
 public:
  explicit OutputDir(std::string dir) : dir_(std::move(dir)) {}
  /// Removes the temporaries handed out and not committed: a run that fails
  /// while writing (a full disk, a file-size limit) leaves no half-written file.
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;
  /// Creates the folder (and parents) and checks it can be written; throws
  /// InputError naming the folder when it cannot. Removes the temporaries
  /// (".name.tmp.PID") a killed earlier run left behind, those of processes
  /// no longer alive. Once done, further calls return at once.
  void prepare();
  /// A temporary path in the folder for the file `name` (".name.tmp.PID").
  std::string temp_path(const std::string& name) const;
  /// Renames the finished temporary file to its final name (atomic on POSIX).
  void commit(const std::string& temp, const std::string& name) const;
  /// Writes `text` to `name` atomically.
  void write_text(const std::string& name, const std::string& text) const;
  std::string path(const std::string& name) const;
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  bool prepared_ = false;
  mutable std::mutex mutex_;
  mutable std::set<std::string> pending_;  // temporaries not yet committed
};

/// Checks before any work starts that `dir` could be created and written
/// (an existing folder must be writable; otherwise its nearest existing
/// parent must be), and that none of the files the command writes there
/// (`names`) is taken by something that is not a file (a folder of that
/// name failed the run with exit 1 after all its work). Throws InputError;
/// creates nothing. An existing folder gets a file made, written and removed
/// in it (the permissions do not tell everything: /proc); with `before_work`
/// false (OutputDir::prepare(), after the work) that probe failing is an
/// OutputError (exit 1: a disk that filled during the run is not bad input).
void check_output_dir_writable(const std::string& dir, const std::vector<std::string>& names = {},
                               bool before_work = true);

/// Locks the output folder `dir` for the rest of the process, so that a
/// second linerlife run into the same folder while this one runs is refused
/// (a review, 2026-12-06: two forecasts into one folder mixed one run's
/// results file with the other's charts). The lock is an flock() on a file in
/// /tmp (whatever TMPDIR says) named by a hash of the folder's absolute path,
/// so it needs no folder yet and is released by the kernel when the process
/// ends, however it ends (a normal exit also removes the file). A folder
/// locked by another process: InputError (exit 2) naming it and the holder's
/// pid. Best effort: where the lock file
/// cannot be made (no temporary folder), nothing is locked. Called by
/// check_output_dir_writable() before the work; a second call for the same
/// folder returns at once.
void lock_output_dir(const std::string& dir);

/// The lock file lock_output_dir() takes for `dir` (for the tests).
std::string output_dir_lock_path(const std::string& dir);

/// The name check_output_dir_writable() gives the file it writes into an
/// existing folder to see that it can (mkstemps template): a temporary of
/// this process, .linerlife-probe-XXXXXX.tmp.PID, so that a run killed
/// between making and removing it leaves a file the next run's
/// OutputDir::prepare() removes. The suffix is ".tmp.PID".
std::string writability_probe_template(const std::string& dir, std::string* suffix = nullptr);

/// Why a file could not be written, for the message: "its folder DIR no
/// longer exists (removed during the run?)" when it does not (a review,
/// 2026-12-06: a folder removed under a running forecast was blamed on a full
/// disk), otherwise "is the disk full or the file size limited?".
std::string write_failure_hint(const std::string& file);

}  // namespace linerlife
