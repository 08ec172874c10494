// The PassGraph as text (see plan_printer.h). Not GLSL: the emitter renders values for the
// shaders (emit/glsl_literal.h); this prints them for people and CHECK-style tests.
#include "plan/plan_printer.h"

#include <fmt/format.h>

namespace shadowc {
namespace {

std::string real(double v) { return fmt::format("{}", v); }  // shortest round-trip form

std::string reals(const std::vector<double>& values) {
  std::string s;
  for (size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + real(values[i]);
  return s;
}

std::string ints(const std::vector<int>& values) {
  std::string s;
  for (size_t i = 0; i < values.size(); ++i) s += fmt::format("{}{}", i ? " " : "", values[i]);
  return s;
}

std::string size(const SizeRule& r) {
  return r.shift == 0 ? toString(r.domain) : fmt::format("{}>>{}", toString(r.domain), r.shift);
}

std::string printTable(const Table& table) {
  struct Print {
    std::string operator()(const RealTable& t) const {
      return fmt::format("table {} real[{}] {}  # {}", t.name, t.values.size(), reals(t.values), t.note);
    }
    std::string operator()(const PointTable& t) const {
      std::string s = fmt::format("table {} point[{}]", t.name, t.points.size());
      for (size_t i = 0; i < t.points.size(); ++i)
        s += fmt::format("{}({}, {})", i ? ", " : " ", real(t.points[i].first), real(t.points[i].second));
      return s + "  # " + t.note;
    }
    std::string operator()(const UnrolledQuadtree& u) const {
      return fmt::format("table {} unrolled_quadtree height {} visit {} leaf {}", u.function, u.height, u.visit,
                         u.leaf);
    }
  };
  return std::visit(Print{}, table);
}

// One group per element, on one line, as the tables are printed.
std::string printBuffer(const BufferDesc& b) {
  const size_t n = b.components ? b.values.size() / b.components : 0;
  std::string out = fmt::format("buffer {} int32x{}[{}]", b.name, b.components, n);
  for (size_t i = 0; i < n; ++i) {
    const auto first = b.values.begin() + std::ptrdiff_t(i * b.components);
    out += " (" + ints(std::vector<int>(first, first + b.components)) + ")";
  }
  return out + "\n";
}

}  // namespace

std::string printValue(const SpecValue& value) {
  struct Print {
    std::string operator()(long long v) const { return fmt::format("int {}", v); }
    std::string operator()(bool v) const { return fmt::format("bool {}", v ? 1 : 0); }
    std::string operator()(const Real& v) const { return "real " + real(v.value); }
    std::string operator()(const EnumCode& v) const { return fmt::format("enum {} ({})", v.name, v.code); }
    std::string operator()(ImageFormat v) const { return fmt::format("format {}", toString(v)); }
    std::string operator()(const RealList& v) const {
      return fmt::format("real[{}] {}", v.values.size(), reals(v.values));
    }
  };
  return std::visit(Print{}, value);
}

std::string needs(const FormNeeds& n) {
  std::string out = fmt::format("needs device {}", toString(n.device));
  if (n.subgroupSizeMin) out += fmt::format(" subgroup_size >= {}", n.subgroupSizeMin);
  for (const std::string& op : n.subgroupOperations) out += " subgroup " + op;
  return out;
}

std::string printPassGraph(const PassGraph& graph) {
  const Manifest& m = graph.manifest;
  std::string out = fmt::format("; shadowc pass graph, filter {}: {} images, {} passes\n", m.filter, m.images.size(),
                                m.passes.size());
  for (const ImageDesc& d : m.images)
    out += fmt::format("image {} {} size {} levels {} layers {} role {}{}\n", d.name, toString(d.format), size(d.size),
                       d.mipLevels, d.layers, toString(d.role), d.linearFilter ? " linear" : "");
  for (const BufferDesc& b : m.buffers) out += printBuffer(b);
  for (size_t i = 0; i < m.passes.size(); ++i) {
    const Pass& p = m.passes[i];
    out += fmt::format("pass {} {} kind {}\n", i, p.name, p.kind);
    if (i < graph.sources.size())
      out += fmt::format("  template {} stem {}\n", graph.sources[i].templatePath, graph.sources[i].stem);
    out += fmt::format("  local {}x{}x{} dispatch {} {}\n", p.localSize[0], p.localSize[1], p.localSize[2],
                       toString(p.dispatch.mode), size(p.dispatch.size));
    for (const Binding& b : p.bindings)
      out += fmt::format("  binding {} {} {}{}\n", b.binding, b.image, toString(b.access),
                         b.level >= 0 ? fmt::format(" level {}", b.level) : "");
    if (!p.form.empty()) out += "  form " + p.form + " " + needs(p.formNeeds) + "\n";
    if (i >= graph.sources.size()) continue;
    for (const Constant& c : graph.sources[i].values.constants)
      out += fmt::format("  value {} {}\n", c.name, printValue(c.value));
    for (const Table& t : graph.sources[i].values.tables) out += "  " + printTable(t) + "\n";
    if (const auto& block = graph.sources[i].values.parameters) {
      out += fmt::format("  parameters binding {} size {}\n", block->binding, block->size);
      for (const BlockMember& m : block->members) {
        std::string vs;
        for (size_t k = 0; k < m.values.size() && k < 8; ++k) vs += fmt::format("{}{:.9g}", k ? " " : "", m.values[k]);
        out += fmt::format("  uniform {} {} {} offset {}{} = {}{}\n", m.macro, m.name, toString(m.type), m.offset,
                           m.stride ? fmt::format(" [{}] stride {}", m.count, m.stride) : std::string(), vs,
                           m.values.size() > 8 ? " ..." : "");
      }
    }
    // The other forms: their own template, dispatch and values (same bindings).
    for (size_t k = 0; k < p.forms.size() && k < graph.sources[i].forms.size(); ++k) {
      const PassForm& f = p.forms[k];
      const PassSource& src = graph.sources[i].forms[k];
      out += fmt::format("  form {} {} template {} stem {} local {}x{}x{} dispatch {} {}\n", f.name, needs(f.needs),
                         src.templatePath, src.stem, f.localSize[0], f.localSize[1], f.localSize[2],
                         toString(f.dispatch.mode), size(f.dispatch.size));
      for (const Constant& c : src.values.constants)
        out += fmt::format("    value {} {}\n", c.name, printValue(c.value));
    }
  }
  return out;
}

}  // namespace shadowc
