// The lookup's placement and frame block (lookup_interface.h).
#include "emit/lookup_interface.h"

#include <fmt/format.h>

#include <stdexcept>

#include "emit/glsl_tidy.h"
#include "emit/template_includes.h"

namespace shadowc {
namespace {

// The image names the lookup declares (docs/manifest.md "Images (fixed names)") and the macro
// of templates/frame_block.glsl / lookup/defaults.glsl that places each.
constexpr std::pair<const char*, const char*> kMacros[] = {
    {"frame", "SHADOWC_BINDING_FRAME"},
    {"shadow_depth", "SHADOWC_BINDING_DEPTH"},
    {"moments", "SHADOWC_BINDING_MOMENTS"},
    {"sat", "SHADOWC_BINDING_SAT"},
    {"minmax", "SHADOWC_BINDING_MINMAX"},
    {"splits", "SHADOWC_BINDING_SPLITS"},
    {"parameters", "SHADOWC_BINDING_PARAMETERS"},    // generic shaders (plan/generic_block.h)
    {"quadtree_table", "SHADOWC_BINDING_QUADTREE"},  // `traversal: table` (plan/quadtree_tables.h)
    {"work_counters", "SHADOWC_BINDING_WORK"}};      // the instrumented build (plan/work_counters.h)

bool isLookupResource(const Binding& b) {
  // The G-buffer and the output are storage images; the quadtree tables a read-only buffer, the
  // work counters (instrumented builds only) a buffer the lookup adds into.
  return b.access == Access::Uniform || b.access == Access::Sampled || b.access == Access::StorageBufferRead ||
         b.access == Access::StorageBufferReadWrite;
}

const char* macroOf(const std::string& image) {
  for (const auto& [name, macro] : kMacros)
    if (image == name) return macro;
  throw std::invalid_argument("lookup interface: the shade pass binds '" + image +
                              "', which the lookup has no macro for");
}

}  // namespace

bool lookupLayout(const Pass& shadePass, const LookupPlacement& placement, const GlslPreprocessor& preprocess,
                  LookupLayout& out, std::string& log, int cascades) {
  if (placement.set > kMaxLookupSet || placement.bindingBase > kMaxLookupBindingBase)
    throw std::invalid_argument(
        fmt::format("lookup placement out of range: set {} (at most {}), binding base {} (at most {})", placement.set,
                    kMaxLookupSet, placement.bindingBase, kMaxLookupBindingBase));
  out = {};
  out.defines = fmt::format("#define SHADOWC_SET {}\n", placement.set);
  for (const Binding& b : shadePass.bindings) {
    if (!isLookupResource(b)) continue;
    Binding placed = b;
    placed.binding += placement.bindingBase;
    out.bindings.push_back(placed);
    out.defines += fmt::format("#define {} {}\n", macroOf(b.image), placed.binding);
  }
  // The block alone, preprocessed with the same placement so that its numbers are literals.
  // A cascaded sun's block has the cascade fields at its end (frame_block.glsl).
  const std::string cascadeDefine = cascades > 0 ? fmt::format("#define SHADOWC_CASCADES {}\n", cascades) : "";
  const std::string wrapper = "#version 460\n#extension GL_GOOGLE_include_directive : require\n" + out.defines +
                              cascadeDefine + "#include \"frame_block.glsl\"\n";
  std::string text;
  if (!preprocess(wrapper, "templates/frame_block.glsl", templateIncludes(), text, log)) return false;
  std::string body;
  for (size_t at = 0; at < text.size();) {
    size_t end = text.find('\n', at);
    end = end == std::string::npos ? text.size() : end + 1;
    const std::string line = text.substr(at, end - at);
    if (!line.starts_with("#version") && !line.starts_with("#extension")) body += line;
    at = end;
  }
  body = stripLineDirectives(body);
  while (!body.empty() && body.front() == '\n') body.erase(body.begin());
  out.frameBlock =
      "// The frame block; define SHADOWC_FRAME_EXTERNAL before including this file to supply\n"
      "// shadowc_Frame shadowc_frame() from your own data instead (docs/integration.md).\n"
      "#ifndef SHADOWC_FRAME_EXTERNAL\n" +
      body + (body.ends_with("\n") ? "" : "\n") + "#endif\n";
  return true;
}

}  // namespace shadowc
