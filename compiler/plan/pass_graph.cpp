#include "plan/pass_graph.h"

namespace shadowc {

const PassSource* shadeSource(const PassGraph& graph) {
  for (size_t i = 0; i < graph.manifest.passes.size() && i < graph.sources.size(); ++i)
    if (graph.manifest.passes[i].kind == "shade") return &graph.sources[i];
  return nullptr;
}

}  // namespace shadowc
