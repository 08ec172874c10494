// The emit stage as the driver runs it: the emitter's texts (emit/filter_emitter.h
// emitSources), every shader and the includable lookup compiled by the backend
// (shader_compile.h), then the emitter's files and manifest.json with the content hash
// (emitOutputs).
#pragma once

#include "driver/shader_compile.h"
#include "emit/filter_emitter.h"

namespace shadowc::driver {

struct EmitStageOptions {
  ShaderOptions shaders;   // -O / -O0, -Werror
  LookupPlacement lookup;  // --lookup-set / --lookup-binding-base
};

FilterEmitResult emitStage(const FilterSpec& spec, const PassGraph& plan, const EmitStageOptions& options);

}  // namespace shadowc::driver
