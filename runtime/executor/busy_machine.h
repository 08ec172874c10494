// Whether the machine was busy while a filter was timed: the share of all CPU time that other
// processes used, and the spread of the runs (docs/runtime.md "Busy machine"). A warning, never
// a correction: a busy machine's times are reported, flagged, and their interval is wider.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "runtime/executor/timing_stats.h"

namespace shadowc::rt {

// Jiffies from /proc/stat's "cpu" line (every state but idle and iowait is busy) and this
// process's own user + system jiffies from /proc/self/stat (lavapipe's threads are ours).
struct CpuSample {
  uint64_t busy = 0, total = 0, self = 0;
};

// The parse of the two files' texts; nullopt when either is not in the kernel's format.
std::optional<CpuSample> parseCpuSample(std::string_view procStat, std::string_view procSelfStat);
// Reads /proc; nullopt where there is no /proc (the busy check then rests on the spread alone).
std::optional<CpuSample> sampleCpu();

// (Δbusy - Δself) / Δtotal, clamped to [0, 1]: the share of the whole machine other processes used
// between the samples. 0 when no time passed.
double otherCpuShare(const CpuSample& before, const CpuSample& after);

// The shortest window the share is read over. /proc/stat counts in jiffies (10 ms at the usual
// USER_HZ of 100), so a window of t ms on c cores holds t / 10 * c of them: 20 ms on 2 cores is 4,
// and the share moves in 25 % steps against a 25 % threshold; 200 ms is 40, steps of 2.5 %.
inline constexpr double kBusyWindowMs = 200;

// A window over which other processes' share is read: opened before the timed runs, closed
// after them. When the runs took less than kBusyWindowMs the window reaches back to the newest
// sample of this process taken at least that long before the close and at most kBusyReachMs
// (an earlier window's opening: a sweep's rows time one after another), and failing that the
// close waits out the rest. So a share is never read over less than kBusyWindowMs.
inline constexpr double kBusyReachMs = 2000;
struct CpuWindow {
  std::optional<CpuSample> before;
  double openedMs = 0;  // on the steady clock
};
CpuWindow openCpuWindow();
// The share over the window, and how long the window was in `windowMs` when given; nullopt
// without /proc.
std::optional<double> closeCpuWindow(const CpuWindow& window, double* windowMs = nullptr);

// The thresholds: other processes used over a quarter of the machine, or the runs' coefficient
// of variation is over 20% (hyperfine warns on a statistical outlier; a coefficient is what our
// few runs support).
inline constexpr double kBusyOtherShare = 0.25;
inline constexpr double kBusyCv = 0.20;

// The warning's text, or empty when neither threshold is passed.
std::string busyWarning(const TimingStats& stats, std::optional<double> otherShare);

}  // namespace shadowc::rt
