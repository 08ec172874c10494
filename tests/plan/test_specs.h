// FilterSpecs built in code for planner/emitter tests, one per technique family, so these
// tests do not depend on the sample files. Each must pass the checker: driver::compileSpec
// re-checks it through its printed description.
#pragma once

#include "spec/filter_spec.h"

namespace shadowc::test {

inline FilterSpec pcfSpec() {
  FilterSpec s;
  s.name = "pcf_test";
  s.representation = Representation::Depth;
  s.kernel.size = KernelSize::Fixed;
  return s;
}

inline FilterSpec vssmInt32Spec() {
  FilterSpec s;
  s.name = "vssm_test";
  s.representation = Representation::Moments;
  s.moments.warp = Warp::Linear;
  s.storage.sat = SatKind::Int32;
  s.blocker.kind = BlockerKind::Moments;
  s.kernel.subdivision = Subdivision::Quadtree;
  s.earlyOutMinMax = true;
  return s;
}

inline FilterSpec layeredEvsmSpec() {
  FilterSpec s;
  s.name = "layered_test";
  s.representation = Representation::Moments;
  s.moments.warp = Warp::Evsm4;
  s.moments.layers = 3;
  s.moments.splits = {0.0, 0.25, 0.6, 1.0};
  s.moments.overlap = 0.02;
  s.moments.positiveExponent = 5.0;
  s.storage.format = StorageFormat::Fp16;
  s.kernel.size = KernelSize::Fixed;  // no blocker estimate: a penumbra kernel would be E0409
  return s;
}

inline FilterSpec blurMipSpec() {
  FilterSpec s;
  s.name = "blur_mip_test";
  s.representation = Representation::Moments;
  s.moments.warp = Warp::PowerCdf;
  s.prefilter.blur = BlurKind::Gaussian;
  s.prefilter.blurRadius = 2;
  s.prefilter.mips = true;
  s.kernel.maxTexels = 32;
  s.kernel.size = KernelSize::Fixed;  // no blocker estimate: a penumbra kernel would be E0409
  return s;
}

}  // namespace shadowc::test
