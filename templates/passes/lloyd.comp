#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// lloyd.comp — layer split placement by Lloyd relaxation (lauritzen2008 sec. 4.1), in one
// workgroup. K-means in 1-D: the "means" are second-occluder depths mu + sigma of 2x2 depth
// regions (exact max{a, b} for a region centred on a two-depth edge), weighted by the variance
// sigma^2 (edges that bleed most weigh most). The interior splits s_1..s_{N-1} are the means;
// s_0 = 0 and s_N = 1 stay fixed so every depth falls in a layer.
// Budget: a fixed SHADOWC_LLOYD_SAMPLES^2 grid of regions whatever the map size, binned into
// 256 depth bins with uint weights (16.16 of sigma^2 <= 0.25: 128^2 samples cannot overflow).
// Regions touching the cleared background (d = 1) are skipped: nothing there receives shadow.
// Output: r32f `splits`, texel (i, 0) = s_i (the layout templates/lookup/layered.glsl reads).
// Simplification: an empty cluster keeps its split (no "teleportation").
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 2
#endif
#ifndef SHADOWC_LLOYD_ITERATIONS
#define SHADOWC_LLOYD_ITERATIONS 8
#endif
#ifndef SHADOWC_LLOYD_SAMPLES
#define SHADOWC_LLOYD_SAMPLES 128
#endif
#define BINS 256

layout(local_size_x = 256, local_size_y = 1, local_size_z = 1) in;
layout(set = 0, binding = 0) uniform sampler2D shadowDepth;
layout(set = 0, binding = 1, r32f) writeonly uniform image2D splitsOut;

shared uint weights[BINS];

void main() {
  const uint t = gl_LocalInvocationID.x;
  weights[t] = 0u;
  barrier();

  const ivec2 size = textureSize(shadowDepth, 0);
  const int n = SHADOWC_LLOYD_SAMPLES * SHADOWC_LLOYD_SAMPLES;
  for (int s = int(t); s < n; s += BINS) {
    const ivec2 g = ivec2(s % SHADOWC_LLOYD_SAMPLES, s / SHADOWC_LLOYD_SAMPLES);
    const ivec2 p = min(g * max(size - 1, ivec2(1)) / SHADOWC_LLOYD_SAMPLES, size - 2);
    const vec4 d = vec4(texelFetch(shadowDepth, p, 0).r, texelFetch(shadowDepth, p + ivec2(1, 0), 0).r,
                        texelFetch(shadowDepth, p + ivec2(0, 1), 0).r, texelFetch(shadowDepth, p + ivec2(1, 1), 0).r);
    if (max(max(d.x, d.y), max(d.z, d.w)) >= 0.9999) continue;
    const float mu = dot(d, vec4(0.25));
    const float var = clamp(dot(d * d, vec4(0.25)) - mu * mu, 0.0, 0.25);
    const uint w = uint(round(var * 65536.0));
    if (w == 0u) continue;
    const float second = clamp(mu + sqrt(var), 0.0, 1.0);  // mu + sigma (sec. 4.1)
    atomicAdd(weights[min(uint(second * float(BINS)), uint(BINS - 1))], w);
  }
  barrier();
  if (t != 0u) return;

  float splits[SHADOWC_LAYERS + 1];
  for (int i = 0; i <= SHADOWC_LAYERS; ++i) splits[i] = float(i) / float(SHADOWC_LAYERS);
  for (int it = 0; it < SHADOWC_LLOYD_ITERATIONS; ++it) {
    float sum[SHADOWC_LAYERS + 1], mass[SHADOWC_LAYERS + 1];
    for (int i = 0; i <= SHADOWC_LAYERS; ++i) sum[i] = mass[i] = 0.0;
    for (int b = 0; b < BINS; ++b) {
      if (weights[b] == 0u) continue;
      const float x = (float(b) + 0.5) / float(BINS);
      // Nearest interior split (the clusters of the 1-D K-means).
      int best = 1;
      for (int i = 2; i < SHADOWC_LAYERS; ++i)
        if (abs(x - splits[i]) < abs(x - splits[best])) best = i;
      sum[best] += float(weights[b]) * x;
      mass[best] += float(weights[b]);
    }
    for (int i = 1; i < SHADOWC_LAYERS; ++i)
      if (mass[i] > 0.0) splits[i] = sum[i] / mass[i];
    // Keep the sequence strictly increasing (layered.glsl searches it).
    for (int i = 1; i < SHADOWC_LAYERS; ++i)
      splits[i] = clamp(splits[i], splits[i - 1] + 1e-3, 1.0 - float(SHADOWC_LAYERS - i) * 1e-3);
  }
  for (int i = 0; i <= SHADOWC_LAYERS; ++i) imageStore(splitsOut, ivec2(i, 0), vec4(splits[i]));
}
