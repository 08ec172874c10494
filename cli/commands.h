// Every subcommand of the shadowc executable registers itself here: it adds a CLI11
// subcommand with its options and returns the function that runs it (exit code).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace shadowc::cli {

using CommandRunner = std::function<int()>;

CommandRunner registerCompile(CLI::App& app);    // cmd_compile.cpp
CommandRunner registerCheck(CLI::App& app);      // cmd_check.cpp
CommandRunner registerValidate(CLI::App& app);   // cmd_validate.cpp
CommandRunner registerDemo(CLI::App& app);       // cmd_demo.cpp
CommandRunner registerStability(CLI::App& app);  // cmd_stability.cpp
CommandRunner registerSweep(CLI::App& app);      // cmd_sweep.cpp
CommandRunner registerAnalyze(CLI::App& app);    // cmd_analyze.cpp
CommandRunner registerPlan(CLI::App& app);       // cmd_plan.cpp

}  // namespace shadowc::cli
