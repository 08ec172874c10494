#include "runtime/executor/run_timing.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace shadowc::rt {

std::string_view toString(TimingClock clock) { return clock == TimingClock::Host ? "host clock" : "device timestamps"; }

TimingClock resolveClock(ClockChoice choice, bool cpuDevice) {
  switch (choice) {
    case ClockChoice::Device:
      return TimingClock::Device;
    case ClockChoice::Host:
      return TimingClock::Host;
    case ClockChoice::Auto:
      break;
  }
  return cpuDevice ? TimingClock::Host : TimingClock::Device;
}

HostClock steadyHostClock() {
  return [] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
  };
}

std::string_view toString(Verdict verdict) {
  switch (verdict) {
    case Verdict::Plausible:
      return "plausible";
    case Verdict::TooShort:
      return "shorter than half the host's time";
    case Verdict::TooLong:
      return "longer than the host's time";
    case Verdict::NotADuration:
      return "not a duration";
  }
  return "?";
}

Verdict judge(const RunReading& r, TimingClock clock, const Plausibility& b) {
  const auto duration = [](double ms) { return std::isfinite(ms) && ms >= 0; };
  if (!duration(r.totalMs) || !duration(r.hostMs) || !std::all_of(r.passMs.begin(), r.passMs.end(), duration))
    return Verdict::NotADuration;
  if (clock == TimingClock::Host)  // the passes are sub-intervals of the run, on the same clock
    return r.totalMs <= r.hostMs ? Verdict::Plausible : Verdict::TooLong;
  if (r.totalMs > 1.01 * r.hostMs + 2 * b.tickMs) return Verdict::TooLong;
  if (r.totalMs < 0.5 * (r.hostMs - b.submitOverheadMs)) return Verdict::TooShort;
  return Verdict::Plausible;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

RunReading measureRun(TimedDevice& device, TimingClock clock, const HostClock& now) {
  if (clock == TimingClock::Device) {
    const double start = now();
    device.submitRun();
    const double end = now();
    RunReading r = device.readTimestamps();
    r.hostMs = end - start;
    return r;
  }
  // One submission per pass: each pass's time is its own submit-to-fence, so it includes one
  // submission's overhead (TimingResult::submitOverheadMs says how much).
  RunReading r;
  const double start = now();
  for (size_t i = 0; i < device.passCount(); ++i) {
    const double before = now();
    device.submitPass(i);
    r.passMs.push_back(now() - before);
    r.totalMs += r.passMs.back();
  }
  r.hostMs = now() - start;
  return r;
}

namespace {

double submitOverhead(TimedDevice& device, const HostClock& now) {
  std::vector<double> ms;
  for (int i = 0; i < 5; ++i) {
    const double start = now();
    device.submitEmpty();
    ms.push_back(now() - start);
  }
  return median(ms);
}

}  // namespace

RunCount parseRunCount(std::string_view text, std::string_view option) {
  if (text == "auto") return RunCount::untilPrecise();
  int n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n < 1 || n > 100000)
    throw std::invalid_argument(fmt::format("{} must be a positive count or 'auto', not '{}'", option, text));
  return RunCount(n);
}

std::string toString(const RunCount& count) {
  return count.automatic ? std::string("auto") : std::to_string(count.runs);
}

void summarize(TimingResult& result) { result.stats = timingStats(result.runTotalsMs); }

namespace {

// Whether another timed run is wanted, given the accepted totals so far and the host time spent.
bool wantsMore(const RunCount& count, const std::vector<double>& totals, double spentMs, bool& stoppedAtCap) {
  const int n = static_cast<int>(totals.size());
  if (!count.automatic) return n < std::max(1, count.runs);
  if (n < count.minRuns) return true;  // no interval yet; the cap bounds only what comes after
  if (n >= count.maxRuns) return false;
  if (timingStats(totals).relativeWiderSide() <= count.targetHalfWidth) return false;  // both sides within
  stoppedAtCap = spentMs >= count.capMs;
  return !stoppedAtCap;
}

}  // namespace

TimingResult timeRuns(TimedDevice& device, TimingClock clock, const HostClock& now, int warmup, const RunCount& runs,
                      const std::vector<std::string>& names, const std::vector<std::string>& kinds) {
  TimingResult result;
  result.clock = clock;
  result.warmup = std::max(0, warmup);
  for (int i = 0; i < result.warmup; ++i) device.submitRun();
  const size_t n = device.passCount();
  const int most = runs.automatic ? std::max(runs.minRuns, runs.maxRuns) : std::max(1, runs.runs);
  if (n == 0) {  // nothing to time: the runs still happen, no reading exists
    const int count = runs.automatic ? runs.minRuns : most;
    for (int i = 0; i < count; ++i) device.submitRun();
    result.runs = count;
    return result;
  }
  result.submitOverheadMs = submitOverhead(device, now);
  const Plausibility bounds{result.submitOverheadMs, device.timestampTickMs()};
  std::vector<std::vector<double>> perPass(n);
  const double start = now();
  for (int attempt = 0; attempt < 2 * most + 2; ++attempt) {
    if (!wantsMore(runs, result.runTotalsMs, now() - start, result.stoppedAtCap)) break;
    const RunReading r = measureRun(device, clock, now);
    const Verdict verdict = judge(r, clock, bounds);
    if (verdict != Verdict::Plausible) {
      result.rejected.push_back({r.totalMs, r.hostMs, verdict});
      continue;
    }
    for (size_t i = 0; i < n; ++i) perPass[i].push_back(r.passMs.at(i));
    result.runTotalsMs.push_back(r.totalMs);
    result.runHostMs.push_back(r.hostMs);
    ++result.runs;
  }
  if (result.runs == 0) {
    const RejectedRun& last = result.rejected.back();
    throw std::runtime_error(
        fmt::format("every one of {} timed runs was rejected: the last measured {:.3f} ms on the {} against {:.3f} ms "
                    "on the host clock ({})",
                    result.rejected.size(), last.totalMs, toString(clock), last.hostMs, toString(last.verdict)));
  }
  for (size_t i = 0; i < n; ++i)
    result.passes.push_back({i < names.size() ? names[i] : "", i < kinds.size() ? kinds[i] : "", median(perPass[i]),
                             *std::min_element(perPass[i].begin(), perPass[i].end())});
  result.totalMs = median(result.runTotalsMs);
  summarize(result);
  return result;
}

std::string clockSummary(const TimingResult& timing) {
  return fmt::format("{}, {} rejected", toString(timing.clock), timing.rejected.size());
}

std::string statsSummary(const TimingStats& s) {
  return fmt::format("median {:.3f} ms [{:.3f}, {:.3f}] ({}), min {:.3f}, p90 {:.3f}, cv {:.0f}%", s.medianMs,
                     s.ciLowMs, s.ciHighMs, coverageText(s.ciCoverage), s.minMs, s.p90Ms, 100 * s.cv);
}

}  // namespace shadowc::rt
