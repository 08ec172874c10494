#include "emit/shader_emitter.h"

#include <algorithm>
#include <regex>
#include <variant>

#include "emit/glsl_tidy.h"
#include "emit/specialization_block.h"
#include "emit/template_includes.h"

namespace shadowc {
namespace {

// glslang's info log says "WARNING:" for warnings that do not fail a compile.
bool hasWarning(const std::string& log) { return log.find("WARNING:") != std::string::npos; }

std::array<uint32_t, 3> localSizeOf(const std::string& glsl) {
  std::array<uint32_t, 3> size{1, 1, 1};
  static const std::regex re(R"(local_size_([xyz])\s*=\s*(\d+))");
  for (auto it = std::sregex_iterator(glsl.begin(), glsl.end(), re); it != std::sregex_iterator(); ++it)
    size[(*it)[1].str()[0] - 'x'] = static_cast<uint32_t>(std::stoul((*it)[2].str()));
  return size;
}

}  // namespace

std::string specializeTemplate(const std::string& templatePath, const Specialization& specialization,
                               std::string& error) {
  const std::string_view text = templateText(templatePath);
  if (text.empty()) {
    error = "templates/" + templatePath + ": error: template not found in this build";
    return {};
  }
  const std::string templ(text);
  if (templ.find(kSpecializeMarker) == std::string::npos) {
    error = "templates/" + templatePath + ": error: template has no '" + kSpecializeMarker + "' line";
    return {};
  }
  return insertSpecialization(templ, specialization);
}

// An unrolled quadtree calls its node test once per node (85 call sites at height 3): kept as
// calls, the -O recipe takes 0.1 s of CPU instead of 2.6 s (backend/dont_inline.h).
std::vector<std::string> keptCalls(const Specialization& specialization) {
  std::vector<std::string> out;
  for (const Table& t : specialization.tables)
    if (const auto* u = std::get_if<UnrolledQuadtree>(&t))
      for (const std::string& f : {u->visit, u->leaf})
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  return out;
}

EmittedShader emitComputeShader(const std::string& templatePath, const Specialization& specialization,
                                const ShaderEmitOptions& options) {
  EmittedShader out;
  const std::string name = "templates/" + templatePath;  // diagnostics point into the template
  std::string error;
  const std::string specialized = specializeTemplate(templatePath, specialization, error);
  if (!error.empty()) {
    out.log = error + "\n";
    return out;
  }
  std::string preprocessed;
  const SpirvResult pp = preprocessGlsl(specialized, ShaderStage::Compute, name, templateIncludes(), preprocessed);
  out.log += pp.log;
  if (!pp.ok) return out;
  if (options.warningsAsErrors && hasWarning(pp.log)) {
    out.log += name + ": error: warnings treated as errors (-Werror)\n";
    return out;
  }
  out.glsl = tidyPreprocessed(preprocessed);
  out.localSize = localSizeOf(out.glsl);
  // Compile the emitted text itself, so the .spv is exactly the .glsl that ships.
  BackendOptions bo;
  bo.optimize = options.optimize;
  bo.keepCalls = keptCalls(specialization);
  SpirvResult spv = compileGlsl(out.glsl, ShaderStage::Compute, name, templateIncludes(), bo);
  out.log += spv.log;
  if (!spv.ok) return out;
  if (options.warningsAsErrors && hasWarning(spv.log)) {
    out.log += name + ": error: warnings treated as errors (-Werror)\n";
    return out;
  }
  out.spirv = std::move(spv.words);
  out.ok = true;
  return out;
}

}  // namespace shadowc
