#include "sweep/merge.h"

#include <algorithm>
#include <set>
#include <tuple>

#include "sweep/results_io.h"

namespace shadowc::sweep {
namespace {

void copyInto(const std::filesystem::path& from, const std::filesystem::path& to, const std::string& rel) {
  if (rel.empty()) return;
  std::error_code ec;
  const std::filesystem::path src = from / rel, dst = to / rel;
  if (!std::filesystem::exists(src, ec) || std::filesystem::equivalent(src, dst, ec)) return;
  std::filesystem::create_directories(dst.parent_path());
  std::filesystem::copy_file(src, dst, std::filesystem::copy_options::overwrite_existing);
}

}  // namespace

Results mergeResults(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out) {
  Results merged;
  merged.shard = "merged";
  std::set<std::string> keys;
  std::set<std::tuple<size_t, std::string, std::string, std::string>> skipped;
  for (const auto& dir : dirs) {
    const Results r = readResultsJson(dir / "results.json");
    if (merged.sweep.empty()) merged.sweep = r.sweep;
    merged.stats.ran += r.stats.ran;
    merged.stats.cached += r.stats.cached;
    for (const Row& row : r.rows) {
      if (!keys.insert(row.key).second) continue;
      for (const std::string* rel : {&row.resultImage, &row.errorImage, &row.referenceImage}) copyInto(dir, out, *rel);
      writeCachedRow(out, row);
      merged.rows.push_back(row);
    }
    for (const Skipped& s : r.skipped)
      if (skipped.insert({s.variantIndex, s.variant, s.code, s.message}).second) merged.skipped.push_back(s);
  }
  std::stable_sort(merged.rows.begin(), merged.rows.end(), [](const Row& a, const Row& b) {
    return std::tie(a.caseIndex, a.variantIndex, a.key) < std::tie(b.caseIndex, b.variantIndex, b.key);
  });
  std::stable_sort(merged.skipped.begin(), merged.skipped.end(),
                   [](const Skipped& a, const Skipped& b) { return a.variantIndex < b.variantIndex; });
  return merged;
}

}  // namespace shadowc::sweep
