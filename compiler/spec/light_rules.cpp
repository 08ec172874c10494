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
  if (given.cascades) {
    const char* why = spec.light.type == LightType::Sun
                          ? "a sun uses one orthographic map fitted to the scene's bounds"
                          : "cascades split a sun's orthographic map along the camera frustum, and this filter has no "
                            "'light sun(...)'";
    reportAt(sink, *given.cascades, DiagId::cascadesNotImplemented, why);
  }
}

}  // namespace shadowc::spec
