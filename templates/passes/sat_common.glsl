// sat_common.glsl — the summed-area table's storage conventions and summation order, shared by
// both forms of the scans (sat_rows*.comp, sat_columns*.comp) and the lookups that read `sat`.
//   SHADOWC_SAT_KIND 1 int32:         uint32 16.16 fixed point, v in [0,1] -> uint(round(v * 65536)),
//                                     sums wrap mod 2^32: box sums stay exact while each box sum fits
//                                     in 32 bits (Lauritzen 2007 via vssm-yang2010 sec. 6.4)
//   SHADOWC_SAT_KIND 2 fp32 centered: fp32 sums of (v - 0.5); the worst 1x1 box mean still errs
//                                     0.09 / 0.11 at 2048^2 / 4096^2 (stability suite sat_box_mean_*,
//                                     docs/stability.md; 0.11 / 0.97 uncentered, 7.5e-6 int32)
//   SHADOWC_SAT_KIND 3 fp32 naive:    fp32 sums of v (kept to show the precision failure)
// Inclusive convention: S(x, y) = sum of texels [0..x] x [0..y]. The box sum over texels
// [x0, x1] x [y0, y1] is S(x1, y1) - S(x0-1, y1) - S(x1, y0-1) + S(x0-1, y0-1), where any term
// with a coordinate of -1 is 0.
#ifndef SHADOWC_SAT_COMMON_GLSL
#define SHADOWC_SAT_COMMON_GLSL

#ifndef SHADOWC_SAT_KIND
#define SHADOWC_SAT_KIND 1
#endif
#ifndef SHADOWC_SAT_FORMAT
#define SHADOWC_SAT_FORMAT rg32ui
#endif

#if SHADOWC_SAT_KIND == 1
#define SHADOWC_SAT_VALUE uvec4
#define SHADOWC_SAT_IMAGE uimage2DArray
// Inputs are clamped (the checker allows only warps in [0,1]); roundEven because round() may go either way at .5.
uvec4 shadowc_satEncode(vec4 v) { return uvec4(roundEven(clamp(v, 0.0, 1.0) * 65536.0)); }
#elif SHADOWC_SAT_KIND == 2
#define SHADOWC_SAT_VALUE vec4
#define SHADOWC_SAT_IMAGE image2DArray
vec4 shadowc_satEncode(vec4 v) {
  precise vec4 e = v - 0.5;
  return e;
}
#else
#define SHADOWC_SAT_VALUE vec4
#define SHADOWC_SAT_IMAGE image2DArray
vec4 shadowc_satEncode(vec4 v) { return v; }
#endif

// The scans read SHADOWC_SAT_BATCH texels of their row or column before they write any of them
// (measured on an NVIDIA H200, docs/performance.md): one invocation per row or column is 1-2 K
// invocations for a whole map, too few to hide a texel read's latency on a GPU, and the column
// scan reads and writes the same image, so one texel at a time each read waited for the store
// before it (2048^2: rows 0.98 ms, columns 1.97 ms). Batches of 4: 0.97 / 1.08 ms; of 8: 0.63 /
// 0.65; of 16: 0.46 / 0.42, but on lavapipe, which reads and writes the same texels either way,
// the scans cost 13 % more with 8 and 22 % with 16 (docs/performance.md "The SAT scans batched").
// The batch loops have a constant trip count (unrolled, the values stay in registers); a row or
// column that is not a whole number of batches ends one texel at a time. Same sums in the same
// order: the table is bit-identical.
#define SHADOWC_SAT_BATCH 8

// Two forms (docs/manifest.md "Pass forms"). The serial scans (sat_rows.comp, sat_columns.comp:
// one invocation per row or column, for CPU devices) add plain running sums. An int32 table also
// has a parallel form (sat_rows_parallel.comp, sat_columns_parallel.comp: a workgroup of
// SHADOWC_SAT_TILE_CHUNKS invocations per row or column, for GPUs) that adds in the blocked order
// (Nehab et al. 2011, blocked prefix sums): a row (column) is cut into chunks of SHADOWC_SAT_BATCH
// texels, SHADOWC_SAT_GROUP_CHUNKS chunks make a group and as many groups a tile (2048 texels);
// texel j of a chunk stores ((tileCarry + groupCarry) + chunkCarry) + local_j, local_j the chunk's
// texels 0..j, each carry the totals before it in its group, tile or row (sat_tiles.glsl). Sums mod
// 2^32 are exact in any order, so both int32 forms give bit-identical tables. An fp32 table has the
// serial form only: in the blocked order two neighbouring texels across a chunk boundary hold
// independently rounded bases, where running sums differ by one rounded add, so small boxes err
// more (vssm_fp32_centered_sat on two_planes, 256^2 screen, 1024^2 map: RMSE 0.0057 running, 0.0081
// blocked; docs/accuracy.md). Every sum of the parallel form is `precise`.
#define SHADOWC_SAT_GROUP_CHUNKS 16
#define SHADOWC_SAT_TILE_CHUNKS 256  // SHADOWC_SAT_GROUP_CHUNKS^2, a literal: it is the local size
#if SHADOWC_SAT_TILE_CHUNKS != SHADOWC_SAT_GROUP_CHUNKS * SHADOWC_SAT_GROUP_CHUNKS
#error "a tile is SHADOWC_SAT_GROUP_CHUNKS groups of SHADOWC_SAT_GROUP_CHUNKS chunks"
#endif

#endif
