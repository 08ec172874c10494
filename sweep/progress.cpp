#include "sweep/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>

namespace shadowc::sweep {

Progress::Progress(std::FILE* out, size_t total, int tty)
    : out_(out),
      total_(total),
      tty_(tty < 0 ? isatty(fileno(out)) != 0 : tty != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

std::string Progress::formatDuration(double s) {
  const long t = long(s + 0.5);
  if (t < 60) return fmt::format("{}s", t);
  if (t < 3600) return fmt::format("{}m{:02}s", t / 60, t % 60);
  return fmt::format("{}h{:02}m", t / 3600, (t % 3600) / 60);
}

void Progress::draw(const std::string& what) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string eta = done_ == 0 ? "?" : formatDuration(elapsed / double(done_) * double(total_ - done_));
  const double frac = total_ == 0 ? 1.0 : double(done_) / double(total_);
  if (tty_) {
    constexpr int kWidth = 28;
    const int filled = int(frac * kWidth + 0.5);
    std::string label = what.size() > 48 ? what.substr(0, 45) + "..." : what;
    fmt::print(out_, "\r\033[K[{}{}] {}/{} {:3.0f}% ETA {}  {}", std::string(size_t(filled), '#'),
               std::string(size_t(kWidth - filled), '.'), done_, total_, 100 * frac, eta, label);
    drawn_ = true;
  } else {
    fmt::print(out_, "sweep: [{}/{}] {} (ETA {})\n", done_, total_, what, eta);
  }
  std::fflush(out_);
}

void Progress::step(const std::string& what) {
  done_ = std::min(done_ + 1, total_);
  draw(what);
}

void Progress::note(const std::string& line) {
  if (tty_ && drawn_) fmt::print(out_, "\r\033[K");
  fmt::print(out_, "sweep: {}\n", line);
  if (tty_ && drawn_) draw("");
  std::fflush(out_);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (tty_ && drawn_) fmt::print(out_, "\n");
  std::fflush(out_);
}

}  // namespace shadowc::sweep
