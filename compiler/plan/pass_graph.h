// PassGraph: what the planner decides for one filter, before any GLSL exists — the complete
// intermediate form between plan/ and emit/. `manifest` is the runtime's view (images, ordered
// passes, bindings, dispatch); `sources` holds, per pass and in the same order, which template
// builds that pass's shader and every typed specialization value it gets (the shade pass
// included: its values also specialize the includable lookup file). Passes that share a shader
// (mip1..mipK, minmax1..K) name the same output stem and are emitted once.
#pragma once

#include <string>
#include <vector>

#include "manifest/manifest.h"
#include "plan/specialization.h"

namespace shadowc {

struct PassSource {
  std::string templatePath;  // relative to templates/, e.g. "passes/sat_rows.comp"
  std::string stem;          // output file stem: <stem>.glsl, <stem>.spv
  Specialization values;
  std::vector<PassSource> forms;  // forms[k] builds the pass's forms[k] (manifest.h "Pass forms")
};

struct PassGraph {
  Manifest manifest;                // formatVersion, filter, images, passes (no spec, hash, shade yet)
  std::vector<PassSource> sources;  // sources[i] builds manifest.passes[i]
};

// The shade pass's source (kind "shade"), or nullptr when the graph has none.
const PassSource* shadeSource(const PassGraph& graph);

}  // namespace shadowc
