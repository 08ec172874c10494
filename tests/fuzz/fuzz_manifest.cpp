// libFuzzer target: the manifest loader (compiler/manifest, manifestFromJson after the same
// parse loadManifest does). Bad input must end in one ManifestError; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "manifest/manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const nlohmann::json j = nlohmann::json::parse(data, data + size, nullptr, false);
  if (j.is_discarded()) return 0;
  try {
    const shadowc::Manifest m = shadowc::manifestFromJson(j);
    // A manifest that loads must serialize again (the compiler writes what the runtime reads).
    (void)shadowc::toJson(m).dump();
  } catch (const shadowc::ManifestError&) {
  }
  return 0;
}
