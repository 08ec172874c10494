// report.html: one page (inline CSS, no scripts, no network; its plots and images are files in
// DIR referenced by relative paths, so it is read with its folder) with, per case, the
// time-vs-RMSE plot, the frontier table and, for each frontier variant, its result, reference and error images and its
// filter description; then every row and the skipped variants. Frontier rows carry class="frontier-row" and data-key,
// so a test can find them in the rendered DOM.
#pragma once

#include <string>

#include "sweep/plot.h"
#include "sweep/sweep_row.h"

namespace shadowc::sweep {

std::string reportHtml(const Results& results, const PlotFiles& plots);

}  // namespace shadowc::sweep
