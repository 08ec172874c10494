// Normalization (checker phase 2): defaults that depend on other settings; docs/dsl.md lists them.
#include "spec/normalize.h"

#include <algorithm>
#include <cmath>

#include "spec/precision.h"

namespace shadowc::spec {

void normalize(FilterSpec& spec, const SettingsRead& given) {
  // A planned resolution above the default map_size raises it (the precision checks below read it);
  // above an explicit one it is E0460 (combination_rules.cpp).
  if (!given.mapSize && spec.resolution > spec.mapSize) spec.mapSize = spec.resolution;
  MomentsSpec& m = spec.moments;
  const bool moments = spec.representation == Representation::Moments;
  if (!moments) m.layers = 1;
  // Kernel: penumbra-driven when there is a blocker estimate; otherwise a fixed region that
  // matches the PCF sampling (grid/bilinear NxN -> N rounded up to odd, Poisson -> 5, none -> 1).
  if (!given.kernel) {
    KernelSpec& k = spec.kernel;
    k.subdivision = Subdivision::None;
    if (spec.blocker.kind != BlockerKind::None) {
      k.size = KernelSize::Penumbra;
    } else {
      k.size = KernelSize::Fixed;
      int w = 1;
      if (given.sampling && spec.sampling.pattern != PcfPattern::Poisson) w = spec.sampling.gridN | 1;
      if (given.sampling && spec.sampling.pattern == PcfPattern::Poisson) w = 5;
      k.fixedTexels = w;
    }
  }
  // Kernel max: what the storage supports. A summed-area table answers a box of
  // any size at the same cost (the int32 one in exact pieces of <= 255 texels, sat.glsl), so a
  // penumbra kernel over a SAT is clamped only by the map. Depth taps, mip chains and the min-max
  // pyramid keep 64: their levels are sized from `max` and taps spread over it.
  if (!given.kernelMax && moments && spec.storage.sat != SatKind::None) spec.kernel.maxTexels = kMaxKernelTexels;
  // Sampling (depth representation): a fixed kernel of W texels is sampled W x W; a penumbra
  // kernel with Poisson taps and stable rotation (pcss-blog).
  if (!given.sampling && !moments) {
    if (spec.kernel.size == KernelSize::Fixed)
      spec.sampling = SamplingSpec{PcfPattern::Grid, spec.kernel.fixedTexels, 16, Rotation::Stable};
    else
      spec.sampling = SamplingSpec{PcfPattern::Poisson, 3, 16, Rotation::Stable};
  }
  // Exponents: the default is the largest safe one for the storage, at most 40 / 5.
  const ExponentLimit limit = warpExponentLimit(spec.storage, spec.mapSize);
  const double safe = std::floor(limit.maxExponent * 10.0) / 10.0;
  const bool exponential = moments && (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4);
  if (!given.exponent && exponential) m.positiveExponent = std::min(40.0, safe);
  if (!given.negativeExponent && exponential) m.negativeExponent = std::min(5.0, safe);
  // fp16 moments need a larger variance floor (vsm-tutorial: variance = max(variance, 0.0005)).
  if (!given.minVariance && moments && spec.storage.format == StorageFormat::Fp16 && spec.storage.sat == SatKind::None)
    m.minVariance = 5e-4;
  // Moment bias: the paper's 3e-5 for 16-bit storage (unorm16 or the 16.16 int32 SAT, both
  // quantized by sec. 4.3); fp32 needs less, 3e-6 (precision.h, docs/techniques.md).
  if (!given.momentBias && moments && m.warp == Warp::Msm) m.momentBias = msmDefaultBias(spec.storage);
  // Splits: layers+1 boundaries in [0,1]. Lloyd starts uniform; the planner refines them with
  // the scene's depth histogram (lauritzen2008 sec. 4.1).
  if (m.split == SplitPlacement::Explicit && given.explicitOk) {
    m.splits = given.explicitSplits;
  } else {
    m.splits.clear();
    for (int i = 0; i <= m.layers; ++i) m.splits.push_back(static_cast<double>(i) / m.layers);
  }
  if (spec.prefilter.blur == BlurKind::None) spec.prefilter.blurRadius = 0;
  // Non-planar sub-kernels (z_avg >= d) of subdivided VSSM walks: PCF with 2x2 samples, the
  // paper's choice for its small sub-kernels (vssm-yang2010 sec. 5.1 option 2), unless `fallback
  // none` asks for option 1 (lit). Without any subdivision the "sub-kernel" is the whole search
  // or penumbra box, where 2x2 samples measured worse than lit (docs/accuracy.md
  // "VSSM options"), so the default stays none there.
  const bool subdivided = spec.kernel.subdivision != Subdivision::None || spec.blocker.subdivision != Subdivision::None;
  if (!given.fallback && moments && spec.blocker.kind == BlockerKind::Moments && subdivided)
    spec.fallback = FallbackSpec{true, 2};
}

}  // namespace shadowc::spec
