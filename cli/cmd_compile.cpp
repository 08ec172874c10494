// `shadowc compile FILE.shadow -o DIR`: the compiler driver (driver/driver.h), then an atomic write.
// glslc-style flags: -O / -O0, -M / -MD, -Werror; see docs/cli.md.
#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "backend/spirv_backend.h"
#include "cli/commands.h"
#include "driver/driver.h"
#include "emit/depfile.h"
#include "plan/plan_printer.h"

namespace shadowc::cli {
namespace {

struct CompileArgs {
  std::string input;
  std::string outputDir;
  std::string emit = "glsl,spirv,manifest";
  bool printSpec = false;
  bool printPlan = false;
  bool printRecipe = false;
  bool optimize = true;
  bool depsToStdout = false;  // -M
  bool depsFile = false;      // -MD
  std::string depsTarget;     // -MT: the rule's target instead of the outputs
  bool werror = false;
  bool generic = false;        // --generic
  bool counters = false;       // --counters
  bool frameExternal = false;  // --frame-external
  uint32_t lookupSet = 0, lookupBindingBase = 0;
};

int error(const std::string& message) {
  std::fflush(stdout);
  fmt::print(stderr, "shadowc: error: {}\n", message);
  return 1;
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
  std::set<driver::OutputKind> kinds;
  {
    static const std::vector<std::pair<std::string, driver::OutputKind>> kKinds{
        {"glsl", driver::OutputKind::Glsl},         {"spirv", driver::OutputKind::Spirv},
        {"manifest", driver::OutputKind::Manifest}, {"hlsl", driver::OutputKind::Hlsl},
        {"msl", driver::OutputKind::Msl},           {"cpp", driver::OutputKind::CppHeader}};
    const char* expected = "(expected a subset of glsl,spirv,manifest,hlsl,msl,cpp)";
    std::stringstream ss(a.emit);
    for (std::string k; std::getline(ss, k, ',');) {
      auto it = std::find_if(kKinds.begin(), kKinds.end(), [&](const auto& e) { return e.first == k; });
      if (it == kKinds.end()) return error("--emit: unknown kind '" + k + "' " + expected);
      kinds.insert(it->second);
    }
    if (kinds.empty()) return error(std::string("--emit: no kind given ") + expected);
  }

  // Stop as early as the request allows: --print-spec alone needs the checker, -M and
  // --print-plan the plan.
  driver::Options options;
  options.optimize = a.optimize;
  options.warningsAsErrors = a.werror;
  if (a.lookupSet > kMaxLookupSet) return error("--lookup-set: at most " + std::to_string(kMaxLookupSet));
  if (a.lookupBindingBase > kMaxLookupBindingBase)
    return error("--lookup-binding-base: at most " + std::to_string(kMaxLookupBindingBase));
  options.lookup = {a.lookupSet, a.lookupBindingBase};
  options.generic = a.generic;
  options.counters = a.counters;
  options.frameExternal = a.frameExternal;
  if (a.frameExternal && !kinds.count(driver::OutputKind::Hlsl) && !kinds.count(driver::OutputKind::Msl))
    return error(
        "--frame-external changes the HLSL and MSL lookups: add hlsl or msl to --emit (the GLSL lookup takes "
        "#define SHADOWC_FRAME_EXTERNAL, docs/integration.md)");
  if (a.counters && kinds.count(driver::OutputKind::CppHeader))
    return error(
        "--counters with --emit cpp: the C++ header describes a filter to ship, the instrumented build "
        "is for measuring one (docs/manifest.md \"Work counters\")");
  for (driver::OutputKind k : {driver::OutputKind::Hlsl, driver::OutputKind::Msl, driver::OutputKind::CppHeader})
    if (kinds.count(k)) options.engineOutputs.insert(k);
  if (a.outputDir.empty())
    options.stopAfter = a.printPlan ? driver::Stage::Plan : driver::Stage::Check;
  else if (a.depsToStdout)
    options.stopAfter = driver::Stage::Plan;
  const driver::Result r = driver::compileFile(a.input, options);
  if (!r.log.empty()) {
    std::fflush(stdout);
    fmt::print(stderr, "{}", r.log);
  }
  if (!r.spec) return 1;
  const FilterSpec& spec = *r.spec;

  if (a.printSpec) {
    fmt::print("{}\n", specToJson(spec).dump(2));
    if (a.outputDir.empty() && !a.printPlan) return 0;
  }
  auto didNotCompile = [&] {
    std::fflush(stdout);
    fmt::print(stderr, "shadowc: error: filter '{}' did not compile; nothing was written\n", spec.name);
    return 1;
  };
  if (a.printPlan) {
    if (!r.plan) return a.outputDir.empty() ? 1 : didNotCompile();
    fmt::print("{}", printPassGraph(*r.plan));
    if (a.outputDir.empty()) return 0;
  }
  if (a.outputDir.empty()) return error("no output directory (use -o DIR)");
  const std::filesystem::path dir(a.outputDir);
  if (!r.plan) return didNotCompile();

  std::vector<std::string> outputs;
  for (const auto& f : driver::plannedOutputs(*r.plan, spec, options.engineOutputs))
    if (kinds.count(driver::outputKindOf(f))) outputs.push_back((dir / f).string());
  if (!a.depsTarget.empty()) outputs = {a.depsTarget};
  if (a.depsToStdout) {  // glslc -M: dependencies only, nothing compiled or written
    fmt::print("{}", makeDependencyRule(outputs, a.input));
    return 0;
  }
  if (!r.artifact) return didNotCompile();
  std::vector<EmittedFile> extra;
  if (a.depsFile) extra.push_back({spec.name + ".d", makeDependencyRule(outputs, a.input)});
  if (const std::string err = driver::writeArtifact(dir, *r.artifact, kinds, extra); !err.empty()) return error(err);
  return 0;
}

}  // namespace

CommandRunner registerCompile(CLI::App& app) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* sub = app.add_subcommand("compile", "Compile a filter description to GLSL, SPIR-V and manifest.json");
  sub->add_option("input", args->input, "the .shadow filter description");
  sub->add_option("-o,--out", args->outputDir, "output directory (created; files replaced atomically)");
  addRenamedOption(sub, "--output", "-o/--out");
  sub->add_option("--emit", args->emit,
                  "comma-separated subset of glsl,spirv,manifest,hlsl,msl,cpp (default: glsl,spirv,manifest)");
  sub->add_option("--lookup-set", args->lookupSet,
                  "descriptor set of everything <filter>_lookup.glsl declares (default 0; manifest shade.set)");
  sub->add_option("--lookup-binding-base", args->lookupBindingBase,
                  "added to every binding <filter>_lookup.glsl declares (default 0: the shade pass's own)");
  sub->add_flag("--generic", args->generic,
                "emit the shade pass as one generic shader: numeric options and tables in a uniform block "
                "filled from manifest.json \"parameters\", loops dynamic (docs/cli.md)");
  sub->add_flag("--frame-external", args->frameExternal,
                "the HLSL/MSL lookup takes the frame as arguments of shadowc_visibilityFrame() instead of "
                "declaring the ShadowcFrame block (docs/integration.md)");
  sub->add_flag("--counters", args->counters,
                "the instrumented build: the shade pass also counts its work (fetches, bounds, walk steps) into "
                "manifest.json's work_counters buffer (docs/manifest.md \"Work counters\")");
  sub->add_flag("--print-spec", args->printSpec, "print the normalized FilterSpec as JSON and stop (unless -o)");
  sub->add_flag("--print-plan", args->printPlan,
                "print the pass graph (images, passes, every specialization value) and stop (unless -o)");
  sub->add_flag("--print-recipe", args->printRecipe, "print the -O spirv-opt recipe, one pass per line");
  sub->footer(
      "glslc-style flags:\n"
      "  -O          optimize with the spirv-opt recipe (default)\n"
      "  -O0         no spirv-opt (glslang output, validated)\n"
      "  -M          print make dependencies of the outputs to stdout; compile nothing\n"
      "  -MD         also write DIR/<filter>.d with those dependencies\n"
      "  -MT TARGET  name TARGET (not the outputs) as the rule's target, with -M or -MD\n"
      "  -Werror     treat warnings (filter description and GLSL) as errors\n"
      "Outputs: DIR/manifest.json, DIR/<pass>.glsl, DIR/<pass>.spv, DIR/<filter>_lookup.glsl (docs/manifest.md);\n"
      "with --emit hlsl/msl also DIR/<pass>.hlsl/.metal and DIR/<filter>_lookup.hlsl/.metal, with cpp DIR/<filter>.h\n"
      "(docs/integration.md).");
  sub->allow_extras();
  return [args, sub] { return run(*args, *sub); };
}

}  // namespace shadowc::cli
