// pipeline_bench: what compiling a filter costs, ours and the driver's (a benchmark, never a
// test). For every sample and for the largest settings the checker accepts (quadtree heights
// up to 5 for the kernel and the blocker, table, computed and unrolled, uniform m and n, taps, layers):
//   - the driver's in-process compile at -O (driver::compileSource, median of N),
//   - lavapipe's pipeline creation through the run harness (RunOutputs::pipelineCreateMs), and
//     each pass's first dispatch, which is where lavapipe JIT-compiles the shader with LLVM
//     (docs/runtime.md "Timing method"): one run, no warm-up, 64^2 screen, 512^2 map, two_planes.
// Each filter runs on the device in a child process with a time limit, because a too-large
// shader makes the JIT take minutes: a child over the limit is killed and reported.
// Run with MESA_SHADER_CACHE_DISABLE=true so that every pipeline is really compiled.
// Usage: pipeline_bench [limit seconds = 30] [filter-substring] [compile runs = 3]
#include <fmt/core.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/driver/driver.h"
#include "runtime/harness/scene_run.h"
#include "runtime/vulkan/vulkan_context.h"
#include "shadowc_source_dir.h"

namespace fs = std::filesystem;
using namespace shadowc;
using Clock = std::chrono::steady_clock;

namespace {

struct Source {
  std::string name, text;
};

// The largest settings the checker accepts (compiler/spec/read_settings.cpp ranges).
std::vector<Source> largestSettings() {
  const std::string vssm = "moments linear\n storage sat(int32)\n";
  std::vector<Source> out;
  for (const char* traversal : {"table", "computed", "unrolled"})
    for (int h = 1; h <= 5; ++h)
      out.push_back({fmt::format("max_kernel_qt{}_{}", h, traversal),
                     fmt::format("filter max_kernel_qt{0}_{1} {{\n {2} blocker moments\n kernel quadtree(height: {0}, "
                                 "traversal: {1})\n}}\n",
                                 h, traversal, vssm)});
  for (const char* traversal : {"table", "computed", "unrolled"}) {
    out.push_back({fmt::format("max_blocker_qt5_{}", traversal),
                   fmt::format("filter max_blocker_qt5_{0} {{\n {1} blocker moments(quadtree(height: 5))\n kernel "
                               "quadtree(height: 1, traversal: {0})\n}}\n",
                               traversal, vssm)});
    out.push_back({fmt::format("max_everything_qt5_{}", traversal),
                   fmt::format("filter max_everything_qt5_{0} {{\n {1} blocker moments(quadtree(height: 5))\n kernel "
                               "quadtree(height: 5, traversal: {0})\n fallback pcf(8x8)\n contact pcf(8x8, epsilon: "
                               "0.01)\n early_out minmax\n}}\n",
                               traversal, vssm)});
  }
  out.push_back({"max_uniform", "filter max_uniform {\n " + vssm +
                                    " blocker moments(uniform(m: 16))\n kernel uniform(n: 32)\n fallback pcf(8x8)\n "
                                    "contact pcf(8x8, epsilon: 0.01)\n early_out minmax\n}\n"});
  out.push_back({"max_pcss_taps",
                 "filter max_pcss_taps {\n depth\n blocker search(64, pattern: poisson)\n kernel "
                 "penumbra\n sampling poisson(64, rotate: stable)\n}\n"});
  out.push_back({"max_pcf_grid", "filter max_pcf_grid {\n depth\n kernel fixed(63)\n sampling grid(16x16)\n}\n"});
  out.push_back({"max_layers_lloyd",
                 "filter max_layers_lloyd {\n moments linear(layers: 16, split: lloyd(iterations: "
                 "64), overlap: 0.25)\n storage fp32\n blur gaussian(radius: 32)\n}\n"});
  out.push_back({"max_layers_sat", "filter max_layers_sat {\n moments linear(layers: 16)\n storage sat(fp32)\n}\n"});
  return out;
}

std::vector<Source> samples(const std::string& only) {
  std::vector<Source> out;
  for (const auto& e : fs::directory_iterator(fs::path(SHADOWC_SOURCE_DIR) / "samples" / "filters"))
    if (e.path().extension() == ".shadow") {
      std::ifstream in(e.path());
      out.push_back({e.path().stem().string(), std::string(std::istreambuf_iterator<char>(in), {})});
    }
  std::sort(out.begin(), out.end(), [](const Source& a, const Source& b) { return a.name < b.name; });
  for (Source& s : largestSettings()) out.push_back(std::move(s));
  std::erase_if(out, [&](const Source& s) { return s.name.find(only) == std::string::npos; });
  return out;
}

// In the child: create the pipelines and run once; one line "create <ms>" then "<pass> <ms>".
void deviceChild(const CompiledPasses& passes, int fd) {
  rt::VulkanContext ctx;
  rt::SceneSettings settings;
  settings.screen = 64;
  settings.map = 512;
  const auto scene = rt::prepareScene(ctx, settings);
  const rt::SceneRunResult r = rt::runOnScene(ctx, passes, *scene, rt::RunOptions{0, 1, {}});
  std::string out = fmt::format("create {:.1f}\n", r.outputs.pipelineCreateMs);
  for (const auto& p : r.outputs.timing->passes) out += fmt::format("{} {:.1f}\n", p.name, p.medianMs);
  if (::write(fd, out.data(), out.size()) != static_cast<ssize_t>(out.size())) ::_exit(3);
}

struct DeviceResult {
  bool finished = false;
  double seconds = 0;     // wall time of the child (context, scene, pipelines, one run)
  double cpuSeconds = 0;  // its CPU time, all threads (steadier than wall time on a loaded machine)
  std::string lines;
};

DeviceResult onDevice(const CompiledPasses& passes, int limitSeconds) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
  const auto t0 = Clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    try {
      deviceChild(passes, fds[1]);
    } catch (const std::exception& e) {
      fmt::print(stderr, "{}\n", e.what());
      ::_exit(2);
    }
    ::_exit(0);
  }
  ::close(fds[1]);
  DeviceResult r;
  int status = 0;
  for (;;) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      r.finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      break;
    }
    if (Clock::now() - t0 > std::chrono::seconds(limitSeconds)) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    ::usleep(20000);
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  rusage usage{};
  ::getrusage(RUSAGE_CHILDREN, &usage);
  const double cpu = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                     1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  static double cpuBefore = 0;  // RUSAGE_CHILDREN accumulates over every waited-for child
  r.cpuSeconds = cpu - cpuBefore;
  cpuBefore = cpu;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) r.lines.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  return r;
}

}  // namespace

int main(int argc, char** argv) try {
  const int limit = argc > 1 ? std::max(1, std::atoi(argv[1])) : 30;
  const std::string only = argc > 2 ? argv[2] : "";
  const int n = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
  fmt::print(
      "pipeline_bench: driver compile at -O (median of {}), lavapipe pipeline creation and first dispatch per "
      "pass (JIT + one run; 64² screen, 512² map), device limit {} s per filter\n\n",
      n, limit);
  fmt::print(
      "| filter | driver compile ms (CPU ms) | pipeline create ms | first dispatch per pass (ms) | create + first "
      "dispatches s | device child CPU s |\n");
  fmt::print("|---|---:|---:|---|---:|---:|\n");
  for (const Source& s : samples(only)) {
    std::vector<double> times, cpuTimes;
    std::optional<driver::Artifact> artifact;
    for (int i = 0; i < n; ++i) {
      const auto t0 = Clock::now();
      const std::clock_t c0 = std::clock();
      driver::Result r = driver::compileSource(s.text, s.name + ".shadow");
      cpuTimes.push_back(1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC);
      times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
      if (!r.artifact) {
        fmt::print("| {} | does not compile | | {} | | |\n", s.name, r.log.substr(0, r.log.find('\n')));
        break;
      }
      artifact = std::move(r.artifact);
    }
    if (!artifact) continue;
    const DeviceResult d = onDevice(artifact->passes(), limit);
    if (!d.finished) {
      fmt::print("| {} | {:.0f} ({:.0f}) | | killed after {:.0f} s (limit) | > {} | {:.1f} |\n", s.name,
                 rt::median(times), rt::median(cpuTimes), d.seconds, limit, d.cpuSeconds);
      continue;
    }
    std::istringstream in(d.lines);
    std::string name, perPass;
    double ms = 0, create = 0, total = 0;
    while (in >> name >> ms) {
      if (name == "create") {
        create = ms;
        continue;
      }
      perPass += fmt::format("{}{} {:.0f}", perPass.empty() ? "" : ", ", name, ms);
      total += ms;
    }
    fmt::print("| {} | {:.0f} ({:.0f}) | {:.0f} | {} | {:.2f} | {:.1f} |\n", s.name, rt::median(times),
               rt::median(cpuTimes), create, perPass, (create + total) / 1000, d.cpuSeconds);
    std::fflush(stdout);
  }
  return 0;
} catch (const std::exception& e) {
  fmt::print(stderr, "pipeline_bench: {}\n", e.what());
  return 1;
}
