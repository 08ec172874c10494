// sat_tiles.glsl — the parallel form's carries (sat_rows_parallel.comp, sat_columns_parallel.comp):
// one workgroup of SHADOWC_SAT_TILE_CHUNKS invocations scans one row or column, a tile of
// SHADOWC_SAT_TILE_CHUNKS chunks at a time, invocation i owning chunk i of the tile. Each
// invocation adds up its own chunk; the chunk totals are then folded in shared memory into the
// carries of the blocked order (sat_common.glsl), in the order that defines:
// 16 invocations fold one group each, then one folds the 16 group totals. That fold is two chains
// of 16 shared-memory adds per tile, against the 2048 dependent texel steps of the serial scan.
// No subgroup operation: their order of addition is the implementation's (a deterministic order
// keeps the form free of device-specific results).
#ifndef SHADOWC_SAT_TILES_GLSL
#define SHADOWC_SAT_TILES_GLSL

#include "passes/sat_common.glsl"

shared SHADOWC_SAT_VALUE shadowc_satChunks[SHADOWC_SAT_TILE_CHUNKS];  // totals, then carries in the group
shared SHADOWC_SAT_VALUE shadowc_satGroups[SHADOWC_SAT_GROUP_CHUNKS];  // totals, then carries in the tile
shared SHADOWC_SAT_VALUE shadowc_satTileTotal;

// Called by every invocation of the workgroup (it holds barriers) with its chunk's local total;
// returns (tileCarry + groupCarry) + chunkCarry for its chunk and adds the tile's total to
// tileCarry (the same value in every invocation).
SHADOWC_SAT_VALUE shadowc_satTileCarry(uint i, SHADOWC_SAT_VALUE total, inout SHADOWC_SAT_VALUE tileCarry) {
  shadowc_satChunks[i] = total;
  barrier();
  if (i < SHADOWC_SAT_GROUP_CHUNKS) {
    precise SHADOWC_SAT_VALUE c = SHADOWC_SAT_VALUE(0);
    for (uint k = 0; k < SHADOWC_SAT_GROUP_CHUNKS; ++k) {
      const uint at = i * SHADOWC_SAT_GROUP_CHUNKS + k;
      const SHADOWC_SAT_VALUE t = shadowc_satChunks[at];
      shadowc_satChunks[at] = c;
      c = c + t;
    }
    shadowc_satGroups[i] = c;
  }
  barrier();
  if (i == 0) {
    precise SHADOWC_SAT_VALUE g = SHADOWC_SAT_VALUE(0);
    for (uint k = 0; k < SHADOWC_SAT_GROUP_CHUNKS; ++k) {
      const SHADOWC_SAT_VALUE t = shadowc_satGroups[k];
      shadowc_satGroups[k] = g;
      g = g + t;
    }
    shadowc_satTileTotal = g;
  }
  barrier();
  precise SHADOWC_SAT_VALUE carry = (tileCarry + shadowc_satGroups[i / SHADOWC_SAT_GROUP_CHUNKS]) + shadowc_satChunks[i];
  precise SHADOWC_SAT_VALUE next = tileCarry + shadowc_satTileTotal;
  tileCarry = next;
  barrier();  // the next tile overwrites the shared values
  return carry;
}

#endif
