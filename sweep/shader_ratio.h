// Specialized vs generic (docs/sweep.md): the same variant on the same case compiled both
// ways (`shaders: ["specialized", "generic"]`), paired, and the frame-time ratio
// specialized ÷ generic (< 1: specialization buys time). results.csv/json carry it on both rows
// of a pair (`specialized_over_generic`), `shadowc sweep` prints the table, report.html too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

struct ShaderPair {
  size_t specialized = 0, generic = 0;  // indices into the rows
  double ratio = 0;                     // specialized total ms / generic total ms
};

// Rows of the same case, base filter and parameter values, one of each kind; in row order.
std::vector<ShaderPair> shaderPairs(const std::vector<Row>& rows);
// The ratio of a row's pair, when it has one.
std::optional<double> pairedRatio(const std::vector<ShaderPair>& pairs, size_t row);

// One block per case: variant, specialized ms, generic ms, ratio, RMSE of each; "" with no pair.
std::string formatShaderRatios(const Results& results);

}  // namespace shadowc::sweep
