// PLACEHOLDER: replaced by the real command during the first build-out.
#include <fmt/core.h>

#include "cli/commands.h"

namespace shadowc::cli {
CommandRunner registerValidate(CLI::App& app) {
  app.add_subcommand("validate", "(not built yet)");
  return [] {
    fmt::print(stderr, "shadowc: error: 'validate' is not built yet\n");
    return 2;
  };
}
}  // namespace shadowc::cli
