// The frontier per case as a terminal table (what `shadowc sweep` prints, and `shadowc demo`'s
// trade-off table). The numbers are the ones results.csv holds (same rows, same rounding).
#pragma once

#include <string>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

// One block per case: a header line, then one line per frontier row by increasing time:
//   "   1  <variant>  <total ms, 3 decimals>  <rmse, 5 decimals>  <slowest passes>".
// With allRows, every row of the case is listed (by time) and frontier rows are marked '*'.
std::string formatFrontierTables(const Results& results, bool allRows = false);

}  // namespace shadowc::sweep
