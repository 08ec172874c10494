// The generic rewrite of the shade pass (generic_block.h). Layout: std140 — scalars packed 4
// bytes apart from offset 0, then each array at a 16-byte boundary with a 16-byte element stride
// (std140 rounds every array element up to a vec4), the block size rounded up to 16.
#include "plan/generic_block.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "plan/internal_error.h"
#include "plan/quadtree_tables.h"
#include "spec/filter_spec.h"

namespace shadowc {
namespace {

// Integers the templates use in #if or as array sizes: they stay compile-time.
// The light views are part of what an engine renders (the manifest's spec), so their count and
// offsets stay compile-time too.
constexpr std::string_view kStaticIntegers[] = {"SHADOWC_LAYERS", "SHADOWC_SAT_PIECES", "SHADOWC_UNIFORM_MAX_DEN",
                                                "SHADOWC_LIGHT_SAMPLES", "SHADOWC_LIGHT_SAMPLE_GRID"};
constexpr std::string_view kLightSampleTable = "shadowc_lightSampleOffsets";

bool staysStatic(const Constant& c) {
  if (!std::holds_alternative<long long>(c.value) && !std::holds_alternative<Real>(c.value)) return true;
  return std::find(std::begin(kStaticIntegers), std::end(kStaticIntegers), c.name) != std::end(kStaticIntegers);
}

uint32_t roundUp(uint32_t v, uint32_t to) { return (v + to - 1) / to * to; }

}  // namespace

std::string genericMemberName(const std::string& macro) {
  std::string_view rest = macro;
  if (rest.starts_with("SHADOWC_")) {
    rest.remove_prefix(8);
    std::string out;
    bool upper = false;
    for (char ch : rest) {
      if (ch == '_') {
        upper = true;
        continue;
      }
      const char lower = char(std::tolower(static_cast<unsigned char>(ch)));
      out += upper ? char(std::toupper(static_cast<unsigned char>(lower))) : lower;
      upper = false;
    }
    return out;
  }
  if (rest.starts_with("shadowc_")) rest.remove_prefix(8);
  return std::string(rest);
}

void makeGeneric(PassGraph& graph) {
  const auto shade = std::find_if(graph.manifest.passes.begin(), graph.manifest.passes.end(),
                                  [](const Pass& p) { return p.kind == "shade"; });
  if (shade == graph.manifest.passes.end() || graph.sources.size() != graph.manifest.passes.size())
    throw InternalError("generic: the pass graph has no shade pass");
  Specialization& values = graph.sources[size_t(shade - graph.manifest.passes.begin())].values;
  if (values.parameters) throw InternalError("generic: the shade pass is generic already");

  ParameterBlock block;
  block.binding = kGenericBinding;
  uint32_t offset = 0;
  std::vector<Constant> kept;
  for (Constant& c : values.constants) {
    if (staysStatic(c)) {
      kept.push_back(std::move(c));
      continue;
    }
    BlockMember m;
    m.name = genericMemberName(c.name);
    m.macro = c.name;
    if (const long long* i = std::get_if<long long>(&c.value)) {
      m.type = ScalarType::I32;
      m.values = {double(*i)};
    } else {
      m.type = ScalarType::F32;
      m.values = {std::get<Real>(c.value).value};
    }
    m.offset = offset;
    offset += 4;
    block.members.push_back(std::move(m));
  }

  // Tables become arrays; the unrolled quadtree becomes the loop walk over the larger tree.
  int unrolledHeight = 0;
  std::vector<Table> tables;
  for (Table& t : values.tables) {
    if (const auto* u = std::get_if<UnrolledQuadtree>(&t)) {
      unrolledHeight = std::max(unrolledHeight, u->height);
      continue;
    }
    if (const auto* p = std::get_if<PointTable>(&t); p && p->name == kLightSampleTable) {
      tables.push_back(std::move(t));
      continue;
    }
    BlockMember m;
    m.type = ScalarType::F32;
    m.stride = 16;
    if (const auto* p = std::get_if<PointTable>(&t)) {
      if (p->points.size() > size_t(kMaxGenericTaps))
        throw InternalError("generic: more Poisson taps than the block holds");
      m.name = genericMemberName(p->name);
      m.macro = p->name;
      m.count = kMaxGenericTaps;
      m.components = 2;
      for (const auto& [x, y] : p->points) m.values.insert(m.values.end(), {x, y});
    } else if (const auto* r = std::get_if<RealTable>(&t)) {
      m.name = genericMemberName(r->name);
      m.macro = r->name;
      m.count = uint32_t(std::max<size_t>(1, r->values.size()));  // layers + 1: the layer count stays static
      m.values = r->values;
    } else {
      tables.push_back(std::move(t));  // no other table reaches the shade pass today
      continue;
    }
    block.members.push_back(std::move(m));
  }
  // m and n become uniforms: the uniform walk's arrays (vssm.glsl) take the largest the checker accepts.
  for (Constant& c : kept)
    if (c.name == "SHADOWC_UNIFORM_MAX_DEN") c.value = static_cast<long long>(std::max(kMaxUniformM, kMaxUniformN));
  if (unrolledHeight > 0) {
    for (Constant& c : kept)
      if (c.name == "SHADOWC_QUADTREE_UNROLLED") c.value = false;
    block.members.push_back(
        {"qtNodes", "SHADOWC_QT_NODES", ScalarType::I32, offset, 0, 1, 1, {double(quadtreeNodeCount(unrolledHeight))}});
    offset += 4;
  }
  // Arrays after the scalars, each 16-aligned (the scalar members keep their order).
  std::stable_partition(block.members.begin(), block.members.end(), [](const BlockMember& m) { return m.stride == 0; });
  for (BlockMember& m : block.members)
    if (m.stride) {
      m.offset = roundUp(offset, 16);
      offset = m.offset + m.count * m.stride;
    }
  block.size = std::max<uint32_t>(16, roundUp(offset, 16));

  // The walk's Next/Child tables for the tallest tree the language allows: they walk every smaller
  // height (plan/quadtree_tables.h), so the heights can be uniforms as well.
  for (BufferDesc& b : graph.manifest.buffers)
    if (b.name == kQuadtreeTableBuffer) b = quadtreeTableBuffer(buildQuadtreeTables(kMaxQuadtreeHeight));

  values.constants = std::move(kept);
  values.tables = std::move(tables);
  values.parameters = block;
  shade->bindings.push_back({kGenericBinding, kParametersBinding, Access::Uniform, -1});
  shade->parameters = std::move(block);
}

}  // namespace shadowc
