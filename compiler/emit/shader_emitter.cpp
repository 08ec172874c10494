#include "emit/shader_emitter.h"

#include <algorithm>
#include <regex>
#include <variant>

#include "emit/glsl_tidy.h"
#include "emit/specialization_block.h"
#include "emit/template_includes.h"

namespace shadowc {
namespace {

std::array<uint32_t, 3> localSizeOf(const std::string& glsl) {
  std::array<uint32_t, 3> size{1, 1, 1};
  static const std::regex re(R"(local_size_([xyz])\s*=\s*(\d+))");
  for (auto it = std::sregex_iterator(glsl.begin(), glsl.end(), re); it != std::sregex_iterator(); ++it)
    size[(*it)[1].str()[0] - 'x'] = static_cast<uint32_t>(std::stoul((*it)[2].str()));
  return size;
}

}  // namespace

bool hasWarning(const std::string& log) { return log.find("WARNING:") != std::string::npos; }

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
                                const GlslPreprocessor& preprocess, bool warningsAsErrors) {
  EmittedShader out;
  out.name = "templates/" + templatePath;  // diagnostics point into the template
  std::string error;
  const std::string specialized = specializeTemplate(templatePath, specialization, error);
  if (!error.empty()) {
    out.log = error + "\n";
    return out;
  }
  std::string preprocessed;
  if (!preprocess(specialized, out.name, templateIncludes(), preprocessed, out.log)) return out;
  if (warningsAsErrors && hasWarning(out.log)) {
    out.log += out.name + ": error: warnings treated as errors (-Werror)\n";
    return out;
  }
  out.glsl = tidyPreprocessed(preprocessed);
  out.localSize = localSizeOf(out.glsl);
  out.keepCalls = keptCalls(specialization);
  out.ok = true;
  return out;
}

}  // namespace shadowc
