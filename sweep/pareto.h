// The Pareto frontier of time vs error per case: the rows no other row of the same case beats
// on both total frame time and RMSE. A row with non-finite output pixels is never on it (its
// RMSE counts only the finite pixels, so it would look better than it is).
//
// A time is an interval, the 95% interval of its median (timing_stats.h), so one row beats
// another on time only when its interval lies wholly below; rows whose intervals overlap are
// tied on time (docs/sweep.md "Ties"). A row with no interval (n = 0: written by hand, or a
// result from before intervals) is its median alone, which gives the classic frontier.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

// The time a row is ranked by: the predicted frame when a cost profile priced it, else the
// measured median. A prediction is a point (it does not move with load); a measurement is known
// to the interval [ci low, ci high], or [total, total] without one.
double rankedMs(const Row& row);
// The cases some row of which a cost profile priced: their rows are ranked, drawn and tabled by
// the prediction, and a row without one is left off (two devices' times do not compare).
std::set<size_t> predictedCases(const std::vector<Row>& rows);
double timeLowMs(const Row& row);
double timeHighMs(const Row& row);

// a dominates b for certain: a's whole interval at or below b's, RMSE no worse, and better on
// one of the two. With point times this is "no worse on both, better on one".
bool dominates(const Row& a, const Row& b);
// a may dominate b: some times inside both intervals make a dominate b.
bool mayDominate(const Row& a, const Row& b);
bool eligible(const Row& row);
// The heading for these rows' time intervals, with the coverage they really have
// (rt::intervalLabel: "93.7 % interval" at 5 runs, "50 % interval" at 2).
std::string intervalLabel(const std::vector<Row>& rows);

// A row's frontier membership. On: no row may dominate it, and it may dominate no frontier row.
// Tied: none dominates it for certain, but it and another frontier row whose interval overlaps
// may beat one another one way (`tiedWith`: those rows, by row index; symmetric: if a names b,
// b names a). Off: dominated for certain. Two sweeps of the same rows agree on a row unless one says On and the
// other Off.
enum class Membership { On, Tied, Off };
struct FrontierMark {
  Membership membership = Membership::Off;
  std::vector<size_t> tiedWith;
};
// One mark per row; an ineligible row is Off, and so is a row without a prediction in a case
// whose other rows a cost profile priced (two devices' times do not compare).
std::vector<FrontierMark> frontierMarks(const std::vector<Row>& rows);

// Case index -> indices into `rows` of that case's frontier (On or Tied), by increasing time
// (ties: RMSE, then row order). Equal points are both kept (neither dominates the other).
std::map<size_t, std::vector<size_t>> frontiers(const std::vector<Row>& rows);

}  // namespace shadowc::sweep
