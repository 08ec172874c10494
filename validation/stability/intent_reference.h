// Double-precision references of what a filter intends to compute on a crafted map: the same
// kernel geometry as templates/lookup/kernel.glsl, but exact box means (no SAT storage error),
// double estimators (Chebyshev vssm-yang2010 eq. 1, ESM, EVSM lauritzen2008 sec. 7, power-CDF
// eq. 3-4 with the exact beta), layered warps (lauritzen2008 eq. 6-7) and the VSSM blocker
// estimate (eq. 4) and subdivisions (sec. 5.2-5.3). The documented guards that are part of the
// design (variance floor, the 1 - P > 1e-4 blocker cut-off, the final [0, 1] clamp) are part of
// the intent; storage precision is not. Used by the stability suite (docs/stability.md).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "spec/filter_spec.h"
#include "validation/stability/crafted_run.h"

namespace shadowc::validation {

// Whether IntentReference models this filter (else a row of it compares nothing and fails).
bool intentModels(const FilterSpec& spec);

// Exact per-channel means of the warped moments (before any blur) over an inclusive rectangle
// of layer `layer`; `size` x `size` map.
struct MomentsField {
  MomentsField(const FilterSpec& spec, const DepthMap& map);
  std::vector<double> boxMean(int x0, int y0, int x1, int y1, int layer) const;  // 4 channels
  // Over the continuous box [x0, x1] x [y0, y1] in texel units (texel i covers [i, i+1)).
  std::vector<double> boxMeanFrac(double x0, double y0, double x1, double y1, int layer) const;
  std::vector<double> texel(int x, int y, int layer) const;  // blurred, clamp to edge
  uint32_t size = 0;
  int layers = 1;

 private:
  std::vector<double> raw_;      // warped, size*size*layers*4
  std::vector<double> blurred_;  // after the separable blur (== raw_ without blur)
  std::vector<double> prefix_;   // (size+1)^2 * layers * 4 inclusive prefix sums of raw_
};

// Deliberately wrong forms of the reference, for the siblings that prove a check can fail.
struct ReferenceForm {
  // Kernel widths by the spot's perspective formulas (frame.glsl) whatever the frame's
  // projection, with lightParams.x as tan(half fov): what a spot-compiled lookup computes.
  bool perspectiveWidths = false;
  // Point light: read the receiver's face-local uv in the cell of the opposite face (f ^ 1).
  bool mirroredCubeFace = false;
};

// The reference for one (filter, map, frame): the moments field is built once.
// operator() gives the reference values for one receiver: usually one; two or three where a
// kernel width lies within 2e-4 (relative) of a texel rounding boundary and fp32 may round either
// way. Empty when the reference does not model the filter (mips, Poisson taps, PCSS search,
// contact path, Lloyd splits, receiver-plane bias); the suite fails such a row (nothing compared). A
// normal offset moves the receiver along its normal first, as bias.glsl does. Kernel widths take the form of the
// frame's projection: frame.glsl (spot), frame_ortho.glsl (sun), frame_cube.glsl (point, in the receiver's face,
// clamped to SHADOWC_CUBE_KERNEL_MAX); a PCSS with a grid blocker search and grid PCF (pcss.glsl) is modelled, a
// Poisson one is not.
class IntentReference {
 public:
  IntentReference(const FilterSpec& spec, const DepthMap& map, const LightFrame& light, ReferenceForm form = {});
  ~IntentReference();
  std::vector<double> operator()(const Receiver& receiver) const;

 private:
  FilterSpec spec_;
  const DepthMap& map_;
  LightFrame light_;
  ReferenceForm form_;
  std::unique_ptr<MomentsField> field_;
};

// Warp of a normalized depth (templates/passes/moments_warp.glsl), in double.
std::vector<double> warpMoments(const FilterSpec& spec, double d);

}  // namespace shadowc::validation
