// FilterSpec: the checked, normalized description of one shadow filter.
//
// This is the contract between the front end (dsl/ -> spec/check) and the planner/emitter
// (plan/, emit/). Every field has an explicit value after checking: no "unset" survives
// the checker, so the planner never guesses a default. The names of the axes follow
// docs/dsl.md "Settings".
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dsl/source_location.h"

namespace shadowc {

// ---- light -------------------------------------------------------------------------------
// How the light projects onto its shadow map (docs/dsl.md "light"):
//  Spot:  an area light (rect or disk, or a point of width 0) seen through a perspective frustum
//         from its centre: today's light, and the default;
//  Sun:   a directional light of angular diameter `angleDegrees`: an orthographic map fitted to
//         the scene, penumbra (d_r - d_b) 2 tan(angle / 2) (templates/frame.glsl);
//  Point: an omnidirectional sphere light of `size` = radius (cube maps): read by the checker,
//         refused until cube maps exist (E0424 / E0425).
enum class LightType { Spot, Sun, Point };
enum class LightShape { Rect, Disk, Point };
struct LightSpec {
  LightShape shape = LightShape::Rect;
  // Width of the light in world units. sizeFromScene = true means the runtime supplies it
  // through the frame uniforms (ShadowcFrame.lightWidth); false folds `size` into the shader.
  // For a sun the flag says the same of the angle (the runtime supplies 2 tan(angle / 2)).
  bool sizeFromScene = true;
  double size = 0.0;
  LightType type = LightType::Spot;
  double angleDegrees = 0.0;  // Sun only: angular diameter (the sun: about 0.53)
};
// The factor of the orthographic penumbra, w = (d_r - d_b) * sunPenumbraSlope(angle): the
// width of the sun's cone of directions one unit behind a blocker.
double sunPenumbraSlope(double angleDegrees);

// ---- cascades -------------------------------------------------------------------------------
// Cascaded shadow maps for a sun (docs/dsl.md "cascades"): the camera frustum is cut into `count`
// depth slices, each shadowed by its own orthographic map, the maps packed as tiles of one atlas.
// Split i of n (camera depths near..far) is placed by:
//  Uniform:     near + (far - near) i / n
//  Log:         near (far / near)^(i / n)
//  Practical:   lambda * Log + (1 - lambda) * Uniform (Zhang et al. 2006's practical split scheme)
// `blend` is the band, as a fraction of a cascade's depth range, before its far split where the
// lookup mixes it with the next cascade. count 0 = no cascades (one map fitted to the scene).
enum class CascadeSplit { Uniform, Log, Practical };
const char* name(CascadeSplit v);
struct CascadeSpec {
  int count = 0;  // 0: not cascaded; else 1..8
  CascadeSplit split = CascadeSplit::Practical;
  double lambda = 0.5;  // Practical only
  double blend = 0.1;   // [0, 0.5]
};
// Tiles per side of the atlas holding `count` cascades (1, 2x2 for 2..4, 3x3 for 5..8).
int cascadeGrid(int count);

// ---- light samples ---------------------------------------------------------------------------
// `light_samples N` (docs/dsl.md "light_samples"): N = k^2 hard shadow maps, each rendered from the
// centre of one of k x k equal-area patches of the light (a rect's grid cells, or their
// concentric map onto a disk, Shirley & Chiu 1997), tiles of one atlas; the lookup filters each
// with the filter's PCF and sums them with the weights of the shadowing term, so the estimate
// converges to the reference as N grows. 0 = one map from the light's centre.
inline constexpr int kMaxLightSamples = 256;
// Tiles per side of the atlas: k = sqrt(N) (the checker accepts squares only).
int lightSampleGrid(int count);
// Where sample i sits on the light, in the light view's z = 0 plane, in units of the light's
// width (x, y in [-0.5, 0.5]): the centre of grid cell (i mod k, i div k), mapped onto the disk of
// diameter 1 for a disk light. The one definition the shader's table and the runtime's views
// share (through the manifest's spec).
std::vector<std::pair<double, double>> lightSampleOffsets(int count, bool disk);

// ---- representation ----------------------------------------------------------------------
// What the prefilter passes store per shadow-map texel.
enum class Representation {
  Depth,    // plain depth, visibility by comparison (hard, PCF, PCSS)
  Moments,  // warped moments, visibility by an estimator (VSM, ESM, EVSM, power-CDF, VSSM)
};
enum class Warp {
  Linear,    // (z, z^2): VSM / VSSM, Chebyshev (vsm-tutorial, vssm-yang2010 eq. 1)
  Exp,       // exp(c z): ESM
  Evsm2,     // (exp(c+ z), exp(c+ z)^2): positive EVSM
  Evsm4,     // (exp(c+ z), exp(c+ z)^2, -exp(-c- z), exp(-c- z)^2)
  PowerCdf,  // (min, max, mean): power-CDF shadow maps
  Msm,       // (z, z^2, z^3, z^4): Hamburger 4MSM (Peters & Klein 2015, Algorithm 3)
};
// The DSL's spelling of a warp (docs/dsl.md: "linear", "power_cdf", ...), for JSON and messages.
const char* name(Warp v);
enum class SplitPlacement { Uniform, Explicit, Lloyd };
struct MomentsSpec {
  Warp warp = Warp::Linear;
  int layers = 1;  // >= 1; layered VSM (lauritzen2008) when > 1
  SplitPlacement split = SplitPlacement::Uniform;
  std::vector<double> splits;      // layers+1 boundaries in [0,1] depth after checking
  double overlap = 0.0;            // delta of lauritzen2008 sec. 4, in normalized depth
  double positiveExponent = 40.0;  // c+ for Exp/Evsm2/Evsm4
  double negativeExponent = 5.0;   // c- for Evsm4
  double minVariance = 1e-5;       // VSM minimum variance (per layer when layered)
  double bleedingReduction = 0.0;  // 0 = off; else Lauritzen's linstep(amount, 1, p)
  int lloydIterations = 8;         // for SplitPlacement::Lloyd (needs scene histogram)
  double momentBias = 3e-5;        // Msm: alpha of b' = (1 - alpha) b + alpha b* (Algorithm 3)
};

// ---- storage -----------------------------------------------------------------------------
enum class StorageFormat { Fp32, Fp16, Unorm16 };
enum class SatKind {
  None,
  Int32,         // uint32 16.16 fixed point, wrap-around sums (Lauritzen 2007, vssm sec. 6.4)
  Fp32Centered,  // fp32 sums of (value - 0.5): the usual precision fix
  Fp32Naive,     // plain fp32 sums: kept only so the stability suite can show it failing
};
struct StorageSpec {
  StorageFormat format = StorageFormat::Fp32;
  SatKind sat = SatKind::None;
  // SAT box corners: whole texels (the box snaps to the texel grid, so visibility is constant
  // per texel) or fractional, the exact integral of the texels under the continuous box read as
  // a bilinear interpolation of the SAT (sat.glsl). `sat(K, corners: C)`.
  bool fractionalCorners = false;
};

// ---- prefilter ---------------------------------------------------------------------------
enum class BlurKind { None, Box, Gaussian };
struct PrefilterSpec {
  BlurKind blur = BlurKind::None;
  int blurRadius = 0;  // texels; separable, two passes
  bool mips = false;   // build a mip chain of the representation (trilinear lookups)
};

// ---- blocker estimate --------------------------------------------------------------------
enum class BlockerKind {
  None,     // fixed kernel: no blocker search
  Search,   // PCSS blocker search (pcss-blog)
  Moments,  // VSSM eq. 4: z_occ = (z_avg - P t) / (1 - P), vssm-yang2010 sec. 4.2
};
enum class SamplePattern { Grid, Poisson };
enum class Subdivision { None, Uniform, Quadtree };
// The largest uniform subdivisions the checker accepts (blocker m x m, kernel n x n). The uniform
// walk of vssm.glsl marks non-planar sub-kernels in two uint words when den^2 <= 64 and bounds its
// loop by den (SHADOWC_UNIFORM_MAX_DEN), so a generic shader, whose m and n are uniforms, sizes
// those for the larger of the two.
inline constexpr int kMaxUniformM = 16;
inline constexpr int kMaxUniformN = 32;
struct BlockerSpec {
  BlockerKind kind = BlockerKind::None;
  int taps = 16;  // Search: number of taps
  SamplePattern pattern = SamplePattern::Poisson;
  Subdivision subdivision = Subdivision::Uniform;  // Moments: paper's mixed scheme uses m = 5
  int uniformM = 5;
  int quadtreeHeight = 3;
  // Uniform: subdivide only a non-planar search region (z_avg >= d, Algorithm 1 L11-L15), or
  // always (m^2 box reads). `uniform(m, subdivide: always|nonplanar)`.
  bool uniformNonPlanarOnly = false;
};

// ---- kernel ------------------------------------------------------------------------------
enum class KernelSize { Fixed, Penumbra };
// Algorithm 2's walk: Next/Child read from tables in a buffer, computed from the node, or unrolled.
enum class QuadtreeTraversal { Table, Computed, Unrolled };
// The one range of quadtree heights (kernel and blocker): the checker rejects others (E0314),
// so the lookup specialization and the table builder may assert it.
inline constexpr int kMinQuadtreeHeight = 1;
inline constexpr int kMaxQuadtreeHeight = 5;
struct KernelSpec {
  KernelSize size = KernelSize::Penumbra;
  int fixedTexels = 3;  // Fixed: kernel width in texels (odd)
  Subdivision subdivision = Subdivision::None;
  int uniformN = 8;                   // Uniform n x n (vssm sec. 5.2)
  bool uniformNonPlanarOnly = false;  // Uniform: subdivide only a non-planar w_p (Algorithm 1 L17-L20)
  int quadtreeHeight = 3;             // Quadtree of height H (vssm sec. 5.3)
  QuadtreeTraversal traversal = QuadtreeTraversal::Table;
  double maxTexels = 64;       // clamp of penumbra-driven kernel width
  double litThreshold = 1e-4;  // Algorithm 2 "Threshold" (vssm sec. 6.5)
};

// ---- sampling (depth representation) -----------------------------------------------------
enum class PcfPattern { Grid, Bilinear, Poisson };
enum class Rotation { None, Stable };  // stable per world position (pcss-blog)
struct SamplingSpec {
  PcfPattern pattern = PcfPattern::Grid;
  int gridN = 3;  // Grid/Bilinear: n x n
  int taps = 16;  // Poisson: k taps
  Rotation rotation = Rotation::Stable;
};

// ---- extras ------------------------------------------------------------------------------
enum class BiasKind { Constant, SlopeScaled, NormalOffset, ReceiverPlane };
struct BiasSpec {
  BiasKind kind = BiasKind::Constant;
  double constant = 1e-3;  // Constant: b; SlopeScaled: max(slope*(1 - N.L), constant)
  double slope = 5e-3;
  double normalOffset = 0;  // NormalOffset: world units along N, scaled by texel size
  // ReceiverPlane (Isidoro 2006): each tap compares against the receiver's tangent plane at that
  // texel, d + dot(dd/dtexel, tap - centre) - constant; the plane's depth slope (light-view depth
  // per unit across the light's direction) is clamped to maxSlope: 50 (88.9 degrees from the
  // light) is the language default; 10 clamped the 3-degree `grazing` floor (slope 19) and left
  // 37 % acne under PCSS, 50 leaves 0.05 % (docs/accuracy.md "Bias").
  double maxSlope = 50;
};
struct FallbackSpec {
  bool pcf = false;  // PCF on non-planar leaves (vssm sec. 5.2 option 2)
  int n = 2;
};
struct ContactSpec {
  bool enabled = false;  // vssm sec. 6.4: |z_avg - d| < epsilon -> n x n PCF
  int n = 3;
  double epsilon = 0.01;
};

// What the engine's light-depth pass leaves for the filter (docs/dsl.md "depth_input"): `linear`
// is the r32f normalized linear depth (z - near) / (far - near) every lookup reads
// (templates/frame.glsl); a hardware format is the depth attachment itself, which the manifest's
// first pass (passes/depth_convert.comp) turns into that linear depth. The projection follows the
// light: perspective for a spot and each face of a point light, orthographic for a sun.
enum class DepthInputFormat { Linear, D32, D24 };
struct DepthInputSpec {
  DepthInputFormat format = DepthInputFormat::Linear;
  bool reversed = false;  // reverse-Z: near at 1, far at 0 (compare GREATER, clear 0)
  friend bool operator==(const DepthInputSpec&, const DepthInputSpec&) = default;
};
const char* name(DepthInputFormat v);

struct FilterSpec {
  std::string name;
  SourceLocation location;  // of the `filter` keyword
  LightSpec light;
  Representation representation = Representation::Depth;
  MomentsSpec moments;
  StorageSpec storage;
  PrefilterSpec prefilter;
  BlockerSpec blocker;
  KernelSpec kernel;
  SamplingSpec sampling;
  BiasSpec bias;
  FallbackSpec fallback;
  ContactSpec contact;
  bool earlyOutMinMax = false;  // min-max hierarchical shadow map (vssm sec. 6.1)
  // `backface shadowed`: a receiver with the whole light behind its tangent plane gets 0, the
  // shadowing term's value there (docs/scenes.md; one dot product before any fetch); `filtered`
  // runs the filter for it too (two-sided surfaces whose normal may face away from the light).
  bool backfaceShadowed = true;
  // `weights form_factor`: every tap, sub-kernel and quadtree leaf counts with the form factor
  // (cos_receiver cos_light / r^2) of the light patch it stands for, as the reference weighs the
  // light; `uniform` counts the visible fraction of the light (docs/dsl.md "weights").
  bool formFactorWeights = false;
  CascadeSpec cascades;  // a sun only (checker, light_rules.cpp)
  DepthInputSpec depthInput;
  int lightSamples = 0;  // a spot's depth filters only (checker, light_rules.cpp)
  // Largest shadow-map side (texels) the precision checks assume: SAT sums of W^2 texels
  // lower the EVSM exponent limit by ln(W^2)/2 (docs/dsl.md "Exponent limits"). The runtime must not
  // run the filter on a larger map. Setting `map_size`.
  int mapSize = 2048;
  // The shadow-map side the filter is planned for (`resolution N`, `shadowc plan --max-map`): what
  // an engine allocates, what `validate` renders unless --map says otherwise; 0 = the engine's
  // choice. Without an explicit map_size, map_size follows it (normalize.cpp).
  int resolution = 0;
  // Debug only, not reachable from the DSL: read every int32 SAT box with one 4-corner sum
  // however wide (no pieces, sat.glsl), and drop the NaN/Inf guards of the VSSM blocker
  // estimate (eq. 4's 1/(1 - P)) and the final [0, 1] sanitation, so the stability suite
  // (validation/, docs/stability.md) can show the naive form failing. Never set by the checker.
  bool naiveUnguarded = false;
};

}  // namespace shadowc
