// The generic variant of a filter (`shadowc compile --generic`, docs/cli.md): the same
// filter as engines usually ship it — one shade shader whose numeric options are members of a
// uniform block the runtime fills from the manifest, so that neither glslang nor the driver's
// JIT can fold them and every loop bound is dynamic. The planner's typed values are rewritten
// here, before any GLSL exists; the emitter renders the block (emit/specialization_block.h).
//
// What becomes a uniform: every integer and real constant of the shade pass (tap counts, grid
// sizes, uniform m and n, quadtree node bound, radii, bias terms, light size, kernel limits,
// exponents, minimum variance, bleeding, overlap, MSM bias, contact epsilon) and every table
// (Poisson taps as vec2[kMaxGenericTaps], layer splits). The unrolled quadtree becomes the
// loop-walked one. What stays compile-time (docs/cli.md "--generic"): the code-path switches
// the templates test with #if (technique, warp, SAT kind, subdivision kinds, PCF pattern, bias
// kind, blocker kind and pattern, the SHADOWC_HAS_* resource switches, penumbra kernel,
// rotation, bleeding on/off, layer blend, fallback, contact, early out, MSM quantized) and the
// layer count (it sizes arrays and picks the layered code), and the int32 SAT's pieces per axis
// (SHADOWC_SAT_PIECES, from `max`: whether sat.glsl sums wide boxes in pieces). The prefilter passes (moments,
// blur, SAT, mips, min-max, Lloyd) stay specialized: they run per map texel, not per pixel.
#pragma once

#include "plan/pass_graph.h"

namespace shadowc {

// The largest Poisson tap count the language allows (read_settings.cpp: taps 1..64): the
// generic block's tap arrays have this length whatever the filter's count, so that filters
// differing only in numbers share one shader.
inline constexpr int kMaxGenericTaps = 64;
inline constexpr uint32_t kGenericBinding = 9;  // shade pass binding after the lookup's 4..8

// Rewrites the shade pass of `graph` to its generic form: its Specialization gets the block
// (Specialization::parameters), the manifest's shade pass the same block and a "parameters"
// uniform binding. Deterministic. Throws InternalError on values it cannot place.
void makeGeneric(PassGraph& graph);

// "SHADOWC_PCF_TAPS" -> "pcfTaps", "shadowc_poissonPcf" -> "poissonPcf".
std::string genericMemberName(const std::string& macro);

}  // namespace shadowc
