#include "sweep/plot.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <set>
#include <vector>

#include "runtime/images/atomic_file.h"
#include "sweep/pareto.h"

extern char** environ;

namespace shadowc::sweep {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

// gnuplot's single-quoted strings have no escapes; a path with a quote is refused instead.
std::string gpPath(const std::filesystem::path& p) {
  const std::string s = p.string();
  if (s.find('\'') != std::string::npos) throw std::runtime_error(s + ": a plot path may not contain a quote");
  return "'" + s + "'";
}

// Runs gnuplot on a script, its messages to `log`. Returns "" or why it failed.
std::string runGnuplot(const std::filesystem::path& script, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::string prog = "gnuplot", arg = script.string();
  char* argv[] = {prog.data(), arg.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return "gnuplot not found (install gnuplot-nox: scripts/install-deps.sh); no plots";
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return fmt::format("gnuplot failed (see {}); no plots", log.string());
  return "";
}

}  // namespace

PlotFiles writePlots(const std::filesystem::path& dir, const Results& res) {
  PlotFiles files;
  const std::filesystem::path plots = std::filesystem::absolute(dir / "plots");
  const auto front = frontiers(res.rows);
  const std::vector<FrontierMark> marks = frontierMarks(res.rows);
  const std::set<size_t> predictedCase = predictedCases(res.rows);
  std::map<size_t, std::vector<size_t>> byCase;
  for (size_t i = 0; i < res.rows.size(); ++i) byCase[res.rows[i].caseIndex].push_back(i);
  for (const auto& [c, members] : byCase) {
    const std::string stem = fmt::format("case{}", c);
    std::string all = "# total_ms rmse ci_low_ms ci_high_ms variant\n", fr = "# total_ms rmse rank variant\n",
                line = "# total_ms rmse variant\n";
    double lo = 1e300, hi = 0, top = 0, low = 1e300;
    // Ranked by a cost profile, the axis is the predicted frame; a row it could not price has no
    // place on that axis (two devices' times).
    const bool predicted = predictedCase.count(c) > 0;
    for (size_t i : members) {
      const Row& r = res.rows[i];
      if (!eligible(r) || (predicted && !r.predictedMs)) continue;
      all += fmt::format("{:.6g} {:.6g} {:.6g} {:.6g} {}\n", rankedMs(r), r.metrics.rmse, timeLowMs(r), timeHighMs(r),
                         quoted(r.variant));
      lo = std::min(lo, timeLowMs(r));
      hi = std::max(hi, timeHighMs(r));
      top = std::max(top, r.metrics.rmse);
      if (r.metrics.rmse > 0) low = std::min(low, r.metrics.rmse);
    }
    // Log axes when the values span more than a decade or so; room on the right and above
    // for the labels.
    const bool logX = hi > 8 * lo, logY = low < 1e300 && top > 10 * low;
    const std::string ranges = (logX ? fmt::format("set logscale x\nset xrange [{:.6g}:{:.6g}]\n", lo / 1.6, hi * 2.5)
                                     : fmt::format("set xrange [0:{:.6g}]\n", hi * 1.2)) +
                               (logY ? fmt::format("set logscale y\nset yrange [{:.6g}:{:.6g}]\n", low / 1.6, top * 2)
                                     : fmt::format("set yrange [0:{:.6g}]\n", top > 0 ? top * 1.2 : 1.0));
    // Frontier points are labelled with their rank in the frontier table: names overlap when
    // points are close, numbers rarely do. A tied row's label ends in "=" as in the table.
    // The line runs through the frontier rows by median time, monotone in RMSE: a tied row whose
    // RMSE is not below the last one on the line (its interval overlaps a faster row's) is drawn
    // and numbered, but the line does not climb to it.
    if (const auto it = front.find(c); it != front.end()) {
      double lineRmse = 1e300;
      for (size_t k = 0; k < it->second.size(); ++k) {
        const Row& r = res.rows[it->second[k]];
        const bool tied = marks[it->second[k]].membership == Membership::Tied;
        fr += fmt::format("{:.6g} {:.6g} \"{}{}\" {}\n", rankedMs(r), r.metrics.rmse, k + 1, tied ? "=" : "",
                          quoted(r.variant));
        if (r.metrics.rmse >= lineRmse) continue;
        lineRmse = r.metrics.rmse;
        line += fmt::format("{:.6g} {:.6g} {}\n", rankedMs(r), r.metrics.rmse, quoted(r.variant));
      }
    }
    rt::writeFileAtomically(plots / (stem + ".dat"), all);
    rt::writeFileAtomically(plots / (stem + "_frontier.dat"), fr);
    rt::writeFileAtomically(plots / (stem + "_line.dat"), line);
    const std::filesystem::path svgTmp = plots / (stem + ".svg.tmp"), pngTmp = plots / (stem + ".png.tmp");
    const std::string plot = fmt::format(
        "plot {0} using 1:2:3:4 with xerrorbars pt 7 ps 0.9 lc rgb '#8c96a3' title 'variants ({3} of the "
        "median time)', \\\n"
        "     {2} using 1:2 with lines lw 2 lc rgb '#c8102e' title 'Pareto frontier (numbered as in the table; "
        "= tied)', \\\n"
        "     {1} using 1:2 with points pt 7 ps 1.3 lc rgb '#c8102e' notitle, \\\n"
        "     {1} using 1:2:3 with labels left offset 0.6,0.7 font ',11' tc rgb '#5a0a16' noenhanced notitle\n",
        gpPath(plots / (stem + ".dat")), gpPath(plots / (stem + "_frontier.dat")), gpPath(plots / (stem + "_line.dat")),
        intervalLabel(res.rows));
    const std::string label = res.rows[members.front()].caseLabel;
    std::string gp = fmt::format(
        "# {} — time vs RMSE, frontier in red (written by shadowc sweep)\n"
        "set title {} noenhanced\n"
        "set xlabel '{}{})'\n"
        "set ylabel 'RMSE against the Embree reference{}'\n"
        "set grid lc rgb '#dddddd'\nset key top right box opaque\nset border lc rgb '#444444'\n{}"
        "set terminal svg size 760,480 dynamic noenhanced font 'sans,11' background rgb 'white'\nset output {}\n{}"
        "set terminal pngcairo size 760,480 noenhanced font 'sans,10' background rgb 'white'\nset output {}\n{}"
        "unset output\n",
        label, quoted(label),
        predicted ? "frame time predicted by the cost profile (ms" : "frame time, median of the timed runs (ms",
        logX ? ", log scale" : "", logY ? " (log scale)" : "", ranges, gpPath(svgTmp), plot, gpPath(pngTmp), plot);
    rt::writeFileAtomically(plots / (stem + ".gp"), gp);
    if (lo > hi) continue;  // nothing finite to draw
    if (const std::string err = runGnuplot(plots / (stem + ".gp"), plots / "gnuplot.log"); !err.empty()) {
      files.warning = err;
      return files;
    }
    std::filesystem::rename(svgTmp, plots / (stem + ".svg"));
    std::filesystem::rename(pngTmp, plots / (stem + ".png"));
    files.svg[c] = "plots/" + stem + ".svg";
    files.png[c] = "plots/" + stem + ".png";
  }
  return files;
}

}  // namespace shadowc::sweep
