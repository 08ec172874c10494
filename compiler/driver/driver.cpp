// The compiler driver (driver.h): load -> check -> plan -> emit -> backend, in this file only.
#include "driver/driver.h"

#include <algorithm>
#include <exception>
#include <map>
#include <utility>

#include "backend/spirv_backend.h"
#include "driver/cross_outputs.h"
#include "driver/emit_stage.h"
#include "emit/cpp_header.h"
#include "emit/filter_emitter.h"
#include "emit/output_writer.h"
#include "plan/generic_block.h"
#include "plan/planner.h"
#include "plan/work_counters.h"
#include "spec/print_filter.h"

namespace shadowc::driver {
namespace {

// A stage that throws (a precondition the checker does not own yet) becomes one located line
// in glslc form, never an exception out of the driver.
std::string locatedError(const FilterSpec& spec, const std::string& message) {
  return spec.location.file + ":" + std::to_string(spec.location.line) + ":" + std::to_string(spec.location.column) +
         ": error: " + message + "\n";
}

// A spec built in code is valid when the checker accepts its printed description
// (spec/print_filter.h): one checker decides for text and for code alike. The errors then point
// into the printed text, which the log shows. The caller's spec itself is compiled (it may carry
// the debug-only naiveUnguarded, which the language cannot express).
LoadResult checkBuiltSpec(const FilterSpec& spec) {
  LoadResult checked = loadFilterSource(printFilter(spec), spec.name + ".shadow");
  if (checked.spec) checked.spec = spec;
  return checked;
}

// Emit and run the backend (emit_stage.h): the one place the planner's output meets the emitter.
FilterEmitResult emitAndCompile(const FilterSpec& spec, const PassGraph& plan, const Options& options) {
  return emitStage(spec, plan, {{options.optimize, options.warningsAsErrors}, options.lookup});
}

// The outputs derived from the SPIR-V (HLSL, MSL, the C++ header), added to the emitted files.
bool engineOutputs(FilterEmitResult& emitted, const Options& options, std::string& log) {
  std::vector<EmittedFile> extra;
  for (const auto& [kind, target] :
       {std::pair{OutputKind::Hlsl, CrossTarget::Hlsl}, {OutputKind::Msl, CrossTarget::Msl}})
    if (options.engineOutputs.count(kind) &&
        !crossOutputs(emitted.manifest, emitted.files, target, options.frameExternal, extra, log))
      return false;
  if (options.engineOutputs.count(OutputKind::CppHeader)) {
    if (options.counters) {
      log +=
          "error: the C++ header describes a filter to ship; the instrumented build (--counters) is for "
          "measuring it (docs/manifest.md \"Work counters\"): compile it without the header\n";
      return false;
    }
    std::map<std::string, std::string> spirv;
    for (const EmittedFile& f : emitted.files)
      if (outputKindOf(f.name) == OutputKind::Spirv) spirv.emplace(f.name, f.bytes);
    extra.push_back({cppHeaderFileName(emitted.manifest.filter), cppHeader(emitted.manifest, spirv)});
  }
  emitted.files.insert(emitted.files.end(), extra.begin(), extra.end());
  std::sort(emitted.files.begin(), emitted.files.end(),
            [](const EmittedFile& a, const EmittedFile& b) { return a.name < b.name; });
  return true;
}

// Everything after the front end, shared by the three entry points.
Result finish(const LoadResult& loaded, const Options& options) {
  Result r;
  r.diagnostics = loaded.diagnostics;
  r.log = formatDiagnostics(loaded);
  if (!loaded.spec) return r;
  const FilterSpec& spec = *loaded.spec;
  r.spec = spec;
  if (options.stopAfter == Stage::Check) {
    r.ok = true;
    return r;
  }
  try {
    r.plan = planPasses(spec);
    if (options.generic) makeGeneric(*r.plan);
    if (options.counters) addWorkCounters(*r.plan);  // after the generic rewrite: its indices stay constants
  } catch (const std::exception& e) {
    r.log += locatedError(spec, e.what());
    return r;
  }
  if (options.stopAfter == Stage::Plan) {
    r.ok = true;
    return r;
  }
  FilterEmitResult emitted;
  try {
    emitted = emitAndCompile(spec, *r.plan, options);
  } catch (const std::exception& e) {
    r.log += locatedError(spec, e.what());
    return r;
  }
  r.log += emitted.log;
  if (!emitted.ok) return r;
  if (!engineOutputs(emitted, options, r.log)) return r;
  r.artifact = Artifact{spec, *r.plan, std::move(emitted.manifest), std::move(emitted.files)};
  r.ok = true;
  return r;
}

LoadOptions loadOptions(const Options& options) {
  LoadOptions lo;
  lo.warningsAsErrors = options.warningsAsErrors;
  return lo;
}

}  // namespace

const std::string* Artifact::file(const std::string& name) const {
  const auto it = std::lower_bound(files.begin(), files.end(), name,
                                   [](const EmittedFile& f, const std::string& n) { return f.name < n; });
  return it != files.end() && it->name == name ? &it->bytes : nullptr;
}

CompiledPasses Artifact::passes() const {
  CompiledPasses c;
  c.manifest = manifest;
  for (const Pass& p : manifest.passes)
    for (const PassForm& f : formsOf(p))
      if (const std::string* bytes = file(f.spirv)) c.files.emplace(f.spirv, *bytes);
  return c;
}

OutputKind outputKindOf(const std::string& fileName) {
  if (fileName == kManifestFile) return OutputKind::Manifest;
  if (fileName.ends_with(".spv")) return OutputKind::Spirv;
  if (fileName.ends_with(".hlsl")) return OutputKind::Hlsl;
  if (fileName.ends_with(".metal")) return OutputKind::Msl;
  if (fileName.ends_with(".h")) return OutputKind::CppHeader;
  return OutputKind::Glsl;
}

Result compileSource(const std::string& text, const std::string& fileName, const Options& options) {
  return finish(loadFilterSource(text, fileName, loadOptions(options)), options);
}

Result compileFile(const std::string& path, const Options& options) {
  return finish(loadFilterFile(path, loadOptions(options)), options);
}

Result compileSpec(const FilterSpec& spec, const Options& options) {
  if (options.checkBuiltSpec) return finish(checkBuiltSpec(spec), options);
  LoadResult unchecked;
  unchecked.spec = spec;
  return finish(unchecked, options);
}

std::vector<std::string> plannedOutputs(const PassGraph& plan, const FilterSpec& spec,
                                        const std::set<OutputKind>& engineOutputs) {
  std::set<std::string> names{kManifestFile, lookupFileName(spec.name)};
  std::set<std::string> stems{lookupFileName(spec.name).substr(0, lookupFileName(spec.name).rfind('.'))};
  for (const Pass& p : plan.manifest.passes)
    for (const PassForm& f : formsOf(p)) {
      names.insert(f.glsl);
      names.insert(f.spirv);
      stems.insert(f.spirv.substr(0, f.spirv.rfind('.')));
    }
  for (const auto& [kind, target] :
       {std::pair{OutputKind::Hlsl, CrossTarget::Hlsl}, {OutputKind::Msl, CrossTarget::Msl}})
    if (engineOutputs.count(kind))
      for (const std::string& stem : stems) names.insert(stem + crossExtension(target));
  if (engineOutputs.count(OutputKind::CppHeader)) names.insert(cppHeaderFileName(spec.name));
  return {names.begin(), names.end()};
}

std::vector<ShaderText> shaderTexts(const Artifact& artifact) {
  std::vector<ShaderText> out;
  for (const EmittedFile& f : artifact.files)
    if (outputKindOf(f.name) == OutputKind::Glsl && f.name != artifact.manifest.shade.glsl) {
      ShaderText s{f.name.substr(0, f.name.rfind('.')), f.bytes, {}};
      for (const PassSource& src : artifact.plan.sources)
        if (src.stem == s.stem) s.keepCalls = keptCalls(src.values);
      out.push_back(std::move(s));
    }
  return out;
}

bool compileShaderText(const ShaderText& shader, std::string& log) {
  EmittedShader sh;
  sh.name = shader.stem;
  sh.glsl = shader.glsl;
  sh.keepCalls = shader.keepCalls;
  std::vector<uint32_t> words;
  return compileEmitted(sh, {}, words, log);
}

const std::vector<std::string>& optimizationRecipe() { return shadowc::optimizationRecipe(); }

std::string writeArtifact(const std::filesystem::path& dir, const Artifact& artifact, const std::set<OutputKind>& kinds,
                          const std::vector<EmittedFile>& extra) {
  std::vector<EmittedFile> files;
  for (const EmittedFile& f : artifact.files)
    if (kinds.empty() || kinds.count(outputKindOf(f.name))) files.push_back(f);
  files.insert(files.end(), extra.begin(), extra.end());
  return writeFilesAtomically(dir, files);
}

}  // namespace shadowc::driver
