// Everything a sweep (or a merge) leaves in its folder for one result set: results.json,
// results.csv, plots/ and report.html. One function so that `sweep` and `sweep merge` write
// the same files the same way.
#pragma once

#include <filesystem>
#include <string>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

// Returns a warning ("" when none): e.g. gnuplot missing, the report then has no plots.
std::string writeOutputs(const std::filesystem::path& dir, const Results& results);

}  // namespace shadowc::sweep
