// commands.h - the subcommands of `linerlife`, one file each
// (cmd_<name>.cpp), listed in one plain table in main.cpp.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/config.h"

namespace linerlife {

/// Adds a subcommand to `app` and sets `run` to what it does once parsed.
using RegisterCommand = void (*)(CLI::App& app, std::function<int()>& run);

void register_defaults(CLI::App& app, std::function<int()>& run);
void register_geometry(CLI::App& app, std::function<int()>& run);
void register_charge(CLI::App& app, std::function<int()>& run);
void register_wear(CLI::App& app, std::function<int()>& run);
void register_forecast(CLI::App& app, std::function<int()>& run);
void register_compare(CLI::App& app, std::function<int()>& run);
void register_calibrate(CLI::App& app, std::function<int()>& run);
void register_plot(CLI::App& app, std::function<int()>& run);

/// The program version ("0.1.0 (git abc1234)").
const char* program_version();

/// The configuration named on the command line, or the bundled default mill.
Config load_config_or_default(const std::string& path);

/// Prints a summary line to stderr unless quiet.
void note(const std::string& text);

}  // namespace linerlife
