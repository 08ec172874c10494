// `shadowc compile FILE.shadow -o DIR`: front end -> planner -> emitter -> atomic write.
// glslc-style flags (STYLE.md): -O / -O0, -M / -MD, -Werror; see docs/cli.md.
#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "cli/commands.h"
#include "emit/depfile.h"
#include "emit/filter_emitter.h"
#include "emit/output_writer.h"
#include "plan/planner.h"
#include "spec/load_filter.h"

namespace shadowc::cli {
namespace {

struct CompileArgs {
  std::string input;
  std::string outputDir;
  std::string emit = "glsl,spirv,manifest";
  bool printSpec = false;
  bool printRecipe = false;
  bool optimize = true;
  bool depsToStdout = false;  // -M
  bool depsFile = false;      // -MD
  std::string depsTarget;     // -MT: the rule's target instead of the outputs
  bool werror = false;
};

// Which file kinds --emit keeps: .glsl (passes and the lookup), .spv, manifest.json.
bool keep(const std::string& file, const std::set<std::string>& kinds) {
  if (file == kManifestFile) return kinds.count("manifest") > 0;
  if (file.ends_with(".spv")) return kinds.count("spirv") > 0;
  return kinds.count("glsl") > 0;
}

int error(const std::string& message) {
  std::fflush(stdout);
  fmt::print(stderr, "shadowc: error: {}\n", message);
  return 1;
}

// Output file names without compiling (for -M): the plan decides every name.
std::vector<std::string> plannedOutputs(const FilterSpec& spec) {
  std::set<std::string> names{kManifestFile, lookupFileName(spec.name)};
  const PassGraph g = planPasses(spec);
  for (const auto& s : g.sources) {
    names.insert(s.stem + ".glsl");
    names.insert(s.stem + ".spv");
  }
  return {names.begin(), names.end()};
}

int run(CompileArgs& a, CLI::App& sub) {
  // CLI11 2.1 has no multi-letter single-dash options: glslc's -O0, -MD and -Werror arrive here.
  const std::vector<std::string> extras = sub.remaining();
  for (size_t i = 0; i < extras.size(); ++i) {
    const std::string& extra = extras[i];
    if (extra == "-MT") {  // glslc's -MT TARGET; Ninja wants a depfile naming only declared outputs
      if (i + 1 == extras.size()) return error("-MT needs a target (shadowc compile FILE -o DIR -MD -MT TARGET)");
      a.depsTarget = extras[++i];
    } else if (extra == "-O")
      a.optimize = true;
    else if (extra == "-O0")
      a.optimize = false;
    else if (extra == "-M")
      a.depsToStdout = true;
    else if (extra == "-MD")
      a.depsFile = true;
    else if (extra == "-Werror")
      a.werror = true;
    else
      return error("unknown argument '" + extra + "' (see shadowc compile --help)");
  }
  if (a.printRecipe) {
    for (const auto& pass : optimizationRecipe()) fmt::print("{}\n", pass);
    if (a.input.empty()) return 0;
  }
  if (a.input.empty()) return error("no input file (shadowc compile FILE.shadow -o DIR)");
  std::set<std::string> kinds;
  {
    std::stringstream ss(a.emit);
    for (std::string k; std::getline(ss, k, ',');) {
      if (k != "glsl" && k != "spirv" && k != "manifest")
        return error("--emit: unknown kind '" + k + "' (expected a subset of glsl,spirv,manifest)");
      kinds.insert(k);
    }
  }

  LoadOptions lo;
  lo.warningsAsErrors = a.werror;
  const LoadResult loaded = loadFilterFile(a.input, lo);
  const std::string diags = formatDiagnostics(loaded);
  if (!diags.empty()) {
    std::fflush(stdout);
    fmt::print(stderr, "{}", diags);
  }
  if (!loaded.spec) return 1;
  const FilterSpec& spec = *loaded.spec;

  if (a.printSpec) {
    fmt::print("{}\n", specToJson(spec).dump(2));
    if (a.outputDir.empty()) return 0;
  }
  if (a.outputDir.empty()) return error("no output directory (use -o DIR)");
  const std::filesystem::path dir(a.outputDir);

  std::vector<std::string> outputs;
  for (const auto& f : plannedOutputs(spec))
    if (keep(f, kinds)) outputs.push_back((dir / f).string());
  if (!a.depsTarget.empty()) outputs = {a.depsTarget};
  if (a.depsToStdout) {  // glslc -M: dependencies only, nothing compiled or written
    fmt::print("{}", makeDependencyRule(outputs, a.input));
    return 0;
  }

  EmitOptions eo;
  eo.optimize = a.optimize;
  eo.warningsAsErrors = a.werror;
  FilterEmitResult r = emitFilter(spec, eo);
  if (!r.ok) {
    std::fflush(stdout);
    fmt::print(stderr, "{}", r.log);
    fmt::print(stderr, "shadowc: error: filter '{}' did not compile; nothing was written\n", spec.name);
    return 1;
  }
  std::vector<EmittedFile> files;
  for (auto& f : r.files)
    if (keep(f.name, kinds)) files.push_back(std::move(f));
  if (a.depsFile) files.push_back({spec.name + ".d", makeDependencyRule(outputs, a.input)});
  if (const std::string err = writeFilesAtomically(dir, files); !err.empty()) return error(err);
  return 0;
}

}  // namespace

CommandRunner registerCompile(CLI::App& app) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* sub = app.add_subcommand("compile", "Compile a filter description to GLSL, SPIR-V and manifest.json");
  sub->add_option("input", args->input, "the .shadow filter description");
  sub->add_option("-o,--output", args->outputDir, "output directory (created; files replaced atomically)");
  sub->add_option("--emit", args->emit, "comma-separated subset of glsl,spirv,manifest (default: all)");
  sub->add_flag("--print-spec", args->printSpec, "print the normalized FilterSpec as JSON and stop (unless -o)");
  sub->add_flag("--print-recipe", args->printRecipe, "print the -O spirv-opt recipe, one pass per line");
  sub->footer(
      "glslc-style flags:\n"
      "  -O          optimize with the spirv-opt recipe (default)\n"
      "  -O0         no spirv-opt (glslang output, validated)\n"
      "  -M          print make dependencies of the outputs to stdout; compile nothing\n"
      "  -MD         also write DIR/<filter>.d with those dependencies\n"
      "  -MT TARGET  name TARGET (not the outputs) as the rule's target, with -M or -MD\n"
      "  -Werror     treat warnings (filter description and GLSL) as errors\n"
      "Outputs: DIR/manifest.json, DIR/<pass>.glsl, DIR/<pass>.spv, DIR/<filter>_lookup.glsl (docs/manifest.md).");
  sub->allow_extras();
  return [args, sub] { return run(*args, *sub); };
}

}  // namespace shadowc::cli
