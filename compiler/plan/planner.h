// Planner: FilterSpec -> PassGraph. Decides which images exist (names, formats, sizes, layers,
// mips) and which passes run in which order, following the fixed image/binding table of the
// shade pass (docs/manifest.md). Only the passes a spec needs are planned: a depth-only PCF
// filter is the shade pass alone.
#pragma once

#include "plan/pass_graph.h"
#include "spec/filter_spec.h"

namespace shadowc {

// Pass order: lloyd, moments, blur_h, blur_v, mip1..mipK, sat_rows, sat_columns, minmax0..minmaxK, shade.
PassGraph planPasses(const FilterSpec& spec);

// Levels of the `moments` mip chain and of the `minmax` pyramid: K + 1 with
// K = ceil(log2(kernel.maxTexels)), clamped to [1, kMaxPyramidLevel], so that the coarsest level
// covers the widest kernel the filter can ask for (a fixed count keeps the manifest independent of
// the map size; the runtime needs a map of at least 2^K texels). A kernel wider than 2^8 (a SAT
// kernel's default max is the whole map) reads every top-level cell it spans (minmax.glsl): at
// most 5 x 5 on a 1024^2 map, and the pyramid still fits maps from 256^2 up.
inline constexpr int kMaxPyramidLevel = 8;
int pyramidLevels(const FilterSpec& spec);

// Separable blur weights w[0..r] (w[-k] = w[k], summing to 1 over [-r, r]) that the blur passes
// fold in; the stability suite's double-precision reference uses the same weights.
std::vector<double> blurWeights(BlurKind kind, int r);

}  // namespace shadowc
