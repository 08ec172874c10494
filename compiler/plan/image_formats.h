// The one place that maps storage choices to image formats (the emitter renders a format as
// its GLSL layout qualifier: emit/glsl_literal.h).
#pragma once

#include "manifest/manifest.h"
#include "spec/filter_spec.h"

namespace shadowc {

// Channels the warp stores (moments_warp.glsl): linear 2, exp 1, evsm2 2, evsm4 4,
// power_cdf 3 (stored as 4: there is no 3-channel storage format).
int momentChannels(Warp warp);

// `moments` format from StorageSpec.format (fp32 -> r/rg/rgba32f, fp16 -> r/rg/rgba16f,
// unorm16 -> r16/rg16/rgba16). With a SAT the moments are only an intermediate, kept fp32.
ImageFormat momentsFormat(const FilterSpec& spec);

// `sat` format: int32 -> r/rg/rgba32ui, fp32 kinds -> r/rg/rgba32f.
ImageFormat satFormat(const FilterSpec& spec);

}  // namespace shadowc
