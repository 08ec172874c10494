// The emit stage (emit_stage.h).
#include "driver/emit_stage.h"

namespace shadowc::driver {

FilterEmitResult emitStage(const FilterSpec& spec, const PassGraph& plan, const EmitStageOptions& options) {
  EmitOptions eo;
  eo.warningsAsErrors = options.shaders.warningsAsErrors;
  eo.lookup = options.lookup;
  eo.preprocess = glslangPreprocessor();
  FilterSources sources = emitSources(spec, plan, eo);
  FilterEmitResult failed;
  failed.log = sources.log;
  if (!sources.ok) return failed;
  std::map<std::string, std::vector<uint32_t>> spirv;
  for (const auto& [stem, shader] : sources.shaders)
    if (!compileEmitted(shader, options.shaders, spirv[stem], failed.log)) return failed;
  // The lookup must compile where an engine includes it: inside an empty compute shader.
  if (!compileUnoptimized(sources.lookupCheck, lookupFileName(spec.name), failed.log)) return failed;
  sources.log = std::move(failed.log);
  return emitOutputs(spec, std::move(sources), spirv);
}

}  // namespace shadowc::driver
