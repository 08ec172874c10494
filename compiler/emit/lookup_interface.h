// The includable lookup's interface to the engine that #includes <filter>_lookup.glsl
// (docs/integration.md "The lookup's interface"):
//  * placement: every resource it declares (the frame block and the shadow-map images) goes to
//    descriptor set N at the shade pass's binding + B — `shadowc compile --lookup-set N
//    --lookup-binding-base B`, in the spirit of glslc's --resource-set-binding and
//    -fubo-binding-base. A shift, not a renumbering, so a binding (sat = B + 6) is the same for
//    every filter and an engine can swap filters without changing its descriptor layout;
//  * the frame block is emitted under #ifndef SHADOWC_FRAME_EXTERNAL: an engine that defines the
//    macro supplies `shadowc_Frame shadowc_frame()` from its own data instead;
//  * recorded in the manifest's "shade" section (set, bindings).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "emit/glsl_preprocessor.h"
#include "manifest/manifest.h"

namespace shadowc {

struct LookupPlacement {
  uint32_t set = 0;          // --lookup-set
  uint32_t bindingBase = 0;  // --lookup-binding-base
};
inline constexpr uint32_t kMaxLookupSet = 31, kMaxLookupBindingBase = 1u << 16;

struct LookupLayout {
  std::vector<Binding> bindings;  // the lookup's bindings, placed (manifest "shade")
  std::string defines;            // #define lines placing them for the preprocessor
  std::string frameBlock;         // frame_block.glsl placed, inside #ifndef SHADOWC_FRAME_EXTERNAL
};

// From the shade pass's bindings: the frame and the shadow-map images (not the G-buffer or the
// visibility output). Throws std::invalid_argument on an image the lookup has no macro for or a
// placement out of range; returns false with the preprocessor's message in `log`.
// `cascades` > 0: the block carries a cascaded sun's fields (frame_block.glsl).
bool lookupLayout(const Pass& shadePass, const LookupPlacement& placement, const GlslPreprocessor& preprocess,
                  LookupLayout& out, std::string& log, int cascades = 0);

}  // namespace shadowc
