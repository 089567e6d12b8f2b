// `linerlife defaults`: the full annotated default configuration (the bundled
// Qiu mill), ready to copy and edit.
#include <iostream>

#include "app/commands.h"

namespace linerlife {

void register_defaults(CLI::App& app, std::function<int()>& run) {
  auto* cmd = app.add_subcommand("defaults", "Print the full annotated default configuration (the bundled Qiu mill)");
  cmd->callback([&run] {
    run = [] {
      std::cout << "# Bundled default mill: Qiu et al. (2001) SAG mill, thesis Table 5.1, with a reconstructed\n"
                   "# liner (see data/mills/qiu2001_sag.toml for the provenance of every value).\n";
      std::cout << config_to_toml(load_default_config(), true);
      return 0;
    };
  });
}

}  // namespace linerlife
