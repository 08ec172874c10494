// `--runs N|auto`, one spelling for every subcommand that times (docs/cli.md "Timed runs"): a
// fixed count, or auto, which times until the median's 95% interval is within 5% of it or the
// runs took 3 s (runtime/executor/run_timing.h RunCount).
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

#include "runtime/executor/run_timing.h"

namespace shadowc::cli {

inline CLI::Option* addRunsOption(CLI::App* sub, rt::RunCount& runs, const std::string& what) {
  CLI::Option* opt = sub->add_option_function<std::string>(
      "--runs",
      [&runs](const std::string& text) {
        try {
          runs = rt::parseRunCount(text);
        } catch (const std::invalid_argument& e) {
          throw CLI::ValidationError("--runs", e.what());
        }
      },
      what + ": a count, or auto (until the median's 95% interval is within 5% of it, at most 3 s)");
  opt->default_str(rt::toString(runs));
  return opt;
}

}  // namespace shadowc::cli
