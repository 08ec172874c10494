// Timed runs: which clock measures them, the host's clock around every submission, and the check
// that rejects a reading the host's clock says cannot be true (docs/runtime.md "Timing method").
// No Vulkan here: the executor offers its runs through `TimedDevice`, the tests plant readings.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/executor/timing_stats.h"

namespace shadowc::rt {

// The clock a result is measured with. Device: the device's timestamps around each pass, one
// submission per run. Host: the host's steady clock around one submission per pass — what a CPU
// device gets, whose timestamps are taken by threads that race the work (docs/runtime.md).
enum class TimingClock { Device, Host };
// "device timestamps" / "host clock": what validate, sweep and the benchmarks print.
std::string_view toString(TimingClock clock);

// What a caller asks for; Auto = Host on a CPU device (VkPhysicalDeviceType CPU), else Device.
enum class ClockChoice { Auto, Device, Host };
TimingClock resolveClock(ClockChoice choice, bool cpuDevice);

// Milliseconds on a monotonic clock. steadyHostClock() reads std::chrono::steady_clock; a test
// plants its own readings.
using HostClock = std::function<double()>;
HostClock steadyHostClock();

// One timed run as measured. passMs and totalMs are on the run's clock; hostMs is the host's
// time from the first submission to the last fence of the run.
struct RunReading {
  std::vector<double> passMs;
  double totalMs = 0;
  double hostMs = 0;
};

// What makes a device reading impossible (docs/runtime.md "Rejected runs"): the stamps lie inside
// [submit, fence], so totalMs <= hostMs, up to two timestamp ticks and a 1% error in the nominal
// timestampPeriod; and the work takes at least hostMs - submitOverheadMs (the host time of an
// empty submission), so stamps that cover under half of that did not bracket it.
struct Plausibility {
  double submitOverheadMs = 0;
  double tickMs = 0;
};
enum class Verdict { Plausible, TooShort, TooLong, NotADuration };
Verdict judge(const RunReading& reading, TimingClock clock, const Plausibility& bounds);
std::string_view toString(Verdict verdict);

struct PassTiming {
  std::string name;
  std::string kind;
  double medianMs = 0;
  double minMs = 0;
};

struct RejectedRun {
  double totalMs = 0, hostMs = 0;
  Verdict verdict = Verdict::Plausible;
};

// How many timed runs: a fixed count, or "auto": at least `minRuns`, then more until the median's
// 95% interval is within `targetHalfWidth` of the median on both sides (TimingStats::
// relativeWiderSide), or the runs have taken `capMs` on the
// host clock, or `maxRuns` were accepted (docs/runtime.md "Timing statistics"). Implicit from an
// int, which is a fixed count.
struct RunCount {
  int runs = 0;  // the fixed count; unused when automatic
  bool automatic = false;
  int minRuns = 6;  // the fewest with a 95% interval of the median from order statistics (timing_stats.h)
  int maxRuns = 200;
  double targetHalfWidth = 0.05;
  double capMs = 3000;
  RunCount() = default;
  RunCount(int fixed) : runs(fixed) {}  // NOLINT(google-explicit-constructor): a count is a count
  static RunCount untilPrecise() {
    RunCount c;
    c.automatic = true;
    return c;
  }
  bool any() const { return automatic || runs > 0; }
};
// "auto" or a positive count ("10"); anything else throws std::invalid_argument naming `option`.
RunCount parseRunCount(std::string_view text, std::string_view option = "--runs");
// "auto" or the count: what a command line, a plan's comment or a sweep key says.
std::string toString(const RunCount& count);

// Every number here is over the accepted runs only; a rejected run is counted, never used.
struct TimingResult {
  std::vector<PassTiming> passes;   // manifest order
  double totalMs = 0;               // median over accepted runs of the run's total on `clock`
  std::vector<double> runTotalsMs;  // each accepted run's total, in run order (interleaved ratios pair them)
  std::vector<double> runHostMs;    // each accepted run's host submit-to-fence time, paired with runTotalsMs
  int warmup = 0, runs = 0;         // runs = accepted timed runs
  TimingClock clock = TimingClock::Device;
  std::vector<RejectedRun> rejected;    // the implausible readings, in run order
  double submitOverheadMs = 0;          // host time of an empty submission (median), the lower bound's allowance
  TimingStats stats;                    // of runTotalsMs: min, median, p90, the median's interval, spread
  bool stoppedAtCap = false;            // auto run count: the time cap ended the runs before the interval was narrow
  std::optional<double> otherCpuShare;  // other processes' share of the CPUs during the runs (busy_machine.h)
};

// Fills `result.stats` from its runTotalsMs (what timeRuns and timeInterleaved do last).
void summarize(TimingResult& result);

// The timings' median: the middle value, or the mean of the middle two; 0 when empty. The
// benchmarks use this one too.
double median(std::vector<double> v);

// What a timed run needs from a device: the executor implements it with Vulkan.
class TimedDevice {
 public:
  virtual ~TimedDevice() = default;
  virtual size_t passCount() const = 0;
  virtual void submitRun() = 0;              // every pass in one submission, waits on its fence
  virtual void submitPass(size_t pass) = 0;  // one pass alone, waits on its fence
  virtual void submitEmpty() = 0;            // an empty submission, waits on its fence
  // Per-pass and total milliseconds from the device timestamps of the last submitRun().
  virtual RunReading readTimestamps() = 0;
  virtual double timestampTickMs() const = 0;
};

// One run on `clock`, the host clock read around it (and around each pass on the host clock).
RunReading measureRun(TimedDevice& device, TimingClock clock, const HostClock& now);

// `warmup` untimed runs, the empty-submission overhead (median of 5), then timed runs until
// `runs` are accepted or 2·runs + 2 were tried (auto: see RunCount, with the cap bounding the
// attempts). Throws std::runtime_error when none was accepted: a result with no measurement in
// it is not a time. `names` and `kinds` label the passes.
TimingResult timeRuns(TimedDevice& device, TimingClock clock, const HostClock& now, int warmup, const RunCount& runs,
                      const std::vector<std::string>& names, const std::vector<std::string>& kinds);

// "host clock, 0 rejected": the words validate and the benchmarks print after the run count.
std::string clockSummary(const TimingResult& timing);
// "median 1.234 ms [1.200, 1.260] (97.8 %), min 1.190, p90 1.300, cv 3%": one line of a total's statistics.
std::string statsSummary(const TimingStats& stats);

}  // namespace shadowc::rt
