// Time-vs-RMSE scatter plots with the frontier, one per case, drawn by gnuplot (Debian's
// gnuplot-nox: SVG and pngcairo terminals): DIR/plots/case<i>.{svg,png}. The data and the
// script stay next to them (case<i>.dat, case<i>_frontier.dat, case<i>.gp) so a user can restyle.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

struct PlotFiles {
  std::map<size_t, std::string> svg, png;  // case index -> path relative to DIR
  std::string warning;                     // set when gnuplot is missing or failed: no plots
};

PlotFiles writePlots(const std::filesystem::path& dir, const Results& results);

}  // namespace shadowc::sweep
