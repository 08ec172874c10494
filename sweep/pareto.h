// The Pareto frontier of time vs error per case: the rows no other row of the same case beats
// on both total frame time and RMSE. A row with non-finite output pixels is never on it (its
// RMSE counts only the finite pixels, so it would look better than it is).
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

// a dominates b: no worse on time and RMSE, better on at least one.
bool dominates(const Row& a, const Row& b);
bool eligible(const Row& row);

// Case index -> indices into `rows` of that case's frontier, by increasing time (ties: RMSE,
// then row order). Equal points are both kept (neither dominates the other).
std::map<size_t, std::vector<size_t>> frontiers(const std::vector<Row>& rows);

}  // namespace shadowc::sweep
