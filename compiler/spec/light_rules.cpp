// Light rules (light_rules.h). The reasons are the ones docs/dsl.md "Light types" lists.
#include "spec/light_rules.h"

#include <optional>

namespace shadowc::spec {
namespace {

using dsl::DiagId;

void reportAt(dsl::DiagnosticSink& sink, const dsl::Setting& s, DiagId id, const auto&... args) {
  const bool v = s.hasValue;
  sink.report(id, v ? s.value.line : s.line, v ? s.value.column : s.column,
              v ? s.value.length : static_cast<int>(s.keyword.size()), args...);
}

// Why a technique cannot filter across the faces of a cube map, or nullopt when it can: the faces
// sit in a 3x3 atlas of the 2D map, each rendered with a guard band (frame_cube.glsl), so PCF,
// PCSS and moments fetches within the band are exact, but a box sum or a tile has no band.
struct CubeRefusal {
  const char* what;
  const char* why;
};
std::optional<CubeRefusal> cubeRefusal(const FilterSpec& s) {
  const bool moments = s.representation == Representation::Moments;
  if (moments && s.storage.sat != SatKind::None)
    return CubeRefusal{"a summed-area table",
                       "its box sums run over one 2D image, and a box across a face seam would add texels of "
                       "another face's projection (vssm sec. 4.1)"};
  if (s.earlyOutMinMax)
    return CubeRefusal{"the min-max depth pyramid ('early_out minmax')",
                       "its tiles bound the depths of one 2D image and a tile across a seam bounds nothing "
                       "(vssm sec. 6.1)"};
  if (s.kernel.subdivision == Subdivision::Quadtree || s.kernel.subdivision == Subdivision::Uniform)
    return CubeRefusal{"a subdivided kernel", "its sub-kernels are box queries of a summed-area table"};
  return std::nullopt;
}

// Why cascades cannot serve this technique yet, or nullopt. The cascades are tiles of one atlas
// (templates/lookup/cascades.glsl): every depth texel the lookup fetches is clamped to its
// cascade's tile, which is exact for the depth representation (PCF, PCSS). The prefilters of the
// other techniques (blur, mips, SAT, min-max pyramid) run over the whole atlas and their kernel
// rectangles are clamped to the map, not to a tile; until they are, they are refused.
std::optional<const char*> cascadeRefusal(const FilterSpec& s) {
  if (s.representation == Representation::Moments)
    return "with moments the blur / mip / summed-area prefilters run over the whole cascade atlas and their boxes "
           "would mix neighbouring cascades' tiles; cascades serve 'depth' filters (PCF, PCSS)";
  if (s.earlyOutMinMax)
    return "the min-max pyramid's coarse levels span several cascades' tiles; cascades serve 'depth' filters "
           "without 'early_out minmax'";
  if (s.depthInput.format != DepthInputFormat::Linear)
    return "a hardware 'depth_input' is converted for one map, a spot's light views or a point light's faces; "
           "the converted cascade atlas does not yet match the linear one (tests/gpu/hardware_depth_test.cpp), "
           "so render the cascades' linear depth (depth_input linear)";
  return std::nullopt;
}

// Why light samples cannot serve this filter, or nullopt. Each view is a hard map of its own tile
// (templates/lookup/light_samples.glsl), filtered by a fixed PCF kernel whose fetches are clamped
// to the tile; the views themselves sample the light, so nothing sizes a kernel by the light.
std::optional<const char*> lightSamplesRefusal(const FilterSpec& s) {
  if (s.representation == Representation::Moments)
    return "'moments' are prefiltered over the whole atlas (blur, mips, summed-area tables), whose boxes would mix "
           "neighbouring views' tiles";
  if (s.blocker.kind != BlockerKind::None)
    return "a blocker search sizes one kernel for the whole light, which the views already sample";
  if (s.kernel.size == KernelSize::Penumbra)
    return "a penumbra-sized kernel ('kernel penumbra') widens each view's hard shadow by the whole light again; use "
           "'kernel fixed(N)'";
  if (s.earlyOutMinMax) return "the min-max pyramid's coarse levels span several views' tiles ('early_out minmax')";
  if (s.contact.enabled) return "the contact path ('contact') belongs to moment filters";
  return std::nullopt;
}

}  // namespace

void checkLightRules(const FilterSpec& spec, const SettingsRead& given, dsl::DiagnosticSink& sink) {
  if (spec.light.type == LightType::Point && given.light) {
    if (auto refusal = cubeRefusal(spec))
      reportAt(sink, *given.light, DiagId::pointLightCubeSeams, refusal->what, refusal->why);
    else if (!spec.light.sizeFromScene && !(spec.light.size > 0) &&
             (spec.blocker.kind != BlockerKind::None || spec.kernel.size == KernelSize::Penumbra))
      // radius 0: hard cube shadows; nothing for a blocker estimate or penumbra kernel to size.
      reportAt(sink, *given.light, DiagId::pointLightNotImplemented,
               spec.blocker.kind != BlockerKind::None ? "a blocker estimate" : "a penumbra kernel");
  }
  if (given.cascades && spec.cascades.count > 0) {
    if (spec.light.type != LightType::Sun)
      reportAt(sink, *given.cascades, DiagId::cascadesNeedSun,
               spec.light.type == LightType::Point ? "an omnidirectional point light" : "a spot light");
    else if (auto why = cascadeRefusal(spec))
      reportAt(sink, *given.cascades, DiagId::cascadesNotImplemented, *why);
  }
  if (given.lightSamples && spec.lightSamples > 0) {
    if (spec.light.type != LightType::Spot || spec.light.shape == LightShape::Point)
      reportAt(sink, *given.lightSamples, DiagId::lightSamplesNeedSpot,
               spec.light.type == LightType::Sun     ? "a sun (one orthographic map of a cone of directions)"
               : spec.light.type == LightType::Point ? "an omnidirectional point light's cube"
                                                     : "a point light of width 0");
    else if (auto why = lightSamplesRefusal(spec))
      reportAt(sink, *given.lightSamples, DiagId::lightSamplesNotImplemented, *why);
  }
}

}  // namespace shadowc::spec
