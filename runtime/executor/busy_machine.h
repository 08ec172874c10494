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

// The thresholds: other processes used over a quarter of the machine, or the runs' coefficient
// of variation is over 20% (hyperfine warns on a statistical outlier; a coefficient is what our
// few runs support).
inline constexpr double kBusyOtherShare = 0.25;
inline constexpr double kBusyCv = 0.20;

// The warning's text, or empty when neither threshold is passed.
std::string busyWarning(const TimingStats& stats, std::optional<double> otherShare);

}  // namespace shadowc::rt
