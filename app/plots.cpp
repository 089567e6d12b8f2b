#include "app/plots.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <sys/wait.h>

namespace linerlife {
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

}  // namespace

bool draw_charts(const std::string& kind, const std::string& results_h5, const std::string& out_dir) {
  const char* py_env = std::getenv("LINERLIFE_PYTHON");
  const char* script_env = std::getenv("LINERLIFE_PLOT_SCRIPT");
  const std::string python = py_env ? py_env : "/usr/bin/python3";
  const std::string script = script_env ? script_env : LINERLIFE_PLOT_SCRIPT;
  if (!std::filesystem::exists(script)) {
    std::cerr << fmt::format("linerlife: warning: charts not drawn: plotting script {} not found\n", script);
    return false;
  }
  const std::string cmd = fmt::format("{} {} {} {} {}", shell_quote(python), shell_quote(script), shell_quote(kind),
                                      shell_quote(results_h5), shell_quote(out_dir));
  const int rc = std::system(cmd.c_str());
  if (rc != 0) {
    std::cerr << fmt::format(
        "linerlife: warning: charts not drawn ({} exited with {}); the results file is complete. "
        "Charts need python3-matplotlib and python3-h5py.\n",
        python, WIFEXITED(rc) ? WEXITSTATUS(rc) : rc);
    return false;
  }
  return true;
}

}  // namespace linerlife
