#include "sweep/pareto.h"

#include <algorithm>

namespace shadowc::sweep {

bool dominates(const Row& a, const Row& b) {
  return a.totalMs <= b.totalMs && a.metrics.rmse <= b.metrics.rmse &&
         (a.totalMs < b.totalMs || a.metrics.rmse < b.metrics.rmse);
}

bool eligible(const Row& row) { return row.metrics.nonFinite == 0 && row.metrics.compared > 0; }

std::map<size_t, std::vector<size_t>> frontiers(const std::vector<Row>& rows) {
  std::map<size_t, std::vector<size_t>> byCase;
  for (size_t i = 0; i < rows.size(); ++i) byCase[rows[i].caseIndex].push_back(i);
  std::map<size_t, std::vector<size_t>> out;
  for (auto& [c, members] : byCase) {
    std::vector<size_t>& f = out[c];
    // Quadratic, and fine: a case has at most a few thousand rows.
    for (size_t i : members) {
      if (!eligible(rows[i])) continue;
      const bool beaten = std::any_of(members.begin(), members.end(), [&](size_t k) {
        return k != i && eligible(rows[k]) && dominates(rows[k], rows[i]);
      });
      if (!beaten) f.push_back(i);
    }
    std::stable_sort(f.begin(), f.end(), [&](size_t a, size_t b) {
      if (rows[a].totalMs != rows[b].totalMs) return rows[a].totalMs < rows[b].totalMs;
      return rows[a].metrics.rmse < rows[b].metrics.rmse;
    });
  }
  return out;
}

}  // namespace shadowc::sweep
