// The shade pass's typed values (see shade_plan.h). Values mirror templates/lookup/defaults.glsl.
#include "plan/shade_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "plan/image_formats.h"
#include "plan/internal_error.h"
#include "plan/planner.h"
#include "plan/poisson_disk.h"
#include "plan/quadtree_tables.h"
#include "plan/template_codes.h"
#include "spec/precision.h"

namespace shadowc {
namespace {

PointTable poissonTable(std::string name, int count, uint64_t seed) {
  return {std::move(name),
          fmt::format("{} Poisson-disk taps in the unit disk (best candidate, seed {}; pcss-blog)", count, seed),
          poissonDisk(count, seed)};
}

// The checker rejects every spec these catch (E0314, E0417, E0418, E0403, E0411, E0304), so a
// failure here is a shadowc bug, not bad input.
void check(bool ok, const std::string& message) {
  if (!ok) throw InternalError("lookup specialization: " + message);
}

}  // namespace

int quadtreeTableHeight(const FilterSpec& s) {
  if (techniqueCode(s).code != kTechniqueVssm || s.kernel.traversal != QuadtreeTraversal::Table) return 0;
  const int k = s.kernel.subdivision == Subdivision::Quadtree ? s.kernel.quadtreeHeight : 0;
  const int b = s.blocker.subdivision == Subdivision::Quadtree ? s.blocker.quadtreeHeight : 0;
  return std::max(k, b);
}

Specialization planShadeSpecialization(const FilterSpec& s) {
  Specialization out;
  auto defInt = [&](const char* name, long long v) { out.add(name, v); };
  auto defBool = [&](const char* name, bool v) { out.add(name, v); };
  auto defReal = [&](const char* name, double v) { out.add(name, Real{v}); };
  auto defCode = [&](const char* name, EnumCode c) { out.add(name, c); };

  const EnumCode tech = techniqueCode(s);
  const bool moments = s.representation == Representation::Moments;
  const bool vssm = tech.code == kTechniqueVssm;
  const int layers = moments ? s.moments.layers : 1;

  check(layers >= 1, "layers must be >= 1");
  check(!vssm || s.moments.warp == Warp::Linear, "the VSSM blocker estimate (eq. 4) needs the linear warp");
  check(moments || s.blocker.kind != BlockerKind::Moments,
        "the moments blocker estimate needs a moments representation");
  check(!vssm || layers == 1, "the VSSM path works on a single (unlayered) moments map");
  check(!(moments && s.moments.warp == Warp::PowerCdf && s.storage.sat != SatKind::None),
        "power_cdf stores min/max, which a summed-area table cannot sum");

  // ---- technique and resources -----------------------------------------------------------
  defCode("SHADOWC_TECHNIQUE", tech);
  defBool("SHADOWC_HAS_MOMENTS", moments);
  defBool("SHADOWC_HAS_SAT", moments && s.storage.sat != SatKind::None);
  defBool("SHADOWC_HAS_MINMAX", s.earlyOutMinMax);
  const bool splitsTexture = moments && layers > 1 && s.moments.split == SplitPlacement::Lloyd;
  defBool("SHADOWC_HAS_SPLITS_TEXTURE", splitsTexture);

  // ---- light ------------------------------------------------------------------------------
  // A sun's "width" is the slope of its orthographic penumbra, 2 tan(angle / 2) (frame.glsl under
  // SHADOWC_LIGHT_ORTHO); the flag is defined only for a sun, so spot lights emit what they did.
  const bool sun = s.light.type == LightType::Sun;
  if (sun) {
    defBool("SHADOWC_LIGHT_ORTHO", true);
    // The box standing for the sun's disk (frame_ortho.glsl): same second moment, side D sqrt(3)/2;
    // Poisson taps of the depth representation fill a disk and keep the diameter.
    const bool diskTaps = s.representation == Representation::Depth && s.sampling.pattern == PcfPattern::Poisson;
    defReal("SHADOWC_SUN_BOX_SCALE", diskTaps ? 1.0 : std::sqrt(3.0) / 2.0);
  }
  // A point light (frame_cube.glsl): six perspective faces in a 3x3 atlas of the map, each with a
  // guard band; kernels are clamped to what the band holds (docs/dsl.md "Point lights").
  const bool cube = s.light.type == LightType::Point;
  if (cube) {
    defBool("SHADOWC_LIGHT_CUBE", true);
    // The runtime renders faces with tan(half fov) = 1.5 (kCubeTanHalf): a band of
    // g = (1 - 1/1.5) / 2 = 1/6 of the face outside its 90 degrees. A kernel of width w reaches
    // w/2 + 1.5 texels from the receiver, a trilinear fetch at lod log2(w) up to 3w; keep a sixth
    // of the band for a blur prefilter's radius: w <= 1.5 g = 0.25, or g / 3 = 1/18 with mips.
    defReal("SHADOWC_CUBE_KERNEL_MAX", s.prefilter.mips ? 1.0 / 18.0 : 0.25);
  }
  // Cascades: tiles of one atlas (templates/lookup/cascades.glsl); defined only when cascaded.
  check(s.cascades.count == 0 || (sun && !moments && !s.earlyOutMinMax),
        "cascades serve a sun's depth filters without a min-max pyramid (light_rules.cpp)");
  if (s.cascades.count > 0) {
    defInt("SHADOWC_CASCADES", s.cascades.count);
    defInt("SHADOWC_CASCADE_GRID", cascadeGrid(s.cascades.count));
    defReal("SHADOWC_CASCADE_BLEND", s.cascades.blend);
  }
  // Light samples: N hard views of a spot light, tiles of one atlas (lookup/light_samples.glsl);
  // defined only with them. Their offsets on the light are a table (FilterSpec lightSampleOffsets).
  check(s.lightSamples == 0 || (!sun && !cube && !moments && !s.earlyOutMinMax && s.blocker.kind == BlockerKind::None &&
                                s.kernel.size == KernelSize::Fixed),
        "light samples serve a spot's fixed-kernel depth filters (light_rules.cpp)");
  if (s.lightSamples > 0) {
    defInt("SHADOWC_LIGHT_SAMPLES", s.lightSamples);
    defInt("SHADOWC_LIGHT_SAMPLE_GRID", lightSampleGrid(s.lightSamples));
    out.tables.push_back(
        PointTable{"shadowc_lightSampleOffsets",
                   fmt::format("{} light views: centres of equal patches of the light, in light widths (docs/dsl.md "
                               "\"light_samples\")",
                               s.lightSamples),
                   lightSampleOffsets(s.lightSamples, s.light.shape == LightShape::Disk)});
  }
  if (!s.light.sizeFromScene && cube)
    defReal("SHADOWC_LIGHT_WIDTH", 2.0 * s.light.size);  // the sphere's diameter
  else if (!s.light.sizeFromScene)
    defReal("SHADOWC_LIGHT_WIDTH", sun                                  ? sunPenumbraSlope(s.light.angleDegrees)
                                   : s.light.shape == LightShape::Point ? 0.0
                                                                        : s.light.size);

  // ---- bias (pcss-blog slope-scaled form) ---------------------------------------------
  defCode("SHADOWC_BIAS_KIND", biasKindCode(s.bias.kind));
  defReal("SHADOWC_BIAS_CONSTANT", s.bias.constant);
  defReal("SHADOWC_BIAS_SLOPE", s.bias.slope);
  defReal("SHADOWC_NORMAL_OFFSET", s.bias.normalOffset);
  // Only for the receiver-plane policy (bias.glsl), so the other filters' defines are unchanged.
  if (s.bias.kind == BiasKind::ReceiverPlane) defReal("SHADOWC_BIAS_MAX_SLOPE", s.bias.maxSlope);

  // ---- kernel -----------------------------------------------------------------------------
  defBool("SHADOWC_KERNEL_PENUMBRA", s.kernel.size == KernelSize::Penumbra);
  defReal("SHADOWC_KERNEL_FIXED_TEXELS", std::max(1, s.kernel.fixedTexels));
  defReal("SHADOWC_KERNEL_MAX_TEXELS", std::clamp(s.kernel.maxTexels, 1.0, spec::kMaxKernelTexels));
  // An int32 SAT box sum fits in 32 bits up to 255^2 texels (255^2 * 65536 < 2^32): a
  // penumbra kernel wider than 255 texels is summed in pieces of at most 255 a side (sat.glsl).
  const bool int32Sat = moments && s.storage.sat == SatKind::Int32;
  if (int32Sat && s.kernel.size == KernelSize::Penumbra)
    defInt("SHADOWC_SAT_PIECES", s.naiveUnguarded ? 1 : spec::int32SatPieces(s.kernel.maxTexels));
  defCode("SHADOWC_KERNEL_SUBDIVISION", subdivisionCode(s.kernel.subdivision));
  defInt("SHADOWC_KERNEL_N", std::max(1, s.kernel.uniformN));
  defInt("SHADOWC_KERNEL_HEIGHT", s.kernel.quadtreeHeight);
  defBool("SHADOWC_QUADTREE_UNROLLED", s.kernel.traversal == QuadtreeTraversal::Unrolled);
  defReal("SHADOWC_LIT_THRESHOLD", s.kernel.litThreshold);

  // ---- PCF sampling (depth representation, fallback and contact paths) --------------------
  defCode("SHADOWC_PCF_PATTERN", pcfPatternCode(s.sampling.pattern));
  defInt("SHADOWC_PCF_N", std::max(1, s.sampling.gridN));
  defInt("SHADOWC_PCF_TAPS", std::max(1, s.sampling.taps));
  defBool("SHADOWC_ROTATION_STABLE", s.sampling.rotation == Rotation::Stable);

  // ---- blocker ----------------------------------------------------------------------------
  defCode("SHADOWC_BLOCKER_KIND", blockerKindCode(s.blocker.kind));
  defInt("SHADOWC_BLOCKER_TAPS", std::max(1, s.blocker.taps));
  defCode("SHADOWC_BLOCKER_PATTERN", samplePatternCode(s.blocker.pattern));
  defInt("SHADOWC_BLOCKER_GRID_N", std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, s.blocker.taps))))));
  defCode("SHADOWC_BLOCKER_SUBDIVISION", subdivisionCode(s.blocker.subdivision));
  defInt("SHADOWC_BLOCKER_M", std::max(1, s.blocker.uniformM));
  defInt("SHADOWC_BLOCKER_HEIGHT", s.blocker.quadtreeHeight);
  // The uniform walk's mark words and step bound are sized by the larger den (vssm.glsl); a generic
  // shader sizes them for the language's largest m and n (generic_block.cpp).
  if (vssm) {
    const int blockerDen = s.blocker.subdivision == Subdivision::Uniform ? s.blocker.uniformM : 1;
    const int kernelDen = s.kernel.subdivision == Subdivision::Uniform ? s.kernel.uniformN : 1;
    defInt("SHADOWC_UNIFORM_MAX_DEN", std::max({1, blockerDen, kernelDen}));
  }

  // ---- moments ----------------------------------------------------------------------------
  if (moments) {
    defCode("SHADOWC_WARP", warpCode(s.moments.warp));
    defCode("SHADOWC_SAT_KIND", satKindCode(s.storage.sat));
    defBool("SHADOWC_MIPS", s.prefilter.mips);
    defReal("SHADOWC_EXP_POSITIVE", s.moments.positiveExponent);
    defReal("SHADOWC_EXP_NEGATIVE", s.moments.negativeExponent);
    defReal("SHADOWC_MIN_VARIANCE", std::max(0.0, s.moments.minVariance));
    // linstep(a, 1, p) divides by 1 - a (vsm-tutorial, lauritzen2008): keep a < 1.
    defReal("SHADOWC_BLEEDING", std::clamp(s.moments.bleedingReduction, 0.0, 0.999));
    defBool("SHADOWC_BLEEDING_ON", s.moments.bleedingReduction > 0.0);
    defInt("SHADOWC_LAYERS", layers);
    defReal("SHADOWC_OVERLAP", std::max(0.0, s.moments.overlap));
    defBool("SHADOWC_LAYER_BLEND", layers > 1 && s.moments.overlap > 0.0);
    if (s.moments.warp == Warp::Msm) {  // Peters & Klein 2015: sec. 4.3 decoding, Algorithm 3's alpha
      defBool("SHADOWC_MSM_QUANTIZED", msmQuantized(s));
      defReal("SHADOWC_MSM_BIAS", s.moments.momentBias);
    }
    if (layers > 1 && !splitsTexture)
      out.tables.push_back(
          RealTable{"shadowc_splitTable", "Layer split depths s_0..s_N (lauritzen2008 sec. 3.4)", s.moments.splits});
  }

  // ---- extras -----------------------------------------------------------------------------
  defBool("SHADOWC_FALLBACK_PCF", s.fallback.pcf);
  defInt("SHADOWC_FALLBACK_N", std::max(1, s.fallback.n));
  defBool("SHADOWC_CONTACT", s.contact.enabled);
  defInt("SHADOWC_CONTACT_N", std::max(1, s.contact.n));
  defReal("SHADOWC_CONTACT_EPSILON", s.contact.epsilon);
  defBool("SHADOWC_EARLY_OUT", s.earlyOutMinMax);
  defBool("SHADOWC_BACKFACE_SHADOWED", s.backfaceShadowed);
  // Form-factor weights (kernel.glsl): a spot light's only; defined only when on, so unweighted
  // filters emit what they did.
  // With light samples the views are weighted instead (light_samples.glsl), each one's kernel not.
  if (s.formFactorWeights && !sun && !cube && s.lightSamples == 0) defBool("SHADOWC_WEIGHTED", true);
  if (s.formFactorWeights && s.lightSamples > 0) defBool("SHADOWC_LIGHT_SAMPLES_WEIGHTED", true);
  // The early out must cover the blur footprint too (shadowc_lookup.glsl, shadowc_influenceRect).
  if (s.earlyOutMinMax && moments && s.prefilter.blur != BlurKind::None && s.prefilter.blurRadius > 0)
    defInt("SHADOWC_EARLY_OUT_GROW", s.prefilter.blurRadius);
  // Uniform walks that subdivide only a non-planar root (Algorithm 1 L11 / L17; vssm.glsl).
  if (s.blocker.subdivision == Subdivision::Uniform && s.blocker.uniformNonPlanarOnly)
    defBool("SHADOWC_BLOCKER_SUBDIVIDE_NONPLANAR", true);
  if (s.kernel.subdivision == Subdivision::Uniform && s.kernel.uniformNonPlanarOnly)
    defBool("SHADOWC_KERNEL_SUBDIVIDE_NONPLANAR", true);
  // SAT box corners (sat.glsl): fractional = exact integral under the continuous box.
  if (s.storage.sat != SatKind::None && s.storage.fractionalCorners) defBool("SHADOWC_SAT_FRACTIONAL", true);
  // Stability-suite demonstration only (FilterSpec::naiveUnguarded; validation/).
  if (s.naiveUnguarded) defBool("SHADOWC_NAIVE_UNGUARDED", true);

  // ---- generated tables -------------------------------------------------------------------
  const bool depthPoisson =
      (tech.code == kTechniquePcf || tech.code == kTechniquePcss) && s.sampling.pattern == PcfPattern::Poisson;
  if (depthPoisson) {
    out.tables.push_back(poissonTable("shadowc_poissonPcf", std::max(1, s.sampling.taps), 0x5eed0001u));
    defBool("SHADOWC_HAS_POISSON_PCF", true);
  }
  const bool searches =
      tech.code == kTechniquePcss || (tech.code == kTechniqueMoments && s.blocker.kind == BlockerKind::Search);
  if (searches && s.blocker.pattern == SamplePattern::Poisson) {
    out.tables.push_back(poissonTable("shadowc_poissonBlocker", std::max(1, s.blocker.taps), 0x5eed0002u));
    defBool("SHADOWC_HAS_POISSON_BLOCKER", true);
  }
  if (vssm) {
    const bool kernelQt = s.kernel.subdivision == Subdivision::Quadtree;
    const bool blockerQt = s.blocker.subdivision == Subdivision::Quadtree;
    if (kernelQt) check(s.kernel.quadtreeHeight >= 1 && s.kernel.quadtreeHeight <= 5, "quadtree height must be 1..5");
    if (blockerQt)
      check(s.blocker.quadtreeHeight >= 1 && s.blocker.quadtreeHeight <= 5, "quadtree height must be 1..5");
    if (kernelQt || blockerQt) {
      if (s.kernel.traversal == QuadtreeTraversal::Unrolled) {
        if (kernelQt)
          out.tables.push_back(UnrolledQuadtree{s.kernel.quadtreeHeight, "shadowc_qtUnrolledKernel", "shadowc_qtVisit",
                                                "shadowc_qtLeaf"});
        if (blockerQt)
          out.tables.push_back(UnrolledQuadtree{s.blocker.quadtreeHeight, "shadowc_qtUnrolledBlocker",
                                                "shadowc_qtVisit", "shadowc_qtLeaf"});
      } else {
        // One loop walk for both trees, bounded by the larger tree's size. `table` reads Next/Child
        // from the buffer the planner adds (quadtreeTableHeight); `computed` derives them from the
        // node (vssm.glsl shadowc_qtNextNode).
        const int h = std::max(kernelQt ? s.kernel.quadtreeHeight : 0, blockerQt ? s.blocker.quadtreeHeight : 0);
        defInt("SHADOWC_QT_NODES", quadtreeNodeCount(h));
        if (s.kernel.traversal == QuadtreeTraversal::Table) defBool("SHADOWC_QT_TABLE", true);
      }
    }
  }
  return out;
}

}  // namespace shadowc
