// `shadowc compile --print-plan`: the PassGraph as stable, readable text (SPIRV-Tools prints
// its recipe the same way): the images with formats and sizes, then the passes in execution
// order, each with its template, output stem, dispatch, bindings and every specialization
// value and generated table. Same graph -> same bytes. The format is documented in
// docs/manifest.md ("Printing the plan").
#pragma once

#include <string>

#include "plan/pass_graph.h"

namespace shadowc {

std::string printPassGraph(const PassGraph& graph);

// One value as --print-plan shows it: "int 3", "bool 1", "real 0.04", "enum SHADOWC_WARP_LINEAR (0)",
// "format rg32f", "real[3] 0, 0.5, 1". Reals in the shortest text that reads back the same double.
std::string printValue(const SpecValue& value);

}  // namespace shadowc
