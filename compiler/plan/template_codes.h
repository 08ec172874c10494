// The one table of integer codes that FilterSpec choices take as template macros. The planner
// stores them as typed values (EnumCode) and the emitter renders the code; the prefilter passes
// and the lookup must agree on them — the moments pass warps with SHADOWC_WARP and the lookup
// un-warps with it — so both read them from here. Codes and names mirror
// templates/lookup/defaults.glsl (SHADOWC_WARP_LINEAR 0, ...) and
// templates/passes/{moments_warp,sat_common}.glsl.
#pragma once

#include <string_view>

#include "spec/filter_spec.h"

namespace shadowc {

// One code: `name` is the template macro that spells the same value (for --print-plan).
struct EnumCode {
  std::string_view name;
  int code = 0;
  friend bool operator==(const EnumCode&, const EnumCode&) = default;
};

// SHADOWC_TECHNIQUE (templates/lookup/shadowc_lookup.glsl).
constexpr EnumCode techniqueCode(const FilterSpec& s) {
  if (s.representation == Representation::Depth)
    return s.blocker.kind == BlockerKind::Search ? EnumCode{"SHADOWC_TECHNIQUE_PCSS", 1}
                                                 : EnumCode{"SHADOWC_TECHNIQUE_PCF", 0};
  return s.blocker.kind == BlockerKind::Moments ? EnumCode{"SHADOWC_TECHNIQUE_VSSM", 3}
                                                : EnumCode{"SHADOWC_TECHNIQUE_MOMENTS", 2};
}
inline constexpr int kTechniquePcf = 0, kTechniquePcss = 1, kTechniqueMoments = 2, kTechniqueVssm = 3;

constexpr EnumCode warpCode(Warp w) {  // SHADOWC_WARP
  switch (w) {
    case Warp::Linear:
      return {"SHADOWC_WARP_LINEAR", 0};
    case Warp::Exp:
      return {"SHADOWC_WARP_EXP", 1};
    case Warp::Evsm2:
      return {"SHADOWC_WARP_EVSM2", 2};
    case Warp::Evsm4:
      return {"SHADOWC_WARP_EVSM4", 3};
    case Warp::PowerCdf:
      return {"SHADOWC_WARP_POWER_CDF", 4};
    case Warp::Msm:
      return {"SHADOWC_WARP_MSM", 5};
  }
  return {"SHADOWC_WARP_LINEAR", 0};
}

constexpr EnumCode satKindCode(SatKind k) {  // SHADOWC_SAT_KIND
  switch (k) {
    case SatKind::None:
      return {"SHADOWC_SAT_NONE", 0};
    case SatKind::Int32:
      return {"SHADOWC_SAT_INT32", 1};
    case SatKind::Fp32Centered:
      return {"SHADOWC_SAT_FP32_CENTERED", 2};
    case SatKind::Fp32Naive:
      return {"SHADOWC_SAT_FP32_NAIVE", 3};
  }
  return {"SHADOWC_SAT_NONE", 0};
}

constexpr EnumCode subdivisionCode(Subdivision s) {  // SHADOWC_KERNEL_SUBDIVISION, SHADOWC_BLOCKER_SUBDIVISION
  switch (s) {
    case Subdivision::None:
      return {"SHADOWC_SUBDIV_NONE", 0};
    case Subdivision::Uniform:
      return {"SHADOWC_SUBDIV_UNIFORM", 1};
    case Subdivision::Quadtree:
      return {"SHADOWC_SUBDIV_QUADTREE", 2};
  }
  return {"SHADOWC_SUBDIV_NONE", 0};
}

constexpr EnumCode pcfPatternCode(PcfPattern p) {  // SHADOWC_PCF_PATTERN
  switch (p) {
    case PcfPattern::Grid:
      return {"SHADOWC_PATTERN_GRID", 0};
    case PcfPattern::Bilinear:
      return {"SHADOWC_PATTERN_BILINEAR", 1};
    case PcfPattern::Poisson:
      return {"SHADOWC_PATTERN_POISSON", 2};
  }
  return {"SHADOWC_PATTERN_GRID", 0};
}

constexpr EnumCode blockerKindCode(BlockerKind k) {  // SHADOWC_BLOCKER_KIND
  switch (k) {
    case BlockerKind::None:
      return {"SHADOWC_BLOCKER_NONE", 0};
    case BlockerKind::Search:
      return {"SHADOWC_BLOCKER_SEARCH", 1};
    case BlockerKind::Moments:
      return {"SHADOWC_BLOCKER_MOMENTS", 2};
  }
  return {"SHADOWC_BLOCKER_NONE", 0};
}

// SHADOWC_BLOCKER_PATTERN: templates/lookup/defaults.glsl documents "0 grid, 1 Poisson" (no macros).
constexpr EnumCode samplePatternCode(SamplePattern p) {
  return p == SamplePattern::Poisson ? EnumCode{"poisson", 1} : EnumCode{"grid", 0};
}

constexpr EnumCode biasKindCode(BiasKind k) {  // SHADOWC_BIAS_KIND
  switch (k) {
    case BiasKind::Constant:
      return {"SHADOWC_BIAS_CONSTANT_KIND", 0};
    case BiasKind::SlopeScaled:
      return {"SHADOWC_BIAS_SLOPE_SCALED_KIND", 1};
    case BiasKind::NormalOffset:
      return {"SHADOWC_BIAS_NORMAL_OFFSET_KIND", 2};
    case BiasKind::ReceiverPlane:
      return {"SHADOWC_BIAS_RECEIVER_PLANE_KIND", 3};
  }
  return {"SHADOWC_BIAS_CONSTANT_KIND", 0};
}

}  // namespace shadowc
