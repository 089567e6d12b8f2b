// linerlife - forecasts when the shell liners and lifters of a tumbling mill
// must be replaced. Exit codes (DESIGN.md §4): 0 success, 2 invalid input,
// 3 simulation failure, 1 internal error.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "geometry/errors.h"
#include "geometry/heap_tuning.h"

using namespace linerlife;

int main(int argc, char** argv) {
  keep_freed_memory();  // the wear run's remeshes would page-fault their buffers back in (heap_tuning.h)
  // a file-size limit makes the write fail (an OutputError, the temporary
  // removed) instead of killing the process with a half-written file
  std::signal(SIGXFSZ, SIG_IGN);
  // likewise a reader that closed the pipe makes the write fail (exit 1, the
  // message below) instead of killing the process silently with SIGPIPE
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{
      "linerlife: forecast of tumbling-mill liner wear and the relining date.\n"
      "Every command without a CONFIG file runs the bundled Qiu (2001) SAG mill."};
  app.set_version_flag("--version", program_version());
  app.require_subcommand(1);

  // The subcommands, in the order `--help` lists them.
  const RegisterCommand commands[] = {register_defaults, register_geometry, register_charge, register_wear,
                                      register_forecast, register_compare, register_calibrate, register_plot};
  std::function<int()> run;
  for (RegisterCommand reg : commands) reg(app, run);

  // an unknown command is named (CLI11 would only say one is required)
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      known = known || sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "linerlife: error: unknown command \"" << argv[1] << "\"; the commands are " << names
                << "\n(run `linerlife --help` for the commands and options)\n";
      return kExitInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "linerlife: error: " << e.what() << "\n(run `linerlife --help` for the commands and options)\n";
    return kExitInput;
  }
  try {
    const int code = run ? run() : kExitInput;
    // stdout that could not be written (a full disk, a closed pipe) is a
    // failed run, not a success with a cut-off summary or configuration
    std::cout.flush();
    if (!std::cout) throw OutputError("cannot write to the standard output (a full disk or a closed pipe?)");
    return code;
  } catch (const InputError& e) {
    std::cerr << "linerlife: error: " << e.what() << "\n";
    return kExitInput;
  } catch (const SimulationError& e) {
    std::cerr << "linerlife: simulation failed: " << e.what() << "\n";
    return kExitSimulation;
  } catch (const OutputError& e) {
    std::cerr << "linerlife: error: " << e.what() << std::endl;
    // HDF5 1.10 keeps a file whose close failed in its list and crashes on it
    // (SIGSEGV in H5F__close_cb) when the library shuts down at exit: leave
    // without the exit handlers. The temporaries are gone already (OutputDir).
    std::cout.flush();
    std::fflush(nullptr);
    std::_Exit(kExitInternal);
  } catch (const std::exception& e) {
    std::cerr << "linerlife: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "linerlife: internal error: an unknown exception\n";
    return kExitInternal;
  }
}
