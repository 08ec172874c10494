#include "sweep/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "sweep/pareto.h"
#include "sweep/shader_ratio.h"

namespace shadowc::sweep {
namespace {

std::string esc(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

constexpr const char* kStyle = R"(
body{font:15px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;color:#1d2329;margin:0;background:#f4f5f7}
main{max-width:1120px;margin:0 auto;padding:24px 28px 48px}
h1{font-size:26px;margin:0 0 4px}h2{font-size:20px;margin:36px 0 10px;border-bottom:2px solid #c8102e;padding-bottom:4px}
h3{font-size:15px;margin:14px 0 8px}.card h3{margin-top:0}.sub{color:#5b6570;margin:0 0 18px}
.stats{display:flex;gap:12px;flex-wrap:wrap;margin:14px 0}
.stat{background:#fff;border:1px solid #dde1e6;border-radius:6px;padding:8px 14px}.stat b{font-size:20px;display:block}
table{border-collapse:collapse;background:#fff;width:100%;margin:8px 0 14px;font-size:14px}
th,td{padding:5px 10px;border-bottom:1px solid #e6e9ed;text-align:left}th{background:#eef0f3;font-weight:600}
td.num{text-align:right;font-variant-numeric:tabular-nums;font-family:ui-monospace,Menlo,monospace}
tr.frontier-row td:first-child{color:#c8102e;font-weight:700}
.tie{color:#8a5a00}
.plot{background:#fff;border:1px solid #dde1e6;border-radius:6px;padding:6px;display:block;max-width:100%}
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(330px,1fr));gap:14px}
.card{background:#fff;border:1px solid #dde1e6;border-radius:6px;padding:12px}
.imgs{display:flex;gap:6px}.imgs figure{margin:0;flex:1;text-align:center;font-size:12px;color:#5b6570}
.imgs img{width:100%;image-rendering:pixelated;border:1px solid #ccd1d7}
pre{background:#f7f8fa;border:1px solid #e1e4e8;padding:8px;font-size:12px;overflow:auto;margin:8px 0 0}
details{margin:10px 0}summary{cursor:pointer;color:#2b5d8a}
.warn{background:#fff4e5;border:1px solid #f0c36d;padding:8px 12px;border-radius:6px}
code{font-family:ui-monospace,Menlo,monospace;font-size:13px}
)";

// `work`: the sweep counted (docs/manifest.md "Work counters"), so a column of counts per receiver.
std::string rowCells(const Row& r, bool work) {
  std::string passes;
  for (const auto& p : r.passes) passes += fmt::format("{}{} {:.2f}", passes.empty() ? "" : ", ", p.name, p.medianMs);
  const std::string interval =
      r.total.n > 0 ? fmt::format("{:.3f}&ndash;{:.3f}", r.total.ciLowMs, r.total.ciHighMs) : std::string("&ndash;");
  return fmt::format(
             "<td>{}</td><td class=\"num\">{:.3f}</td><td class=\"num\">{}</td><td class=\"num\">{:.5f}</td>"
             "<td class=\"num\">{:.5f}</td><td class=\"num\">{:.4f}</td><td><code>{}</code></td>",
             esc(r.variant), r.totalMs, interval, r.metrics.rmse, r.metrics.mae, r.metrics.maxAbsError, esc(passes)) +
         (work ? fmt::format("<td><code>{}</code></td>", r.work ? esc(rt::workFields(*r.work)) : "&ndash;") : "");
}

// The rows' heading; `interval`: the label with the coverage the runs give (pareto.h).
std::string rowHead(const std::string& interval, bool work) {
  return fmt::format(
             "<th>variant</th><th>total ms</th><th>{}</th><th>RMSE</th><th>MAE</th><th>max error</th>"
             "<th>passes (median ms)</th>",
             esc(interval)) +
         (work ? "<th>shade work per receiver (exact counts)</th>" : "");
}

// The rank cell of a frontier row: "3", or "3 =" when it is tied on time (docs/sweep.md "Ties").
std::string rankCell(size_t rank, const FrontierMark& mark) {
  return mark.membership == Membership::Tied
             ? fmt::format(
                   "{} <span class=\"tie\" title=\"tied on time: its interval overlaps a frontier row that "
                   "may beat it\">=</span>",
                   rank)
             : fmt::format("{}", rank);
}

}  // namespace

std::string reportHtml(const Results& res, const PlotFiles& plots) {
  const auto front = frontiers(res.rows);
  const std::vector<FrontierMark> marks = frontierMarks(res.rows);
  const std::string interval = intervalLabel(res.rows);  // with the coverage the runs give
  const bool counted = std::any_of(res.rows.begin(), res.rows.end(), [](const Row& r) { return r.work.has_value(); });
  std::map<size_t, std::vector<size_t>> byCase;
  for (size_t i = 0; i < res.rows.size(); ++i) byCase[res.rows[i].caseIndex].push_back(i);
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += fmt::format("<title>shadowc sweep: {}</title>\n<style>{}</style>\n</head>\n<body>\n<main>\n", esc(res.sweep),
                   kStyle);
  h += fmt::format("<h1>What accuracy costs in time: <code>{}</code></h1>\n", esc(res.sweep));
  const std::string device = res.rows.empty() ? "" : res.rows.front().device;
  h += fmt::format(
      "<p class=\"sub\">shadowc sweep{} &middot; {} &middot; time = median frame total after warm-up, with the {} "
      "of the "
      "median; error = RMSE of the visibility against the Embree ray-traced reference over the geometry pixels. The "
      "frontier holds the variants nothing else beats for certain on both; = marks a row tied on time with one that "
      "may beat it.</p>\n",
      res.shard == "0/1" ? "" : " (" + esc(res.shard) + ")", esc(device), esc(interval));
  h += "<div class=\"stats\">";
  h += fmt::format("<div class=\"stat\"><b>{}</b>rows</div><div class=\"stat\"><b>{}</b>cases</div>", res.rows.size(),
                   byCase.size());
  h += fmt::format("<div class=\"stat\"><b>{}</b>ran now</div><div class=\"stat\"><b>{}</b>from the cache</div>",
                   res.stats.ran, res.stats.cached);
  h += fmt::format("<div class=\"stat\"><b>{}</b>variants skipped</div></div>\n", res.skipped.size());
  if (!plots.warning.empty()) h += fmt::format("<p class=\"warn\">{}</p>\n", esc(plots.warning));

  for (const auto& [c, members] : byCase) {
    const Row& first = res.rows[members.front()];
    const auto it = front.find(c);
    const std::vector<size_t> frontier = it == front.end() ? std::vector<size_t>{} : it->second;
    const std::set<size_t> onFrontier(frontier.begin(), frontier.end());
    h += fmt::format("<section id=\"case{}\">\n<h2>{}</h2>\n", c, esc(first.caseLabel));
    h += fmt::format(
        "<p class=\"sub\">scene <code>{}</code>, screen {}&times;{}, shadow map {}&sup2;, reference {}&times;{} "
        "light samples, median of {} runs after {} warm-up &middot; {} of {} rows on the frontier</p>\n",
        esc(first.scene), first.screen, first.screen, first.map, first.referenceSamples, first.referenceSamples,
        first.runs, first.warmup, frontier.size(), members.size());
    if (const auto p = plots.svg.find(c); p != plots.svg.end())
      h += fmt::format("<img class=\"plot\" src=\"{}\" alt=\"time vs RMSE, {}\" width=\"760\" height=\"480\">\n",
                       esc(p->second), esc(first.caseLabel));
    h += fmt::format("<h3>Frontier</h3>\n<table class=\"frontier\" id=\"frontier-case{}\">\n<tr><th>#</th>{}</tr>\n", c,
                     rowHead(interval, counted));
    size_t rank = 0;
    for (size_t i : frontier)
      h += fmt::format("<tr class=\"frontier-row\" data-case=\"{}\" data-key=\"{}\"><td>{}</td>{}</tr>\n",
                       esc(first.caseLabel), res.rows[i].key, rankCell(++rank, marks[i]),
                       rowCells(res.rows[i], counted));
    h += "</table>\n<div class=\"cards\">\n";
    rank = 0;
    for (size_t i : frontier) {
      const Row& r = res.rows[i];
      h += fmt::format("<div class=\"card\"><h3>{}. {}</h3>\n<div class=\"imgs\">", ++rank, esc(r.variant));
      for (const auto& [label, src] : {std::pair<const char*, const std::string&>{"result", r.resultImage},
                                       {"reference", r.referenceImage},
                                       {"error", r.errorImage}})
        if (!src.empty())
          h += fmt::format("<figure><img src=\"{}\" alt=\"{} {}\"><figcaption>{}</figcaption></figure>", esc(src),
                           label, esc(r.variant), label);
      h += fmt::format(
          "</div>\n<details><summary>filter description</summary><pre>{}</pre></details>\n"
          "<details><summary>normalized (every default explicit)</summary><pre>{}</pre></details>\n"
          "<div class=\"sub\"><code>{}</code></div></div>\n",
          esc(r.filterText), esc(r.normalizedText), esc(r.contentHash));
    }
    h += "</div>\n";
    h += fmt::format(
        "<details><summary>all {} rows of this case</summary>\n<table class=\"all\">\n<tr><th></th>{}</tr>\n",
        members.size(), rowHead(interval, counted));
    for (size_t i : members)
      h +=
          fmt::format("<tr><td>{}</td>{}</tr>\n", onFrontier.count(i) ? "&#9733;" : "", rowCells(res.rows[i], counted));
    h += "</table>\n</details>\n</section>\n";
  }
  if (const std::vector<ShaderPair> pairs = shaderPairs(res.rows); !pairs.empty()) {
    h += "<h2>Specialized vs generic</h2>\n<p>The same variant compiled by <code>shadowc compile</code> and by "
         "<code>shadowc compile --generic</code> (options as uniforms, dynamic loops), on the same case. Ratio = "
         "specialized &divide; generic frame time: below 1, specialization buys time.</p>\n";
    h += "<table class=\"ratios\">\n<tr><th>case</th><th>variant</th><th>specialized ms</th><th>generic "
         "ms</th><th>ratio</th><th>rmse specialized</th><th>rmse generic</th></tr>\n";
    for (const ShaderPair& p : pairs) {
      const Row& sp = res.rows[p.specialized];
      const Row& g = res.rows[p.generic];
      h += fmt::format(
          "<tr class=\"ratio-row\"><td>{}</td><td>{}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.5f}</td>"
          "<td>{:.5f}</td></tr>\n",
          esc(sp.caseLabel), esc(sp.variant), sp.totalMs, g.totalMs, p.ratio, sp.metrics.rmse, g.metrics.rmse);
    }
    h += "</table>\n";
  }
  if (!res.skipped.empty()) {
    std::map<std::string, size_t> byCode;
    for (const auto& s : res.skipped) ++byCode[s.code];
    std::string counts;
    for (const auto& [code, n] : byCode)
      counts += fmt::format("{}{} &times; {}", counts.empty() ? "" : ", ", n, esc(code));
    h += fmt::format(
        "<h2>Skipped variants</h2>\n<p>{}: rejected by the checker (its diagnostic code) or the run.</p>\n", counts);
    h += "<table class=\"skipped\">\n<tr><th>variant</th><th>code</th><th>message</th></tr>\n";
    for (const auto& s : res.skipped)
      h += fmt::format("<tr><td>{}</td><td><code>{}</code></td><td><code>{}</code></td></tr>\n", esc(s.variant),
                       esc(s.code), esc(s.message));
    h += "</table>\n";
  }
  h += "<p class=\"sub\">Data: <code>results.csv</code>, <code>results.json</code>; plots and their gnuplot scripts in "
       "<code>plots/</code>. Made by <code>shadowc sweep</code> (docs/sweep.md).</p>\n</main>\n</body>\n</html>\n";
  return h;
}

}  // namespace shadowc::sweep
