// vssm.glsl — variance soft shadow mapping (vssm-yang2010), Algorithm 1 L7-L20:
//  L7      search region w_i: the light cone cut at the near plane (frame.glsl);
//  L8-10   min-max early out (minmax.glsl, applied by shadowc_lookup.glsl);
//  L11-15  average blocker depth by eq. 4 over the sub-kernels of w_i,
//            z_occ = (z_avg - P t) / (1 - P),  z_unocc = t,  P = Chebyshev (eq. 1),
//          with the paper's mixed scheme (sec. 6.3): uniform m x m subdivision for the blocker;
//  L16     penumbra kernel w_p from z_occ (PCSS formula, frame.glsl);
//  sec 6.4 contact path: |z_occ - d| < epsilon -> n x n bilinear PCF over w_p;
//  L17-20  visibility over w_p by uniform n x n subdivision (sec. 5.2) or the adaptive quadtree
//          of Algorithm 2 (sec. 5.3): Next/Child read from tables, computed, or fully unrolled.
// Every sub-kernel is classified as in Algorithm 2 L9-L26:
//   E(x) >= d and s^2 < Threshold  -> fully lit, LitArea += T                    (L9-L11)
//   E(x) <  d                      -> normal: accumulate E(x) T, E(x^2) T, T    (L13-L17)
//   otherwise ("non-planar")       -> descend; at a leaf: PCF with FALLBACK_N^2 depth samples
//                                     (sec. 5.1 option 2), or lit when the fallback is off
//                                     (option 1).
// Normal sub-kernels are combined by eq. 5 (area-weighted moments) into one Chebyshev estimate;
// the final visibility is (L VSMArea + LitArea + L1 PCFArea) / (VSMArea + LitArea + PCFArea).
// Guards: eq. 4 is only used when 1 - P > 1e-4 (P -> 1 means no blocker mass, and the
// non-planar case z_avg >= t never reaches it: Chebyshev returns P = 1 there); z_occ is clamped
// to [0, d]; every average divides by an area or count tested > 0 first; no blocker -> lit.
// Kernels are boxes in texel units (texel i covers [i, i+1)). With whole-texel corners the root
// snaps to the texel grid and sub-kernels use integer arithmetic (ix * W / 2^level), so they
// partition the root exactly and one narrower than a texel is empty (area 0) and skipped; with
// fractional corners (SHADOWC_SAT_FRACTIONAL, sat.glsl) root and sub-kernels are continuous boxes.
// State lives in private globals so that the generated unrolled traversal (plain functions with
// builtin types, emitted before this file) can call back into it.
#ifndef SHADOWC_VSSM_GLSL
#define SHADOWC_VSSM_GLSL

vec4 shadowc_vRoot;      // root kernel box (texel units), inside the map
float shadowc_vD;        // biased receiver depth
float shadowc_vMinVariance;
float shadowc_aEx;       // Algorithm 2 VSMEx
float shadowc_aEx2;      // VSMEx2
float shadowc_aVsmArea;  // VSMArea
float shadowc_aLitArea;  // LitArea
float shadowc_aPcfArea;  // PCFArea
float shadowc_aPcfOcc;   // PCFBArea: area-weighted occluded fraction of the PCF leaves
float shadowc_aPcfDepth; // area-weighted sum of the occluding PCF samples' depths (blocker)

void shadowc_vssmBegin(vec4 root, float d) {
  shadowc_vRoot = root;
  shadowc_vD = d;
#if SHADOWC_HAS_SAT
  shadowc_vMinVariance = max(SHADOWC_MIN_VARIANCE, shadowc_satVarianceFloor);  // sat.glsl: int32 noise
#else
  shadowc_vMinVariance = SHADOWC_MIN_VARIANCE;
#endif
  shadowc_aEx = 0.0;
  shadowc_aEx2 = 0.0;
  shadowc_aVsmArea = 0.0;
  shadowc_aLitArea = 0.0;
  shadowc_aPcfArea = 0.0;
  shadowc_aPcfOcc = 0.0;
  shadowc_aPcfDepth = 0.0;
}

// Sub-kernel (ix, iy) of a den x den partition of the root kernel, as a box (uniform walk: den
// is a compile-time constant there, so the divisions fold to multiplications).
vec4 shadowc_subBox(ivec3 node) {
#if SHADOWC_SAT_FRACTIONAL
  vec2 size = shadowc_vRoot.zw - shadowc_vRoot.xy;
  return vec4(shadowc_vRoot.xy + vec2(node.xy) * size / float(node.z),
              shadowc_vRoot.xy + vec2(node.xy + 1) * size / float(node.z));
#else
  ivec2 root = ivec2(shadowc_vRoot.xy);
  ivec2 size = ivec2(shadowc_vRoot.zw) - root;
  return vec4(root + (node.xy * size) / node.z, root + ((node.xy + 1) * size) / node.z);
#endif
}

// The same box for a quadtree node (den = 2^level, dynamic in the walk): with whole-texel corners
// the partition is a shift (ix * W >= 0, so it equals the division), because lavapipe has no
// vector integer divide and splits each one into a scalar divide per lane (nothing per
// node that could be cheaper).
vec4 shadowc_qtBox(ivec3 node) {
#if SHADOWC_SAT_FRACTIONAL
  return shadowc_subBox(node);
#else
  ivec2 root = ivec2(shadowc_vRoot.xy);
  ivec2 size = ivec2(shadowc_vRoot.zw) - root;
  int s = findLSB(node.z);
  return vec4(root + ((node.xy * size) >> s), root + (((node.xy + 1) * size) >> s));
#endif
}

float shadowc_boxArea(vec4 box) { return (box.z - box.x) * (box.w - box.y); }

// What a sub-kernel counts for in Algorithm 2's sums: its area, or with `weights form_factor` its
// area times the weight of the light patch it stands for (the weight at its centre: kernel.glsl,
// shadowc_kernelWeight; midpoint rule over the patch, docs/dsl.md "weights"). Eq. 5 then averages
// moments by weight, and the visibility is the weighted share of the light, as the reference's.
float shadowc_boxWeight(vec4 box) {
#if SHADOWC_WEIGHTED
  return shadowc_boxArea(box) * shadowc_kernelWeight(0.5 * (box.xy + box.zw));
#else
  return shadowc_boxArea(box);
#endif
}

// Algorithm 2 L9-L19 for one sub-kernel of `area` texels with mean moments m: 0 = accepted (lit,
// or normal when `acceptNormal`) or not there (area <= 0: an empty box, or a walk slot without a
// cell; it adds nothing, x + 0.0 being x, whatever m holds), 1 = not accepted (non-planar; or
// normal, which the uniform walk's `always` root does not accept: it walks unless the root is
// fully lit).
// Without a branch: lavapipe runs both sides of a branch masked anyway, and a function with early
// returns costs a return flag and a masked store per exit (callgrind, mixed scheme with the HSM
// on two_planes light 4: 1430 M JIT instructions with the two returns, 1388 M without), so the
// callers classify unconditionally and an absent cell is area 0, not a branch around the call.
int shadowc_classify(vec4 m, float area, bool acceptNormal) {
  bool there = area > 0.0; SHADOWC_COUNT(SHADOWC_WORK_KERNEL_BOXES, there)
  float variance = m.y - m.x * m.x;
  bool lit = there && m.x >= shadowc_vD && variance < SHADOWC_LIT_THRESHOLD;
  bool normal = there && acceptNormal && !lit && m.x < shadowc_vD;
  shadowc_aLitArea += lit ? area : 0.0;
  shadowc_aEx += normal ? m.x * area : 0.0;
  shadowc_aEx2 += normal ? m.y * area : 0.0;
  shadowc_aVsmArea += normal ? area : 0.0;
  return there && !lit && !normal ? 1 : 0;
}

// 0 = lit or normal (accepted), 1 = non-planar.
int shadowc_qtAccept(vec4 m, float area) { return shadowc_classify(m, area, true); }

// Algorithm 2 L6-L19 for one sub-kernel box: 0 = accepted (lit or normal, or empty), 1 = non-planar.
int shadowc_qtClassifyBox(vec4 box) {
  return shadowc_qtAccept(shadowc_boxMoments(box, 0), shadowc_boxWeight(box));
}

// A quadtree node: a leaf as above; an inner node with `weights form_factor` accepts only "lit"
// and descends where it is normal too, so that the light is weighed patch by patch at the leaves
// (a normal box accepted whole would be one patch, weighed uniformly inside).
int shadowc_qtClassifyNode(vec4 box, bool leaf) {
#if SHADOWC_WEIGHTED
  return shadowc_classify(shadowc_boxMoments(box, 0), shadowc_boxWeight(box), leaf);
#else
  return shadowc_qtClassifyBox(box);
#endif
}

// A non-planar leaf (Algorithm 2 L22-L26); `box` is the one its classification read (area > 0).
void shadowc_qtResolveLeaf(vec4 box) {
  float area = shadowc_boxWeight(box);
#if SHADOWC_FALLBACK_PCF
  const int n = SHADOWC_FALLBACK_N;
  vec2 size = box.zw - box.xy;
  float occluded = 0.0;
  float depthSum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
#if SHADOWC_SAT_FRACTIONAL
      ivec2 t = ivec2(floor(box.xy + (vec2(i, j) + 0.5) * size / float(n)));
#else
      ivec2 t = ivec2(box.xy) + ivec2(floor((vec2(i, j) + 0.5) * size / float(n)));
#endif
      float z = shadowc_depthAt(t);
      if (z < SHADOWC_TAP_DEPTH(t, shadowc_vD)) {  // the receiver plane at t (bias.glsl)
        occluded += 1.0;
        depthSum += z;
      }
    }
  float scale = area / float(n * n);
  shadowc_aPcfArea += area;
  shadowc_aPcfOcc += occluded * scale;
  shadowc_aPcfDepth += depthSum * scale;
#else
  shadowc_aLitArea += area;  // option 1 of sec. 5.1: a small non-planar sub-kernel is lit
#endif
}

// Classify a leaf and resolve it when it is non-planar (its box is computed once).
void shadowc_qtLeafBox(vec4 box) {
  if (shadowc_qtClassifyBox(box) == 1) shadowc_qtResolveLeaf(box);
}

#if SHADOWC_FALLBACK_PCF
// The two mask words of the non-planar leaves whose PCF runs after a walk (shadowc_uniformWalk,
// the quadtree walks): bit b (0..63) of lo (b < 32) or hi. Set it when `on`.
void shadowc_markSet(inout uint lo, inout uint hi, int b, bool on) {
  uint m = on ? 1u << (b & 31) : 0u;
  lo |= b < 32 ? m : 0u;
  hi |= b >= 32 ? m : 0u;
}

// The lowest set bit, cleared (the walk's own order); call while (lo | hi) != 0. -1 when both
// words are empty, which only the loop's first iteration in a group whose lanes marked nothing
// sees (lavapipe runs it masked): the callers then read texel (0, 0), which stays in cache,
// instead of a leaf at an arbitrary place (callgrind, 2048^2 map: the masked taps' 52-108 K
// first-level misses a frame went to 0; docs/performance.md "A row of corners a step").
int shadowc_markPop(inout uint lo, inout uint hi) {
  int b = lo != 0u ? findLSB(lo) : hi != 0u ? 32 + findLSB(hi) : -1;
  if (b < 32) lo &= lo - 1u;
  else hi &= hi - 1u;
  return b;
}

// The PCF of the leaf mark b names, whose box is `box`: texel (0, 0) for b = -1 (above).
void shadowc_markResolve(int b, vec4 box) { shadowc_qtResolveLeaf(b < 0 ? vec4(0.0, 0.0, 1.0, 1.0) : box); }
#endif

// Callbacks of the generated unrolled traversal (quadtree_tables.cpp).
bool shadowc_qtVisit(ivec3 node) { SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1) return shadowc_qtClassifyNode(shadowc_qtBox(node), false) == 1; }
void shadowc_qtLeaf(ivec3 node) { SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1) shadowc_qtLeafBox(shadowc_qtBox(node)); }

#include "lookup/uniform_walk.glsl"

#if defined(SHADOWC_QT_NODES)
#if !SHADOWC_QT_TABLE
// Next (Fig. 5) of a node of the full quadtree in pre-order, computed from the node itself
// (`traversal: computed`): climb while the node is its parent's last child (Z order (0,0) (1,0)
// (0,1) (1,1), as quadtree_tables.cpp builds them), then step to the next sibling; the root's
// Next is Null (z = 0). tests/emit/quadtree_tables_test.cpp checks it against the Next table.
ivec3 shadowc_qtNextNode(ivec3 n) {
  // Levels to climb: the trailing ones of ix & iy (a last child has both low bits set), at
  // most the node's level (findLSB(z) for z = 2^level); no loop.
  int up = min(findLSB(~(n.x & n.y)), findLSB(n.z));
  n = ivec3(n.xy >> up, n.z >> up);
  int c = (n.x & 1) + 2 * (n.y & 1) + 1;
  return n.z <= 1 ? ivec3(0) : ivec3((n.x & ~1) | (c & 1), (n.y & ~1) | (c >> 1), n.z);
}
#endif

#if SHADOWC_FALLBACK_PCF
// Leaf (x, y) of a quadtree of height <= 3 as its Morton code (x in the even bits, y in the odd):
// pre-order visits the leaves in Z order, (0,0) (1,0) (0,1) (1,1) at every level, so ascending
// codes are the walk's own order.
int shadowc_qtMorton(ivec2 p) {
  ivec2 s = (p & 1) | ((p & 2) << 1) | ((p & 4) << 2);
  return s.x | (s.y << 1);
}
int shadowc_qtUnmorton(int b) { return (b & 1) | ((b >> 1) & 2) | ((b >> 2) & 4); }
#endif

// With the PCF fallback and height <= 3 the non-planar leaves are marked in two mask words (64
// leaves) and get their PCF after the walk, in the walk's order (Morton order), so each PCF sum is
// bit-identical: lavapipe runs a branch body or a loop's first iteration at every step of every
// group, masked (shadowc_uniformWalk), so a PCF inside the walk cost every group one PCF per step;
// after it, the most any lane of the group needs plus one. Higher trees resolve a leaf in place.
bool shadowc_qtDefers(int height) {
#if SHADOWC_FALLBACK_PCF
  return height <= 3;
#else
  return false;
#endif
}

// One node n = (ix, iy, 2^level) of Algorithm 2 (L6-L26): classify it; a non-planar leaf is
// resolved in place or marked for after the walk. True when the walk takes Child, else Next.
bool shadowc_qtStep(ivec3 n, int height, bool defer, inout uint marksLo, inout uint marksHi) { SHADOWC_COUNT(SHADOWC_WORK_WALK_STEPS, 1)
  vec4 box = shadowc_qtBox(n);
  bool leaf = n.z >= (1 << height);
  bool nonPlanar = shadowc_qtClassifyNode(box, leaf) == 1;
#if SHADOWC_FALLBACK_PCF
  if (defer) {
    shadowc_markSet(marksLo, marksHi, shadowc_qtMorton(n.xy), nonPlanar && leaf);
  } else
#endif
  if (nonPlanar && leaf) shadowc_qtResolveLeaf(box);  // in place (a 0/1-step loop would cost the same)
  return nonPlanar && !leaf;
}

// The PCF of the leaves a walk marked (Morton codes 0..31 in lo, 32..63 in hi), in order.
void shadowc_qtResolveMarked(int height, uint marksLo, uint marksHi) {
#if SHADOWC_FALLBACK_PCF
  while ((marksLo | marksHi) != 0u) {
    int b = shadowc_markPop(marksLo, marksHi);
    shadowc_markResolve(b, shadowc_qtBox(ivec3(shadowc_qtUnmorton(b), shadowc_qtUnmorton(b >> 1), 1 << height)));
  }
#endif
}

#if !SHADOWC_QT_TABLE
// Stackless walk of Algorithm 2 ([Bun05], Fig. 5) with Next/Child computed from the node
// (`traversal: computed`): Child on "descend", else Next. Nodes at level `height` are leaves.
// Bounded by the node count, as the table walk is.
void shadowc_qtComputedWalk(int height) {
  ivec3 n = ivec3(0, 0, 1);
  bool defer = shadowc_qtDefers(height);
  uint marksLo = 0u;
  uint marksHi = 0u;
  for (int step = 0; step < SHADOWC_QT_NODES && n.z > 0; ++step)
    n = shadowc_qtStep(n, height, defer, marksLo, marksHi) ? ivec3(2 * n.xy, 2 * n.z)  // Child: the first of the four
                                                           : shadowc_qtNextNode(n);
  shadowc_qtResolveMarked(height, marksLo, marksHi);
}

#else
// Algorithm 2 as the paper has it (`traversal: table`): TreeNode = TreeNode.Child or
// TreeNode.Next, read from the tables the planner built (resources.glsl shadowc_qtTable), root
// at 0, -1 for Null. The tables may be taller than `height` (one serves the blocker and the
// kernel walk): a node at level `height` is a leaf, and its Next is the same (quadtree_tables.h).
void shadowc_qtTableWalk(int height) {
  int i = 0;
  bool defer = shadowc_qtDefers(height);
  uint marksLo = 0u;
  uint marksHi = 0u;
  for (int step = 0; step < SHADOWC_QT_NODES && i >= 0; ++step) {
    ivec4 t = shadowc_qtTable[i];
    i = shadowc_qtStep(ivec3(t.x & 0xffff, t.x >> 16, t.y), height, defer, marksLo, marksHi) ? t.z : t.w;
  }
  shadowc_qtResolveMarked(height, marksLo, marksHi);
}
#endif
#endif

// Average blocker depth over the search rectangle (L11-L15), or -1 when nothing occludes.
float shadowc_vssmBlocker(vec4 searchBox, float d) {
  shadowc_vssmBegin(searchBox, d);
#if SHADOWC_BLOCKER_SUBDIVISION == SHADOWC_SUBDIV_QUADTREE
#if SHADOWC_QUADTREE_UNROLLED
  shadowc_qtUnrolledBlocker();
#elif SHADOWC_QT_TABLE
  shadowc_qtTableWalk(SHADOWC_BLOCKER_HEIGHT);
#else
  shadowc_qtComputedWalk(SHADOWC_BLOCKER_HEIGHT);
#endif
#elif SHADOWC_BLOCKER_SUBDIVISION == SHADOWC_SUBDIV_UNIFORM
  shadowc_uniformWalk(SHADOWC_BLOCKER_M, SHADOWC_BLOCKER_SUBDIVIDE_NONPLANAR != 0);
#else
  shadowc_uniformWalk(1, false);
#endif
  // Normal group: eq. 5 moments, then eq. 4 with z_unocc = t; its blocker area is (1 - P) T.
  float a1 = 0.0;
  float z1 = 0.0;
  if (shadowc_aVsmArea > 0.0) {
    float mean = shadowc_aEx / shadowc_aVsmArea;
    float meanSq = shadowc_aEx2 / shadowc_aVsmArea;
    float p = shadowc_chebyshev(mean, meanSq, d, shadowc_vMinVariance); SHADOWC_NAIVE_BLOCKER_RETURN(mean, p, d)
    if (1.0 - p > 1e-4) {
      z1 = clamp((mean - p * d) / (1.0 - p), 0.0, d);
      a1 = (1.0 - p) * shadowc_aVsmArea;
    }
  }
  // Non-planar group: the PCF samples' occluding depths (sec. 5.2), weighted by blocker area.
  float a = a1 + shadowc_aPcfOcc;
  if (!(a > 1e-6)) return -1.0;
  return clamp((z1 * a1 + shadowc_aPcfDepth) / a, 0.0, d);
}

// Visibility over the penumbra rectangle (L17-L20, Algorithm 2 L28-L31).
float shadowc_vssmVisibility(vec4 box, float d) {
  shadowc_vssmBegin(box, d);
#if SHADOWC_KERNEL_SUBDIVISION == SHADOWC_SUBDIV_QUADTREE
#if SHADOWC_QUADTREE_UNROLLED
  shadowc_qtUnrolledKernel();
#elif SHADOWC_QT_TABLE
  shadowc_qtTableWalk(SHADOWC_KERNEL_HEIGHT);
#else
  shadowc_qtComputedWalk(SHADOWC_KERNEL_HEIGHT);
#endif
#elif SHADOWC_KERNEL_SUBDIVISION == SHADOWC_SUBDIV_UNIFORM
  shadowc_uniformWalk(SHADOWC_KERNEL_N, SHADOWC_KERNEL_SUBDIVIDE_NONPLANAR != 0);
#else
  shadowc_uniformWalk(1, false);
#endif
  float l = 1.0;
  if (shadowc_aVsmArea > 0.0)
    l = shadowc_reduceBleeding(shadowc_chebyshev(shadowc_aEx / shadowc_aVsmArea, shadowc_aEx2 / shadowc_aVsmArea, d,
                                                 shadowc_vMinVariance));
  float l1 = shadowc_aPcfArea > 0.0 ? 1.0 - shadowc_aPcfOcc / shadowc_aPcfArea : 1.0;
  float total = shadowc_aVsmArea + shadowc_aLitArea + shadowc_aPcfArea;
  if (!(total > 0.0)) return 1.0;
  return shadowc_unit((l * shadowc_aVsmArea + shadowc_aLitArea + l1 * shadowc_aPcfArea) / total);
}

float shadowc_vssm(shadowc_Receiver r) {
  vec4 searchBox = shadowc_kernelBox(r.texel, shadowc_searchTexels(r));
#if SHADOWC_WEIGHTED
  shadowc_weightsKernel(r.texel, shadowc_searchTexels(r));  // the search region stands for the light
#endif
  float zb = shadowc_vssmBlocker(searchBox, r.d); SHADOWC_NAIVE_VSSM_RETURN(zb) SHADOWC_COUNT(SHADOWC_WORK_BLOCKERS_FOUND, zb >= 0.0)
#if SHADOWC_CONTACT
  // sec. 6.4: blocker and receiver nearly touch; the SAT is least precise there and the penumbra
  // is small, so a few bilinear PCF taps are both cheaper and more accurate. Detected on eq. 4's
  // blocker depth, or on z_avg (the plain mean depth of the search region) when it lies just in
  // front of d: right behind a flat occluder 1 - P -> 0 and eq. 4 finds no blocker (or a
  // meaningless one), and the walk returned "lit" before the contact test (stability
  // case contact_before_no_blocker_lit).
  float zAvg = shadowc_boxMoments(searchBox, 0).x;
  bool touching = r.d - zAvg > 0.0 && r.d - zAvg < SHADOWC_CONTACT_EPSILON;
  if (touching || (zb >= 0.0 && abs(r.d - zb) < SHADOWC_CONTACT_EPSILON)) {
#if SHADOWC_KERNEL_PENUMBRA
    float cw = shadowc_penumbraTexels(r, zb >= 0.0 ? zb : zAvg);
#else
    float cw = SHADOWC_KERNEL_FIXED_TEXELS;
#endif
    return shadowc_pcfBilinearGrid(r.texel, cw, r.d, SHADOWC_CONTACT_N);
  }
#endif
  if (zb < 0.0) return 1.0;  // no blocker in the search region
#if SHADOWC_KERNEL_PENUMBRA
  float w = shadowc_penumbraTexels(r, zb);
#else
  float w = SHADOWC_KERNEL_FIXED_TEXELS;
#endif
#if SHADOWC_WEIGHTED
  shadowc_weightsKernel(r.texel, w);
#endif
  return shadowc_vssmVisibility(shadowc_kernelBox(r.texel, w), r.d);
}

#endif
