// SPIRV-Cross wrapper (cross_compile.h). SPIRV-Cross reports failures by throwing
// spirv_cross::CompilerError; they become one located log line here.
#include "backend/cross_compile.h"

#include <exception>
#include <memory>
#include <spirv_hlsl.hpp>
#include <spirv_msl.hpp>
#include <utility>

namespace shadowc {
namespace {

std::unique_ptr<spirv_cross::CompilerGLSL> makeCompiler(std::vector<uint32_t> words, CrossTarget target) {
  if (target == CrossTarget::Hlsl) {
    auto hlsl = std::make_unique<spirv_cross::CompilerHLSL>(std::move(words));
    spirv_cross::CompilerHLSL::Options o;
    o.shader_model = kHlslShaderModel;
    hlsl->set_hlsl_options(o);
    return hlsl;
  }
  auto msl = std::make_unique<spirv_cross::CompilerMSL>(std::move(words));
  spirv_cross::CompilerMSL::Options o;
  o.platform = spirv_cross::CompilerMSL::Options::macOS;
  o.msl_version = spirv_cross::CompilerMSL::Options::make_msl_version(kMslVersionMajor, kMslVersionMinor);
  msl->set_msl_options(o);
  return msl;
}

}  // namespace

const char* crossExtension(CrossTarget target) { return target == CrossTarget::Hlsl ? ".hlsl" : ".metal"; }

CrossResult crossCompile(const std::vector<uint32_t>& spirv, CrossTarget target, const std::string& name,
                         const std::string& entryName) {
  CrossResult r;
  try {
    std::unique_ptr<spirv_cross::CompilerGLSL> compiler = makeCompiler(spirv, target);
    if (!entryName.empty()) {
      const auto entries = compiler->get_entry_points_and_stages();
      if (entries.size() != 1) {
        r.log = name + ": error: expected one entry point, found " + std::to_string(entries.size()) + "\n";
        return r;
      }
      compiler->rename_entry_point(entries[0].name, entryName, entries[0].execution_model);
    }
    r.source = compiler->compile();
    r.ok = true;
  } catch (const std::exception& e) {
    r.log = name + ": error: SPIRV-Cross (" + (target == CrossTarget::Hlsl ? "HLSL" : "MSL") + "): " + e.what() + "\n";
  }
  return r;
}

}  // namespace shadowc
