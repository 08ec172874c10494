#include "sweep/frontier_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "sweep/pareto.h"

namespace shadowc::sweep {
namespace {

// The two or three passes that take the time, so a reader sees where it goes.
std::string topPasses(const Row& r) {
  std::vector<PassTime> p = r.passes;
  std::stable_sort(p.begin(), p.end(), [](const PassTime& a, const PassTime& b) { return a.medianMs > b.medianMs; });
  std::string out;
  for (size_t i = 0; i < p.size() && i < 3; ++i)
    out += fmt::format("{}{} {:.2f}", i ? ", " : "", p[i].name, p[i].medianMs);
  return out;
}

}  // namespace

std::string formatFrontierTables(const Results& res, bool allRows) {
  const auto front = frontiers(res.rows);
  const std::vector<FrontierMark> marks = frontierMarks(res.rows);
  const std::set<size_t> predictedCase = predictedCases(res.rows);
  bool anyTie = false;
  const std::string interval = intervalLabel(res.rows);  // the coverage the runs give (timing_stats.h)
  std::map<size_t, std::vector<size_t>> byCase;
  for (size_t i = 0; i < res.rows.size(); ++i) byCase[res.rows[i].caseIndex].push_back(i);
  std::string out;
  for (const auto& [c, members] : byCase) {
    const auto it = front.find(c);
    const std::vector<size_t> frontier = it == front.end() ? std::vector<size_t>{} : it->second;
    const std::set<size_t> onFrontier(frontier.begin(), frontier.end());
    std::vector<size_t> shown = allRows ? members : frontier;
    if (allRows)
      std::stable_sort(shown.begin(), shown.end(),
                       [&](size_t a, size_t b) { return rankedMs(res.rows[a]) < rankedMs(res.rows[b]); });
    size_t width = 7;
    for (size_t i : shown) width = std::max(width, res.rows[i].variant.size());
    const Row& first = res.rows[members.front()];
    const bool predicted = predictedCase.count(c) > 0;
    out += fmt::format(
        "{} {}: {} of {} rows on the frontier (time = {}, RMSE vs the Embree reference)\n",
        allRows ? "trade-off" : "frontier", first.caseLabel, frontier.size(), members.size(),
        predicted ? "the cost profile's predicted frame; the measured median beside it" : "median frame total");
    out += fmt::format("  {:>4}  {:<{}}  {}{:>10}  {:>19}  {:>9}  {}\n", "#", "variant", width,
                       predicted ? fmt::format("{:>12}  ", "predicted ms") : std::string(), "total ms", interval,
                       "rmse", "slowest passes (ms)");
    size_t rank = 0;
    for (size_t i : shown) {
      const Row& r = res.rows[i];
      // "=": tied on time with a frontier row whose interval overlaps (docs/sweep.md "Ties").
      const bool tied = marks[i].membership == Membership::Tied;
      anyTie = anyTie || tied;
      const std::string mark =
          (allRows ? std::string(onFrontier.count(i) ? "*" : " ") : fmt::format("{}", ++rank)) + (tied ? "=" : "");
      const std::string range =
          r.total.n > 0 ? fmt::format("[{:.3f}, {:.3f}]", r.total.ciLowMs, r.total.ciHighMs) : std::string("-");
      const std::string prediction = !predicted      ? std::string()
                                     : r.predictedMs ? fmt::format("{:>12.3f}  ", *r.predictedMs)
                                                     : fmt::format("{:>12}  ", "-");
      out += fmt::format("  {:>4}  {:<{}}  {}{:>10.3f}  {:>19}  {:>9.5f}  {}\n", mark, r.variant, width, prediction,
                         r.totalMs, range, r.metrics.rmse, topPasses(r));
    }
    if (allRows) out += "  (* = on the frontier: nothing else here is both faster and more accurate)\n";
  }
  if (anyTie)
    out += "  (= tied: its time interval overlaps a frontier row's that may beat it; these runs do not order them)\n";
  return out;
}

}  // namespace shadowc::sweep
