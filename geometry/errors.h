// errors.h - the ways a linerlife run can fail, each with its exit code
// (DESIGN.md §4): invalid input (2), simulation failure (3), internal error
// and output that cannot be written (1).
//
// User input and runtime data are checked always (deal.II's AssertThrow); the
// error names the key or file, the value, and what is allowed. Programming
// errors are debug asserts.
#pragma once

#include <stdexcept>
#include <string>

namespace linerlife {

/// Invalid input: a configuration key, a file, a command-line option or a
/// physically impossible mill. Exit code 2; no output files are created.
class InputError : public std::runtime_error {
 public:
  /// key: the configuration key as "section.name" (e.g. "liner.lifter_height_m"),
  /// a file path, or a command-line option; empty when none applies.
  InputError(std::string key, const std::string& message)
      : std::runtime_error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

/// A simulation that cannot produce a trustworthy result (instability, a
/// remesh that cannot give a valid profile, an integrator failure). Exit code 3.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A results file or stdout that cannot be written (a full disk, a file-size
/// limit, a closed pipe): not the input's fault nor the simulation's. Exit
/// code 1, with a message naming the file; no half-written file is left
/// (OutputDir removes its temporaries).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitInput = 2;
constexpr int kExitSimulation = 3;

}  // namespace linerlife
