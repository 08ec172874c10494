// cascade_tile.glsl — a cascaded sun's texel fetch (frame_cascades.glsl): every depth texel the
// lookup reads is clamped to the tile of the cascade being looked up, so a kernel near a tile's
// edge repeats the edge texel (as a single map clamps at its border) and never reads a
// neighbouring cascade, whose texels belong to another projection. Included at the end of
// kernel.glsl, after the map-clamped shadowc_depthAtAtlas it wraps.
#ifndef SHADOWC_CASCADE_TILE_GLSL
#define SHADOWC_CASCADE_TILE_GLSL

#undef shadowc_depthAt

// Inclusive texel rectangle of cascade `c`'s tile: tile (c mod G, c div G), side mapSize / G.
ivec4 shadowc_cascadeTileRect(int c) {
  ivec2 side = shadowc_mapSize() / SHADOWC_CASCADE_GRID;
  ivec2 lo = ivec2(c % SHADOWC_CASCADE_GRID, c / SHADOWC_CASCADE_GRID) * side;
  return ivec4(lo, lo + side - 1);
}

float shadowc_depthAt(ivec2 t) {
  ivec4 tile = shadowc_cascadeTileRect(shadowc_cascade);
  return shadowc_depthAtAtlas(clamp(t, tile.xy, tile.zw));
}

#endif
