#include "backend/spirv_backend.h"

#include <memory>
#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "backend/dont_inline.h"

namespace shadowc {
namespace {

constexpr spv_target_env kTargetEnv = SPV_ENV_VULKAN_1_2;

void initGlslangOnce() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage toGlslang(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return EShLangVertex;
    case ShaderStage::Fragment: return EShLangFragment;
    case ShaderStage::Compute: return EShLangCompute;
  }
  return EShLangCompute;
}

// Bridges glslang's include callback to our resolver. The texts are kept alive in `kept`
// until the includer goes away, as glslang requires.
class Includer : public glslang::TShader::Includer {
 public:
  explicit Includer(const IncludeResolver& r) : resolver_(r) {}
  IncludeResult* includeLocal(const char* name, const char*, size_t) override { return resolve(name); }
  IncludeResult* includeSystem(const char* name, const char*, size_t) override { return resolve(name); }
  void releaseInclude(IncludeResult* r) override { delete r; }

 private:
  IncludeResult* resolve(const char* name) {
    if (!resolver_) return nullptr;
    auto text = resolver_(name);
    if (!text) return nullptr;
    kept_.push_back(std::make_unique<std::string>(std::move(*text)));
    return new IncludeResult(name, kept_.back()->data(), kept_.back()->size(), nullptr);
  }
  const IncludeResolver& resolver_;
  std::vector<std::unique_ptr<std::string>> kept_;
};

void setupShader(glslang::TShader& shader, std::string_view source, const std::string& name, const char*& src,
                 int& len, const char*& nm, glslang::EShSource language = glslang::EShSourceGlsl) {
  src = source.data();
  len = static_cast<int>(source.size());
  nm = name.c_str();
  shader.setStringsWithLengthsAndNames(&src, &len, &nm, 1);
  shader.setEnvInput(language, shader.getStage(), glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
}

constexpr auto kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

std::string messageText(spv_message_level_t level, const char* source, const spv_position_t& pos, const char* msg) {
  const char* sev = level <= SPV_MSG_ERROR ? "error" : level == SPV_MSG_WARNING ? "warning" : "info";
  std::string where = source && *source ? std::string(source) + ":" : std::string();
  return where + std::to_string(pos.index) + ": " + sev + ": " + msg + "\n";
}

}  // namespace

const std::vector<std::string>& optimizationRecipe() {
  // A trimmed form of spirv-opt -O: the passes that matter for straight-line, fully
  // specialized filter code (constant folding after unrolling, dead branch removal,
  // scalar replacement), each named as the spirv-opt flag it equals.
  static const std::vector<std::string> recipe = {
      "--merge-return",           "--inline-entry-points-exhaustive",
      "--eliminate-dead-functions", "--private-to-local",
      "--eliminate-local-single-block", "--eliminate-local-single-store",
      "--scalar-replacement=100", "--convert-local-access-chains",
      "--ccp",                    "--loop-unroll",
      "--eliminate-dead-branches", "--merge-blocks",
      "--eliminate-local-multi-store", "--eliminate-dead-code-aggressive",
      "--vector-dce",             "--eliminate-dead-inserts",
      "--if-conversion",          "--copy-propagate-arrays",
      "--reduce-load-size",       "--redundancy-elimination",
      "--simplify-instructions",  "--eliminate-dead-code-aggressive",
      "--cfg-cleanup",
  };
  return recipe;
}

SpirvResult preprocessGlsl(std::string_view source, ShaderStage stage, const std::string& name,
                           const IncludeResolver& includes, std::string& out) {
  initGlslangOnce();
  glslang::TShader shader(toGlslang(stage));
  const char* src;
  int len;
  const char* nm;
  setupShader(shader, source, name, src, len, nm);
  Includer includer(includes);
  SpirvResult r;
  r.ok = shader.preprocess(GetDefaultResources(), 460, ENoProfile, false, false, kMessages, &out, includer);
  r.log = shader.getInfoLog();
  return r;
}

SpirvResult compileGlsl(std::string_view source, ShaderStage stage, const std::string& name,
                        const IncludeResolver& includes, const BackendOptions& options) {
  initGlslangOnce();
  SpirvResult r;
  glslang::TShader shader(toGlslang(stage));
  const char* src;
  int len;
  const char* nm;
  setupShader(shader, source, name, src, len, nm);
  Includer includer(includes);
  if (!shader.parse(GetDefaultResources(), 460, false, kMessages, includer)) {
    r.log = std::string(shader.getInfoLog()) + shader.getInfoDebugLog();
    return r;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(kMessages)) {
    r.log = program.getInfoLog();
    return r;
  }
  glslang::SpvOptions spvOptions;
  spvOptions.disableOptimizer = true;  // our own recipe runs below
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(toGlslang(stage)), r.words, &logger, &spvOptions);
  r.log += logger.getAllMessages();

  if (options.validate) {
    if (auto err = validateSpirv(r.words); !err.empty()) {
      r.log += name + ": error: glslang produced invalid SPIR-V: " + err;
      return r;
    }
  }
  if (options.optimize) {
    markDontInline(r.words, options.keepCalls);
    spvtools::Optimizer opt(kTargetEnv);
    std::string optLog;
    opt.SetMessageConsumer([&](spv_message_level_t level, const char* s, const spv_position_t& p, const char* m) {
      optLog += messageText(level, s, p, m);
    });
    if (!opt.RegisterPassesFromFlags(optimizationRecipe())) {
      r.log += name + ": error: bad optimization recipe: " + optLog;
      return r;
    }
    std::vector<uint32_t> optimized;
    spvtools::OptimizerOptions oo;
    oo.set_run_validator(options.validate);
    if (!opt.Run(r.words.data(), r.words.size(), &optimized, oo)) {
      r.log += name + ": error: spirv-opt failed: " + optLog;
      return r;
    }
    r.words = std::move(optimized);
    if (options.validate) {
      if (auto err = validateSpirv(r.words); !err.empty()) {
        r.log += name + ": error: optimized SPIR-V is invalid: " + err;
        return r;
      }
    }
  }
  r.ok = true;
  return r;
}

SpirvResult compileHlsl(std::string_view source, ShaderStage stage, const std::string& name, const std::string& entry) {
  initGlslangOnce();
  SpirvResult r;
  glslang::TShader shader(toGlslang(stage));
  const char* src;
  int len;
  const char* nm;
  setupShader(shader, source, name, src, len, nm, glslang::EShSourceHlsl);
  // SPIR-V 1.3: glslang's HLSL front end before 12.1 decorates storage buffers BufferBlock, which
  // SPIR-V 1.4 and later no longer have (KhronosGroup/glslang PR 3121); 1.3 is what that
  // decoration is valid in, and Vulkan 1.2 takes it.
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  shader.setEntryPoint(entry.c_str());
  const auto messages = static_cast<EShMessages>(kMessages | EShMsgReadHlsl);
  Includer includer(IncludeResolver{});
  if (!shader.parse(GetDefaultResources(), 100, false, messages, includer)) {
    r.log = std::string(shader.getInfoLog()) + shader.getInfoDebugLog();
    return r;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    r.log = program.getInfoLog();
    return r;
  }
  glslang::SpvOptions spvOptions;
  spvOptions.disableOptimizer = true;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(toGlslang(stage)), r.words, &logger, &spvOptions);
  r.log += logger.getAllMessages();
  if (auto err = validateSpirv(r.words); !err.empty()) {
    r.log += name + ": error: glslang's HLSL front end produced invalid SPIR-V: " + err;
    return r;
  }
  r.ok = true;
  return r;
}

std::string validateSpirv(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(kTargetEnv);
  std::string log;
  tools.SetMessageConsumer([&](spv_message_level_t level, const char* s, const spv_position_t& p, const char* m) {
    log += messageText(level, s, p, m);
  });
  spvtools::ValidatorOptions vo;
  if (words.empty()) return "empty module";
  if (!tools.Validate(words.data(), words.size(), vo)) return log.empty() ? "invalid module" : log;
  return {};
}

std::string disassembleSpirv(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(kTargetEnv);
  std::string text;
  tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_INDENT | SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES);
  return text;
}

}  // namespace shadowc
