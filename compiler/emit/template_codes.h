// The integer codes that FilterSpec enums take as template #defines. The prefilter passes
// (planner) and the lookup (lookup_specialization) must agree on them — the moments pass warps
// with SHADOWC_WARP and the lookup un-warps with it — so both read them from here. Values
// mirror templates/lookup/defaults.glsl and templates/passes/{moments_warp,sat_common}.glsl.
#pragma once

#include "spec/filter_spec.h"

namespace shadowc {

constexpr int warpDefineValue(Warp w) {  // SHADOWC_WARP
  switch (w) {
    case Warp::Linear: return 0;
    case Warp::Exp: return 1;
    case Warp::Evsm2: return 2;
    case Warp::Evsm4: return 3;
    case Warp::PowerCdf: return 4;
    case Warp::Msm: return 5;
  }
  return 0;
}

constexpr int satKindDefineValue(SatKind k) {  // SHADOWC_SAT_KIND
  switch (k) {
    case SatKind::None: return 0;
    case SatKind::Int32: return 1;
    case SatKind::Fp32Centered: return 2;
    case SatKind::Fp32Naive: return 3;
  }
  return 0;
}

}  // namespace shadowc
