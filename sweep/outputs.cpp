#include "sweep/outputs.h"

#include "runtime/images/atomic_file.h"
#include "sweep/plot.h"
#include "sweep/report.h"
#include "sweep/results_io.h"

namespace shadowc::sweep {

std::string writeOutputs(const std::filesystem::path& dir, const Results& results) {
  rt::writeFileAtomically(dir / "results.json", resultsJson(results));
  rt::writeFileAtomically(dir / "results.csv", resultsCsv(results));
  const PlotFiles plots = writePlots(dir, results);
  rt::writeFileAtomically(dir / "report.html", reportHtml(results, plots));
  return plots.warning;
}

}  // namespace shadowc::sweep
