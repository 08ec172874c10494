// Renders typed specialization values as GLSL (see specialization_block.h). Deterministic:
// the same values give the same bytes.
#include "emit/specialization_block.h"

#include <fmt/format.h>

#include <algorithm>

#include "emit/glsl_literal.h"
#include "emit/quadtree_glsl.h"

namespace shadowc {

std::string renderTable(const Table& table) {
  struct Render {
    std::string operator()(const RealTable& t) const {
      std::string out = fmt::format("// {}\nconst float {}[{}] = float[](", t.note, t.name, t.values.size());
      for (size_t i = 0; i < t.values.size(); ++i) out += (i ? ", " : "") + glslFloat(t.values[i]);
      return out + ");\n";
    }
    std::string operator()(const PointTable& t) const {
      std::string out = fmt::format("// {}\nconst vec2 {}[{}] = vec2[](", t.note, t.name, t.points.size());
      for (size_t i = 0; i < t.points.size(); ++i)
        out +=
            fmt::format("{}vec2({}, {})", i ? ", " : "", glslFloat(t.points[i].first), glslFloat(t.points[i].second));
      return out + ");\n";
    }
    std::string operator()(const UnrolledQuadtree& u) const {
      return emitUnrolledQuadtreeGlsl(u.height, u.function, u.visit, u.leaf);
    }
  };
  return std::visit(Render{}, table);
}

// The generic shader's uniform block (plan/generic_block.h), its members at the manifest's
// offsets, and one alias per member so that the template reads the uniform where it read the
// constant. (The few `const int n = SHADOWC_X;` locals stay legal: GLSL 4.20+ allows a const
// local with a non-constant initializer.)
std::string renderParameters(const ParameterBlock& b) {
  std::string out = fmt::format(
      "// generic: the options below are uniforms the runtime fills from manifest.json \"parameters\"\n"
      "#ifndef SHADOWC_SET\n#define SHADOWC_SET 0\n#endif\n"
      "#ifndef SHADOWC_BINDING_PARAMETERS\n#define SHADOWC_BINDING_PARAMETERS {}\n#endif\n"
      "layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_PARAMETERS, std140) uniform shadowc_GenericBlock {{\n",
      b.binding);
  for (const BlockMember& m : b.members) {
    const char* scalar = m.type == ScalarType::F32 ? "float" : m.type == ScalarType::I32 ? "int" : "uint";
    const std::string type = m.components == 1 ? scalar
                                               : fmt::format("{}vec{}",
                                                             m.type == ScalarType::F32   ? ""
                                                             : m.type == ScalarType::I32 ? "i"
                                                                                         : "u",
                                                             m.components);
    out += fmt::format("  layout(offset = {}) {} {}{};\n", m.offset, type, m.name,
                       m.stride ? fmt::format("[{}]", m.count) : std::string());
  }
  out += "} shadowc_generic;\n";
  for (const BlockMember& m : b.members) out += fmt::format("#define {} shadowc_generic.{}\n", m.macro, m.name);
  return out;
}

std::string specializationBlock(const Specialization& s, int markerLine) {
  std::string out = "// shadowc specialization (generated)\n";
  if (s.parameters) out += renderParameters(*s.parameters);
  for (const Constant& c : s.constants) out += fmt::format("#define {} {}\n", c.name, glslValue(c.value));
  for (const Table& t : s.tables) out += renderTable(t);
  out += fmt::format("#line {}\n", markerLine + 1);
  return out;
}

std::string insertSpecialization(const std::string& templateText, const Specialization& s) {
  const size_t pos = templateText.find(kSpecializeMarker);
  if (pos == std::string::npos) return templateText;
  const size_t lineStart = templateText.rfind('\n', pos) == std::string::npos ? 0 : templateText.rfind('\n', pos) + 1;
  size_t lineEnd = templateText.find('\n', pos);
  lineEnd = lineEnd == std::string::npos ? templateText.size() : lineEnd + 1;
  const int markerLine = 1 + static_cast<int>(std::count(templateText.begin(), templateText.begin() + pos, '\n'));
  return templateText.substr(0, lineStart) + specializationBlock(s, markerLine) + templateText.substr(lineEnd);
}

}  // namespace shadowc
