#include "runtime/executor/busy_machine.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

namespace shadowc::rt {

namespace {

std::string slurp(const char* path) {
  std::ifstream in(path);
  return in ? std::string(std::istreambuf_iterator<char>(in), {}) : std::string();
}

}  // namespace

std::optional<CpuSample> parseCpuSample(std::string_view procStat, std::string_view procSelfStat) {
  // "cpu  user nice system idle iowait irq softirq steal ..."
  std::istringstream stat{std::string(procStat.substr(0, procStat.find('\n')))};
  std::string label;
  stat >> label;
  if (label != "cpu") return std::nullopt;
  std::vector<uint64_t> fields;
  for (uint64_t v = 0; stat >> v;) fields.push_back(v);
  if (fields.size() < 5) return std::nullopt;
  CpuSample s;
  for (size_t i = 0; i < fields.size() && i < 8; ++i) {  // guest time is already in user
    s.total += fields[i];
    if (i != 3 && i != 4) s.busy += fields[i];
  }
  // "pid (comm) state ppid ..." — comm may hold spaces and parentheses, so fields count from the
  // last ')': utime and stime are fields 14 and 15, the 12th and 13th after it.
  const size_t close = procSelfStat.rfind(')');
  if (close == std::string_view::npos) return std::nullopt;
  std::istringstream self{std::string(procSelfStat.substr(close + 1))};
  std::vector<std::string> rest{std::istream_iterator<std::string>(self), {}};
  if (rest.size() < 13) return std::nullopt;
  try {
    s.self = std::stoull(rest[11]) + std::stoull(rest[12]);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return s;
}

std::optional<CpuSample> sampleCpu() { return parseCpuSample(slurp("/proc/stat"), slurp("/proc/self/stat")); }

namespace {

double steadyMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Recent samples of this process, oldest first, to reach back to (closeCpuWindow).
struct Stamped {
  CpuSample sample;
  double ms;
};
std::mutex historyMutex;
std::deque<Stamped> history;

void remember(const std::optional<CpuSample>& s, double ms) {
  if (!s) return;
  const std::lock_guard lock(historyMutex);
  history.push_back({*s, ms});
  while (!history.empty() && history.front().ms < ms - kBusyReachMs) history.pop_front();
}

}  // namespace

CpuWindow openCpuWindow() {
  CpuWindow w{sampleCpu(), steadyMs()};
  remember(w.before, w.openedMs);
  return w;
}

std::optional<double> closeCpuWindow(const CpuWindow& window, double* windowMs) {
  std::optional<CpuSample> before = window.before;
  double from = window.openedMs, now = steadyMs();
  if (now - from < kBusyWindowMs) {
    const std::lock_guard lock(historyMutex);
    for (auto it = history.rbegin(); it != history.rend(); ++it)
      if (now - it->ms >= kBusyWindowMs && now - it->ms <= kBusyReachMs) {
        before = it->sample;
        from = it->ms;
        break;
      }
  }
  if (now - from < kBusyWindowMs) {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(kBusyWindowMs - (now - from)));
    now = steadyMs();
  }
  const std::optional<CpuSample> after = sampleCpu();
  remember(after, now);
  if (windowMs) *windowMs = now - from;
  if (!before || !after) return std::nullopt;
  return otherCpuShare(*before, *after);
}

double otherCpuShare(const CpuSample& before, const CpuSample& after) {
  if (after.total <= before.total) return 0;
  const double total = double(after.total - before.total);
  const double busy = after.busy >= before.busy ? double(after.busy - before.busy) : 0;
  const double self = after.self >= before.self ? double(after.self - before.self) : 0;
  return std::clamp((busy - self) / total, 0.0, 1.0);
}

std::string busyWarning(const TimingStats& stats, std::optional<double> otherShare) {
  std::vector<std::string> why;
  if (otherShare && *otherShare > kBusyOtherShare)
    why.push_back(fmt::format("other processes used {:.0f}% of the CPUs", 100 * *otherShare));
  if (stats.n > 1 && stats.cv > kBusyCv)
    why.push_back(fmt::format("the runs vary by {:.0f}% (coefficient of variation)", 100 * stats.cv));
  if (why.empty()) return {};
  std::string text = "the machine was busy while timing: " + why.front();
  if (why.size() > 1) text += " and " + why.back();
  return text + "; the times are less certain (see the interval): rerun on a quiet machine for tighter ones";
}

}  // namespace shadowc::rt
