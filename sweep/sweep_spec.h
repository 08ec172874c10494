// The sweep description (docs/sweep.md): which base filters, which parameter values, which
// scenes and settings a `shadowc sweep` runs. JSON, read with nlohmann; every error names the
// file and the JSON path of the field ("sweep.json: error: params.taps: ..."), and malformed
// JSON gets file:line:col.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "runtime/executor/run_timing.h"

namespace shadowc::sweep {

struct SweepSpecError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One parameter: its name (the ${name} placeholder) and the values it takes, as the text that
// replaces the placeholder ("16", "0.25", "int32").
struct Param {
  std::string name;
  std::vector<std::string> values;
};

// A base filter: a description (read from a file or given inline) whose ${name} placeholders
// the sweep fills in, plus settings it replaces (`set`: keyword -> value text, nullopt removes
// the setting), so a sample file can be varied without copying it.
struct BaseFilter {
  std::string name;    // label in tables (default: the file's stem, else "filter<i>")
  std::string source;  // where the text came from: the file path, or "<sweep.json>:filters[i]"
  std::string text;
  std::vector<std::pair<std::string, std::optional<std::string>>> set;
  std::vector<Param> params;  // filter-local ranges; they override the sweep's of the same name
};

// A scene a sweep runs on: a built-in name or a .json path, optionally with the light's width
// replaced (the light-size study runs one geometry under lights from a near-point to very large).
struct SceneEntry {
  std::string label;  // name in tables and file names (default: the scene's, plus the light size)
  std::string scene;  // built-in name or path (resolved against the sweep file's folder)
  std::optional<double> lightSize;
};

// How each variant is built: the specialized shader (`shadowc compile`) or the generic one
// (`shadowc compile --generic`: options as uniforms, dynamic loops; plan/generic_block.h).
// With both, each pair's frame-time ratio is reported (sweep/shader_ratio.h).
enum class ShaderKind { Specialized, Generic };
const char* shaderKindName(ShaderKind kind);

struct SweepSpec {
  std::string name;
  std::filesystem::path file;  // the sweep description (empty when parsed from text)
  std::vector<BaseFilter> filters;
  std::vector<Param> params;
  std::vector<SceneEntry> scenes;
  std::vector<uint32_t> screens{256};
  std::vector<uint32_t> maps{1024};
  // "sizes": (screen, map) pairs run instead of every screen with every map; empty = the product.
  std::vector<std::pair<uint32_t, uint32_t>> sizes;
  int referenceSamples = 16;
  rt::RunCount runs = 5;  // a count, or "auto" (run_timing.h RunCount)
  int warmup = 2;
  std::vector<ShaderKind> shaders{ShaderKind::Specialized};
  // "counters": also run each row's instrumented build once and keep its work per receiver
  // (docs/manifest.md "Work counters"); the times stay the plain build's.
  bool counters = false;
};

// `label` names the text in messages; relative file paths resolve against `baseDir`.
SweepSpec parseSweepSpec(const std::string& jsonText, const std::string& label, const std::filesystem::path& baseDir);
SweepSpec loadSweepSpec(const std::filesystem::path& file);

}  // namespace shadowc::sweep
