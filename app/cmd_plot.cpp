// `linerlife plot RESULTS.h5 [--out DIR]`: redraws the charts of any results
// file (the kind is the file's `command` attribute).
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

int run_plot(const PlotOptions& o) {
  const std::string kind = results_kind(o.file);
  const std::string dir = o.out.empty() ? std::filesystem::path(o.file).parent_path().string() : o.out;
  OutputDir out(dir.empty() ? "." : dir);
  out.prepare();
  if (!draw_charts(kind, o.file, out.dir())) return kExitInternal;
  std::cout << fmt::format("Drew the {} charts of {} in {}\n", kind, o.file, out.dir());
  return 0;
}

}  // namespace

void register_plot(CLI::App& app, std::function<int()>& run) {
  auto o = std::make_shared<PlotOptions>();
  auto* cmd = app.add_subcommand("plot", "Redraw the charts of a results file");
  cmd->add_option("RESULTS", o->file, "A results file written by --out (geometry.h5, forecast.h5, ...)")->required();
  cmd->add_option("--out", o->out, "Folder for the charts (default: the file's folder)");
  cmd->callback([&run, o] { run = [o] { return run_plot(*o); }; });
}

}  // namespace linerlife
