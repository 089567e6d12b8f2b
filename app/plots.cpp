#include "app/plots.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace linerlife {
namespace {

/// Runs argv[0] (looked up on PATH when it has no slash) with argv, its
/// standard output read into `text`, its standard error ours; returns its
/// wait status, or -1 when it could not be started. The child gets SIGKILL
/// when linerlife dies (prctl PR_SET_PDEATHSIG): a linerlife killed while its
/// charts are drawn must not leave the script running on in the folder, where
/// it held a temporary chart past the next run's clean-up and would rename
/// the dead run's charts over the next run's (a CI failure, 2026-12-07: a
/// resumed forecast ended with a .forecast_*.tmp.PID.png of the killed run's
/// script in its folder). The popen() used before could not set this.
int run_reading_stdout(const std::vector<std::string>& argv, std::string& text) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return -1;
  std::vector<char*> args;
  std::vector<std::string> a = argv;
  for (std::string& s : a) args.push_back(s.data());
  args.push_back(nullptr);
  const pid_t parent = getpid();
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return -1;
  }
  if (pid == 0) {
    // only async-signal-safe calls from here to exec
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(127);  // parent already gone
    // the pipe's end onto the standard output (when it already is fd 1, a
    // linerlife started without standard input and output, dup2 would leave
    // its close-on-exec flag set)
    if (fds[1] == STDOUT_FILENO ? fcntl(fds[1], F_SETFD, 0) != 0 : dup2(fds[1], STDOUT_FILENO) < 0) _exit(127);
    execvp(args[0], args.data());
    _exit(127);
  }
  close(fds[1]);
  char buf[4096];
  for (;;) {
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n > 0) text.append(buf, static_cast<size_t>(n));
    else if (n == 0 || errno != EINTR) break;
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
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
  // the script's standard output is read (its report of a damaged dataset);
  // its standard error goes to ours
  std::string text;
  const int rc = run_reading_stdout({python, script, kind, results_h5, out_dir}, text);
  if (rc == -1) return 127;
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
