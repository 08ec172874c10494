#include "sweep/shader_ratio.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace shadowc::sweep {

std::vector<ShaderPair> shaderPairs(const std::vector<Row>& rows) {
  using Key = std::tuple<std::string, std::string, std::vector<std::pair<std::string, std::string>>>;
  std::map<Key, size_t> specialized;
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].shader == "specialized") specialized.emplace(Key{rows[i].caseLabel, rows[i].base, rows[i].params}, i);
  std::vector<ShaderPair> out;
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].shader != "generic") continue;
    const auto it = specialized.find(Key{rows[i].caseLabel, rows[i].base, rows[i].params});
    if (it == specialized.end() || rows[i].totalMs <= 0) continue;
    out.push_back({it->second, i, rows[it->second].totalMs / rows[i].totalMs});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const ShaderPair& a, const ShaderPair& b) { return a.specialized < b.specialized; });
  return out;
}

std::optional<double> pairedRatio(const std::vector<ShaderPair>& pairs, size_t row) {
  for (const ShaderPair& p : pairs)
    if (p.specialized == row || p.generic == row) return p.ratio;
  return std::nullopt;
}

std::string formatShaderRatios(const Results& res) {
  const std::vector<ShaderPair> pairs = shaderPairs(res.rows);
  if (pairs.empty()) return {};
  std::map<std::string, std::vector<ShaderPair>> byCase;
  std::vector<std::string> order;
  for (const ShaderPair& p : pairs) {
    const std::string& c = res.rows[p.specialized].caseLabel;
    if (!byCase.count(c)) order.push_back(c);
    byCase[c].push_back(p);
  }
  std::string out;
  for (const std::string& c : order) {
    size_t width = 7;
    for (const ShaderPair& p : byCase[c]) width = std::max(width, res.rows[p.specialized].variant.size());
    out += fmt::format("specialized vs generic {}: frame-time ratio specialized / generic (< 1: specialization pays)\n",
                       c);
    out += fmt::format("  {:<{}}  {:>11}  {:>10}  {:>6}  {:>9}  {:>9}\n", "variant", width, "special. ms", "generic ms",
                       "ratio", "rmse sp.", "rmse gen.");
    for (const ShaderPair& p : byCase[c]) {
      const Row& s = res.rows[p.specialized];
      const Row& g = res.rows[p.generic];
      out += fmt::format("  {:<{}}  {:>11.3f}  {:>10.3f}  {:>6.3f}  {:>9.5f}  {:>9.5f}\n", s.variant, width, s.totalMs,
                         g.totalMs, p.ratio, s.metrics.rmse, g.metrics.rmse);
    }
  }
  return out;
}

}  // namespace shadowc::sweep
