// The driver's shader compile (shader_compile.h).
#include "driver/shader_compile.h"

#include "backend/spirv_backend.h"
#include "emit/template_includes.h"

namespace shadowc::driver {

GlslPreprocessor glslangPreprocessor() {
  return [](std::string_view source, const std::string& name, const TemplateResolver& includes, std::string& out,
            std::string& log) {
    const SpirvResult pp = preprocessGlsl(source, ShaderStage::Compute, name, includes, out);
    log += pp.log;
    return pp.ok;
  };
}

bool compileEmitted(const EmittedShader& shader, const ShaderOptions& options, std::vector<uint32_t>& words,
                    std::string& log) {
  BackendOptions bo;
  bo.optimize = options.optimize;
  bo.keepCalls = shader.keepCalls;
  SpirvResult spv = compileGlsl(shader.glsl, ShaderStage::Compute, shader.name, templateIncludes(), bo);
  log += spv.log;
  if (!spv.ok) return false;
  if (options.warningsAsErrors && hasWarning(spv.log)) {
    log += shader.name + ": error: warnings treated as errors (-Werror)\n";
    return false;
  }
  words = std::move(spv.words);
  return true;
}

CompiledShader compileShader(const std::string& templatePath, const Specialization& specialization,
                             const ShaderOptions& options) {
  CompiledShader out;
  EmittedShader sh = emitComputeShader(templatePath, specialization, glslangPreprocessor(), options.warningsAsErrors);
  out.log = sh.log;
  if (!sh.ok) return out;
  out.localSize = sh.localSize;
  out.glsl = sh.glsl;
  out.ok = compileEmitted(sh, options, out.spirv, out.log);
  return out;
}

bool compileUnoptimized(const std::string& glsl, const std::string& name, std::string& log) {
  BackendOptions bo;
  bo.optimize = false;
  const SpirvResult r = compileGlsl(glsl, ShaderStage::Compute, name, {}, bo);
  if (!r.ok) log += r.log;
  return r.ok;
}

}  // namespace shadowc::driver
