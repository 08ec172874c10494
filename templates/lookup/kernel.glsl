// kernel.glsl — receiver setup and kernel geometry shared by every technique.
// Kernels are squares of the shadow map measured in texels. Their widths come from
// frame.glsl (PCSS / vssm-yang2010 sec. 3, L7 and L16); the texel rectangle of a kernel is
// clamped to the map so that texels outside it are never read.
#ifndef SHADOWC_KERNEL_GLSL
#define SHADOWC_KERNEL_GLSL

struct shadowc_Receiver {
  vec2 uv;           // shadow-map uv
  vec2 texel;        // uv * map size: continuous texel coordinates (texel i covers [i, i+1))
  float d;           // normalized receiver depth minus bias: texel z occludes when z < d
  float zr;          // view-space depth of the receiver (>= near)
  vec3 worldPos;
  float lightWidth;  // world units
};

float shadowc_lightWidth() {
#ifdef SHADOWC_LIGHT_WIDTH
  return SHADOWC_LIGHT_WIDTH;
#else
  return max(shadowc_frame().lightParams.w, 0.0);
#endif
}

ivec2 shadowc_mapSize() { return textureSize(shadowc_shadowDepth, 0); }

float shadowc_depthAt(ivec2 t) { SHADOWC_COUNT(SHADOWC_WORK_DEPTH_FETCHES, 1)
  return texelFetch(shadowc_shadowDepth, clamp(t, ivec2(0), shadowc_mapSize() - 1), 0).r;
}

// NaN-safe clamp of a width in texels to [1, SHADOWC_KERNEL_MAX_TEXELS]: comparisons with
// NaN are false, so a NaN width becomes 1 texel.
float shadowc_clampTexels(float w) { return (w >= 1.0) ? min(w, SHADOWC_KERNEL_MAX_TEXELS) : 1.0; }

// Inclusive texel rectangle (x0, y0, x1, y1) of a kernel `w` texels wide centred at `c`,
// clamped to the map (kernels larger than the map become the whole map).
ivec4 shadowc_kernelRect(vec2 c, float w) {
  int n = int(shadowc_clampTexels(w) + 0.5);
  ivec2 lo = ivec2(floor(c - 0.5 * float(n) + 0.5));
  ivec2 hi = lo + ivec2(n - 1);
  ivec2 last = shadowc_mapSize() - 1;
  return ivec4(clamp(lo, ivec2(0), last), clamp(hi, ivec2(0), last));
}

// The kernel as a box in texel units (texel i covers [i, i+1)) for SAT queries: with whole-texel
// corners the rectangle above; with fractional corners (sat.glsl) the continuous box
// [c - w/2, c + w/2] of the unrounded width, clamped to the map and at least one texel wide.
vec4 shadowc_kernelBox(vec2 c, float w) {
#if SHADOWC_SAT_FRACTIONAL
  float h = 0.5 * shadowc_clampTexels(w);
  vec2 size = vec2(shadowc_mapSize());
  vec2 lo = clamp(c - h, vec2(0.0), size - 1.0);
  vec2 hi = clamp(c + h, lo + 1.0, size);
  return vec4(lo, hi);
#else
  ivec4 r = shadowc_kernelRect(c, w);
  return vec4(r.xy, r.zw + 1);
#endif
}

// Blocker search width (L7): the cone from the receiver to the light cut at the near plane.
float shadowc_searchTexels(shadowc_Receiver r) {
  return shadowc_clampTexels(shadowc_searchWidthUV(r.lightWidth, r.zr) * float(shadowc_mapSize().x));
}

// Penumbra width (L16, PCSS) for an average blocker at normalized depth zBlocker. The blocker
// view depth is kept >= near so that the division by zb in frame.glsl stays finite.
float shadowc_penumbraTexels(shadowc_Receiver r, float zBlocker) {
  float zb = max(shadowc_viewZ(clamp(zBlocker, 0.0, 1.0)), shadowc_frame().lightParams.y);
  return shadowc_clampTexels(shadowc_penumbraWidthUV(r.lightWidth, r.zr, zb) * float(shadowc_mapSize().x));
}

// Map a value to [0, 1]; NaN becomes 0 (shadowed) rather than propagating.
float shadowc_unit(float v) { return (v >= 0.0) ? min(v, 1.0) : 0.0; }

#ifdef SHADOWC_CASCADES
#include "lookup/cascade_tile.glsl"
#endif
#endif
