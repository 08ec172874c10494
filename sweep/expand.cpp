#include "sweep/expand.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "sweep/filter_text.h"

namespace shadowc::sweep {
namespace {

// The parameter list a filter sees: its own ranges first take the name, then the sweep's.
const Param* findParam(const BaseFilter& f, const SweepSpec& spec, const std::string& name) {
  for (const auto& p : f.params)
    if (p.name == name) return &p;
  for (const auto& p : spec.params)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

std::string Shard::text() const { return fmt::format("{}/{}", index, count); }

Shard parseShard(const std::string& text) {
  const size_t slash = text.find('/');
  Shard s;
  try {
    size_t used = 0;
    if (slash == std::string::npos) throw std::invalid_argument("");
    s.index = std::stoi(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("");
    s.count = std::stoi(text.substr(slash + 1), &used);
    if (used != text.size() - slash - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument(fmt::format("--shard '{}': expected I/N, e.g. 0/4", text));
  }
  if (s.count < 1 || s.index < 0 || s.index >= s.count)
    throw std::invalid_argument(fmt::format("--shard '{}': need 0 <= I < N", text));
  return s;
}

Expansion expand(const SweepSpec& spec) {
  Expansion e;
  std::set<std::string> used;
  for (size_t fi = 0; fi < spec.filters.size(); ++fi) {
    const BaseFilter& f = spec.filters[fi];
    for (size_t k = 0; k < fi; ++k)
      if (spec.filters[k].name == f.name)
        throw SweepSpecError(fmt::format("{}: error: filters[{}]: two filters are named '{}'; give one a \"name\"",
                                         spec.file.string(), fi, f.name));
    std::string text = f.text;
    for (const auto& [keyword, value] : f.set) text = setSetting(text, keyword, value);
    // The axes this filter varies along, in the order the sweep lists them (filter-local first).
    std::vector<const Param*> axes;
    for (const std::string& name : placeholders(text)) {
      const Param* p = findParam(f, spec, name);
      if (!p)
        throw SweepSpecError(fmt::format("{}: error: filters[{}] ({}): ${{{}}} has no values in \"params\"",
                                         spec.file.string(), fi, f.name, name));
      axes.push_back(p);
      used.insert(name);
    }
    // The product of the axes, last axis fastest.
    std::vector<size_t> at(axes.size(), 0);
    for (bool more = true; more;) {
      std::map<std::string, std::string> values;
      std::vector<std::pair<std::string, std::string>> params;
      for (size_t a = 0; a < axes.size(); ++a) {
        values[axes[a]->name] = axes[a]->values[at[a]];
        params.emplace_back(axes[a]->name, axes[a]->values[at[a]]);
      }
      std::string label = f.name;
      if (!params.empty()) {
        label += "[";
        for (size_t a = 0; a < params.size(); ++a) label += (a ? "," : "") + params[a].first + "=" + params[a].second;
        label += "]";
      }
      const std::string variantText = fillPlaceholders(text, values);
      for (ShaderKind shader : spec.shaders) {
        Variant v;
        v.index = e.variants.size();
        v.base = f.name;
        v.source = f.source;
        v.params = params;
        v.shader = shader;
        v.label = label + (shader == ShaderKind::Generic ? " (generic)" : "");
        v.text = variantText;
        e.variants.push_back(std::move(v));
      }
      more = false;
      for (size_t a = axes.size(); a-- > 0;) {
        if (++at[a] < axes[a]->values.size()) {
          more = true;
          break;
        }
        at[a] = 0;
      }
    }
  }
  for (const auto& p : spec.params)
    if (!used.count(p.name)) e.warnings.push_back(fmt::format("parameter '{}' is used by no filter", p.name));
  for (const auto& f : spec.filters)
    for (const auto& p : f.params)
      if (!used.count(p.name))
        e.warnings.push_back(fmt::format("parameter '{}' of filter '{}' is not used", p.name, f.name));
  std::vector<std::pair<uint32_t, uint32_t>> sizes = spec.sizes;
  if (sizes.empty())
    for (uint32_t screen : spec.screens)
      for (uint32_t map : spec.maps) sizes.emplace_back(screen, map);
  for (const SceneEntry& scene : spec.scenes)
    for (const auto& [screen, map] : sizes) {
      Case c;
      c.index = e.cases.size();
      c.scene = scene;
      c.screen = screen;
      c.map = map;
      c.label = fmt::format("{} {}px map {}", scene.label, screen, map);
      e.cases.push_back(std::move(c));
    }
  return e;
}

}  // namespace shadowc::sweep
