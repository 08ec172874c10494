// shadowc check FILE...: runs the driver up to the checker (lex, parse, check) and prints diagnostics in glslc
// form. Exit 0 when every file is clean, 1 when any has an error (warnings count with -Werror),
// 2 on usage errors (CLI11). --print-spec prints each clean file's normalized spec as JSON.
#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "driver/driver.h"

namespace shadowc::cli {
namespace {
struct CheckOptions {
  std::vector<std::string> files;
  bool werror = false;
  bool printSpec = false;
};
}  // namespace

CommandRunner registerCheck(CLI::App& app) {
  auto opts = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand("check", "Check filter descriptions: diagnostics only, no output files");
  cmd->add_option("files", opts->files, "filter description files (.shadow)");
  cmd->add_flag("--Werror", opts->werror, "treat warnings as errors (also spelled -Werror, as in glslc)");
  cmd->add_flag("--print-spec", opts->printSpec, "print the normalized FilterSpec of each clean file as JSON");
  // CLI11 has no multi-letter single-dash options: glslc's -Werror arrives as an extra.
  cmd->allow_extras();
  return [opts, cmd] {
    for (const std::string& extra : cmd->remaining()) {
      if (extra == "-Werror") {
        opts->werror = true;
      } else {
        fmt::print(stderr, "shadowc check: error: unknown argument '{}' (see shadowc check --help)\n", extra);
        return 2;
      }
    }
    if (opts->files.empty()) {
      fmt::print(stderr, "shadowc check: error: no input files (shadowc check FILE.shadow...)\n");
      return 2;
    }
    int exitCode = 0;
    for (const std::string& file : opts->files) {
      driver::Options options;
      options.warningsAsErrors = opts->werror;
      options.stopAfter = driver::Stage::Check;
      const driver::Result result = driver::compileFile(file, options);
      if (!result.log.empty()) {
        std::fflush(stdout);
        fmt::print(stderr, "{}", result.log);
        std::fflush(stderr);
      }
      if (!result.ok) exitCode = 1;
      if (opts->printSpec && result.spec) fmt::print("{}\n", specToJson(*result.spec).dump(2));
    }
    return exitCode;
  };
}
}  // namespace shadowc::cli
