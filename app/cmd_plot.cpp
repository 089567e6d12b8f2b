// `linerlife plot RESULTS.h5 [--out DIR]`: redraws the charts of any results
// file (the kind is the file's `command` attribute).
#include <algorithm>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/h5_reader.h"
#include "app/output_dir.h"
#include "app/plots.h"
#include "geometry/errors.h"

namespace linerlife {
namespace {

struct PlotOptions {
  std::string file;
  std::string out;
};

std::string results_kind(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, fmt::format("results file {} does not exist", path));
  if (fs::is_directory(path, ec)) throw InputError(path, fmt::format("results file {} is a directory", path));
  const H5Reader h5(path);
  return h5.attr_string("/", "command");
}

/// The outermost folder of `dir` that does not exist yet (the one creating
/// `dir` makes first), or empty if `dir` exists.
std::filesystem::path first_missing_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path created;
  for (fs::path p = fs::absolute(dir, ec); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created = p;
    if (p == p.parent_path()) break;
  }
  return created;
}

/// Removes the folder `dir` this run created, unless it holds a file.
void remove_if_no_files(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) return;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (!e.is_directory(ec)) return;
  fs::remove_all(dir, ec);
}

int run_plot(const PlotOptions& o) {
  const std::string kind = results_kind(o.file);
  if (kind == "checkpoint")
    throw InputError(o.file, fmt::format("{} is a forecast checkpoint, not a results file: plot the forecast.h5 "
                                         "next to it", o.file));
  const std::vector<std::string> kinds = chart_kinds();
  if (!kinds.empty() && std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
    std::string list;
    for (const std::string& k : kinds) list += (list.empty() ? "" : ", ") + k;
    throw InputError(o.file, fmt::format("{} is a \"{}\" file (its command attribute); charts are drawn for the "
                                         "results of {}", o.file, kind, list));
  }
  const std::string dir = o.out.empty() ? std::filesystem::path(o.file).parent_path().string() : o.out;
  OutputDir out(dir.empty() ? "." : dir);
  const std::filesystem::path created = first_missing_folder(out.dir());
  check_output_dir_writable(out.dir());  // before any work, as every command: exit 2
  out.prepare();
  std::string report;
  const int rc = run_plot_script(kind, o.file, out.dir(), &report);
  if (rc == 3 || rc == 4) remove_if_no_files(created);  // a damaged file: nothing written
  if (rc == 3)
    throw InputError(o.file, fmt::format("results file {} is damaged or incomplete: it lacks a group, dataset or "
                                         "attribute a {} results file has (above)", o.file, kind));
  if (rc == 4)
    throw InputError(o.file, fmt::format("results file {} is damaged: dataset {}; allowed only finite numbers there, "
                                         "of magnitude at most 1e12, "
                                         "in a {} results file: nothing drawn", o.file, report, kind));
  if (rc == 5)  // a chart could not be written there (a folder of its name, a full disk)
    throw InputError(out.dir(), fmt::format("charts not drawn in {}: {}", out.dir(), report));
  if (rc != 0) {
    std::cerr << (rc == -1 ? "linerlife: error: the plotting script is not installed\n"
                           : fmt::format("linerlife: error: charts not drawn (the plotting script exited with {}): "
                                         "charts need python3-matplotlib and python3-h5py\n", rc));
    return kExitInternal;
  }
  std::cout << fmt::format("Drew the {} charts of {} in {}\n", kind, o.file, out.dir());
  return 0;
}

}  // namespace

void register_plot(CLI::App& app, std::function<int()>& run) {
  auto o = std::make_shared<PlotOptions>();
  auto* cmd = app.add_subcommand("plot", "Redraw the charts of a results file");
  cmd->add_option("RESULTS", o->file, "A results file written by --out (geometry.h5, forecast.h5, ...)")->required();
  cmd->add_option("--out", o->out, "Folder for the charts (default: the file's folder)")
      ->check(out_folder_check("without --out the charts go into the results file's folder"));
  cmd->callback([&run, o] { run = [o] { return run_plot(*o); }; });
}

}  // namespace linerlife
