// The combination rules as one table (docs/dsl.md "Impossible combinations" and "Warnings").
// A row: the diagnostic (code and message format from dsl/diagnostics.def), the token the caret
// points at, when the rule fires, and the message's arguments. Rows fire in table order; the
// front end sorts diagnostics by location afterwards.
#include "spec/combination_rules.h"

#include <fmt/args.h>

#include <algorithm>
#include <cmath>

#include "spec/precision.h"

namespace shadowc::spec {
namespace {

using dsl::DiagId;

// What the rules ask about, computed once.
struct Facts {
  const FilterSpec& s;
  const SettingsRead& r;
  bool moments = false, sat = false, int32Sat = false, chebyshev = false, exponential = false, fp16 = false;
  ExponentLimit limit;
  // Explicit splits with the right count: the first boundary out of order (-1: none) and why.
  int badSplit = -1;
  const char* badSplitReason = "";
  double narrowest = 1.0;  // narrowest layer (normalized depth)

  Facts(const FilterSpec& spec, const SettingsRead& given) : s(spec), r(given) {
    const MomentsSpec& m = s.moments;
    moments = s.representation == Representation::Moments;
    sat = s.storage.sat != SatKind::None;
    int32Sat = s.storage.sat == SatKind::Int32;
    chebyshev = m.warp == Warp::Linear || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4;
    exponential = moments && (m.warp == Warp::Exp || m.warp == Warp::Evsm2 || m.warp == Warp::Evsm4);
    fp16 = s.storage.format == StorageFormat::Fp16;
    limit = warpExponentLimit(s.storage, s.mapSize);
    const std::vector<double>& e = r.explicitSplits;
    for (size_t i = 0; i < e.size() && badSplit < 0; ++i) {
      if (i == 0 && e[i] != 0.0)
        badSplitReason = "start at 0 so every depth falls in a layer";
      else if (i + 1 == e.size() && e[i] != 1.0)
        badSplitReason = "end at 1 so every depth falls in a layer";
      else if (i > 0 && e[i] <= e[i - 1])
        badSplitReason = "increase strictly (each layer needs a depth range)";
      else
        continue;
      badSplit = static_cast<int>(i);
    }
    for (size_t i = 1; i < m.splits.size(); ++i) narrowest = std::min(narrowest, m.splits[i] - m.splits[i - 1]);
  }
  bool explicitSplits() const { return moments && s.moments.split == SplitPlacement::Explicit && r.explicitOk; }
  bool splitCountOk() const { return static_cast<int>(r.explicitSplits.size()) == s.moments.layers + 1; }
  bool vssm() const { return moments && s.blocker.kind == BlockerKind::Moments; }
  bool msm() const { return moments && s.moments.warp == Warp::Msm; }
  // Exponential moments summed in an fp32 SAT: cancellation, E0420.
  bool expFp32Sat() const {
    return exponential && (s.storage.sat == SatKind::Fp32Centered || s.storage.sat == SatKind::Fp32Naive);
  }
  double largestExponent() const {
    const MomentsSpec& m = s.moments;
    return m.warp == Warp::Evsm4 ? std::max(m.positiveExponent, m.negativeExponent) : m.positiveExponent;
  }
  bool msmFp32Sat() const {
    return msm() && (s.storage.sat == SatKind::Fp32Centered || s.storage.sat == SatKind::Fp32Naive);
  }
  // The tallest quadtree the unrolled traversal copies into the shader (kernel or blocker), or 0.
  int unrolledHeight() const {
    if (s.kernel.traversal != QuadtreeTraversal::Unrolled) return 0;
    const int k = s.kernel.subdivision == Subdivision::Quadtree ? s.kernel.quadtreeHeight : 0;
    const int b = vssm() && s.blocker.subdivision == Subdivision::Quadtree ? s.blocker.quadtreeHeight : 0;
    return std::max(k, b);
  }
};

// The token a rule's caret points at. Settings point at their value (the keyword when it has
// none, the `filter` keyword when the setting is absent); values at themselves.
enum class Caret {
  Light,
  Representation,
  Storage,
  Blur,
  Mips,
  Blocker,
  Kernel,
  Sampling,
  Fallback,
  Contact,
  Bleeding,
  Weights,
  Resolution,
  Bias,
  KernelElseStorage,         // the kernel setting when written, else storage
  LayersElseRepresentation,  // the `layers:` value when written, else the representation
  Exponent,
  NegativeExponent,
  MinVariance,
  MomentBias,
  Split,
  BadSplitBoundary,  // the first explicit split boundary out of order
};

using Args = fmt::dynamic_format_arg_store<fmt::format_context>;

struct Rule {
  DiagId id;
  Caret caret;
  bool (*when)(const Facts&);
  void (*args)(const Facts&, Args&) = nullptr;  // nullptr: the message takes no arguments
};

template <typename... T>
void push(Args& a, const T&... v) {
  (a.push_back(v), ...);
}

// clang-format off
const Rule kRules[] = {
    // ---- the depth representation has no moments -------------------------------------------
    {DiagId::satNeedsMoments, Caret::Storage, [](const Facts& f) { return !f.moments && f.sat; }},
    {DiagId::noEffect, Caret::Storage,
     [](const Facts& f) { return !f.moments && !f.sat && f.r.storage && f.s.storage.format != StorageFormat::Fp32; },
     [](const Facts&, Args& a) { push(a, "storage", "the depth representation reads the r32f depth map directly"); }},
    {DiagId::needsMoments, Caret::Blocker,
     [](const Facts& f) { return !f.moments && f.s.blocker.kind == BlockerKind::Moments; },
     [](const Facts&, Args& a) { push(a, "'blocker moments'", "average"); }},
    {DiagId::noEffect, Caret::Blur, [](const Facts& f) { return !f.moments && f.s.prefilter.blur != BlurKind::None; },
     [](const Facts&, Args& a) { push(a, "blur", "depth is compared per tap; blurring depth does not filter shadows"); }},
    {DiagId::noEffect, Caret::Mips, [](const Facts& f) { return !f.moments && f.s.prefilter.mips && f.r.mips; },
     [](const Facts&, Args& a) { push(a, "mips", "depth is compared per tap, not filtered"); }},
    {DiagId::noEffect, Caret::Bleeding,
     [](const Facts& f) { return !f.moments && f.r.bleeding && f.s.moments.bleedingReduction > 0; },
     [](const Facts&, Args& a) { push(a, "bleeding", "light bleeding is a moments artifact"); }},
    // ---- a moments map stores no depth to search ----------------------------------------------
    {DiagId::searchOnMoments, Caret::Blocker,
     [](const Facts& f) { return f.moments && f.s.blocker.kind == BlockerKind::Search; }},
    {DiagId::noEffect, Caret::Sampling, [](const Facts& f) { return f.moments && f.r.sampling; },
     [](const Facts&, Args& a) { push(a, "sampling", "it chooses PCF taps of the depth representation"); }},
    // ---- summed-area tables (vssm-yang2010 sec. 5-6) -------------------------------------------
    {DiagId::quadtreeNeedsSat, Caret::Kernel,
     [](const Facts& f) { return f.s.kernel.subdivision == Subdivision::Quadtree && !f.sat; },
     [](const Facts&, Args& a) { push(a, "quadtree"); }},
    {DiagId::uniformKernelNeedsSat, Caret::Kernel,
     [](const Facts& f) { return f.s.kernel.subdivision == Subdivision::Uniform && !f.sat; }},
    {DiagId::momentBlockerNeedsSat, Caret::Blocker, [](const Facts& f) { return f.vssm() && !f.sat; }},
    {DiagId::satNeedsFp32, Caret::Storage,
     [](const Facts& f) { return f.sat && f.moments && f.s.storage.format != StorageFormat::Fp32; },
     [](const Facts& f, Args& a) { push(a, f.fp16 ? "fp16" : "unorm16"); }},
    {DiagId::powerCdfSat, Caret::Storage,
     [](const Facts& f) { return f.sat && f.moments && f.s.moments.warp == Warp::PowerCdf; }},
    {DiagId::negativeMomentsUnrepresentable, Caret::Storage,
     [](const Facts& f) { return f.moments && f.int32Sat && f.s.moments.warp == Warp::Evsm4; },
     [](const Facts&, Args& a) { push(a, "an int32 16.16 SAT"); }},
    {DiagId::expWarpFp32Sat, Caret::Storage, [](const Facts& f) { return f.expFp32Sat(); },
     [](const Facts& f, Args& a) {
       const double w = static_cast<double>(f.s.mapSize);
       push(a, shadowc::name(f.s.moments.warp), f.s.mapSize, w * w, std::exp(f.largestExponent()));
     }},
    {DiagId::naiveFp32Sat, Caret::Storage,
     [](const Facts& f) { return f.moments && f.s.storage.sat == SatKind::Fp32Naive; }},
    {DiagId::blurOnSat, Caret::Blur,
     [](const Facts& f) { return f.sat && f.moments && f.s.prefilter.blur != BlurKind::None; }},
    {DiagId::noEffect, Caret::Mips, [](const Facts& f) { return f.sat && f.moments && f.s.prefilter.mips; },
     [](const Facts&, Args& a) { push(a, "mips", "SAT box queries replace mip lookups"); }},
    {DiagId::negativeMomentsUnrepresentable, Caret::Storage,
     [](const Facts& f) {
       return f.moments && !f.sat && f.s.storage.format == StorageFormat::Unorm16 && f.s.moments.warp == Warp::Evsm4;
     },
     [](const Facts&, Args& a) { push(a, "unorm16"); }},
    // ---- VSSM reads one plain (z, z^2) map (vssm-yang2010 sec. 4.2, eq. 4) ---------------------
    {DiagId::vssmNeedsLinearWarp, Caret::Representation,
     [](const Facts& f) { return f.vssm() && f.s.moments.warp != Warp::Linear; },
     [](const Facts& f, Args& a) { push(a, shadowc::name(f.s.moments.warp)); }},
    {DiagId::vssmNeedsOneLayer, Caret::LayersElseRepresentation,
     [](const Facts& f) { return f.vssm() && f.s.moments.layers > 1; },
     [](const Facts& f, Args& a) { push(a, f.s.moments.layers); }},
    // ---- moment shadow maps: what four moments need from the storage (Peters & Klein 2015) ------
    {DiagId::msmLayers, Caret::LayersElseRepresentation,
     [](const Facts& f) { return f.msm() && f.s.moments.layers > 1; },
     [](const Facts& f, Args& a) { push(a, f.s.moments.layers); }},
    {DiagId::msmFp16, Caret::Storage, [](const Facts& f) { return f.msm() && !f.sat && f.fp16; }},
    {DiagId::msmSatPrecision, Caret::Storage,
     [](const Facts& f) { return f.msmFp32Sat() && msmFp32SatPrecision(f.s).meanError > f.s.moments.momentBias; },
     [](const Facts& f, Args& a) {
       const MsmSatPrecision p = msmFp32SatPrecision(f.s);
       push(a, f.s.mapSize, p.boxTexels, p.meanError, f.s.moments.momentBias);
     }},
    // ---- an unrolled quadtree is one copy of the sub-kernel test per node (docs/performance.md) --
    {DiagId::unrolledQuadtreeTooTall, Caret::Kernel, [](const Facts& f) { return f.unrolledHeight() >= 4; },
     [](const Facts& f, Args& a) { push(a, f.unrolledHeight(), ((1 << (2 * (f.unrolledHeight() + 1))) - 1) / 3); }},
    {DiagId::unrolledQuadtreeSlow, Caret::Kernel, [](const Facts& f) { return f.unrolledHeight() == 3; }},
    // ---- exponential warps: exp(c) must stay representable (precision.h) -----------------------
    {DiagId::exponentOverflow, Caret::Exponent,
     [](const Facts& f) {
       // An fp32 SAT of exponential moments is E0420 at any exponent: one diagnostic, not two.
       return f.exponential && !f.expFp32Sat() && f.r.exponent && f.s.moments.positiveExponent > f.limit.maxExponent;
     },
     [](const Facts& f, Args& a) {
       push(a, f.s.moments.warp == Warp::Evsm4 ? "positive" : "warp", f.r.exponent->text, f.limit.storageName, "c",
            f.limit.maxExponent, f.limit.reason);
     }},
    {DiagId::exponentOverflow, Caret::NegativeExponent,
     [](const Facts& f) {
       return f.exponential && !f.expFp32Sat() && f.s.moments.warp == Warp::Evsm4 && f.r.negativeExponent &&
              f.s.moments.negativeExponent > f.limit.maxExponent;
     },
     [](const Facts& f, Args& a) {
       push(a, "negative", f.r.negativeExponent->text, f.limit.storageName, "c", f.limit.maxExponent, f.limit.reason);
     }},
    // ---- kernel sizing needs a blocker estimate; a point light has no penumbra ------------------
    {DiagId::penumbraNeedsBlocker, Caret::Kernel,
     [](const Facts& f) { return f.s.kernel.size == KernelSize::Penumbra && f.s.blocker.kind == BlockerKind::None; },
     [](const Facts& f, Args& a) {
       const Subdivision sub = f.s.kernel.subdivision;
       push(a, sub == Subdivision::Quadtree ? "quadtree" : sub == Subdivision::Uniform ? "uniform" : "penumbra");
     }},
    {DiagId::pointLightPenumbra, Caret::Blocker,
     [](const Facts& f) { return f.s.light.shape == LightShape::Point && f.s.blocker.kind != BlockerKind::None; },
     [](const Facts&, Args& a) { push(a, "a blocker estimate"); }},
    {DiagId::pointLightPenumbra, Caret::Kernel,
     [](const Facts& f) {
       return f.s.light.shape == LightShape::Point && f.s.blocker.kind == BlockerKind::None &&
              f.s.kernel.size == KernelSize::Penumbra;
     },
     [](const Facts&, Args& a) { push(a, "a penumbra kernel"); }},
    {DiagId::contactNeedsMomentBlocker, Caret::Contact,
     [](const Facts& f) { return f.s.contact.enabled && f.s.blocker.kind != BlockerKind::Moments; }},
    {DiagId::noEffect, Caret::Fallback,
     [](const Facts& f) { return f.r.fallback && f.s.fallback.pcf && !f.vssm(); },
     [](const Facts&, Args& a) {
       push(a, "fallback", "PCF replaces the non-planar sub-kernels of the VSSM walks (vssm sec. 5.1-5.2), which need 'blocker moments'");
     }},
    // The receiver plane moves depth taps only (bias.glsl); a moments filter has some only in the
    // VSSM fallback and contact PCF.
    {DiagId::noEffect, Caret::Bias,
     [](const Facts& f) {
       return f.moments && f.s.bias.kind == BiasKind::ReceiverPlane &&
              !(f.vssm() && (f.s.fallback.pcf || f.s.contact.enabled));
     },
     [](const Facts&, Args& a) {
       push(a, "receiver_plane", "it offsets depth taps, and this filter reads none (only VSSM's 'fallback pcf' and 'contact pcf' do); only its constant and normal_offset apply");
     }},
    {DiagId::noEffect, Caret::Kernel,
     [](const Facts& f) {
       const KernelSpec& k = f.s.kernel;
       return k.subdivision == Subdivision::Uniform && k.uniformNonPlanarOnly && k.uniformN == 1;
     },
     [](const Facts&, Args& a) { push(a, "subdivide", "a 1 x 1 uniform kernel is the root box, never subdivided"); }},
    {DiagId::noEffect, Caret::Blocker,
     [](const Facts& f) {
       const BlockerSpec& b = f.s.blocker;
       return f.vssm() && b.subdivision == Subdivision::Uniform && b.uniformNonPlanarOnly && b.uniformM == 1;
     },
     [](const Facts&, Args& a) { push(a, "subdivide", "a 1 x 1 uniform blocker walk is the root box, never subdivided"); }},
    // ---- layers (lauritzen2008 sec. 3-4) ----------------------------------------------------------
    {DiagId::splitCount, Caret::Split, [](const Facts& f) { return f.explicitSplits() && !f.splitCountOk(); },
     [](const Facts& f, Args& a) { push(a, f.s.moments.layers + 1, f.r.explicitSplits.size()); }},
    {DiagId::splitOrder, Caret::BadSplitBoundary,
     [](const Facts& f) { return f.explicitSplits() && f.splitCountOk() && f.badSplit >= 0; },
     [](const Facts& f, Args& a) {
       push(a, f.badSplitReason, f.r.explicitSplits[static_cast<size_t>(f.badSplit)], f.badSplit + 1);
     }},
    {DiagId::noEffect, Caret::Split,
     [](const Facts& f) {
       return f.moments && f.s.moments.split == SplitPlacement::Lloyd && f.s.moments.layers == 1 && f.r.split;
     },
     [](const Facts&, Args& a) { push(a, "lloyd", "one layer has no splits to place"); }},
    {DiagId::wideOverlap, Caret::Representation,
     [](const Facts& f) {
       const MomentsSpec& m = f.s.moments;
       return f.moments && m.layers > 1 && m.overlap > 0 && m.overlap >= f.narrowest / 2;
     },
     [](const Facts& f, Args& a) { push(a, f.s.moments.overlap, f.narrowest); }},
    // ---- dubious but legal ---------------------------------------------------------------------
    {DiagId::strongBleeding, Caret::Bleeding,
     [](const Facts& f) { return f.moments && f.s.moments.bleedingReduction >= 0.5; },
     [](const Facts& f, Args& a) { push(a, f.s.moments.bleedingReduction); }},
    {DiagId::noEffect, Caret::Bleeding,
     [](const Facts& f) { return f.moments && !f.chebyshev && !f.msm() && f.s.moments.bleedingReduction > 0; },
     [](const Facts&, Args& a) { push(a, "bleeding", "only Chebyshev warps (linear, evsm2, evsm4) and msm bleed"); }},
    // Form-factor weights (docs/dsl.md "weights") need taps or sub-kernels that stand for parts of
    // a spot light.
    {DiagId::noEffect, Caret::Weights,
     [](const Facts& f) { return f.s.formFactorWeights && f.s.light.type != LightType::Spot; },
     [](const Facts&, Args& a) {
       push(a, "weights", "form-factor weights are built for spot lights; a sun's cap and a point light's sphere are weighed uniformly");
     }},
    {DiagId::noEffect, Caret::Weights,
     [](const Facts& f) {
       return f.s.formFactorWeights && f.s.light.type == LightType::Spot && f.moments &&
              f.s.blocker.kind != BlockerKind::Search &&
              (!f.vssm() || (f.s.kernel.subdivision == Subdivision::None && f.s.blocker.subdivision == Subdivision::None));
     },
     [](const Facts&, Args& a) {
       push(a, "weights", "one filtered box stands for the whole light; weigh sub-kernels with kernel uniform(n) or quadtree");
     }},
    {DiagId::resolutionOverMapSize, Caret::Resolution,
     [](const Facts& f) { return f.s.resolution > f.s.mapSize; },
     [](const Facts& f, Args& a) { push(a, f.s.resolution, f.s.mapSize); }},
    {DiagId::zeroMinVariance, Caret::MinVariance,
     [](const Facts& f) { return f.moments && f.chebyshev && f.r.minVariance && f.s.moments.minVariance == 0; }},
    {DiagId::msmSmallBias, Caret::MomentBias,
     [](const Facts& f) { return f.msm() && f.r.momentBias && f.s.moments.momentBias < msmDefaultBias(f.s.storage); },
     [](const Facts& f, Args& a) { push(a, f.s.moments.momentBias, msmDefaultBias(f.s.storage)); }},
    {DiagId::fp16LargeLight, Caret::Light,
     [](const Facts& f) { return f.moments && f.fp16 && !f.sat && f.r.lightSizeGiven && f.s.light.size > 0.1; },
     [](const Facts& f, Args& a) { push(a, f.s.light.size); }},
    {DiagId::fp16MinVariance, Caret::MinVariance,
     [](const Facts& f) {
       return f.moments && f.fp16 && !f.sat && f.s.moments.warp == Warp::Linear && f.r.minVariance &&
              f.s.moments.minVariance < 1e-4;
     },
     [](const Facts& f, Args& a) { push(a, f.s.moments.minVariance); }},
};
// clang-format on

struct Span {
  int line, column, length;
};

Span settingSpan(const dsl::Setting* s, const dsl::FilterDecl& filter) {
  if (s && s->hasValue) return {s->value.line, s->value.column, s->value.length};
  if (s) return {s->line, s->column, static_cast<int>(s->keyword.size())};
  return {filter.line, filter.column, 6};  // `filter`
}
Span valueSpan(const dsl::Value& v) { return {v.line, v.column, v.length}; }

Span caretOf(Caret c, const Facts& f, const dsl::FilterDecl& filter) {
  const SettingsRead& r = f.r;
  switch (c) {
    case Caret::Light:
      return settingSpan(r.light, filter);
    case Caret::Representation:
      return settingSpan(r.representation, filter);
    case Caret::Storage:
      return settingSpan(r.storage, filter);
    case Caret::Blur:
      return settingSpan(r.blur, filter);
    case Caret::Mips:
      return settingSpan(r.mips, filter);
    case Caret::Blocker:
      return settingSpan(r.blocker, filter);
    case Caret::Kernel:
      return settingSpan(r.kernel, filter);
    case Caret::Sampling:
      return settingSpan(r.sampling, filter);
    case Caret::Fallback:
      return settingSpan(r.fallback, filter);
    case Caret::Contact:
      return settingSpan(r.contact, filter);
    case Caret::Bleeding:
      return settingSpan(r.bleeding, filter);
    case Caret::Weights:
      return settingSpan(r.weights, filter);
    case Caret::Resolution:
      return settingSpan(r.resolution, filter);
    case Caret::Bias:
      return settingSpan(r.bias, filter);
    case Caret::KernelElseStorage:
      return settingSpan(r.kernel ? r.kernel : r.storage, filter);
    case Caret::LayersElseRepresentation:
      return r.layers ? valueSpan(*r.layers) : settingSpan(r.representation, filter);
    // The rules that point at a value fire only when it was written.
    case Caret::Exponent:
      return valueSpan(*r.exponent);
    case Caret::NegativeExponent:
      return valueSpan(*r.negativeExponent);
    case Caret::MinVariance:
      return valueSpan(*r.minVariance);
    case Caret::MomentBias:
      return valueSpan(*r.momentBias);
    case Caret::Split:
      return valueSpan(*r.split);
    case Caret::BadSplitBoundary:
      return valueSpan(r.split->arguments[static_cast<size_t>(f.badSplit)].value);
  }
  return settingSpan(nullptr, filter);
}

}  // namespace

void checkCombinations(const FilterSpec& spec, const SettingsRead& given, const dsl::FilterDecl& filter,
                       dsl::DiagnosticSink& sink) {
  const Facts facts(spec, given);
  for (const Rule& rule : kRules) {
    if (!rule.when(facts)) continue;
    Args args;
    if (rule.args) rule.args(facts, args);
    const Span at = caretOf(rule.caret, facts, filter);
    sink.vreport(rule.id, at.line, at.column, at.length, args);
  }
}

}  // namespace shadowc::spec
