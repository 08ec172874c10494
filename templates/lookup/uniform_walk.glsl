// uniform_walk.glsl — the uniform m x m / n x n subdivision of a VSSM kernel (vssm-yang2010
// sec. 5.2; Algorithm 1 L11-L15 / L17-L20): the walks over the sub-kernels' SAT corners that
// vssm.glsl's blocker and visibility call. Included by vssm.glsl after the classification
// (shadowc_classify), the leaf PCF (shadowc_qtResolveLeaf, shadowc_markResolve) and the mark
// words it uses.
#ifndef SHADOWC_UNIFORM_WALK_GLSL
#define SHADOWC_UNIFORM_WALK_GLSL

// Whether the root box (mean moments m over `area` texels) needs the den x den walk: `always`
// walks unless the root is fully lit (Algorithm 2 L9-L11 at the root, sec. 5.2's "reasonable
// acceleration strategy": 4 SAT reads instead of the whole walk for most lit receivers; the
// quadtree walk does the same at its root); `nonPlanarOnly` (Algorithm 1 L11-L15 / L17-L20) only
// when it is non-planar, and otherwise accepts it as one lit or normal box. An empty root needs nothing.
bool shadowc_rootNeedsWalk(vec4 m, float area, bool nonPlanarOnly) {
  return shadowc_classify(m, area, nonPlanarOnly) == 1;
}

// Uniform den x den subdivision (sec. 5.2); den = 1 is no subdivision. With `always` a fully lit
// root is accepted first (shadowc_rootNeedsWalk). `nonPlanarOnly`:
// Algorithm 1 L11-L15 / L17-L20, the root box alone when it is lit or normal (one box read),
// the den x den walk only when it is non-planar (classify accumulates nothing then).
// What lavapipe charges (docs/performance.md "One loop, one line of corners a step"): an
// 8-lane SIMD group runs every branch body and every loop's first iteration, masked, whatever its
// lanes decide (gallivm pushes an execution mask for an `if` and tests for live lanes only at a
// loop's end); only further iterations are skipped once no lane is left. So the whole walk is ONE
// loop whose step 0 is the root box, which every lane needs, and whose later steps only walking
// lanes take (a second loop for the sub-kernels cost every group one masked row). What a group
// that does not walk pays is therefore one step, whatever the step holds, and what a walking group
// pays is the steps times that: each step reads ONE row of a column band (its two corners, 2
// texel reads) and classifies the ONE cell between it and the row carried from the step before.
// The root's top row is read before the loop, so step 0 is the root (4 reads, one
// classification: what the quadtree walk's first step costs), and the grid takes den + 1 steps a
// band (its first row has no cell above it): den = 5 reads 60 corners in 30 steps (100 as
// separate boxes). A step with two cells (two rows, 15 steps for den = 5) cost every group that
// does not walk a second classification: the mixed scheme was 4 % behind H = 3 alone on planar
// scenes with the min-max early out, where no group walks (callgrind, docs/performance.md
// "One loop, one line of corners a step"). Rows, not columns: a step's two corners lie on one
// texel row, and so do the root's first two. Measured, not derived (cache simulation of the CPU lavapipe runs on,
// 2048^2 map with the early out on two_planes, where no group walks): the column walk's shade
// missed the first-level cache 174 K times a 256^2 frame and this one 154 K, and the mixed scheme
// went from 3-9 % behind H = 3 alone to 1-6 % ahead (docs/performance.md "Rows, not columns").
// Reading the root's rows but walking the grid by columns did not do it (183 K misses).
// Every sum is the same four corners in the same order as sat.glsl's, so each box mean is
// bit-identical to a separate box query. Non-planar sub-kernels are marked in a bit mask and get
// their PCF in one loop over the set bits after the walk, in row-major order (their sums are their
// own accumulators, so the results are bit-identical): a group pays the most PCFs any of its lanes
// needs, plus one masked PCF, instead of a masked PCF per step. With den^2 > 64 (and generic
// shaders) a leaf's PCF is done in place. (A mask *array* gave wrong images in the stability
// suite; not isolated between glslang, spirv-opt and lavapipe: masks are scalars.)
// A wide int32 SAT (SHADOWC_SAT_WIDE: boxes cut into pieces of at most 255 texels, sat.glsl) has
// its own walk: "box" bands sum the root (and, for a root wider than den pieces, each sub-kernel
// in turn) piece by piece in shadowc_summedSum's order, "grid" bands classify the sub-kernels, two
// columns a step (a box within one piece is one step). It keeps two columns a step because its
// step is heavier (box bands, pieces): with one column a step the samples' default `always`
// blocker, which nearly every group walks, cost 5-7 % more instructions (duck, two_planes).
#if SHADOWC_FALLBACK_PCF && SHADOWC_UNIFORM_MAX_DEN * SHADOWC_UNIFORM_MAX_DEN <= 64
#define SHADOWC_WALK_DEFER 1  // two mask words hold every sub-kernel
#else
#define SHADOWC_WALK_DEFER 0
#endif

#if SHADOWC_HAS_SAT && !SHADOWC_SAT_FRACTIONAL
// The walk keeps the two moments VSSM reads (E(x), E(x^2)) of each corner and sum, not the SAT's
// four channels: every value the loop carries from step to step is state each step loads, masks
// and stores again on lavapipe, per channel.
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
#define shadowc_WalkSum uvec2
#else
#define shadowc_WalkSum vec2
#endif

// A box sum (one cell, or pieces of a wide box added in float) as mean moments over `area`
// texels: per channel the same arithmetic as shadowc_satMeanOfSum.
vec4 shadowc_walkMean(vec2 sum, float area) {
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
  return vec4(sum / (65536.0 * area), 0.0, 0.0);
#else
  return shadowc_satMeanOfSum(vec4(sum, 0.0, 0.0), area);
#endif
}
#endif

#if SHADOWC_WALK_DEFER
// The PCF of the sub-kernels a uniform walk marked non-planar (bit j * den + i), in the walk's order.
void shadowc_uniformResolveMarks(uint marksLo, uint marksHi, int den) {
  while ((marksLo | marksHi) != 0u) {
    int b = shadowc_markPop(marksLo, marksHi);
    int j = b / den;
    shadowc_markResolve(b, shadowc_subBox(ivec3(b - j * den, j, den)));
  }
}
#endif

#if SHADOWC_HAS_SAT && !SHADOWC_SAT_FRACTIONAL && !SHADOWC_SAT_WIDE && SHADOWC_UNIFORM_MAX_DEN <= 8 && !SHADOWC_WEIGHTED
#define SHADOWC_BAND_WALK 1
// `always` (sec. 5.2, every root that is not fully lit is subdivided): nearly every group that
// gets here walks, so what counts is the walk's reads, not what a group that does not walk pays.
// The root's four corners first (Algorithm 2 L9-L11 at the root, as shadowc_rootNeedsWalk), then
// one step a ROW of corners: den + 1 reads, the row above carried in `top`, the den cells of the
// band between them classified left to right (every cell sum is sat.glsl's four corners in its
// order). den = 5: 4 + 36 corner reads in 6 steps, against 64 in 31 steps for the row-pair walk
// below; a group that does not walk pays the first step (the top row, no
// cells) on top of the root. The inner loop has a constant trip count once den is (the driver
// unrolls it and `top` stays in registers), hence den <= 8 only.
void shadowc_uniformBandWalk(int den) {
  ivec2 root = ivec2(shadowc_vRoot.xy);
  ivec2 size = ivec2(shadowc_vRoot.zw) - root;
  shadowc_WalkSum lo = shadowc_summedCorner(root.x - 1, root.y - 1, 0).xy;
  shadowc_WalkSum hi = shadowc_summedCorner(root.x - 1, root.y + size.y - 1, 0).xy;
  shadowc_WalkSum la = shadowc_summedCorner(root.x + size.x - 1, root.y - 1, 0).xy;
  shadowc_WalkSum ha = shadowc_summedCorner(root.x + size.x - 1, root.y + size.y - 1, 0).xy;
  float area = float(size.x * size.y);
  bool there = size.x > 0 && size.y > 0;
  int rows = shadowc_classify(shadowc_walkMean(vec2(ha - hi - la + lo), max(area, 1.0)), there ? area : 0.0,
                              false) == 1 ? den + 1 : 0;
#if SHADOWC_WALK_DEFER
  uint marksLo = 0u;  // bit k = j * den + i (k - 32 in marksHi): sub-kernel (i, j) is non-planar
  uint marksHi = 0u;
#endif
  shadowc_WalkSum top[SHADOWC_UNIFORM_MAX_DEN + 1];  // the row of corners above the band
  for (int c = 0; c <= den; ++c) top[c] = shadowc_WalkSum(0);
  int yt = root.y;  // its texel edge
  for (int r = 0; r < rows; ++r) { SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1)
    // Row r of corners (row 0: the root's top edge, no cells above it), texel edge yb.
    int yb = root.y + int(uint(r * size.y) / uint(den));
    shadowc_WalkSum left = shadowc_summedCorner(root.x - 1, yb - 1, 0).xy;
    int xl = root.x;
    for (int c = 1; c <= den; ++c) {
      int xr = root.x + int(uint(c * size.x) / uint(den));
      shadowc_WalkSum right = shadowc_summedCorner(xr - 1, yb - 1, 0).xy;
      shadowc_WalkSum sum = right - left - top[c] + top[c - 1];  // cell (c - 1, r - 1)
      float cellArea = float((xr - xl) * (yb - yt));
      bool cell = r > 0 && xr > xl && yb > yt;
      bool nonPlanar = shadowc_classify(shadowc_walkMean(vec2(sum), max(cellArea, 1.0)), cell ? cellArea : 0.0,
                                        true) == 1;
#if SHADOWC_WALK_DEFER
      shadowc_markSet(marksLo, marksHi, (r - 1) * den + c - 1, nonPlanar);
#else
      if (nonPlanar) shadowc_qtResolveLeaf(vec4(xl, yt, xr, yb));
#endif
      top[c - 1] = left;
      left = right;
      xl = xr;
    }
    top[den] = left;
    yt = yb;
  }
#if SHADOWC_WALK_DEFER
  shadowc_uniformResolveMarks(marksLo, marksHi, den);
#endif
}
#else
#define SHADOWC_BAND_WALK 0
#endif

void shadowc_uniformWalk(int den, bool nonPlanarOnly) {
  vec4 whole = shadowc_subBox(ivec3(0, 0, 1));
  if (den == 1) {  // no subdivision: the root is the one leaf (the same corners as the walk's)
    shadowc_qtLeafBox(whole);
    return;
  }
#if SHADOWC_BAND_WALK
  if (!nonPlanarOnly) {
    shadowc_uniformBandWalk(den);
    return;
  }
#endif
#if SHADOWC_HAS_SAT && !SHADOWC_SAT_FRACTIONAL && !SHADOWC_SAT_WIDE && !SHADOWC_WEIGHTED
  ivec2 root = ivec2(shadowc_vRoot.xy);
  ivec2 size = ivec2(shadowc_vRoot.zw) - root;
#if SHADOWC_WALK_DEFER
  uint marksLo = 0u;  // bit k = j * den + i (k - 32 in marksHi): sub-kernel (i, j) is non-planar
  uint marksHi = 0u;
#endif
  // The carried row: its left and right corners in the band, and its y (texel edge).
  shadowc_WalkSum lo = shadowc_summedCorner(root.x - 1, root.y - 1, 0).xy;
  shadowc_WalkSum hi = shadowc_summedCorner(root.x + size.x - 1, root.y - 1, 0).xy;
  int yc = root.y;
  bool more = true;
  for (int step = 0; step < 1 + den * (den + 1) && more; ++step) { SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1)
    // Step 0: the root's bottom row. Step 1 + i * (den + 1) + r: row r of grid band i.
    bool grid = step > 0;
    int g = step - 1;
    int i = int(uint(g) / uint(den + 1));
    int r = g - i * (den + 1);
    int x0 = grid ? root.x + int(uint(i * size.x) / uint(den)) : root.x;
    int x1 = grid ? root.x + int(uint((i + 1) * size.x) / uint(den)) : root.x + size.x;
    int ya = grid ? root.y + int(uint(r * size.y) / uint(den)) : root.y + size.y;
    shadowc_WalkSum la = shadowc_summedCorner(x0 - 1, ya - 1, 0).xy;
    shadowc_WalkSum ha = shadowc_summedCorner(x1 - 1, ya - 1, 0).xy;
    shadowc_WalkSum sum = ha - la - hi + lo;  // the cell (carried row, this one)
    // The cell is there unless this is a band's first row or it is empty (area 0: nothing added,
    // verdict 0; shadowc_classify). The root as shadowc_rootNeedsWalk, a sub-kernel as
    // shadowc_qtAccept.
    float area = float((x1 - x0) * (ya - yc));
    bool cell = (!grid || r > 0) && x1 > x0 && ya > yc;
    bool nonPlanar = shadowc_classify(shadowc_walkMean(vec2(sum), max(area, 1.0)), cell ? area : 0.0,
                                      grid || nonPlanarOnly) == 1;
#if SHADOWC_WALK_DEFER
    shadowc_markSet(marksLo, marksHi, (r - 1) * den + i, grid && nonPlanar);  // sub-kernel (i, r - 1)
#else
    if (grid && nonPlanar) shadowc_qtResolveLeaf(vec4(x0, yc, x1, ya));
#endif
    lo = la;
    hi = ha;
    yc = ya;
    more = grid || nonPlanar;  // the root walks on only when it needs it
  }
#if SHADOWC_WALK_DEFER
  shadowc_uniformResolveMarks(marksLo, marksHi, den);
#endif
#elif SHADOWC_SAT_WIDE && !SHADOWC_SAT_FRACTIONAL && !SHADOWC_WEIGHTED
  ivec2 root = ivec2(shadowc_vRoot.xy);
  ivec2 size = ivec2(shadowc_vRoot.zw) - root;
  int subs = den * den;
  const int piece = shadowc_satPiece;
  // Every sub-kernel is at most ceil(size / den) texels a side, so only a root wider than den
  // pieces can have a sub-kernel wider than one.
  bool wideSubs = SHADOWC_SAT_PIECES > den && max(size.x, size.y) > piece * den;
#if SHADOWC_WALK_DEFER
  uint marksLo = 0u;  // bit k = j * den + i (k - 32 in marksHi): sub-kernel (i, j) is non-planar
  uint marksHi = 0u;
#endif
  int k = -1;              // box bands: the box (-1 the root, else sub-kernel k); k = subs: grid
  int j = 0;               // band
  int c = 0;               // the step reads columns c and c + 1
  vec2 acc = vec2(0.0);    // a wide box's sum so far (box bands; a box within one piece is one cell)
  shadowc_WalkSum lo = shadowc_WalkSum(0);  // the carried column's top and bottom corners, and its x
  shadowc_WalkSum hi = shadowc_WalkSum(0);
  int xc = 0;
  bool more = true;
  const int limit = (1 + SHADOWC_UNIFORM_MAX_DEN * SHADOWC_UNIFORM_MAX_DEN) * SHADOWC_SAT_PIECES *
                        (SHADOWC_SAT_PIECES / 2 + 1) + SHADOWC_UNIFORM_MAX_DEN * (SHADOWC_UNIFORM_MAX_DEN / 2 + 1);
  for (int step = 0; step < limit && more; ++step) { SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1)
    bool grid = k == subs;
    // The box (box bands) and its pieces per axis.
    ivec4 box = k < 0 || !wideSubs ? ivec4(root, root + size) : ivec4(shadowc_subBox(ivec3(k % den, k / den, den)));
    ivec2 cells = max((box.zw - box.xy + piece - 1) / piece, 1);
    // Band j's rows and the columns c, cb (texel edges): grid bands at the sub-kernel edges, box
    // bands at the box's piece cuts (sat.glsl's shadowc_satCut).
    int ncol = grid ? den + 1 : cells.x + 1;
    int cb = min(c + 1, ncol - 1);
    int y0 = grid ? root.y + (j * size.y) / den : min(box.y + j * piece, box.w);
    int y1 = grid ? root.y + ((j + 1) * size.y) / den : min(box.y + (j + 1) * piece, box.w);
    int xa = grid ? root.x + (c * size.x) / den : min(box.x + c * piece, box.z);
    int xb = grid ? root.x + (cb * size.x) / den : min(box.x + cb * piece, box.z);
    shadowc_WalkSum la = shadowc_summedCorner(xa - 1, y0 - 1, 0).xy;
    shadowc_WalkSum ha = shadowc_summedCorner(xa - 1, y1 - 1, 0).xy;
    shadowc_WalkSum lb = shadowc_summedCorner(xb - 1, y0 - 1, 0).xy;
    shadowc_WalkSum hb = shadowc_summedCorner(xb - 1, y1 - 1, 0).xy;
    shadowc_WalkSum s1 = ha - hi - la + lo;  // cell (carried column, a)
    shadowc_WalkSum s2 = hb - ha - lb + la;  // cell (a, b)
    bool cell1 = c > 0 && xa > xc && y1 > y0;
    bool cell2 = cb > c && xb > xa && y1 > y0;
    float area1 = float((xa - xc) * (y1 - y0));
    float area2 = float((xb - xa) * (y1 - y0));
    // Box bands add their cells in shadowc_summedSum's order (adding 0.0 changes no sum).
    if (!grid) {
      acc += cell1 ? vec2(s1) : vec2(0.0);
      acc += cell2 ? vec2(s2) : vec2(0.0);
    }
    int bit = j * den + c;  // grid: sub-kernel (c, j)
    c += 2;
    bool bandEnd = c >= ncol;
    if (bandEnd) {
      c = 0;
      ++j;
    }
    // Both slots classify whether their cell is there or not (area 0 where it is not: nothing
    // added, verdict 0; the mean divides by at least 1): no branch around a call (shadowc_classify).
    // Slot 1 (c, j as the step read them, before the advance above): grid sub-kernel (c - 1, j).
    bool on1 = grid && cell1;
    bool nonPlanar1 = shadowc_classify(shadowc_walkMean(vec2(s1), max(area1, 1.0)), on1 ? area1 : 0.0, true) == 1;
#if SHADOWC_WALK_DEFER
    shadowc_markSet(marksLo, marksHi, bit - 1, nonPlanar1);
#else
    if (nonPlanar1) shadowc_qtResolveLeaf(vec4(xc, y0, xa, y1));
#endif
    // Slot 2: grid sub-kernel (c, j) likewise, or a box whose last piece this step read.
    float area = grid ? area2 : float((box.z - box.x) * (box.w - box.y));
    bool on2 = grid ? cell2 : bandEnd && j >= cells.y && area > 0.0;
    vec4 m = shadowc_walkMean(grid ? vec2(s2) : acc, max(area, 1.0));
    // The root (k < 0) as shadowc_rootNeedsWalk (area > 0 where on2), a sub-kernel as
    // shadowc_qtAccept: one classification either way.
    bool nonPlanar = shadowc_classify(m, on2 ? area : 0.0, k >= 0 || nonPlanarOnly) == 1;
#if SHADOWC_WALK_DEFER
    shadowc_markSet(marksLo, marksHi, grid ? bit : k, k >= 0 && nonPlanar);
#else
    if (k >= 0 && nonPlanar) shadowc_qtResolveLeaf(grid ? vec4(xa, y0, xb, y1) : vec4(box));
#endif
    lo = lb;
    hi = hb;
    xc = xb;
    if (bandEnd && j >= (grid ? den : cells.y)) {  // the last band of a box or of the grid
      more = k < 0 ? nonPlanar : k + 1 < subs;  // the root walks on only when it needs it (its last band is this step)
      k = k < 0 && !wideSubs ? subs : k + 1;  // on to the grid, or to the next (wide) sub-kernel
      j = 0;
      acc = vec2(0.0);
    }
  }
#if SHADOWC_WALK_DEFER
  shadowc_uniformResolveMarks(marksLo, marksHi, den);
#endif
#else
  // Box by box (and every walk with `weights form_factor`: shadowc_qtClassifyBox weighs each
  // sub-kernel by its light patch; the root alone needs no weight, it is one patch).
  float area = shadowc_boxArea(whole);
  int rows = shadowc_rootNeedsWalk(shadowc_boxMoments(whole, 0), area, nonPlanarOnly) ? den : 0; SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1 + rows * den)
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < den; ++i) shadowc_qtLeafBox(shadowc_subBox(ivec3(i, j, den)));
#endif
}

#endif
