// PLACEHOLDER: replaced by the real command during the first build-out.
#include <fmt/core.h>

#include "cli/commands.h"

namespace shadowc::cli {
CommandRunner registerDemo(CLI::App& app) {
  app.add_subcommand("demo", "(not built yet)");
  return [] {
    fmt::print(stderr, "shadowc: error: 'demo' is not built yet\n");
    return 2;
  };
}
}  // namespace shadowc::cli
