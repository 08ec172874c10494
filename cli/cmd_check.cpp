// PLACEHOLDER: replaced by the real command during the first build-out.
#include <fmt/core.h>

#include "cli/commands.h"

namespace shadowc::cli {
CommandRunner registerCheck(CLI::App& app) {
  app.add_subcommand("check", "(not built yet)");
  return [] {
    fmt::print(stderr, "shadowc: error: 'check' is not built yet\n");
    return 2;
  };
}
}  // namespace shadowc::cli
