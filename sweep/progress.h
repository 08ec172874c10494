// Sweep progress on stderr: on a terminal one bar redrawn in place with the count, percentage
// and ETA (from the mean time per finished row); otherwise (a log file, a CI job, Slurm) one
// plain line per row, so logs stay readable.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace shadowc::sweep {

class Progress {
 public:
  // `tty`: draw a bar; the default asks isatty on the stream.
  Progress(std::FILE* out, size_t total, int tty = -1);
  ~Progress();
  // One row finished (ran, not cached): `what` says which and its numbers.
  void step(const std::string& what);
  // A line between steps (scene preparation, reference progress) without breaking the bar.
  void note(const std::string& line);
  void finish();
  static std::string formatDuration(double seconds);  // "42s", "3m05s", "1h02m"

 private:
  void draw(const std::string& what);
  std::FILE* out_;
  size_t total_, done_ = 0;
  bool tty_, drawn_ = false, finished_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace shadowc::sweep
