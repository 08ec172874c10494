// resources.glsl — the shadow-map resources of the lookup (bindings 4..8 and 10 of the shade pass,
// briefing table). Only what the filter uses is declared, so an engine that #includes the
// emitted <filter>_lookup.glsl binds exactly the images listed in the manifest. The set is
// SHADOWC_SET (default 0) and every binding can be moved with SHADOWC_BINDING_*; the emitter
// sets them from `shadowc compile --lookup-set N --lookup-binding-base B` (lookup_interface.h).
#ifndef SHADOWC_RESOURCES_GLSL
#define SHADOWC_RESOURCES_GLSL

// Normalized linear depth d = (z - near) / (far - near), 1.0 where nothing was hit. Nearest,
// read with texelFetch only.
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_DEPTH) uniform sampler2D shadowc_shadowDepth;

#if SHADOWC_HAS_MOMENTS && !SHADOWC_HAS_SAT
// Warped moments, one array layer per depth layer; linear filtering (+ mips when prefiltered).
// With a SAT the lookup reads only the table (moments_filter.glsl), and the fused prefilter
// makes no moments image at all (plan/planner.cpp), so none is declared.
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_MOMENTS) uniform sampler2DArray shadowc_moments;
#endif

#if SHADOWC_HAS_SAT
// Summed-area table of the moments (inclusive corners, see sat.glsl), texelFetch only.
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_SAT) uniform usampler2DArray shadowc_summedArea;
#else
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_SAT) uniform sampler2DArray shadowc_summedArea;
#endif
#endif

#if SHADOWC_HAS_MINMAX
// Min-max depth pyramid (r = min, g = max), full mip chain, texelFetch per level.
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_MINMAX) uniform sampler2D shadowc_minMaxPyramid;
#endif

#if SHADOWC_QT_TABLE
// The quadtree's Next/Child tables (vssm-yang2010 Algorithm 2, Fig. 5), one ivec4 per node in
// pre-order: (ix | iy << 16, 2^level, Child, Next), -1 for Null (plan/quadtree_tables.h). The
// manifest carries the values (its "buffers"), the runtime uploads them once.
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_QUADTREE, std430) readonly buffer shadowc_QuadtreeTable {
  ivec4 shadowc_qtTable[];
};
#endif

#if SHADOWC_HAS_SPLITS_TEXTURE
// Lloyd-relaxed layer splits s_0..s_N in texels (i, 0) of an r32f image N+1 wide.
layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_SPLITS) uniform sampler2D shadowc_splitsTexture;
#endif

#if SHADOWC_COUNTERS
#include "lookup/counters.glsl"
#endif

#endif
