#include "app/plots.h"

#include <algorithm>
#include <cstdio>
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

std::string plot_script() {
  const char* script_env = std::getenv("LINERLIFE_PLOT_SCRIPT");
  return script_env ? script_env : LINERLIFE_PLOT_SCRIPT;
}

int run_plot_script(const std::string& kind, const std::string& results_h5, const std::string& out_dir,
                    std::string* report) {
  const char* py_env = std::getenv("LINERLIFE_PYTHON");
  const std::string python = py_env ? py_env : "/usr/bin/python3";
  const std::string script = plot_script();
  if (!std::filesystem::exists(script)) return -1;
  const std::string cmd = fmt::format("{} {} {} {} {}", shell_quote(python), shell_quote(script), shell_quote(kind),
                                      shell_quote(results_h5), shell_quote(out_dir));
  // the script's standard output is read (its report of a damaged dataset);
  // its standard error goes to ours
  std::fflush(nullptr);
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return 127;
  std::string text;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
  const int rc = pclose(p);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (report) *report = text;
  else if (!text.empty()) std::cout << text << "\n";
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + (WIFSIGNALED(rc) ? WTERMSIG(rc) : 0);
}

std::vector<std::string> chart_kinds() {
  std::vector<std::string> out;
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::path(plot_script()).parent_path();
  for (const auto& e : std::filesystem::directory_iterator(dir.empty() ? "." : dir, ec)) {
    const std::string n = e.path().filename().string();
    if (n.rfind("plot_", 0) == 0 && n.size() > 8 && n.compare(n.size() - 3, 3, ".py") == 0 && n != "plot_common.py")
      out.push_back(n.substr(5, n.size() - 8));
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool draw_charts(const std::string& kind, const std::string& results_h5, const std::string& out_dir) {
  std::string report;
  const int rc = run_plot_script(kind, results_h5, out_dir, &report);
  if (rc == -1) {
    std::cerr << fmt::format("linerlife: warning: charts not drawn: plotting script {} not found\n", plot_script());
    return false;
  }
  if (rc == 4) {  // a result that is not a finite number where a chart needs one: a bug, said as it is
    std::cerr << fmt::format("linerlife: warning: charts not drawn: {} holds values that are not finite numbers: {}\n",
                             results_h5, report);
    return false;
  }
  if (rc == 5) {  // a chart file could not be written (a folder in the way, a full disk)
    std::cerr << fmt::format("linerlife: warning: charts not drawn: {}; the results file is complete\n", report);
    return false;
  }
  if (rc != 0) {
    if (!report.empty()) std::cerr << report << "\n";
    std::cerr << fmt::format(
        "linerlife: warning: charts not drawn (the plotting script exited with {}); the results file is complete. "
        "Charts need python3-matplotlib and python3-h5py.\n",
        rc);
    return false;
  }
  return true;
}

}  // namespace linerlife
