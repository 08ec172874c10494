// light_sample_tile.glsl — with `light_samples N` the map of every kernel.glsl function is the
// tile of the light view being looked up (frame_light_samples.glsl): its side is the atlas side
// over SHADOWC_LIGHT_SAMPLE_GRID (rounded down, as the runtime cuts the atlas), and each fetch is
// clamped to the tile, so a kernel at its edge repeats the edge texel as a single map clamps at
// its border and never reads a neighbouring view. Included by kernel.glsl in place of its
// one-map definitions.
#ifndef SHADOWC_LIGHT_SAMPLE_TILE_GLSL
#define SHADOWC_LIGHT_SAMPLE_TILE_GLSL

ivec2 shadowc_mapSize() { return textureSize(shadowc_shadowDepth, 0) / SHADOWC_LIGHT_SAMPLE_GRID; }

float shadowc_depthAt(ivec2 t) { SHADOWC_COUNT(SHADOWC_WORK_DEPTH_FETCHES, 1)
  ivec2 side = shadowc_mapSize();
  ivec2 origin = ivec2(shadowc_lightSample % SHADOWC_LIGHT_SAMPLE_GRID, shadowc_lightSample / SHADOWC_LIGHT_SAMPLE_GRID) * side; SHADOWC_COUNT_DEPTH_BLOCK(origin + clamp(t, ivec2(0), side - 1))
  return texelFetch(shadowc_shadowDepth, origin + clamp(t, ivec2(0), side - 1), 0).r;
}

#endif
