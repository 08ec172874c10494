// counters.glsl — the work counters of the instrumented build (`shadowc compile --counters`,
// docs/manifest.md "Work counters"). Each invocation adds into its own shadowc_work[] while the
// lookup runs (the SHADOWC_COUNT hooks at the fetches, bounds and walk steps); the shade pass
// adds its totals into the work_counters buffer once, at its end: one atomic add per nonzero
// counter, not one per fetch. Every counter is a 64-bit sum kept as (low, high) words: a low
// word that wraps carries one into the high word, so the totals stay exact at any screen size.
// The planner defines SHADOWC_WORK_FIELDS and each SHADOWC_WORK_<NAME> index from its one list
// (compiler/plan/work_counters.h).
#ifndef SHADOWC_COUNTERS_GLSL
#define SHADOWC_COUNTERS_GLSL

layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_WORK, std430) buffer shadowc_WorkCounters {
  uvec2 shadowc_workTotals[];
};

uint shadowc_work[SHADOWC_WORK_FIELDS];
int shadowc_lastDepthBlock;  // the 8x8 texel block of the last depth fetch, -1 before the first

#define SHADOWC_COUNT(k, n) shadowc_work[k] += uint(n);
#define SHADOWC_WORK_BEGIN(receiver) shadowc_workBegin(receiver);
#define SHADOWC_COUNT_DEPTH_BLOCK(texel) shadowc_countDepthBlock(texel);

// A fetch in another block than the one before: a texture cache holds blocks of texels, so
// taps close together cost one fill and spread taps one each (the footprint fetch counts miss).
void shadowc_countDepthBlock(ivec2 t) {
  int block = (t.y >> 3) * 65536 + (t.x >> 3);
  if (block != shadowc_lastDepthBlock) shadowc_work[SHADOWC_WORK_DEPTH_BLOCK_SWITCHES] += 1u;
  shadowc_lastDepthBlock = block;
}
#define SHADOWC_WORK_END shadowc_workEnd();

void shadowc_workBegin(bool receiver) {
  for (int k = 0; k < SHADOWC_WORK_FIELDS; ++k) shadowc_work[k] = 0u;
  shadowc_work[SHADOWC_WORK_RECEIVERS] = receiver ? 1u : 0u;
  shadowc_lastDepthBlock = -1;
}

void shadowc_workEnd() {
  for (int k = 0; k < SHADOWC_WORK_FIELDS; ++k) {
    uint n = shadowc_work[k];
    if (n == 0u) continue;
    uint before = atomicAdd(shadowc_workTotals[k].x, n);
    if (before + n < before) atomicAdd(shadowc_workTotals[k].y, 1u);  // the low word wrapped
  }
}

#endif
