// defaults.glsl — the specialization constants of the lookup and their defaults.
// compiler/emit/lookup_specialization.cpp defines every one of these from the FilterSpec;
// the defaults let the templates compile on their own (a 3x3 PCF) and document the meaning.
#ifndef SHADOWC_DEFAULTS_GLSL
#define SHADOWC_DEFAULTS_GLSL

// ---- enumerations (values fixed by lookup_specialization.cpp) ------------------------------
#define SHADOWC_TECHNIQUE_PCF 0      // depth map, fixed kernel
#define SHADOWC_TECHNIQUE_PCSS 1     // depth map, blocker search + penumbra kernel
#define SHADOWC_TECHNIQUE_MOMENTS 2  // moments (VSM/ESM/EVSM/power-CDF, layered), filtered kernel
#define SHADOWC_TECHNIQUE_VSSM 3     // moments + VSSM blocker estimate (vssm-yang2010)
#define SHADOWC_WARP_LINEAR 0
#define SHADOWC_WARP_EXP 1
#define SHADOWC_WARP_EVSM2 2
#define SHADOWC_WARP_EVSM4 3
#define SHADOWC_WARP_POWER_CDF 4
#define SHADOWC_WARP_MSM 5
#define SHADOWC_SAT_NONE 0
#define SHADOWC_SAT_INT32 1
#define SHADOWC_SAT_FP32_CENTERED 2
#define SHADOWC_SAT_FP32_NAIVE 3
#define SHADOWC_SUBDIV_NONE 0
#define SHADOWC_SUBDIV_UNIFORM 1
#define SHADOWC_SUBDIV_QUADTREE 2
#define SHADOWC_PATTERN_GRID 0
#define SHADOWC_PATTERN_BILINEAR 1
#define SHADOWC_PATTERN_POISSON 2
#define SHADOWC_BLOCKER_NONE 0
#define SHADOWC_BLOCKER_SEARCH 1
#define SHADOWC_BLOCKER_MOMENTS 2
#define SHADOWC_BIAS_CONSTANT_KIND 0
#define SHADOWC_BIAS_SLOPE_SCALED_KIND 1
#define SHADOWC_BIAS_NORMAL_OFFSET_KIND 2
#define SHADOWC_BIAS_RECEIVER_PLANE_KIND 3

// ---- resources ------------------------------------------------------------------------------
#ifndef SHADOWC_SET
#define SHADOWC_SET 0  // descriptor set of bindings 4..8 (engines may move them)
#endif
#ifndef SHADOWC_BINDING_DEPTH
#define SHADOWC_BINDING_DEPTH 4
#endif
#ifndef SHADOWC_BINDING_MOMENTS
#define SHADOWC_BINDING_MOMENTS 5
#endif
#ifndef SHADOWC_BINDING_SAT
#define SHADOWC_BINDING_SAT 6
#endif
#ifndef SHADOWC_BINDING_MINMAX
#define SHADOWC_BINDING_MINMAX 7
#endif
#ifndef SHADOWC_BINDING_SPLITS
#define SHADOWC_BINDING_SPLITS 8
#endif
#ifndef SHADOWC_BINDING_QUADTREE
#define SHADOWC_BINDING_QUADTREE 10  // the quadtree's Next/Child tables (9: a generic shader's block)
#endif

// ---- technique --------------------------------------------------------------------------------
#ifndef SHADOWC_TECHNIQUE
#define SHADOWC_TECHNIQUE SHADOWC_TECHNIQUE_PCF
#endif
#ifndef SHADOWC_HAS_MOMENTS
#define SHADOWC_HAS_MOMENTS 0
#endif
#ifndef SHADOWC_HAS_SAT
#define SHADOWC_HAS_SAT 0
#endif
#ifndef SHADOWC_HAS_MINMAX
#define SHADOWC_HAS_MINMAX 0
#endif
#ifndef SHADOWC_HAS_SPLITS_TEXTURE
#define SHADOWC_HAS_SPLITS_TEXTURE 0  // Lloyd split placement: splits read from binding 8
#endif
#ifndef SHADOWC_HAS_POISSON_PCF
#define SHADOWC_HAS_POISSON_PCF 0
#endif
#ifndef SHADOWC_HAS_POISSON_BLOCKER
#define SHADOWC_HAS_POISSON_BLOCKER 0
#endif

// ---- bias (normalized depth units) ----------------------------------------------------------
#ifndef SHADOWC_BIAS_KIND
#define SHADOWC_BIAS_KIND SHADOWC_BIAS_CONSTANT_KIND
#endif
#ifndef SHADOWC_BIAS_CONSTANT
#define SHADOWC_BIAS_CONSTANT 1e-3
#endif
#ifndef SHADOWC_BIAS_SLOPE
#define SHADOWC_BIAS_SLOPE 5e-3
#endif
#ifndef SHADOWC_NORMAL_OFFSET
#define SHADOWC_NORMAL_OFFSET 0.0  // along N, in shadow-map texels at the receiver
#endif
#ifndef SHADOWC_BIAS_MAX_SLOPE
#define SHADOWC_BIAS_MAX_SLOPE 50.0  // receiver plane: clamp of its depth slope (bias.glsl)
#endif

// ---- kernel (texels of the shadow map) ------------------------------------------------------
#ifndef SHADOWC_KERNEL_PENUMBRA
#define SHADOWC_KERNEL_PENUMBRA 0
#endif
#ifndef SHADOWC_KERNEL_FIXED_TEXELS
#define SHADOWC_KERNEL_FIXED_TEXELS 3.0
#endif
#ifndef SHADOWC_KERNEL_MAX_TEXELS
#define SHADOWC_KERNEL_MAX_TEXELS 4096.0  // clamps search and penumbra kernels (and the map does)
#endif
#ifndef SHADOWC_SAT_PIECES
#define SHADOWC_SAT_PIECES 1  // pieces per axis of the widest int32 SAT box (sat.glsl)
#endif
#ifndef SHADOWC_BACKFACE_SHADOWED
#define SHADOWC_BACKFACE_SHADOWED 1  // the whole light behind the tangent plane -> 0 (shadowc_lookup.glsl)
#endif
#ifndef SHADOWC_LIGHT_SAMPLES_WEIGHTED
#define SHADOWC_LIGHT_SAMPLES_WEIGHTED 0  // form-factor weights of the light views (light_samples.glsl)
#endif
#ifndef SHADOWC_WEIGHTED
#define SHADOWC_WEIGHTED 0  // form-factor weights of a spot light's patches (kernel.glsl)
#endif
#ifndef SHADOWC_KERNEL_SUBDIVISION
#define SHADOWC_KERNEL_SUBDIVISION SHADOWC_SUBDIV_NONE
#endif
#ifndef SHADOWC_KERNEL_N
#define SHADOWC_KERNEL_N 8
#endif
#ifndef SHADOWC_KERNEL_HEIGHT
#define SHADOWC_KERNEL_HEIGHT 3
#endif
#ifndef SHADOWC_QUADTREE_UNROLLED
#define SHADOWC_QUADTREE_UNROLLED 0
#endif
#ifndef SHADOWC_QT_TABLE
#define SHADOWC_QT_TABLE 0  // 1: the walk reads Next/Child from shadowc_qtTable (resources.glsl)
#endif
#ifndef SHADOWC_LIT_THRESHOLD
#define SHADOWC_LIT_THRESHOLD 1e-4
#endif

// ---- PCF sampling ------------------------------------------------------------------------------
#ifndef SHADOWC_PCF_PATTERN
#define SHADOWC_PCF_PATTERN SHADOWC_PATTERN_GRID
#endif
#ifndef SHADOWC_PCF_N
#define SHADOWC_PCF_N 3
#endif
#ifndef SHADOWC_PCF_TAPS
#define SHADOWC_PCF_TAPS 16
#endif
#ifndef SHADOWC_ROTATION_STABLE
#define SHADOWC_ROTATION_STABLE 1
#endif
#ifndef SHADOWC_ROTATION_CELLS
#define SHADOWC_ROTATION_CELLS 4096.0  // rotation cells per world unit (stable per position)
#endif

// ---- blocker ----------------------------------------------------------------------------------
#ifndef SHADOWC_BLOCKER_KIND
#define SHADOWC_BLOCKER_KIND SHADOWC_BLOCKER_NONE
#endif
#ifndef SHADOWC_BLOCKER_TAPS
#define SHADOWC_BLOCKER_TAPS 16
#endif
#ifndef SHADOWC_BLOCKER_PATTERN
#define SHADOWC_BLOCKER_PATTERN 0  // 0 grid, 1 Poisson
#endif
#ifndef SHADOWC_BLOCKER_GRID_N
#define SHADOWC_BLOCKER_GRID_N 4
#endif
#ifndef SHADOWC_BLOCKER_SUBDIVISION
#define SHADOWC_BLOCKER_SUBDIVISION SHADOWC_SUBDIV_UNIFORM
#endif
#ifndef SHADOWC_BLOCKER_M
#define SHADOWC_BLOCKER_M 5
#endif
#ifndef SHADOWC_BLOCKER_HEIGHT
#define SHADOWC_BLOCKER_HEIGHT 3
#endif
// The largest den of this shader's uniform walks (vssm.glsl sizes its marks and step bound by it); the
// planner defines it for every VSSM filter, the language's largest n (kMaxUniformN) otherwise.
#ifndef SHADOWC_UNIFORM_MAX_DEN
#define SHADOWC_UNIFORM_MAX_DEN 32
#endif

// ---- moments -----------------------------------------------------------------------------------
#ifndef SHADOWC_WARP
#define SHADOWC_WARP SHADOWC_WARP_LINEAR
#endif
#ifndef SHADOWC_SAT_KIND
#define SHADOWC_SAT_KIND SHADOWC_SAT_NONE
#endif
#ifndef SHADOWC_MIPS
#define SHADOWC_MIPS 0
#endif
// Uniform walks: 1 = subdivide only when the root box is non-planar (vssm-yang2010 Algorithm 1).
#ifndef SHADOWC_BLOCKER_SUBDIVIDE_NONPLANAR
#define SHADOWC_BLOCKER_SUBDIVIDE_NONPLANAR 0
#endif
#ifndef SHADOWC_KERNEL_SUBDIVIDE_NONPLANAR
#define SHADOWC_KERNEL_SUBDIVIDE_NONPLANAR 0
#endif
// SAT box corners: 0 = whole texels, 1 = fractional (sat.glsl, `sat(K, corners: bilinear)`).
#ifndef SHADOWC_SAT_FRACTIONAL
#define SHADOWC_SAT_FRACTIONAL 0
#endif
#ifndef SHADOWC_EXP_POSITIVE
#define SHADOWC_EXP_POSITIVE 40.0
#endif
#ifndef SHADOWC_EXP_NEGATIVE
#define SHADOWC_EXP_NEGATIVE 5.0
#endif
#ifndef SHADOWC_MIN_VARIANCE
#define SHADOWC_MIN_VARIANCE 1e-5
#endif
#ifndef SHADOWC_BLEEDING
#define SHADOWC_BLEEDING 0.0  // linstep(a, 1, p) light-bleeding reduction amount a
#endif
#ifndef SHADOWC_BLEEDING_ON
#define SHADOWC_BLEEDING_ON 0  // 1 when SHADOWC_BLEEDING > 0 (preprocessor-visible)
#endif
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#ifndef SHADOWC_OVERLAP
#define SHADOWC_OVERLAP 0.0
#endif
#ifndef SHADOWC_LAYER_BLEND
#define SHADOWC_LAYER_BLEND 0  // 1 when layers > 1 and overlap > 0 (preprocessor-visible)
#endif

// ---- extras ------------------------------------------------------------------------------------
#ifndef SHADOWC_FALLBACK_PCF
#define SHADOWC_FALLBACK_PCF 0
#endif
#ifndef SHADOWC_FALLBACK_N
#define SHADOWC_FALLBACK_N 2
#endif
#ifndef SHADOWC_CONTACT
#define SHADOWC_CONTACT 0
#endif
#ifndef SHADOWC_CONTACT_N
#define SHADOWC_CONTACT_N 3
#endif
#ifndef SHADOWC_CONTACT_EPSILON
#define SHADOWC_CONTACT_EPSILON 0.01
#endif
#ifndef SHADOWC_EARLY_OUT
#define SHADOWC_EARLY_OUT 0
#endif
#ifndef SHADOWC_EARLY_OUT_GROW
#define SHADOWC_EARLY_OUT_GROW 0  // texels the prefilter spreads a depth by (blur radius)
#endif

// ---- stability-suite demonstration (FilterSpec::naiveUnguarded; docs/stability.md) ----------
// 1: eq. 4 of vssm-yang2010 as printed (no 1 - P guard, no clamp), the raw blocker depth written
// to the visibility image without sanitation, so the suite can show the naive form failing (the
// planner also gives such a spec SHADOWC_SAT_PIECES 1: int32 SAT boxes in one piece, however wide).
// Single-line hooks so that the normal path's text and line numbers do not change.
#ifndef SHADOWC_NAIVE_UNGUARDED
#define SHADOWC_NAIVE_UNGUARDED 0
#endif
#if SHADOWC_NAIVE_UNGUARDED
#define SHADOWC_NAIVE_BLOCKER_RETURN(mean, p, d) return (mean - p * d) / (1.0 - p);
#define SHADOWC_NAIVE_VSSM_RETURN(zb) return zb;
#define SHADOWC_NAIVE_SANITIZE(v) (v)
#define SHADOWC_NAIVE_STORE_RAW(v) { imageStore(visibility, pixel, vec4(v, 0.0, 0.0, 0.0)); return; }
#else
#define SHADOWC_NAIVE_BLOCKER_RETURN(mean, p, d)
#define SHADOWC_NAIVE_VSSM_RETURN(zb)
#define SHADOWC_NAIVE_SANITIZE(v) shadowc_unit(v)
#define SHADOWC_NAIVE_STORE_RAW(v)
#endif

// ---- work counters (docs/manifest.md "Work counters"; compile --counters) --------------------
// 1: the instrumented build, whose hooks counters.glsl defines. Every hook sits at the end of an
// existing line and expands to nothing here, so a plain build's text is the same as without them.
#ifndef SHADOWC_COUNTERS
#define SHADOWC_COUNTERS 0
#endif
#ifndef SHADOWC_BINDING_WORK
#define SHADOWC_BINDING_WORK 11
#endif
#if !SHADOWC_COUNTERS
#define SHADOWC_COUNT(k, n)
#define SHADOWC_WORK_BEGIN(receiver)
#define SHADOWC_WORK_END
#define SHADOWC_COUNT_DEPTH_BLOCK(texel)
#endif

#endif
