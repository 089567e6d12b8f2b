// Runs the linerlife executable and captures its exit code and output.
#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace linerlife::test {

struct RunResult {
  int code = -1;
  std::string out, err;
};

inline std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

/// Writes `text` to `path` (a test's input file).
inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
}

/// Runs `linerlife ARGS` through the shell (ARGS is shell syntax); with
/// timeout_s > 0 a run still going after that many seconds is killed and
/// returns code 124 (coreutils' timeout).
inline RunResult run_linerlife(const std::string& args, int timeout_s = 0) {
  static int counter = 0;
  const std::string err_path = (std::filesystem::temp_directory_path() /
                                ("linerlife_test_err_" + std::to_string(getpid()) + "_" + std::to_string(counter++)))
                                   .string();
  const std::string cmd = (timeout_s > 0 ? "timeout -k 5 " + std::to_string(timeout_s) + " " : std::string()) +
                          std::string(LINERLIFE_BINARY) + " " + args + " 2>" + err_path;
  RunResult r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(err_path);
  std::filesystem::remove(err_path);
  return r;
}

/// A fresh empty temporary folder for one test.
inline std::filesystem::path temp_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("linerlife_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace linerlife::test
