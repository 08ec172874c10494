#include "sweep/pareto.h"

#include <algorithm>

namespace shadowc::sweep {

double rankedMs(const Row& row) { return row.predictedMs ? *row.predictedMs : row.totalMs; }
std::set<size_t> predictedCases(const std::vector<Row>& rows) {
  std::set<size_t> cases;
  for (const Row& r : rows)
    if (r.predictedMs) cases.insert(r.caseIndex);
  return cases;
}
double timeLowMs(const Row& row) {
  return row.predictedMs ? *row.predictedMs : row.total.n > 0 ? row.total.ciLowMs : row.totalMs;
}
double timeHighMs(const Row& row) {
  return row.predictedMs ? *row.predictedMs : row.total.n > 0 ? row.total.ciHighMs : row.totalMs;
}

bool dominates(const Row& a, const Row& b) {
  const double aHigh = timeHighMs(a), bLow = timeLowMs(b);
  return aHigh <= bLow && a.metrics.rmse <= b.metrics.rmse && (aHigh < bLow || a.metrics.rmse < b.metrics.rmse);
}

bool mayDominate(const Row& a, const Row& b) {
  // The most favourable times for a: its lowest against b's highest.
  const double aLow = timeLowMs(a), bHigh = timeHighMs(b);
  return aLow <= bHigh && a.metrics.rmse <= b.metrics.rmse && (aLow < bHigh || a.metrics.rmse < b.metrics.rmse);
}

bool eligible(const Row& row) { return row.metrics.nonFinite == 0 && row.metrics.compared > 0; }

std::string intervalLabel(const std::vector<Row>& rows) {
  std::vector<double> coverages;
  for (const Row& r : rows)
    if (r.total.n > 0) coverages.push_back(r.total.ciCoverage);
  return rt::intervalLabel(coverages);
}

std::vector<FrontierMark> frontierMarks(const std::vector<Row>& rows) {
  std::map<size_t, std::vector<size_t>> byCase;
  const std::set<size_t> predicted = predictedCases(rows);
  for (size_t i = 0; i < rows.size(); ++i)
    if (eligible(rows[i]) && (rows[i].predictedMs || !predicted.count(rows[i].caseIndex)))
      byCase[rows[i].caseIndex].push_back(i);
  std::vector<FrontierMark> marks(rows.size());
  // Quadratic, and fine: a case has at most a few thousand rows.
  for (const auto& [c, members] : byCase) {
    for (size_t i : members) {
      const bool beaten =
          std::any_of(members.begin(), members.end(), [&](size_t k) { return k != i && dominates(rows[k], rows[i]); });
      marks[i].membership = beaten ? Membership::Off : Membership::On;
    }
    // A tie is symmetric: when k may beat i, these runs order neither, so both carry the mark
    // and each names the other.
    for (size_t i : members) {
      if (marks[i].membership == Membership::Off) continue;
      for (size_t k : members)
        if (k != i && marks[k].membership != Membership::Off &&
            (mayDominate(rows[k], rows[i]) || mayDominate(rows[i], rows[k])))
          marks[i].tiedWith.push_back(k);
    }
    for (size_t i : members)
      if (!marks[i].tiedWith.empty()) marks[i].membership = Membership::Tied;
  }
  return marks;
}

std::map<size_t, std::vector<size_t>> frontiers(const std::vector<Row>& rows) {
  const std::vector<FrontierMark> marks = frontierMarks(rows);
  std::map<size_t, std::vector<size_t>> out;
  for (size_t i = 0; i < rows.size(); ++i)
    out[rows[i].caseIndex];  // every case with rows has a frontier, empty when none is eligible
  for (size_t i = 0; i < rows.size(); ++i)
    if (marks[i].membership != Membership::Off) out[rows[i].caseIndex].push_back(i);
  for (auto& [c, f] : out)
    std::stable_sort(f.begin(), f.end(), [&](size_t a, size_t b) {
      if (rankedMs(rows[a]) != rankedMs(rows[b])) return rankedMs(rows[a]) < rankedMs(rows[b]);
      return rows[a].metrics.rmse < rows[b].metrics.rmse;
    });
  return out;
}

}  // namespace shadowc::sweep
