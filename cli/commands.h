// Every subcommand of the shadowc executable registers itself here: it adds a CLI11
// subcommand with its options and returns the function that runs it (exit code).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace shadowc::cli {

using CommandRunner = std::function<int()>;

CommandRunner registerCompile(CLI::App& app);      // cmd_compile.cpp
CommandRunner registerCheck(CLI::App& app);        // cmd_check.cpp
CommandRunner registerValidate(CLI::App& app);     // cmd_validate.cpp
CommandRunner registerDemo(CLI::App& app);         // cmd_demo.cpp
CommandRunner registerStability(CLI::App& app);    // cmd_stability.cpp
CommandRunner registerSweep(CLI::App& app);        // cmd_sweep.cpp
CommandRunner registerAnalyze(CLI::App& app);      // cmd_analyze.cpp
CommandRunner registerPlan(CLI::App& app);         // cmd_plan.cpp
CommandRunner registerCostProfile(CLI::App& app);  // cmd_cost_profile.cpp
CommandRunner registerExportScene(CLI::App& app);  // cmd_export_scene.cpp

// An option's old spelling, kept only to say its new one: one spelling for each option across
// subcommands (docs/cli.md), so `--size 64` from an old script fails with a message naming
// `--screen` instead of "The following argument was not expected". Hidden from --help.
inline void addRenamedOption(CLI::App* sub, const std::string& oldName, const std::string& newName,
                             bool takesValue = true) {
  auto refuse = [oldName, newName] {
    throw CLI::ValidationError(oldName, "this option is now spelled " + newName + " (docs/cli.md)");
  };
  CLI::Option* opt = takesValue
                         ? sub->add_option_function<std::string>(oldName, [refuse](const std::string&) { refuse(); })
                         : sub->add_flag_function(oldName, [refuse](int64_t) { refuse(); });
  opt->group("");
}

}  // namespace shadowc::cli
