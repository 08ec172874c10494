// CompiledPasses: a manifest and the bytes of the shader files it names, in memory. The
// contract between the compiler driver (driver::Artifact::passes()) and the run harness
// (runtime/harness/run_harness.h), like the manifest itself; also read back from a directory
// written by `shadowc compile` (fromDirectory).
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "manifest/manifest.h"

namespace shadowc {

struct CompiledPasses {
  Manifest manifest;
  std::map<std::string, std::string> files;  // file name (as in Pass::spirv) -> bytes
  // Reads DIR/manifest.json (or the manifest file itself; loadManifest gives one message for a
  // wrong version or a malformed file) and every .spv it names. Throws std::runtime_error
  // naming a missing file.
  static CompiledPasses fromDirectory(const std::filesystem::path& dirOrManifest);
  // Whether `path` is what fromDirectory reads, by content, whatever its name: a directory with
  // a manifest.json, or a file whose first non-whitespace byte opens a JSON object (a filter
  // description cannot: its first token is `filter`, docs/dsl.md "Grammar").
  static bool isManifest(const std::filesystem::path& path);
};

}  // namespace shadowc
