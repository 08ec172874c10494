// The busy check on planted /proc texts and planted statistics: other processes' share of the
// CPUs is Δbusy − Δself over Δtotal (docs/runtime.md "Busy machine"), and the warning appears
// exactly when a threshold is passed; and the window the share is read over is never shorter than
// kBusyWindowMs (jiffies are 10 ms: a shorter window moves in steps as large as the threshold),
// reaching back to an earlier window's sample when there is one, waiting when there is not.
#include "runtime/executor/busy_machine.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace shadowc::test {
namespace {

// /proc/stat's first line: user nice system idle iowait irq softirq steal guest guest_nice.
std::string stat(uint64_t user, uint64_t idle) {
  return fmt::format("cpu  {} 0 0 {} 0 0 0 0 0 0\ncpu0 1 2 3\n", user, idle);
}
// /proc/self/stat with a command name holding a space and a parenthesis; utime, stime are 14, 15.
std::string self(uint64_t utime) {
  return fmt::format("4242 (shadowc (x) y) R 1 2 3 4 5 6 7 8 9 10 {} 0 0 0 20 0 1 0\n", utime);
}

TEST(BusyMachine, ParsesTheKernelsFormats) {
  const std::optional<rt::CpuSample> s = rt::parseCpuSample(stat(300, 700), self(120));
  ASSERT_TRUE(s);
  EXPECT_EQ(s->busy, 300u);
  EXPECT_EQ(s->total, 1000u);
  EXPECT_EQ(s->self, 120u);
  EXPECT_FALSE(rt::parseCpuSample("intr 1 2 3\n", self(1)));
  EXPECT_FALSE(rt::parseCpuSample(stat(1, 1), "4242 no parenthesis"));
}

TEST(BusyMachine, OtherProcessesShareIsBusyMinusOursOverAll) {
  const rt::CpuSample before = *rt::parseCpuSample(stat(300, 700), self(100));
  // 1000 more jiffies, 600 of them busy, 200 of those ours: others used 400 / 1000.
  const rt::CpuSample after = *rt::parseCpuSample(stat(900, 1100), self(300));
  EXPECT_DOUBLE_EQ(rt::otherCpuShare(before, after), 0.4);
  EXPECT_EQ(rt::otherCpuShare(before, before), 0.0) << "no time passed";
}

TEST(BusyMachine, WarnsPastEitherThresholdAndOnlyThen) {
  rt::TimingStats quiet;
  quiet.n = 10;
  quiet.cv = rt::kBusyCv / 2;
  EXPECT_EQ(rt::busyWarning(quiet, rt::kBusyOtherShare / 2), "");
  EXPECT_EQ(rt::busyWarning(quiet, std::nullopt), "");
  EXPECT_NE(rt::busyWarning(quiet, rt::kBusyOtherShare * 2).find("other processes used 50%"), std::string::npos);
  rt::TimingStats spread = quiet;
  spread.cv = rt::kBusyCv * 2;
  EXPECT_NE(rt::busyWarning(spread, std::nullopt).find("vary by 40%"), std::string::npos);
}

double elapsedMs(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

TEST(BusyWindow, AShortWindowWithNothingToReachBackToWaitsOutTheRest) {
  // Let every earlier sample of this process age past the reach first.
  std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(rt::kBusyReachMs + 50));
  const auto start = std::chrono::steady_clock::now();
  double window = 0;
  rt::closeCpuWindow(rt::openCpuWindow(), &window);
  EXPECT_GE(window, rt::kBusyWindowMs);
  EXPECT_GE(elapsedMs(start), rt::kBusyWindowMs) << "the close must wait when nothing is old enough";
}

TEST(BusyWindow, AShortWindowReachesBackToAnEarlierSampleInsteadOfWaiting) {
  rt::openCpuWindow();  // an earlier window's opening, e.g. the previous sweep row's
  std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(rt::kBusyWindowMs + 50));
  const auto start = std::chrono::steady_clock::now();
  double window = 0;
  rt::closeCpuWindow(rt::openCpuWindow(), &window);
  EXPECT_GE(window, rt::kBusyWindowMs);
  EXPECT_LE(window, rt::kBusyReachMs);
  // Sibling of the test above: here nothing waited (well under the window; 2 cores may be busy).
  EXPECT_LT(elapsedMs(start), rt::kBusyWindowMs / 2);
}

}  // namespace
}  // namespace shadowc::test
