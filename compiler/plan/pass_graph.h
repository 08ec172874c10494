// PassGraph: what the planner decides for one filter, before any GLSL exists.
// `manifest` is the runtime's view (images, ordered passes, bindings, dispatch); `sources`
// holds, per pass and in the same order, how the emitter builds that pass's shader: which
// template, which #define constants. Passes that share a shader (mip1..mipK, minmax1..K)
// name the same output stem and are emitted once.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "manifest/manifest.h"

namespace shadowc {

struct PassSource {
  std::string templatePath;                                  // relative to templates/, e.g. "passes/sat_rows.comp"
  std::string stem;                                          // output file stem: <stem>.glsl, <stem>.spv
  std::vector<std::pair<std::string, std::string>> defines;  // emitted as `#define name value`
  bool lookup = false;  // true for the shade pass: defines come from specializeLookup()
};

struct PassGraph {
  Manifest manifest;                // formatVersion, filter, images, passes (no spec, hash, shade yet)
  std::vector<PassSource> sources;  // sources[i] builds manifest.passes[i]
};

}  // namespace shadowc
