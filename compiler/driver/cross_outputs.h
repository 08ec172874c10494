// `--emit hlsl` / `--emit msl`: the filter's shaders in HLSL (SM 5.0) and MSL (2.1) through
// SPIRV-Cross (backend/cross_compile.h):
//   * <stem>.hlsl / <stem>.metal for every pass shader, translated from its <stem>.spv (the
//     optimized module the runtime runs, so the shade pass carries the lookup inlined);
//   * <filter>_lookup.hlsl / <filter>_lookup.metal, the lookup for inclusion: the GLSL lookup
//     compiled without spirv-opt (so its functions survive with their names) inside a one-line
//     probe entry point `shadowc_lookup_probe` that calls shadowc_visibility; SPIRV-Cross keeps
//     every reachable function. In HLSL the resources are globals and the function keeps its GLSL
//     signature; Metal has no global resources, so in MSL they are trailing arguments.
//     With the external frame (`--frame-external`) the frame is not our uniform block but
//     arguments of shadowc_visibilityFrame(worldPos, worldNormal, frame[, cascades]).
#pragma once

#include <string>
#include <vector>

#include "backend/cross_compile.h"
#include "emit/content_hash.h"
#include "manifest/manifest.h"

namespace shadowc {

inline constexpr const char* kLookupProbeEntry = "shadowc_lookup_probe";
// The external-frame lookup's function: shadowc_visibility with the frame as arguments.
inline constexpr const char* kLookupExternalFunction = "shadowc_visibilityFrame";

// Appends the translated files to `out`. `files` are the emitted files (every .spv the manifest
// names and the lookup GLSL). `externalFrame`: the lookup takes the frame as arguments instead of
// declaring our uniform block. False with a located message in `log` when a translation fails.
bool crossOutputs(const Manifest& manifest, const std::vector<EmittedFile>& files, CrossTarget target,
                  bool externalFrame, std::vector<EmittedFile>& out, std::string& log);

}  // namespace shadowc
