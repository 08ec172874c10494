// The work counters of the instrumented shade pass (work_counters.h).
#include "plan/work_counters.h"

#include <algorithm>

#include "plan/internal_error.h"

namespace shadowc {

const std::vector<WorkCounter>& workCounters() {
  static const std::vector<WorkCounter> counters = {
      {"receivers", "SHADOWC_WORK_RECEIVERS", "pixels with geometry the lookup ran for"},
      {"depth_fetches", "SHADOWC_WORK_DEPTH_FETCHES",
       "depth-map texels read: PCF and contact taps (4 a bilinear tap), blocker search taps, PCF fallback taps"},
      {"depth_block_switches", "SHADOWC_WORK_DEPTH_BLOCK_SWITCHES",
       "depth fetches in another 8x8 texel block than the fetch before (1 for the first): near taps share a "
       "block, spread ones do not, as a texture cache sees them"},
      {"moment_fetches", "SHADOWC_WORK_MOMENT_FETCHES", "filtered reads of the moments image (no SAT)"},
      {"sat_fetches", "SHADOWC_WORK_SAT_FETCHES", "summed-area table corners read"},
      {"kernel_boxes", "SHADOWC_WORK_KERNEL_BOXES",
       "VSSM sub-kernel boxes classified (vssm-yang2010 Algorithm 2 L6-L19; each one box mean)"},
      {"minmax_fetches", "SHADOWC_WORK_MINMAX_FETCHES", "min-max pyramid cells read by the early out"},
      {"split_fetches", "SHADOWC_WORK_SPLIT_FETCHES", "layer split depths read from the Lloyd splits image"},
      {"moment_bounds", "SHADOWC_WORK_MOMENT_BOUNDS", "Chebyshev (or MSM Hamburger) bounds evaluated"},
      {"walk_steps", "SHADOWC_WORK_WALK_STEPS", "steps of VSSM's walks: quadtree nodes, uniform-walk loop steps"},
      {"blockers_found", "SHADOWC_WORK_BLOCKERS_FOUND", "blocker estimates that found an occluder"},
      {"early_outs", "SHADOWC_WORK_EARLY_OUTS", "receivers the min-max early out decided (lit or umbra)"},
  };
  return counters;
}

void addWorkCounters(PassGraph& graph) {
  auto& passes = graph.manifest.passes;
  const auto shade = std::find_if(passes.begin(), passes.end(), [](const Pass& p) { return p.kind == "shade"; });
  if (shade == passes.end() || graph.sources.size() != passes.size())
    throw InternalError("counters: the pass graph has no shade pass");
  for (const Binding& b : shade->bindings)
    if (b.image == kWorkCounterBuffer) throw InternalError("counters: the shade pass is counted already");

  BufferDesc buffer;
  buffer.name = kWorkCounterBuffer;
  buffer.components = 2;  // (low, high) words of a 64-bit sum (templates/lookup/counters.glsl)
  for (const WorkCounter& c : workCounters()) buffer.fields.push_back(c.name);
  buffer.values.assign(2 * buffer.fields.size(), 0);
  graph.manifest.buffers.push_back(std::move(buffer));
  shade->bindings.push_back({kWorkCounterBinding, kWorkCounterBuffer, Access::StorageBufferReadWrite, -1});

  Specialization& values = graph.sources[size_t(shade - passes.begin())].values;
  values.add("SHADOWC_COUNTERS", true);
  values.add("SHADOWC_WORK_FIELDS", static_cast<long long>(workCounters().size()));
  for (size_t k = 0; k < workCounters().size(); ++k) values.add(workCounters()[k].macro, static_cast<long long>(k));
}

}  // namespace shadowc
