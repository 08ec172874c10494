// shadowc: compile soft-shadow filter descriptions to specialized GLSL/SPIR-V, run them on
// lavapipe against a ray-traced ground truth. See docs/cli.md.
#include <fmt/core.h>

#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/commands.h"

int main(int argc, char** argv) {
  using namespace shadowc::cli;
  CLI::App app{"shadowc " SHADOWC_VERSION " - a compiler for soft-shadow filters", "shadowc"};
  app.set_version_flag("--version", "shadowc " SHADOWC_VERSION);
  app.require_subcommand(1);
  // Usage errors in the same form as every other error (one "error:" line, glslc style).
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    std::string m = "shadowc: error: " + std::string(e.what()) + "\n";
    if (a->get_help_ptr() != nullptr) m += "Run with " + a->get_help_ptr()->get_name() + " for more information.\n";
    return m;
  });
  std::vector<std::pair<CLI::App*, CommandRunner>> commands;
  auto add = [&](CommandRunner (*reg)(CLI::App&)) {
    const size_t before = app.get_subcommands({}).size();
    CommandRunner run = reg(app);
    commands.emplace_back(app.get_subcommands({})[before], std::move(run));
  };
  add(registerCompile);
  add(registerCheck);
  add(registerValidate);
  add(registerDemo);
  add(registerStability);
  add(registerSweep);
  add(registerAnalyze);
  add(registerPlan);
  add(registerCostProfile);
  add(registerExportScene);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (auto& [sub, run] : commands)
      if (sub->parsed()) return run();
  } catch (const std::exception& e) {
    std::fflush(stdout);
    // Errors that already name their place ("scene.json:1:28: error: ...", glslc form) are
    // printed as they are; the rest get the program's name.
    const std::string_view what = e.what();
    if (what.find(": error: ") != std::string_view::npos)
      fmt::print(stderr, "{}\n", what);
    else
      fmt::print(stderr, "shadowc: error: {}\n", what);
    return 1;
  }
  return 1;
}
