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

#ifdef SHADOWC_LIGHT_SAMPLES
#include "lookup/light_sample_tile.glsl"  // the map is the light view's tile of the atlas
#else
ivec2 shadowc_mapSize() { return textureSize(shadowc_shadowDepth, 0); }

float shadowc_depthAt(ivec2 t) { SHADOWC_COUNT(SHADOWC_WORK_DEPTH_FETCHES, 1) SHADOWC_COUNT_DEPTH_BLOCK(clamp(t, ivec2(0), shadowc_mapSize() - 1))
  return texelFetch(shadowc_shadowDepth, clamp(t, ivec2(0), shadowc_mapSize() - 1), 0).r;
}
#endif

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

#if SHADOWC_WEIGHTED
// Kernels weighted like the light (`weights form_factor`, docs/dsl.md "weights"). The reference
// weighs each light point q by cos(theta_receiver) cos(theta_light) / r^2 (docs/scenes.md "Ground
// truth"); a kernel counts its taps alike. Which light point a position in a kernel stands for:
// a blocker at light-view depth zb that hides light point q (light plane z = 0) from receiver p
// projects (frame.glsl) to the receiver's own map position plus q (zr - zb) / (zb zr), and the
// penumbra kernel is the light's width W times that factor (shadowc_penumbraWidthUV), so a
// position `o` texels from the kernel centre of a kernel `w` texels wide stands for
//     q = o W / w,  same axes as the light view (+u = +x, +v = +y),
// exact for planar occluders parallel to the light; a search region (or a fixed kernel) is read
// the same way. The weight, with v = q - p and n the receiver's unit normal in light view:
//     (n . v)+ p_z / |v|^4  times p_z^2 (one factor per receiver, so the weights are <= 1),
// zero for light points behind the tangent plane, plus 1e-12 so that a receiver with the whole
// light behind it (`backface filtered`) gets the uniform average instead of 0 / 0.
#if SHADOWC_NAIVE_UNGUARDED
#define SHADOWC_WEIGHT_FLOOR 0.0  // stability suite: no floor, 0 / 0 where the light is behind
#else
#define SHADOWC_WEIGHT_FLOOR 1e-12
#endif
vec3 shadowc_wP;      // the receiver (unbiased) in light view
vec3 shadowc_wN;      // its unit normal in light view (0 when the normal is 0)
vec3 shadowc_wKernel; // the kernel the VSSM walks weigh: xy centre (texels), z light width / kernel width

void shadowc_weightsReceiver(vec3 worldPos, vec3 worldNormal) {
  shadowc_wP = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec3 n = mat3(shadowc_frame().lightView) * worldNormal;
  float len = length(n);
  shadowc_wN = len > 0.0 ? n / len : vec3(0.0);
}

// The weight of light point q (light-view x, y of the plane z = 0).
float shadowc_lightWeight(vec2 q) {
  vec3 v = vec3(q, 0.0) - shadowc_wP;
  float r2 = dot(v, v);
  float z = shadowc_wP.z;
  return max(dot(shadowc_wN, v), 0.0) * z * z * z / max(r2 * r2, 1e-30) + SHADOWC_WEIGHT_FLOOR;
}

// The weight of position `pos` (texels) in a kernel `w` texels wide centred at `c`.
float shadowc_tapWeight(vec2 pos, vec2 c, float w) { return shadowc_lightWeight((pos - c) * (shadowc_lightWidth() / w)); }

// The kernel the VSSM walks weigh their boxes in (vssm.glsl).
void shadowc_weightsKernel(vec2 c, float w) { shadowc_wKernel = vec3(c, shadowc_lightWidth() / w); }
float shadowc_kernelWeight(vec2 pos) { return shadowc_lightWeight((pos - shadowc_wKernel.xy) * shadowc_wKernel.z); }
#endif

// Map a value to [0, 1]; NaN becomes 0 (shadowed) rather than propagating.
float shadowc_unit(float v) { return (v >= 0.0) ? min(v, 1.0) : 0.0; }

#ifdef SHADOWC_CASCADES
#include "lookup/cascade_tile.glsl"
#endif
#endif
